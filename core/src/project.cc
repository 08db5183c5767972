#include "highlift/core/project.h"

#include <sstream>

namespace highlift {

namespace {
template <class Vector>
auto FindById(Vector& components, std::string_view id) -> decltype(&components.front()) {
  for (auto& c : components)
    if (c.id == id) return &c;
  return nullptr;
}
}  // namespace

const Component* Project::FindComponent(std::string_view id) const {
  if (const Component* c = FindById(components, id)) return c;
  return FindById(elements, id);
}

Component* Project::FindComponent(std::string_view id) {
  if (Component* c = FindById(components, id)) return c;
  return FindById(elements, id);
}

const Scenario* Project::FindScenario(std::string_view name) const {
  for (const auto& s : scenarios)
    if (s.name == name) return &s;
  return nullptr;
}

std::vector<std::vector<double>> SpeedCommandRows(const LoadCase* load_case) {
  std::vector<std::vector<double>> rows;
  if (load_case && load_case->pdu_speed && !load_case->pdu_speed->x.empty()) {
    const double direction = load_case->direction == "retract" ? -1.0 : 1.0;
    const Table& t = *load_case->pdu_speed;
    for (std::size_t i = 0; i < t.x.size(); ++i) rows.push_back({t.x[i], direction * t.y[i]});
  } else {
    rows = {{0.0, 0.0}, {1.0, 0.0}};
  }
  if (rows.size() == 1) rows.push_back({rows[0][0] + 1.0, rows[0][1]});
  return rows;
}

const LoadCase* Project::FindLoadCase(std::string_view name) const {
  for (const auto& l : load_cases)
    if (l.name == name) return &l;
  return nullptr;
}

}  // namespace highlift

// ---------------------------------------------------------------------------------------------
// Comparison for round-trip tests (source locations are not compared).

namespace highlift {

namespace {

std::string Show(const std::optional<double>& v) {
  if (!v) return "unset";
  std::ostringstream s;
  s.precision(17);
  s << *v;
  return s.str();
}

std::string Show(double v) { return Show(std::optional<double>(v)); }

std::string Show(const Domain& d) { return "[" + Show(d.lo) + ", " + Show(d.hi) + "]"; }

std::string Compare(const Parameter& a, const Parameter& b) {
  if (a.nominal != b.nominal) return "nominal " + Show(a.nominal) + " vs " + Show(b.nominal);
  if (!(a.domain == b.domain)) return "domain " + Show(a.domain) + " vs " + Show(b.domain);
  if (a.provenance != b.provenance) return "provenance " + ToString(a.provenance) + " vs " + ToString(b.provenance);
  if (a.note != b.note) return "note '" + a.note + "' vs '" + b.note + "'";
  if (a.design != b.design) return std::string("design ") + (a.design ? "true" : "false") + " vs " + (b.design ? "true" : "false");
  if (a.database_part != b.database_part) return "part '" + a.database_part + "' vs '" + b.database_part + "'";
  return "";
}

std::string Compare(const Component& a, const Component& b) {
  if (a.id != b.id) return "id '" + a.id + "' vs '" + b.id + "'";
  if (a.type != b.type) return "type '" + a.type + "' vs '" + b.type + "'";
  if (a.description != b.description) return "description differs";
  if (a.labels != b.labels) return "labels differ";
  if (a.texts != b.texts) return "text parameters differ";
  if (a.tables != b.tables) return "table parameters differ";
  for (const auto& [name, p] : a.parameters) {
    auto it = b.parameters.find(name);
    if (it == b.parameters.end()) return "parameter '" + name + "' missing in the second";
    if (auto d = Compare(p, it->second); !d.empty()) return "parameter '" + name + "': " + d;
  }
  for (const auto& [name, p] : b.parameters)
    if (!a.parameters.count(name)) return "parameter '" + name + "' missing in the first";
  return "";
}

bool SameTable(const Table& a, const Table& b) { return a.abscissa == b.abscissa && a.x == b.x && a.y == b.y; }

template <class T, class F>
std::string CompareLists(const std::string& what, const std::vector<T>& a, const std::vector<T>& b, F compare) {
  if (a.size() != b.size())
    return what + ": " + std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " entries";
  for (std::size_t i = 0; i < a.size(); ++i)
    if (auto d = compare(a[i], b[i]); !d.empty()) return what + "[" + std::to_string(i) + "]: " + d;
  return "";
}

}  // namespace

std::string DescribeDifference(const Project& a, const Project& b) {
  if (a.name != b.name) return "name '" + a.name + "' vs '" + b.name + "'";
  if (a.description != b.description) return "description differs";
  if (a.sources != b.sources) return "sources differ";
  const Settings &sa = a.settings, &sb = b.settings;
  if (sa.shaft_elements != sb.shaft_elements || sa.relative_tolerance != sb.relative_tolerance ||
      sa.output_interval != sb.output_interval || sa.structural_damping != sb.structural_damping ||
      sa.initial != sb.initial || sa.values != sb.values)
    return "settings differ";
  auto components = [](const Component& x, const Component& y) {
    auto d = Compare(x, y);
    return d.empty() ? d : "'" + x.id + "': " + d;
  };
  auto connections = [](const Connection& x, const Connection& y) {
    return (x.a == y.a && x.b == y.b) ? std::string()
                                      : x.a.ToString() + "-" + x.b.ToString() + " vs " + y.a.ToString() + "-" + y.b.ToString();
  };
  if (auto d = CompareLists("components", a.components, b.components, components); !d.empty()) return d;
  if (auto d = CompareLists("connections", a.connections, b.connections, connections); !d.empty()) return d;
  if (auto d = CompareLists("elements", a.elements, b.elements, components); !d.empty()) return d;
  if (auto d = CompareLists("element_connections", a.element_connections, b.element_connections, connections); !d.empty())
    return d;
  auto requirements = [](const Requirement& x, const Requirement& y) {
    return (x.id == y.id && x.expression == y.expression && x.description == y.description) ? std::string()
                                                                                           : "'" + x.id + "' differs";
  };
  if (auto d = CompareLists("requirements", a.requirements, b.requirements, requirements); !d.empty()) return d;
  auto load_cases = [](const LoadCase& x, const LoadCase& y) {
    bool same = x.name == y.name && x.description == y.description && x.direction == y.direction &&
                x.values == y.values && x.pdu_speed.has_value() == y.pdu_speed.has_value() &&
                (!x.pdu_speed || SameTable(*x.pdu_speed, *y.pdu_speed)) && x.actuator_loads.size() == y.actuator_loads.size();
    if (same) {
      for (const auto& [id, t] : x.actuator_loads) {
        auto it = y.actuator_loads.find(id);
        if (it == y.actuator_loads.end() || !SameTable(t, it->second)) same = false;
      }
    }
    return same ? std::string() : "'" + x.name + "' differs";
  };
  if (auto d = CompareLists("load_cases", a.load_cases, b.load_cases, load_cases); !d.empty()) return d;
  auto scenarios = [](const Scenario& x, const Scenario& y) {
    const bool same = x.name == y.name && x.kind == y.kind && x.description == y.description &&
                      x.load_case == y.load_case && x.stop_time == y.stop_time &&
                      x.output_interval == y.output_interval && x.jam_component == y.jam_component &&
                      x.jam_time == y.jam_time && x.rupture_component == y.rupture_component &&
                      x.rupture_time == y.rupture_time && x.wtb_trigger == y.wtb_trigger && x.wtb_time == y.wtb_time &&
                      x.values == y.values;
    return same ? std::string() : "'" + x.name + "' differs";
  };
  return CompareLists("scenarios", a.scenarios, b.scenarios, scenarios);
}

}  // namespace highlift
