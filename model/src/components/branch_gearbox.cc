// branch_gearbox: the through shaft (ports input, through) with a branch to a station,
// ratio = w_through / w_branch; one HighLift.Mechanical.BranchGearbox (gearbox.h).
#include "gearbox.h"

namespace highlift::model::components {
namespace {

class BranchGearboxModel final : public NamedModel {
 public:
  BranchGearboxModel() : NamedModel("branch_gearbox") {}

  std::vector<std::string> PowerPorts() const override { return {"branch", "through"}; }  // the station first

  /// Steady state: the through shaft 1:1, the branch a gear stage, plus its Stribeck friction.
  template <class T>
  T SteadyLaw(const ParameterReader<T>& p, const SteadyFlow<T>& in) const {
    const T eta = MeshEfficiency(p);
    return in.through + GearInputTorque(in.branch, p("ratio"), eta, eta) + in.friction * StribeckOf(p, in.w);
  }
  HIGHLIFT_STEADY_LAW

  void Expand(const Component& c, ExpansionContext& x) const override {
    x.Add("BranchGearbox", c.id, GearboxScalars(c, x), c.id);
    x.MapPort(c, "input", c.id + ".flange_a");
    x.MapPort(c, "through", c.id + ".flange_b");
    x.MapPort(c, "branch", c.id + ".flange_branch");
  }

  std::vector<EstimationLaw> EstimationLaws() const override { return GearboxEstimationLaws(); }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(BranchGearbox, BranchGearboxModel)
