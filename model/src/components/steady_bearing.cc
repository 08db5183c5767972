// steady_bearing: a bearing of the transmission with Stribeck friction, ports a and b; one
// HighLift.Mechanical.LossyInertia, or a member of a lumped chain at reduced resolution.
#include "component_util.h"

namespace highlift::model::components {
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
