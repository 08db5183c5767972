// Checks of the component graph and of references between the parts of a project.
#include "highlift/core/validate.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "highlift/core/graph.h"
#include "highlift/core/project_io.h"
#include "highlift/core/text_table.h"

namespace highlift {

bool ValidationReport::ok() const {
  return std::none_of(issues.begin(), issues.end(),
                      [](const ValidationIssue& i) { return i.severity == ValidationIssue::Severity::kError; });
}

std::string ValidationReport::BriefReport() const {
  const auto errors = std::count_if(issues.begin(), issues.end(), [](const ValidationIssue& i) {
    return i.severity == ValidationIssue::Severity::kError;
  });
  const auto warnings = static_cast<long>(issues.size()) - errors;
  std::string s = ok() ? "valid" : "invalid";
  s += ": " + std::to_string(errors) + (errors == 1 ? " error, " : " errors, ") + std::to_string(warnings) +
       (warnings == 1 ? " warning" : " warnings");
  return s;
}

std::string ValidationReport::FullReport() const {
  std::string out;
  for (const auto& i : issues) {
    out += i.severity == ValidationIssue::Severity::kError ? "error: " : "warning: ";
    if (!i.where.empty()) out += i.where.ToString() + ": ";
    out += i.message + "\n";
  }
  out += BriefReport() + "\n";
  return out;
}

namespace {

using Severity = ValidationIssue::Severity;

std::string Join(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
  return out;
}

/// The name of a gear's geared flange (the one turning 1/ratio as fast as "input").
std::string GearedPort(const Component& c) {
  const ComponentTypeSpec* type = FindComponentType(c.type);
  const PortSpec* port = type ? type->GearedPort() : nullptr;
  return port ? port->name : "output";
}

bool IsActuator(const std::string& type) { return RolesOf(type).actuator; }

std::string JoinOr(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? (i + 1 == items.size() ? " or " : ", ") : "") + items[i];
  return out;
}

// Element types that ground or drive a network (an island without one floats).
bool IsAnchor(const std::string& type) {
  static const std::set<std::string> anchors = {
      "Fixed",         "Speed",        "Position",          "Accelerate",    "Move",
      "Torque",        "Torque2",      "ConstantSpeed",     "ConstantTorque", "TorqueStep",
      "SignTorque",    "LinearSpeedDependentTorque", "QuadraticSpeedDependentTorque", "EddyCurrentTorque"};
  return anchors.count(type) > 0;
}

class Validator {
 public:
  explicit Validator(const Project& project) : project_(project) {
    // One lookup table (the first of duplicate ids): Project::FindComponent is a linear search,
    // and calling it per component made validation quadratic in the component count.
    for (const auto& c : project.components) by_id_.emplace(c.id, &c);
    for (const auto& c : project.elements) by_id_.emplace(c.id, &c);
  }

  ValidationReport Run() {
    CheckNetwork(project_.components, project_.connections, false);
    CheckNetwork(project_.elements, project_.element_connections, true);
    CheckPowerPath();
    CheckGeometry();
    CheckElementIslands();
    CheckLoadCases();
    CheckScenarios();
    if (project_.components.empty() && project_.elements.empty())
      Add(Severity::kWarning, "", "", "the project has no components and no elements; add \"components\"", {});
    return std::move(report_);
  }

 private:
  void Add(Severity severity, std::string component, std::string port, std::string message, SourceLocation where) {
    report_.issues.push_back({severity, std::move(component), std::move(port), std::move(message), std::move(where)});
  }

  const ComponentTypeSpec* Spec(const Component& c, bool element) const {
    return element ? FindElementType(c.type) : FindComponentType(c.type);
  }

  // Elements of the element network are "element", drive-system components "component".
  std::string Describe(const Component& c) const {
    const auto& e = project_.elements;
    const bool element = !e.empty() && &c >= e.data() && &c < e.data() + e.size();
    return (element ? "element '" : "component '") + c.id + "' (" + c.type + ")";
  }

  // Types, parameters, ports, connections -------------------------------------------------------
  void CheckNetwork(const std::vector<Component>& components, const std::vector<Connection>& connections, bool element) {
    const std::string kind = element ? "element" : "component";
    std::map<std::string, const Component*> by_id;
    std::vector<std::string> ids;
    for (const auto& c : components) {
      if (!by_id.emplace(c.id, &c).second)
        Add(Severity::kError, c.id, "", "duplicate " + kind + " id '" + c.id + "'; give every " + kind + " a unique id", c.where);
      ids.push_back(c.id);
      const ComponentTypeSpec* spec = Spec(c, element);
      if (spec == nullptr) {
        std::vector<std::string> names;
        for (const auto& t : element ? ElementTypes() : ComponentTypes()) names.push_back(t.name);
        Add(Severity::kError, c.id, "",
            kind + " '" + c.id + "': unknown " + kind + " type '" + c.type + "'" + SuggestionHint(c.type, names, "valid types"),
            c.where);
        continue;
      }
      CheckParameters(c, *spec);
    }
    // Each port: which connections use it.
    std::map<PortRef, std::vector<const Connection*>> uses;
    for (const auto& k : connections) {
      bool ends_ok = true;
      for (const PortRef* end : {&k.a, &k.b}) {
        auto it = by_id.find(end->component);
        if (it == by_id.end()) {
          Add(Severity::kError, end->component, end->port,
              kind + " connection " + k.a.ToString() + " - " + k.b.ToString() + ": unknown " + kind + " '" +
                  end->component + "'" + DidYouMean(end->component, ids),
              k.where);
          ends_ok = false;
          continue;
        }
        const ComponentTypeSpec* spec = Spec(*it->second, element);
        if (spec == nullptr) continue;
        if (spec->FindPort(end->port) == nullptr) {
          std::vector<std::string> ports;
          for (const auto& p : spec->ports) ports.push_back(p.name);
          Add(Severity::kError, end->component, end->port,
              Describe(*it->second) + " has no port '" + end->port + "'" + SuggestionHint(end->port, ports, "ports"),
              k.where);
          ends_ok = false;
          continue;
        }
        uses[*end].push_back(&k);
      }
      (void)ends_ok;
    }
    // A drive-system flange takes one connection (a shaft branches only through a gearbox). In an
    // element network, as in Modelica, any number of connections may meet at one flange (e.g.
    // several elements grounded on one `Fixed`): the connected flanges form one node.
    for (const auto& [port, list] : uses) {
      if (element || list.size() < 2) continue;
      std::vector<std::string> others;
      for (const Connection* k : list) others.push_back("'" + (k->a == port ? k->b : k->a).ToString() + "'");
      const Component* c = by_id.at(port.component);
      Add(Severity::kError, port.component, port.port,
          Describe(*c) + ": port '" + port.port + "' is connected " + std::to_string(list.size()) + " times (to " +
              Join(others) + "); a flange takes one connection, branch the shaft with a branch_gearbox",
          list[1]->where);
    }
    for (const auto& c : components) {
      const ComponentTypeSpec* spec = Spec(c, element);
      if (spec == nullptr) continue;
      for (const auto& p : spec->ports) {
        if (!p.required || uses.count(PortRef{c.id, p.name})) continue;
        Add(Severity::kError, c.id, p.name,
            Describe(c) + ": required port '" + p.name + "' is not connected; connect it (" + p.description +
                ") or remove the " + kind,
            c.where);
      }
    }
  }

  void CheckParameters(const Component& c, const ComponentTypeSpec& spec) {
    auto check_name = [&](const std::string& name) {
      if (spec.FindParameter(name) != nullptr) return true;
      std::vector<std::string> names;
      for (const auto& p : spec.parameters) names.push_back(p.name);
      Add(Severity::kError, c.id, "",
          Describe(c) + ": unknown parameter '" + name + "'" + SuggestionHint(name, names, "parameters of " + c.type),
          c.where);
      return false;
    };
    for (const auto& [name, p] : c.parameters) {
      if (!check_name(name)) continue;
      const ParameterSpec& ps = *spec.FindParameter(name);
      const Domain& valid = ps.valid_range;
      auto show = [&](double v) {
        if (std::isinf(v)) return std::string(v > 0 ? "inf" : "-inf");
        try {
          return FormatNumber(FromSI(v, ps.unit.empty() ? "1" : ps.unit, ps.dimension), 6);
        } catch (const InputError&) {
          return FormatNumber(v, 6);
        }
      };
      // The messages' numbers are formatted only for a message (a conversion to the display
      // unit per number: most of the validation's time when done for every parameter).
      const std::string unit = (ps.unit.empty() || ps.unit == "1") ? "" : " " + ps.unit;
      if (p.nominal && !valid.contains(*p.nominal)) {
        const std::string range = "[" + show(valid.lo) + ", " + show(valid.hi) + "]" + unit;
        Add(Severity::kError, c.id, "",
            Describe(c) + ": parameter '" + name + "' = " + show(*p.nominal) + unit + " is outside its valid range " + range,
            p.where.empty() ? c.where : p.where);
      } else if (p.domain.empty()) {
        Add(Severity::kError, c.id, "", Describe(c) + ": parameter '" + name + "' has an empty domain (min > max)",
            p.where.empty() ? c.where : p.where);
      } else if (p.nominal && !p.domain.contains(*p.nominal)) {
        Add(Severity::kError, c.id, "",
            Describe(c) + ": parameter '" + name + "': nominal value " + show(*p.nominal) + unit +
                " lies outside its domain [" + show(p.domain.lo) + ", " + show(p.domain.hi) + "]" + unit,
            p.where.empty() ? c.where : p.where);
      }
    }
    for (const auto& [name, t] : c.tables) check_name(name);
    for (const auto& [name, t] : c.texts) check_name(name);
  }

  // Power path: PDU, reachability, gear-ratio conventions -------------------------------------
  void CheckPowerPath() {
    if (project_.components.empty()) return;
    std::vector<const Component*> pdus;
    for (const auto& c : project_.components)
      if (RolesOf(c.type).drive_unit) pdus.push_back(&c);
    if (pdus.empty()) {
      Add(Severity::kError, "", "",
          "the project has components but no power drive unit; add a component of type \"" +
              JoinOr(ComponentTypesWith(&ComponentRoles::drive_unit)) + "\" that drives the transmission",
          {});
      return;
    }
    for (std::size_t i = 1; i < pdus.size(); ++i)
      Add(Severity::kError, pdus[i]->id, "",
          "component '" + pdus[i]->id + "' is a second pdu (the first is '" + pdus[0]->id +
              "'); a project has one PDU driving both wings",
          pdus[i]->where);
    const ComponentGraph graph(project_);
    for (const auto& island : graph.Islands()) {
      if (std::find(island.begin(), island.end(), graph.pdu()) != island.end()) continue;
      std::vector<std::string> quoted;
      for (const auto& id : island) quoted.push_back("'" + id + "'");
      for (const auto& id : island) {
        const Component* c = Find(id);
        Add(Severity::kError, id, "",
            Describe(*c) + " is not connected to the PDU '" + graph.pdu() + "' (disconnected sub-system: " +
                Join(quoted) + "); connect it to the transmission or remove it",
            c->where);
      }
    }
    CheckLoops(graph);
    for (const auto& id : graph.ReachOrder()) {
      const PowerPath* path = graph.PathTo(id);
      const Component* c = Find(id);
      if (RolesOf(c->type).torque_limiter() && path->entry_port == "output")
        Add(Severity::kWarning, id, "output",
            Describe(*c) + ": reached from the PDU through its port 'output'; its extend and retract lock-out torques "
                           "refer to power flowing from 'input' to 'output', so swap the connections of its ports",
            c->where);
      if (!path->reversed) continue;
      const std::string& previous = path->previous;
      Add(Severity::kError, id, path->entry_port,
          Describe(*c) + ": inconsistent gear-ratio convention: the gearbox is reached from the PDU through its port '" +
              path->entry_port + "' (from '" + previous +
              "'), but 'input' must be the flange nearer the PDU (ratio = input speed / " +
              GearedPort(*c) + " speed); swap the connections of its ports",
          c->where);
    }
  }

  // A drive transmission is a tree from the PDU: a connection back to a component already
  // reached (a PDU output through a branch gearbox to its other output) closes a loop, which no
  // sizing, lumped model or mode analysis can handle.
  void CheckLoops(const ComponentGraph& graph) {
    for (const std::size_t index : graph.LoopConnections()) {
      const Connection& k = project_.connections[index];
      Add(Severity::kError, k.a.component, k.a.port, DescribeLoop(graph, project_, index), k.where);
    }
  }

  // Geometry a parameter's own range cannot see ------------------------------------------------
  void CheckGeometry() {
    for (const auto& c : project_.components) {
      const ComponentTypeSpec* type = FindComponentType(c.type);
      if (!type) continue;
      for (const ParameterRelation& r : type->relations) {
        const auto value = c.parameters.find(r.parameter), bound = c.parameters.find(r.bound);
        if (value == c.parameters.end() || bound == c.parameters.end() || !value->second.nominal ||
            !bound->second.nominal)
          continue;
        const double v = *value->second.nominal, b = *bound->second.nominal;
        if (r.strict ? v * r.divisor < b : !(v * r.divisor > b)) continue;
        const ParameterSpec* vs = type->FindParameter(r.parameter);
        const ParameterSpec* bs = type->FindParameter(r.bound);
        auto shown = [](double si, const ParameterSpec* spec) {
          return spec ? FormatNumber(FromSI(si, spec->unit, spec->dimension), 6) + " " + spec->unit : FormatNumber(si, 6);
        };
        const std::string divisor = r.divisor == 1.0 ? "" : " / " + FormatNumber(r.divisor, 6);
        Add(Severity::kError, c.id, "",
            Describe(c) + ": " + r.parameter + " " + shown(v, vs) + (r.strict ? " is not below " : " is more than ") +
                r.meaning + " (" + r.bound + " " + shown(b, bs) + divisor + "); give " + r.parameter +
                (r.strict ? " < " : " <= ") + r.bound + divisor +
                (r.note.empty() ? "" : " (" + r.note + ")"),
            value->second.where.empty() ? c.where : value->second.where);
      }
    }
  }

  void CheckElementIslands() {
    if (project_.elements.empty()) return;
    const ComponentGraph graph = ComponentGraph::Elements(project_);
    for (const auto& island : graph.Islands()) {
      bool anchored = false;
      for (const auto& id : island) {
        const Component* c = Find(id);
        if (c && IsAnchor(c->type)) anchored = true;
      }
      if (anchored) continue;
      std::vector<std::string> quoted;
      for (const auto& id : island) quoted.push_back("'" + id + "'");
      const Component* first = Find(island.front());
      Add(Severity::kWarning, island.front(), "",
          "element network island " + Join(quoted) +
              " has no Fixed element and no source; it floats freely (add a Fixed, Speed or Torque element, or "
              "connect it)",
          first ? first->where : SourceLocation{});
    }
  }

  // References from load cases and scenarios ---------------------------------------------------
  std::vector<std::string> ComponentIds() const {
    std::vector<std::string> ids;
    for (const auto& c : project_.components) ids.push_back(c.id);
    for (const auto& c : project_.elements) ids.push_back(c.id);
    return ids;
  }

  void CheckLoadCases() {
    for (const auto& lc : project_.load_cases) {
      for (const auto& [id, table] : lc.actuator_loads) {
        const Component* c = Find(id);
        if (c == nullptr) {
          Add(Severity::kError, id, "",
              "load case '" + lc.name + "': actuator load for unknown component '" + id + "'" +
                  DidYouMean(id, ComponentIds()),
              lc.where);
        } else if (!IsActuator(c->type) && FindElementType(c->type) == nullptr) {
          Add(Severity::kError, id, "",
              "load case '" + lc.name + "': actuator load on " + Describe(*c) +
                  ", which is not an actuator; give loads for " + JoinOr(ComponentTypesWith(&ComponentRoles::actuator)) +
                  " components",
              lc.where);
        }
      }
    }
  }

  void CheckReference(const Scenario& s, const std::optional<std::string>& id, const std::string& what,
                      const std::vector<std::string>& allowed_types) {
    if (!id) return;
    const Component* c = Find(*id);
    if (c == nullptr) {
      Add(Severity::kError, *id, "",
          "scenario '" + s.name + "': " + what + " of unknown component '" + *id + "'" + DidYouMean(*id, ComponentIds()),
          s.where);
      return;
    }
    if (!allowed_types.empty() && std::find(allowed_types.begin(), allowed_types.end(), c->type) == allowed_types.end() &&
        FindElementType(c->type) == nullptr)
      Add(Severity::kError, *id, "",
          "scenario '" + s.name + "': " + what + " of " + Describe(*c) + "; it must be one of: " + Join(allowed_types),
          s.where);
  }

  void CheckScenarios() {
    std::vector<std::string> load_cases;
    for (const auto& lc : project_.load_cases) load_cases.push_back(lc.name);
    for (const auto& s : project_.scenarios) {
      if (!s.load_case.empty() && project_.FindLoadCase(s.load_case) == nullptr)
        Add(Severity::kError, "", "",
            "scenario '" + s.name + "': unknown load case '" + s.load_case + "'" + SuggestionHint(s.load_case, load_cases, "load cases"),
            s.where);
      CheckReference(s, s.jam_component, kJamKind, ComponentTypesWith(&ComponentRoles::jammable));
      CheckReference(s, s.rupture_component, "rupture", ComponentTypesWith(&ComponentRoles::rupturable));
      if (s.kind == kJamKind && !s.jam_component)
        Add(Severity::kError, "", "", "scenario '" + s.name + "': kind jam without a jammed component", s.where);
      if (s.kind == "rupture" && !s.rupture_component)
        Add(Severity::kError, "", "", "scenario '" + s.name + "': kind rupture without a ruptured component", s.where);
      for (const auto& [time, name] : {std::pair{s.jam_time, kJamKind.c_str()}, std::pair{s.rupture_time, "rupture"},
                                       std::pair{s.wtb_time, "wtb"}}) {
        if (time && *time > s.stop_time)
          Add(Severity::kWarning, "", "",
              "scenario '" + s.name + "': the " + name + " time " + FormatNumber(*time) + " s is after the stop time " +
                  FormatNumber(s.stop_time) + " s, so it never happens; raise 'stop_time'",
              s.where);
      }
    }
  }

  const Component* Find(std::string_view id) const {
    const auto it = by_id_.find(id);
    return it == by_id_.end() ? nullptr : it->second;
  }

  const Project& project_;
  std::map<std::string, const Component*, std::less<>> by_id_;
  ValidationReport report_;
};

}  // namespace

ValidationReport ValidateProject(const Project& project) { return Validator(project).Run(); }

Project LoadValidProject(const std::filesystem::path& file) {
  Project project = LoadProject(file);
  const ValidationReport report = ValidateProject(project);
  std::vector<const ValidationIssue*> errors;
  for (const auto& issue : report.issues)
    if (issue.severity == ValidationIssue::Severity::kError) errors.push_back(&issue);
  if (errors.empty()) return project;
  SourceLocation where = errors.front()->where;
  if (where.file.empty()) where.file = file.string();
  std::string message = errors.front()->message;
  if (errors.size() > 1)
    message += " (and " + std::to_string(errors.size() - 1) + " more error" + (errors.size() > 2 ? "s" : "") +
               ": `highlift validate " + file.string() + "` lists them)";
  throw InputError(message, where);
}

}  // namespace highlift
