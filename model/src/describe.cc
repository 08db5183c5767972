#include "highlift/model/describe.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <type_traits>

#include "highlift/core/catalogue.h"
#include "highlift/core/graph.h"
#include "highlift/core/text_table.h"
#include "highlift/core/units.h"
#include "highlift/model/component_model.h"

namespace highlift::model {

std::string ToString(ParameterConcern::Kind kind) {
  return kind == ParameterConcern::Kind::kUnknown ? "unknown" : "wide";
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A parameter of the component, or its catalogue default when the project has none for it.
std::optional<Parameter> Effective(const Component& c, std::string_view name) {
  if (const auto it = c.parameters.find(std::string(name)); it != c.parameters.end()) return it->second;
  const ComponentTypeSpec* type = FindComponentType(c.type);
  const ParameterSpec* spec = type ? type->FindParameter(std::string(name)) : nullptr;
  if (!spec) return std::nullopt;
  Parameter p;
  p.nominal = spec->nominal;
  p.domain = spec->default_domain;
  p.note = spec->source;
  return p;
}

/// The value of a parameter for reports: its nominal value, else the middle of a domain that was
/// given (a catalogue default without a nominal value is the valid range: no value).
std::optional<double> PointValue(const Component& c, std::string_view name) {
  const std::optional<Parameter> p = Effective(c, name);
  if (!p) return std::nullopt;
  if (p->nominal) return p->nominal;
  if (p->provenance != Provenance::kDefault && p->domain.bounded() && !p->domain.empty()) return p->domain.mid();
  return std::nullopt;
}

/// A component's parameters as its laws read them: the point value (double), or its domain
/// when bounded (Interval; else the point). A parameter without a value throws InputError, which
/// leaves the quantity unknown.
template <class T>
class DescribeReader final : public ParameterReader<T> {
 public:
  explicit DescribeReader(const Component& c) : c_(c) {}
  T operator()(std::string_view name) const override {
    const double v = Nominal(name);
    if constexpr (std::is_same_v<T, Interval>) {
      const Domain d = Effective(c_, name)->domain;
      if (d.bounded() && !d.empty() && d.contains(v)) return Interval(d.lo, d.hi);
    }
    return T(v);
  }
  bool Has(std::string_view name) const override { return PointValue(c_, name).has_value(); }
  double Nominal(std::string_view name) const override {
    if (const auto v = PointValue(c_, name)) return *v;
    throw InputError("component '" + c_.id + "' (" + c_.type + "): parameter '" + std::string(name) + "' has no value",
                     c_.where);
  }

 private:
  const Component& c_;
};

/// Nominal value and range of a quantity from a component's laws.
struct Estimate {
  double nominal = 0;
  double lo = 0;
  double hi = 0;
  bool known = false;  ///< false when a value the law needs is unknown
};

/// The inertia of a component at its input flange (its lumped law), kg*m^2.
Estimate ComponentInertia(const Component& c, const ComponentModel& m) {
  try {
    const Interval J = m.LumpedAtInput(DescribeReader<Interval>(c)).J;
    return {m.LumpedAtInput(DescribeReader<double>(c)).J, J.lo, J.hi, true};
  } catch (const InputError&) {
    return {};
  }
}

/// Length and mass of a distributed segment (nominal values; a mass that cannot be computed is 0).
struct SegmentNumbers {
  double length = 0;  ///< m
  double mass = 0;    ///< kg
};

SegmentNumbers Segment(const Component& c) {
  const DescribeReader<double> p(c);
  SegmentNumbers s;
  s.length = PointValue(c, "length").value_or(0.0);
  try {
    s.mass = SegmentMass(p);
  } catch (const InputError&) {
  }
  return s;
}

std::string Label(const Component& c, const std::string& key) {
  const auto it = c.labels.find(key);
  return it == c.labels.end() ? std::string() : it->second;
}

std::string Display(double si, const ParameterSpec* spec, int digits = 4) {
  if (!spec || std::isinf(si) || std::isnan(si)) return FormatNumber(si, digits);
  try {
    return FormatNumber(FromSI(si, spec->unit, spec->dimension), digits);
  } catch (const InputError&) {
    return FormatNumber(si, digits);
  }
}

std::string DisplayUnit(const ParameterSpec* spec) {
  if (!spec || spec->unit.empty() || spec->unit == "1") return "";
  return spec->unit;
}

std::string DomainText(const Domain& d, const ParameterSpec* spec) {
  const std::string unit = DisplayUnit(spec);
  return "[" + Display(d.lo, spec) + ", " + Display(d.hi, spec) + "]" + (unit.empty() ? "" : " " + unit);
}

/// Group key of concerns that read the same (same type, parameter, values, provenance, note).
struct ConcernGroup {
  const ParameterConcern* first = nullptr;
  std::vector<std::string> components;
};

std::vector<ConcernGroup> GroupConcerns(const std::vector<ParameterConcern>& concerns, ParameterConcern::Kind kind) {
  std::vector<ConcernGroup> groups;
  std::map<std::string, std::size_t> index;
  for (const auto& c : concerns) {
    if (c.kind != kind) continue;
    const std::string key = c.type + "|" + c.parameter + "|" + FormatNumber(c.nominal.value_or(kNaN), 10) + "|" +
                            FormatNumber(c.domain.lo, 10) + "|" + FormatNumber(c.domain.hi, 10) + "|" +
                            ToString(c.provenance) + "|" + c.note;
    const auto [it, inserted] = index.emplace(key, groups.size());
    if (inserted) groups.push_back({&c, {}});
    groups[it->second].components.push_back(c.component);
  }
  return groups;
}

std::string JoinIds(const std::vector<std::string>& ids, std::size_t max_shown = 4) {
  std::string s;
  for (std::size_t i = 0; i < ids.size() && i < max_shown; ++i) s += (i ? ", " : "") + ids[i];
  if (ids.size() > max_shown) s += ", ... (" + std::to_string(ids.size()) + ")";
  return s;
}

nlohmann::json DomainJson(const Domain& d) {
  auto bound = [](double v) -> nlohmann::json {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
  };
  return nlohmann::json::array({bound(d.lo), bound(d.hi)});
}

}  // namespace

ProjectDescription DescribeProject(const Project& project, const DescribeOptions& options) {
  ProjectDescription r;
  r.name = project.name;
  r.file = project.file;
  r.components = project.components.size();
  r.connections = project.connections.size();
  r.elements = project.elements.size();
  r.requirements = project.requirements.size();
  r.load_cases = project.load_cases.size();
  r.scenarios = project.scenarios.size();

  // Components by type, in catalogue order; unknown types (invalid projects) at the end.
  std::map<std::string, int> counts;
  for (const auto& c : project.components) counts[c.type]++;
  for (const auto& type : ComponentTypes()) {
    if (const auto it = counts.find(type.name); it != counts.end()) {
      r.components_by_type.emplace_back(type.name, it->second);
      counts.erase(it);
    }
  }
  for (const auto& [type, count] : counts) r.components_by_type.emplace_back(type, count);

  // Shafts per side.
  auto side_of = [&](const std::string& label) -> SideSummary& {
    const std::string side = label.empty() ? "(none)" : label;
    for (auto& s : r.sides)
      if (s.side == side) return s;
    r.sides.push_back({side, 0, 0, 0, 0});
    return r.sides.back();
  };
  for (const auto& c : project.components) {
    const ComponentModel* m = FindComponentModel(c.type);
    if (!m) continue;  // validation reports unknown types
    if (m->roles().segment) {
      const SegmentNumbers s = Segment(c);
      SideSummary& side = side_of(Label(c, "side"));
      side.shaft_count++;
      side.shaft_length += s.length;
      side.shaft_mass += s.mass;
      r.shaft_count++;
      r.shaft_length += s.length;
      r.shaft_mass += s.mass;
    } else if (m->roles().actuator) {
      side_of(Label(c, "side")).stations++;
    }
  }

  // Speeds relative to the PDU output along the power path (core graph API). Inertias are
  // referred to a component's input flange (gearboxes, limiters, actuators) or to its flanges
  // that turn together (shafts, bearings, joints, brakes, sensors).
  const ComponentGraph graph(project);
  std::map<std::string, double> speed;  // component id -> reference-flange speed / PDU speed
  for (const auto& c : project.components) {
    const ComponentTypeSpec* type = FindComponentType(c.type);
    const bool has_input = type && type->FindPort("input");
    const std::optional<double> s = has_input ? graph.SpeedRatioAtPort(c.id, "input") : graph.SpeedRatio(c.id);
    if (s) speed[c.id] = *s;
  }

  // Stations and the reflected inertia.
  double lo = 0, hi = 0;
  for (const auto& c : project.components) {
    const auto s = speed.find(c.id);
    const ComponentModel* m = FindComponentModel(c.type);
    if (!m) continue;
    if (m->roles().actuator) {
      StationSummary st;
      st.actuator = c.id;
      st.type = c.type;
      st.side = Label(c, "side");
      st.station = Label(c, "station");
      if (s != speed.end() && s->second > 0) {
        st.speed_ratio = 1.0 / s->second;
        const std::optional<double> ratio = PointValue(c, "ratio");
        if (ratio) st.total_ratio = st.speed_ratio * *ratio;
        st.path = graph.Route(c.id);
      }
      r.stations.push_back(std::move(st));
    }
    const Estimate J = ComponentInertia(c, *m);
    if (!J.known || J.hi == 0) continue;
    if (s == speed.end() || !(s->second > 0) || !std::isfinite(s->second)) {
      r.unreachable.push_back(c.id);
      continue;
    }
    const double k = s->second * s->second;  // J / (PDU speed / local speed)^2
    InertiaContribution contribution{c.id, c.type, J.nominal, 1.0 / s->second, J.nominal * k};
    r.inertias.push_back(contribution);
    r.reflected_inertia += J.nominal * k;
    lo += J.lo * k;
    hi += J.hi * k;
  }
  r.reflected_inertia_domain = Domain{lo, hi};

  // Unknown and wide parameters.
  for (const auto& c : project.components) {
    const ComponentTypeSpec* type = FindComponentType(c.type);
    if (!type) continue;
    for (const ParameterSpec& spec : type->parameters) {
      if (spec.kind != ParameterKind::kScalar) continue;
      r.parameters++;
      const Parameter p = *Effective(c, spec.name);
      ParameterConcern concern;
      concern.component = c.id;
      concern.type = c.type;
      concern.parameter = spec.name;
      concern.unit = spec.unit;
      concern.nominal = p.nominal;
      concern.domain = p.domain;
      concern.provenance = p.provenance;
      concern.note = p.database_part.empty() ? p.note : "database part " + p.database_part;
      const double mid = p.domain.mid();
      concern.relative_width = p.domain.bounded() ? (mid != 0 ? p.domain.width() / std::fabs(mid)
                                                              : (p.domain.width() > 0 ? INFINITY : 0.0))
                                                  : INFINITY;
      if (!p.nominal) {
        // Optional parameters (derived from others, e.g. a shaft's stiffness) may stay unknown.
        if (spec.optional && p.provenance == Provenance::kDefault) continue;
        concern.kind = ParameterConcern::Kind::kUnknown;
      } else if (concern.relative_width > options.wide_relative_width) {
        concern.kind = ParameterConcern::Kind::kWide;
      } else {
        continue;
      }
      r.concerns.push_back(std::move(concern));
    }
  }
  std::stable_sort(r.concerns.begin(), r.concerns.end(), [](const auto& a, const auto& b) {
    return a.kind == ParameterConcern::Kind::kUnknown && b.kind != ParameterConcern::Kind::kUnknown;
  });
  return r;
}

int ProjectDescription::CountConcerns(ParameterConcern::Kind kind) const {
  return static_cast<int>(std::count_if(concerns.begin(), concerns.end(), [&](const auto& c) { return c.kind == kind; }));
}

std::string ProjectDescription::BriefReport() const {
  std::string s = name + ": " + std::to_string(components) + " components, " + std::to_string(stations.size()) +
                  " stations, " + FormatNumber(shaft_length, 4) + " m of shaft (" + FormatNumber(shaft_mass, 3) +
                  " kg), inertia at the PDU output " + FormatNumber(reflected_inertia, 3) + " kg*m^2 [" +
                  FormatNumber(reflected_inertia_domain.lo, 3) + ", " + FormatNumber(reflected_inertia_domain.hi, 3) +
                  "]; " + std::to_string(CountConcerns(ParameterConcern::Kind::kUnknown)) + " unknown and " +
                  std::to_string(CountConcerns(ParameterConcern::Kind::kWide)) + " wide parameters";
  return s;
}

std::string ProjectDescription::FullReport() const {
  std::string out = name + (file.empty() ? "" : "  (" + file + ")") + "\n";
  out += std::to_string(components) + " components, " + std::to_string(connections) + " connections, ";
  if (elements > 0) out += std::to_string(elements) + " elements, ";
  out += std::to_string(requirements) + " requirements, " + std::to_string(load_cases) + " load cases, " +
         std::to_string(scenarios) + " scenarios\n\n";

  out += "Components by type\n";
  TextTable types({"type", "count"}, {1});
  for (const auto& [type, count] : components_by_type) types.AddRow({type, std::to_string(count)});
  out += types.ToString() + "\n";

  out += "Torque shafts\n";
  TextTable shafts({"side", "segments", "length [m]", "mass [kg]", "stations"}, {1, 2, 3, 4});
  for (const auto& s : sides)
    shafts.AddRow({s.side, std::to_string(s.shaft_count), FormatNumber(s.shaft_length, 4),
                   FormatNumber(s.shaft_mass, 4), std::to_string(s.stations)});
  shafts.AddRow({"all", std::to_string(shaft_count), FormatNumber(shaft_length, 4), FormatNumber(shaft_mass, 4),
                 std::to_string(stations.size())});
  out += shafts.ToString() + "\n";

  out += "Stations (" + std::to_string(stations.size()) + ")\n";
  TextTable st({"actuator", "side", "station", "PDU speed / input speed", "PDU speed / output speed"}, {3, 4});
  for (const auto& s : stations)
    st.AddRow({s.actuator, s.side, s.station, s.speed_ratio > 0 ? FormatNumber(s.speed_ratio, 4) : "not reached",
               s.total_ratio > 0 ? FormatNumber(s.total_ratio, 4) : "-"});
  out += st.ToString() + "\n";

  out += "Inertia reflected to the PDU output: " + FormatNumber(reflected_inertia, 4) + " kg*m^2 (range [" +
         FormatNumber(reflected_inertia_domain.lo, 4) + ", " + FormatNumber(reflected_inertia_domain.hi, 4) +
         "] from the parameter domains), sum of J / (PDU speed / local speed)^2\n";
  std::vector<std::pair<std::string, std::pair<int, double>>> by_type;
  for (const auto& c : inertias) {
    auto it = std::find_if(by_type.begin(), by_type.end(), [&](const auto& e) { return e.first == c.type; });
    if (it == by_type.end()) it = by_type.insert(by_type.end(), {c.type, {0, 0.0}});
    it->second.first++;
    it->second.second += c.reflected;
  }
  TextTable inertia({"type", "count", "reflected J [kg*m^2]", "share"}, {1, 2, 3});
  for (const auto& [type, e] : by_type)
    inertia.AddRow({type, std::to_string(e.first), FormatNumber(e.second, 4),
                    FormatNumber(reflected_inertia > 0 ? 100 * e.second / reflected_inertia : 0.0, 3) + " %"});
  out += inertia.ToString();
  if (!unreachable.empty()) out += "not reached from the PDU (left out): " + JoinIds(unreachable, 8) + "\n";
  out += "\n";

  const auto concern_table = [&](ParameterConcern::Kind kind) {
    TextTable t({"type.parameter", "components", "referred to", "nominal", "domain", "width", "provenance", "note"},
                {3});
    for (const auto& g : GroupConcerns(concerns, kind)) {
      const ParameterConcern& c = *g.first;
      const ComponentTypeSpec* type = FindComponentType(c.type);
      const ParameterSpec* spec = type ? type->FindParameter(c.parameter) : nullptr;
      t.AddRow({c.type + "." + c.parameter, JoinIds(g.components), spec ? ReferenceSideLabel(spec->referred_to) : "",
                c.nominal ? Display(*c.nominal, spec) : "?", DomainText(c.domain, spec),
                std::isinf(c.relative_width) ? "unbounded" : FormatNumber(100 * c.relative_width, 3) + " %",
                ToString(c.provenance), c.note});
    }
    return t;
  };
  const int unknown = CountConcerns(ParameterConcern::Kind::kUnknown);
  const int wide = CountConcerns(ParameterConcern::Kind::kWide);
  out += "Unknown parameters (no nominal value): " + std::to_string(unknown) + " of " + std::to_string(parameters) +
         "\n";
  if (unknown > 0) out += concern_table(ParameterConcern::Kind::kUnknown).ToString();
  out += "\nWide parameters (domain wider than 20 % of its middle): " + std::to_string(wide) + " of " +
         std::to_string(parameters) + "\n";
  if (wide > 0) out += concern_table(ParameterConcern::Kind::kWide).ToString();
  return out;
}

nlohmann::json ProjectDescription::ToJson() const {
  nlohmann::json j;
  j["name"] = name;
  j["file"] = file;
  j["counts"] = {{"components", components}, {"connections", connections}, {"elements", elements},
                 {"requirements", requirements}, {"load_cases", load_cases}, {"scenarios", scenarios},
                 {"stations", stations.size()}, {"parameters", parameters}};
  j["components_by_type"] = nlohmann::json::object();
  for (const auto& [type, count] : components_by_type) j["components_by_type"][type] = count;
  nlohmann::json sides_json = nlohmann::json::array();
  for (const auto& s : sides)
    sides_json.push_back({{"side", s.side}, {"shaft_segments", s.shaft_count}, {"shaft_length_m", s.shaft_length},
                          {"shaft_mass_kg", s.shaft_mass}, {"stations", s.stations}});
  j["shafts"] = {{"segments", shaft_count}, {"length_m", shaft_length}, {"mass_kg", shaft_mass},
                 {"by_side", sides_json}};
  nlohmann::json st = nlohmann::json::array();
  for (const auto& s : stations)
    st.push_back({{"actuator", s.actuator}, {"type", s.type}, {"side", s.side}, {"station", s.station},
                  {"speed_ratio", s.speed_ratio}, {"total_ratio", s.total_ratio}, {"path", s.path}});
  j["stations"] = st;
  nlohmann::json in = nlohmann::json::array();
  for (const auto& c : inertias)
    in.push_back({{"component", c.component}, {"type", c.type}, {"inertia_kg_m2", c.inertia},
                  {"speed_ratio", c.speed_ratio}, {"reflected_kg_m2", c.reflected}});
  j["reflected_inertia"] = {{"nominal_kg_m2", reflected_inertia},
                            {"range_kg_m2", DomainJson(reflected_inertia_domain)},
                            {"components", in},
                            {"unreachable", unreachable}};
  const auto concern_json = [&](ParameterConcern::Kind kind) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& c : concerns) {
      if (c.kind != kind) continue;
      const ComponentTypeSpec* type = FindComponentType(c.type);
      const ParameterSpec* spec = type ? type->FindParameter(c.parameter) : nullptr;
      nlohmann::json e = {{"component", c.component}, {"type", c.type}, {"parameter", c.parameter},
                          {"unit", c.unit}, {"domain_si", DomainJson(c.domain)},
                          {"domain", DomainText(c.domain, spec)},
                          {"provenance", ToString(c.provenance)}, {"note", c.note},
                          {"referred_to", ToString(spec ? spec->referred_to : ReferenceSide::kNone)}};
      e["nominal_si"] = c.nominal ? nlohmann::json(*c.nominal) : nlohmann::json(nullptr);
      e["relative_width"] = std::isinf(c.relative_width) ? nlohmann::json("inf") : nlohmann::json(c.relative_width);
      a.push_back(std::move(e));
    }
    return a;
  };
  j["unknown_parameters"] = concern_json(ParameterConcern::Kind::kUnknown);
  j["wide_parameters"] = concern_json(ParameterConcern::Kind::kWide);
  return j;
}

}  // namespace highlift::model
