#include "graph_model.h"

#include <algorithm>
#include <set>

#include "highlift/core/error.h"

namespace highlift::reduced_models::detail {
namespace {

/// The flanges through which power leaves a component entered at its near flange.
std::vector<std::string> OutgoingPorts(const Component& c) {
  const model::ComponentModel* m = ModelOf(c);
  return m ? m->PowerPorts() : std::vector<std::string>{"b"};
}

bool IsNearPort(const Component& c, const std::string& port) {
  return port == "input" || port == "a" || HasRole(c, &model::ComponentRoles::drive_unit);
}

}  // namespace

std::optional<ParameterView> FindParameter(const Component& c, std::string_view name) {
  // A scan that compares the lengths first: a component has a few dozen parameters at most, and
  // the map's own find wanted a std::string key (an allocation for most names) and a full
  // comparison at every level.
  for (const auto& [key, p] : c.parameters)
    if (key.size() == name.size() && key == name) return ParameterView{p.nominal, p.domain, p.provenance};
  const ComponentTypeSpec* type = FindComponentType(c.type);
  const ParameterSpec* spec = type ? type->FindParameter(name) : nullptr;
  if (!spec) return std::nullopt;
  return ParameterView{spec->nominal, spec->default_domain, Provenance::kDefault};
}

bool HasValue(const Component& c, std::string_view name) {
  const auto p = FindParameter(c, name);
  return p && ValueOf(*p);
}

double NominalValue(const Component& c, std::string_view name) {
  const auto p = FindParameter(c, name);
  if (const std::optional<double> value = p ? ValueOf(*p) : std::nullopt) return *value;
  throw InputError("component '" + c.id + "' (" + c.type + "): parameter '" + std::string(name) +
                       "' has no value, which the reduced models need; give it a value or an interval",
                   c.where);
}

Graph BuildGraph(const Project& project) {
  Graph g;
  std::map<PortRef, PortRef> peer;
  for (const Connection& connection : project.connections) {
    peer[connection.a] = connection.b;
    peer[connection.b] = connection.a;
  }
  const Component* pdu = nullptr;
  for (const Component& c : project.components)
    if (HasRole(c, &model::ComponentRoles::drive_unit)) {
      if (pdu)
        throw InputError("the project has two PDUs ('" + pdu->id + "' and '" + c.id +
                         "'); the reduced models need exactly one power drive unit");
      pdu = &c;
    }
  if (!pdu)
    throw InputError("the project '" + project.name +
                     "' has no component of type 'pdu'; the reduced models start the power flow at "
                     "the PDU: add one");
  // Depth-first, so each wing and each station reads in order; parents precede children.
  struct Pending { const Component* component; int parent; std::string port; std::string entry; };
  std::vector<Pending> stack{{pdu, -1, "", ""}};
  while (!stack.empty()) {
    const Pending item = stack.back();
    stack.pop_back();
    const int index = static_cast<int>(g.nodes.size());
    g.nodes.push_back({item.component, item.parent, item.port, {}, item.entry, ModelOf(*item.component)});
    if (item.parent >= 0) g.nodes[item.parent].children.push_back(index);
    g.index[item.component->id] = index;
    const Component& c = *item.component;
    const std::vector<std::string> ports = OutgoingPorts(c);
    for (auto port = ports.rbegin(); port != ports.rend(); ++port) {
      auto it = peer.find(PortRef{c.id, *port});
      if (it == peer.end()) continue;
      const PortRef& next = it->second;
      const Component* other = project.FindComponent(next.component);
      if (!other)
        throw InputError("connection '" + c.id + "." + *port + "' - '" + next.ToString() +
                         "' refers to an unknown component; fix the id or add the component");
      if (g.index.count(other->id) || std::any_of(stack.begin(), stack.end(), [&](const Pending& p) { return p.component == other; }))
        throw InputError("component '" + other->id + "' is reached twice from the PDU (the drive forms a "
                         "loop); the reduced models need a tree: remove one connection");
      if (!IsNearPort(*other, next.port))
        throw InputError("component '" + other->id + "' (" + other->type + ") is reached from the PDU through its '" +
                         next.port + "' flange; connect its 'input' (or 'a') flange towards the PDU so its "
                         "gear ratio reads input speed / output speed");
      stack.push_back({other, index, *port, next.port});
    }
  }
  return g;
}

std::vector<std::pair<std::string, std::string>> UncertainParameters(const Graph& graph) {
  static const std::set<std::string> used = {
      "motor_inertia", "ratio", "gear_inertia", "efficiency", "eta_mesh", "inertia", "input_inertia",
      "load_inertia", "stiffness", "stiffness_normal", "length", "outer_diameter", "wall_thickness",
      "shear_modulus", "density", "linear_density", "drag_per_length", "coulomb_torque",
      "viscous_coefficient", "stribeck_torque", "stribeck_decay", "eta_opposing", "eta_aiding",
      "engagement_latency", "time_to_max_torque", "latency", "asymmetry_threshold", "overspeed_factor",
      "max_output_speed"};
  std::vector<std::pair<std::string, std::string>> out;
  for (const GraphNode& node : graph.nodes) {
    const ComponentTypeSpec* type = FindComponentType(node.component->type);
    if (!type) continue;
    for (const ParameterSpec& spec : type->parameters) {
      if (!used.count(spec.name) || spec.kind != ParameterKind::kScalar) continue;
      const auto p = FindParameter(*node.component, spec.name);
      if (p && (p->nominal || p->provenance != Provenance::kDefault) && p->domain.bounded() && !p->domain.empty() &&
          !p->domain.is_point())
        out.push_back({node.component->id, spec.name});
    }
  }
  return out;
}

}  // namespace highlift::reduced_models::detail
