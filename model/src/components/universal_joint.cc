// universal_joint: a joint of the transmission with efficiency, optional stiffness and backlash,
// ports a and b; a HighLift.Mechanical.GeneralRotationalElement when elastic, else a
// LossyInertia; a member of a lumped chain at reduced resolution.
#include "declaration.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec UniversalJointDeclaration() {
  ComponentTypeSpec t;
  t.name = "universal_joint";
  t.display_name = "universal joint";
  t.description = "Universal (Cardan) joint compensating a change in shaft direction.";
  t.ports = {Flange("a", "flange nearer the PDU"), Flange("b", "flange farther from the PDU")};
  auto& ps = t.parameters;
  ps.push_back(Efficiency("efficiency", "eta", 0.985, 0.98, 0.99, "efficiency of the joint", "domain.md s6 (E): 0.98-0.99"));
  ps.push_back(Inertia(2e-4, 1e-4, 3e-4, "inertia of the joint", "domain.md s6 (E): 1e-4 to 3e-4 kg m2", ReferenceSide::kShaft));
  ps.push_back(Param("joint_angle", "beta", Dimensionless(), "deg", "bend angle of the joint")
                   .Valid(0, 45)
                   .Optional()
                   .Source("none: from the installation"));
  ps.push_back(Backlash("total backlash of the joint", ReferenceSide::kShaft));
  ps.push_back(OptionalStiffness("torsional stiffness of the joint", ReferenceSide::kShaft));
  ps.push_back(SpanPosition());
  t.roles = {.chain_member = true};
  return t;
}

namespace {

class UniversalJointModel final : public NamedModel {
 public:
  UniversalJointModel() : NamedModel("universal_joint") {}

  void Expand(const Component& c, ExpansionContext& x) const override {
    CheckBacklash(c);
    const auto c_joint = Value(c, "stiffness");
    Scalars s = x.Regularised({{"J", Require(c, "inertia")}, {"eta_GE", Require(c, "efficiency")}});
    if (c_joint) {
      s["elastic"] = 1;
      s["c"] = *c_joint;
      s["d"] = x.beta() * *c_joint;
      s["b"] = ValueOr(c, "backlash", 0.0);
      s["ratio"] = 1;
      x.Add("GeneralRotationalElement", c.id, s, c.id);
    } else {
      x.Add("LossyInertia", c.id, s, c.id);
    }
    MapAB(c, x);
  }

  /// Steady state: a 1:1 stage with its efficiency both ways.
  template <class T>
  T SteadyLaw(const ParameterReader<T>& p, const SteadyFlow<T>& in) const {
    const T eta = p("efficiency");
    return GearInputTorque(in.through, T(1.0), eta, eta);
  }
  HIGHLIFT_STEADY_LAW

  ChainMember Chain(const Component& c, double beta) const override { return RigidOrElasticMember(c, beta); }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(UniversalJoint, UniversalJointModel)
