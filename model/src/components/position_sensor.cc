// position_sensor: an angle sensor on the transmission (its rotor an Inertia, ports a and b).
// A tip sensor (APPU, any role but "fppu") feeds the failure monitor, whose thresholds are its
// parameters (or the catalogue defaults of this type without one).
#include "declaration.h"
#include "highlift/core/catalogue.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec PositionSensorDeclaration() {
  ComponentTypeSpec t;
  t.name = "position_sensor";
  t.display_name = "position sensor";
  t.description =
      "Position pick-off unit (APPU at the shaft end, FPPU at the PDU) feeding the monitor that "
      "fires the wing-tip brakes on asymmetry or overspeed.";
  t.ports = {Flange("a", "flange on the transmission"), Flange("b", "through flange when inline", false)};
  auto& ps = t.parameters;
  ps.push_back(Param::Text("role", "'appu' (asymmetry position pick-off) or 'fppu' (feedback at the PDU)")
                   .Optional()
                   .Source("domain.md s1 (P)"));
  ps.push_back(Param("latency", "t_s", Time(), "ms", "delay of the sensor and monitor chain")
                   .Nominal(10)
                   .Default(5, 30)
                   .Valid(0, 1e4)
                   .Source("estimate"));
  ps.push_back(Param("asymmetry_threshold", "dphi_asym", Dimensionless(), "rev",
                     "shaft angle difference (left/right or sensor/command) that triggers the WTBs")
                   .Nominal(2)
                   .Default(1, 3)
                   .Valid(0, 1000)
                   .Source("domain.md s3 (E): 1-3 shaft revolutions")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(Param("overspeed_factor", "k_os", Dimensionless(), "1", "overspeed trigger, multiple of the maximum shaft speed")
                   .Nominal(1.3)
                   .Default(1.2, 1.4)
                   .Valid(1, 10)
                   .Source("domain.md s3 (E): 1.3 x w_max"));
  ps.push_back(Inertia(1e-5, 0, 5e-5, "inertia of the sensor shaft", "estimate: small", ReferenceSide::kShaft));
  ps.push_back(SpanPosition());
  t.roles = {.tip_sensor = true};
  return t;
}

namespace {

constexpr const char* kType = "position_sensor";

class PositionSensorModel final : public NamedModel {
 public:
  PositionSensorModel() : NamedModel(kType) {}

  void Expand(const Component& c, ExpansionContext& x) const override {
    x.Add("Inertia", c.id, {{"J", Require(c, "inertia")}}, c.id);
    MapAB(c, x);
    auto role = c.texts.find("role");
    if (role == c.texts.end() || role->second != "fppu") x.AddTipSensor(c);
  }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(PositionSensor, PositionSensorModel)

namespace highlift::model {

MonitorThresholds MonitorSettings(const Component* tip_sensor) {
  auto value = [&](const std::string& name) {
    if (tip_sensor) return components::Require(*tip_sensor, name);
    const ComponentTypeSpec* spec = FindComponentType(components::kType);
    const ParameterSpec* p = spec ? spec->FindParameter(name) : nullptr;
    HIGHLIFT_CHECK(p && p->nominal, std::string("catalogue: ") + components::kType + "." + name + " has no default");
    return *p->nominal;
  };
  return {value("asymmetry_threshold"), value("overspeed_factor"), value("latency")};
}

}  // namespace highlift::model
