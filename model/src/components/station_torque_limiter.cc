// station_torque_limiter: the torque limiter in front of a station's actuator (torque_limiter.h).
#include "torque_limiter.h"

namespace highlift::model::components {
namespace {
class StationTorqueLimiterModel final : public TorqueLimiterModel {
 public:
  StationTorqueLimiterModel() : TorqueLimiterModel("station_torque_limiter") {}

  /// Extend: against the station's largest extend torque. Retract: the aiding airload leaves
  /// little drive torque; the rule applies to what remains, and the project's asymmetric setting
  /// (domain.md s3: 0.7 x extend) is checked against it (no upper bound).
  std::vector<SettingRule> SettingRules() const override {
    const std::string rule = "1.3-1.6 x station max operating torque (domain.md s6)";
    return {{"lockout_torque_extend", rule, SettingRule::Against::kOperatingExtend, 1.5, 1.3, 1.6},
            {"lockout_torque_retract", rule, SettingRule::Against::kOperatingRetract, 1.5, 1.3, kInfinity}};
  }
};
}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(StationTorqueLimiter, StationTorqueLimiterModel)
