// disconnector: a coupling that a rupture scenario may open, ports a and b; one
// HighLift.Mechanical.Disconnector (stiff spring-damper until t_disconnect).
#include "declaration.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec DisconnectorDeclaration() {
  ComponentTypeSpec t;
  t.name = "disconnector";
  t.display_name = "disconnector";
  t.description = "Failure element: a rigid (or elastic) coupling that breaks at the scenario's rupture time (shaft rupture).";
  t.ports = {Flange("a", "flange nearer the PDU"), Flange("b", "flange farther from the PDU")};
  t.parameters.push_back(OptionalStiffness("torsional stiffness before the rupture", ReferenceSide::kShaft));
  t.parameters.push_back(SpanPosition());
  t.roles = {.rupturable = true};
  return t;
}

namespace {

constexpr double kDefaultStiffness = 1e6;  // N*m/rad, far above any shaft segment
constexpr double kDefaultDamping = 100;    // N*m*s/rad

class DisconnectorModel final : public NamedModel {
 public:
  DisconnectorModel() : NamedModel("disconnector") {}

  /// No inertia of its own in the lumped models; its stiffness when given.
  template <class T>
  Lumped<T> Law(const ParameterReader<T>& p) const {
    Lumped<T> out = DefaultLumped(p);
    out.J = T(0.0);
    return out;
  }
  HIGHLIFT_LUMPED_LAW

  void Expand(const Component& c, ExpansionContext& x) const override {
    Scalars s = {{"c", ValueOr(c, "stiffness", kDefaultStiffness)}, {"d", kDefaultDamping}};
    if (const Scenario* scenario = x.scenario(); scenario && scenario->rupture_component == c.id)
      s["t_disconnect"] = *scenario->rupture_time;
    x.Add("Disconnector", c.id, s, c.id);
    MapAB(c, x);
  }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(Disconnector, DisconnectorModel)
