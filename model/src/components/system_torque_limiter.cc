// system_torque_limiter: the torque limiter at the PDU output (torque_limiter.h).
#include "torque_limiter.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec SystemTorqueLimiterDeclaration() {
  ComponentTypeSpec t;
  t.name = "system_torque_limiter";
  t.display_name = "system torque limiter";
  t.description =
      "System torque limiter (STL) at a PDU output: a ball-ramp coupling that locks the "
      "transmission to structure above its lock-out torque (paper fig. 4 and 5).";
  t.ports = {Flange("input", "flange towards the PDU"), Flange("output", "flange towards the wing")};
  AddTorqueLimiter(t.parameters, 470, 1.0, 2e4, "domain.md s3 (E): 1.3 x 360 N m root torque",
                   "estimate: about 10 x the adjacent shaft stiffness (domain.md s3 c = 1.4-3.3 kN*m/rad)",
                   ReferenceSide::kShaft);
  t.parameters.push_back(Inertia(1e-3, 5e-4, 2e-3, "inertia of the limiter", "estimate: comparable to a station gearbox",
                                 ReferenceSide::kShaft));
  t.parameters.push_back(SpanPosition());
  t.roles = {.lumps_inertia = true, .wing_limiter = true};
  t.relations = TorqueLimiterRelations();
  return t;
}

namespace {
class SystemTorqueLimiterModel final : public TorqueLimiterModel {
 public:
  SystemTorqueLimiterModel() : TorqueLimiterModel("system_torque_limiter") {}

  /// Both trip torques against the largest operating wing torque of either direction.
  std::vector<SettingRule> SettingRules() const override {
    const std::string rule = "1.2-1.4 x max operating wing torque (domain.md s6)";
    return {{"lockout_torque_extend", rule, SettingRule::Against::kOperating, 1.3, 1.2, 1.4},
            {"lockout_torque_retract", rule, SettingRule::Against::kOperating, 1.3, 1.2, 1.4}};
  }
};
}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(SystemTorqueLimiter, SystemTorqueLimiterModel)
