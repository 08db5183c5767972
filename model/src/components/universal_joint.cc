// universal_joint: a joint of the transmission with efficiency, optional stiffness and backlash,
// ports a and b; a HighLift.Mechanical.GeneralRotationalElement when elastic, else a
// LossyInertia; a member of a lumped chain at reduced resolution.
#include "component_util.h"

namespace highlift::model::components {
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
