// angle_gearbox: a gear stage between ports input and output, ratio = w_input / w_output; one
// HighLift.Mechanical.GeneralRotationalElement (gearbox.h).
#include "gearbox.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec AngleGearboxDeclaration() {
  ComponentTypeSpec t;
  t.name = "angle_gearbox";
  t.display_name = "angle gearbox";
  t.description = "Angle, bevel, offset or kink gearbox (root gearbox) changing the shaft direction.";
  t.ports = {Flange("input", "flange nearer the PDU"), GearedFlange("output", "flange farther from the PDU")};
  AddGearbox(t.parameters, "gear ratio, input speed / output speed (MSL IdealGear)", 1, 1, 2,
             "domain.md s6 (E): 1:1 to 2:1", 2e-3, "domain.md s3 (E): root gearbox 2e-3 kg m2");
  t.parameters.push_back(Param("shaft_angle", "alpha", Dimensionless(), "deg", "angle between input and output shafts")
                             .Valid(0, 180)
                             .Optional()
                             .Source("domain.md s1 (P): e.g. 19 deg, 63.5 deg (A320 slats)"));
  t.parameters.push_back(SpanPosition());
  t.roles = {.lumps_inertia = true};
  return t;
}

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
