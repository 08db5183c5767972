// system_torque_limiter: the torque limiter at the PDU output (torque_limiter.h).
#include "torque_limiter.h"

namespace highlift::model::components {
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
