// angle_gearbox: a gear stage between ports input and output, ratio = w_input / w_output; one
// HighLift.Mechanical.GeneralRotationalElement (gearbox.h).
#include "gearbox.h"

namespace highlift::model::components {
namespace {

class AngleGearboxModel final : public NamedModel {
 public:
  AngleGearboxModel() : NamedModel("angle_gearbox") {}

  std::vector<std::string> PowerPorts() const override { return {"output"}; }

  /// Steady state: a gear stage (eta = eta_mesh^meshes both ways) plus its Stribeck friction.
  template <class T>
  T SteadyLaw(const ParameterReader<T>& p, const SteadyFlow<T>& in) const {
    const T eta = MeshEfficiency(p);
    return GearInputTorque(in.through, p("ratio"), eta, eta) + in.friction * StribeckOf(p, in.w);
  }
  HIGHLIFT_STEADY_LAW

  void Expand(const Component& c, ExpansionContext& x) const override {
    x.Add("GeneralRotationalElement", c.id, GearboxScalars(c, x), c.id);
    x.MapPort(c, "input", c.id + ".flange_a");
    x.MapPort(c, "output", c.id + ".flange_b");
  }

  std::vector<EstimationLaw> EstimationLaws() const override { return GearboxEstimationLaws(); }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(AngleGearbox, AngleGearboxModel)
