// branch_gearbox: the through shaft (ports input, through) with a branch to a station,
// ratio = w_through / w_branch; one HighLift.Mechanical.BranchGearbox (gearbox.h).
#include "gearbox.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec BranchGearboxDeclaration() {
  ComponentTypeSpec t;
  t.name = "branch_gearbox";
  t.display_name = "branch gearbox";
  t.description =
      "T-gearbox or down-drive (station gearbox): the shaft passes through 1:1 and a branch "
      "drives the station. ratio = input speed / branch speed.";
  t.ports = {Flange("input", "flange nearer the PDU"),
             Flange("through", "through-drive flange, 1:1 with the input (open at the last station)", false),
             GearedFlange("branch", "down-drive flange to the station")};
  AddGearbox(t.parameters, "gear ratio, input speed / branch speed", 2, 1, 2,
             "domain.md s3 (E): station gearbox 2:1; s6 1:1 to 2:1", 6.25e-4,
             "domain.md s3 (E): station input 1e-3 kg m2 at the shaft in all = this 6.25e-4 + (limiter 5e-4 + "
             "actuator input 1e-3) / 2^2 behind the default 2:1");
  t.parameters.push_back(SpanPosition());
  t.roles = {.lumps_inertia = true};
  return t;
}

namespace {

class BranchGearboxModel final : public NamedModel {
 public:
  BranchGearboxModel() : NamedModel("branch_gearbox") {}

  std::vector<std::string> PowerPorts() const override { return {"branch", "through"}; }  // the station first

  /// Steady state: the through shaft 1:1, the branch a gear stage, plus its Stribeck friction.
  template <class T>
  T SteadyLaw(const ParameterReader<T>& p, const SteadyFlow<T>& in) const {
    return BranchGearboxInputTorque(p, in);
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
