// jam: a jam element on a flange (port a), tying it to the structure at the scenario's time;
// one HighLift.Mechanical.Jam.
#include "declaration.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec JamDeclaration() {
  ComponentTypeSpec t;
  t.name = "jam";
  t.display_name = "jam";
  t.description = "Failure element: locks its flange to structure at the scenario's jam time.";
  t.ports = {Flange("a", "flange on the transmission (usually an actuator input)")};
  t.parameters.push_back(Param("stiffness", "c", Torque(), "N*m/rad", "stiffness of the jammed load path to structure, at the flange it locks (an actuator input)")
                             .Nominal(1e5)
                             .Default(2e4, 5e5)
                             .Valid(0, 1e12)
                             .Source("estimate: stiff compared with the shaft segments (1.4-3.3 kN*m/rad)")
                             .Side(ReferenceSide::kActuatorInput));
  t.parameters.push_back(SpanPosition());
  t.roles = {.jammable = true, .lumps_inertia = true};
  return t;
}

namespace {

class JamModel final : public NamedModel {
 public:
  JamModel() : NamedModel("jam") {}

  std::vector<std::string> PowerPorts() const override { return {}; }

  /// A jam stands for the structure: no inertia, no stiffness in the lumped models.
  template <class T>
  Lumped<T> Law(const ParameterReader<T>&) const {
    return {};
  }
  HIGHLIFT_LUMPED_LAW

  void Expand(const Component& c, ExpansionContext& x) const override {
    const double stiffness = Require(c, "stiffness");
    Scalars s = {{"c", stiffness}, {"d", x.beta() * stiffness}};
    if (const Scenario* scenario = x.scenario(); scenario && scenario->jam_component == c.id)
      s["t_jam"] = *scenario->jam_time;
    x.Add("Jam", c.id, s, c.id);
    x.MapPort(c, "a", c.id + ".flange");
  }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(Jam, JamModel)
