// station_torque_limiter: the torque limiter in front of a station's actuator (torque_limiter.h).
#include "torque_limiter.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec StationTorqueLimiterDeclaration() {
  ComponentTypeSpec t;
  t.name = "station_torque_limiter";
  t.display_name = "station torque limiter";
  t.description =
      "Bi-directional station torque limiter before an actuator (ball ramp, friction discs, "
      "lock-out indicator), asymmetric: lower trip torque in retract. Paper fig. 4 and 5.";
  t.ports = {Flange("input", "flange towards the transmission"), Flange("output", "flange towards the actuator")};
  AddTorqueLimiter(t.parameters, 180, 0.7, 2e4,
                   "domain.md s3 (E): 1.5 x 58.8 N m station input torque = 90 N m at the shaft, x 2 behind the "
                   "default 2:1 station gearbox",
                   "estimate: 2e4 at the actuator input = 5e3 at the shaft behind the default 2:1 station gearbox, "
                   "2-3 x the adjacent shaft segments (domain.md s3 c = 1.4-3.3 kN*m/rad)",
                   ReferenceSide::kActuatorInput);
  t.parameters.push_back(Inertia(5e-4, 2e-4, 1e-3, "inertia of the limiter", "estimate: half a station gearbox",
                                 ReferenceSide::kActuatorInput));
  t.parameters.push_back(SpanPosition());
  t.roles = {.lumps_inertia = true, .station_limiter = true};
  t.relations = TorqueLimiterRelations();
  return t;
}

namespace {
class StationTorqueLimiterModel final : public TorqueLimiterModel {
 public:
  StationTorqueLimiterModel() : TorqueLimiterModel("station_torque_limiter") {}

  std::vector<SettingRule> SettingRules() const override { return StationLimiterSettingRules(); }
};
}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(StationTorqueLimiter, StationTorqueLimiterModel)
