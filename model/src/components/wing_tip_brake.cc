// wing_tip_brake: the brake at a wing tip, ports a and b; one HighLift.Mechanical.WingTipBrake
// whose input apply the monitor's command drives (drive_network.cc, EmitMonitoring).
#include "component_util.h"

namespace highlift::model::components {
namespace {

class WingTipBrakeModel final : public NamedModel {
 public:
  WingTipBrakeModel() : NamedModel("wing_tip_brake") {}

  // No allowable against the peak loads: in a rupture the torque through the brake is its own
  // friction torque (at most the larger of max_dynamic_torque and static_capacity, which is
  // where the peak analysis caps the case), so a margin against its own capacity says nothing.
  // Its static capacity is sized by the setting rule below.

  /// As the stop of a rupture it slips: while the shaft turns it passes its dynamic torque
  /// (rising to max_dynamic_torque), once halted it holds up to its static capacity; the shaft
  /// at the brake never carries more than the larger of the two (paper, shaft brake).
  template <class T>
  std::optional<T> StopLaw(const ParameterReader<T>& p) const {
    if (!p.Has("max_dynamic_torque") || !p.Has("static_capacity")) return std::nullopt;
    using std::max;
    return max(p("max_dynamic_torque"), p("static_capacity"));
  }
  HIGHLIFT_STOP_LIMIT_LAW

  /// Its static capacity holds the wing: against the drive torque of the wing (a PDU driving
  /// into the engaged brake) and against its airloads back-driving the shaft.
  std::vector<SettingRule> SettingRules() const override {
    return {{"static_capacity", ">= 1.5 x the larger of the wing's operating and back-drive torques (domain.md s3, s6)",
             SettingRule::Against::kWingHolding,
             1.5, 1.5, kInfinity}};
  }

  void Expand(const Component& c, ExpansionContext& x) const override {
    x.Add("WingTipBrake", c.id,
          {{"tauB_max", Require(c, "max_dynamic_torque")},
           {"tauB_lim", Require(c, "static_capacity")},
           {"t_B", Require(c, "time_to_max_torque")},
           {"t_lat", Require(c, "engagement_latency")},
           {"J", Require(c, "inertia")}},
          c.id);
    MapAB(c, x);
    x.AddTipBrake(c);
  }

  std::vector<FitRule> FitRules() const override { return {{"inertia", "max_dynamic_torque"}}; }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(WingTipBrake, WingTipBrakeModel)
