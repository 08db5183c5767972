// wing_tip_brake: the brake at a wing tip, ports a and b; one HighLift.Mechanical.WingTipBrake
// whose input apply the monitor's command drives (drive_network.cc, EmitMonitoring).
#include "component_util.h"

namespace highlift::model::components {
namespace {

class WingTipBrakeModel final : public NamedModel {
 public:
  WingTipBrakeModel() : NamedModel("wing_tip_brake") {}

  /// Against the peak loads: the torque it holds once engaged.
  template <class T>
  std::optional<Allowable<T>> PeakLaw(const ParameterReader<T>& p) const {
    if (!p.Has("static_capacity")) return std::nullopt;
    return Allowable<T>{"static capacity", p("static_capacity")};
  }
  HIGHLIFT_PEAK_ALLOWABLE_LAW

  /// Its static capacity holds the wing against its airloads back-driving the shaft.
  std::vector<SettingRule> SettingRules() const override {
    return {{"static_capacity", ">= 1.5 x wing back-drive torque (domain.md s6)", SettingRule::Against::kWingBackdrive,
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
