// steady_bearing: a bearing of the transmission with Stribeck friction, ports a and b; one
// HighLift.Mechanical.LossyInertia, or a member of a lumped chain at reduced resolution.
#include "declaration.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec SteadyBearingDeclaration() {
  ComponentTypeSpec t;
  t.name = "steady_bearing";
  t.display_name = "steady bearing";
  t.description = "Steady bearing supporting the shaft; Stribeck friction (paper eq. 3).";
  t.ports = {Flange("a", "flange nearer the PDU"), Flange("b", "flange farther from the PDU")};
  AddStribeck(t.parameters, 0.1, 0.05, 0.2, "domain.md s6 (E): drag 0.05-0.2 N m each", ReferenceSide::kShaft);
  t.parameters.push_back(
      Inertia(5e-5, 1e-5, 1e-4, "inertia of the bearing's rotating parts", "estimate: small", ReferenceSide::kShaft));
  t.parameters.push_back(SpanPosition());
  t.roles = {.chain_member = true};
  return t;
}

namespace {

class SteadyBearingModel final : public NamedModel {
 public:
  SteadyBearingModel() : NamedModel("steady_bearing") {}

  void Expand(const Component& c, ExpansionContext& x) const override {
    Scalars s = x.Regularised(Stribeck(c));
    s["J"] = Require(c, "inertia");
    x.Add("LossyInertia", c.id, s, c.id);
    MapAB(c, x);
  }

  /// Steady state: its Stribeck friction adds to what it passes on.
  template <class T>
  T SteadyLaw(const ParameterReader<T>& p, const SteadyFlow<T>& in) const {
    return in.through + in.friction * StribeckOf(p, in.w);
  }
  HIGHLIFT_STEADY_LAW

  ChainMember Chain(const Component& c, double beta) const override { return RigidOrElasticMember(c, beta); }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(SteadyBearing, SteadyBearingModel)
