// wing_tip_brake: the brake at a wing tip, ports a and b; one HighLift.Mechanical.WingTipBrake
// whose input apply the monitor's command drives (drive_network.cc, EmitMonitoring).
#include "declaration.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec WingTipBrakeDeclaration() {
  ComponentTypeSpec t;
  t.name = "wing_tip_brake";
  t.display_name = "wing-tip brake";
  t.description =
      "Wing-tip brake (WTB) at the shaft end: on a monitor command, friction packs stop and hold "
      "the transmission (paper 'shaft brake').";
  t.ports = {Flange("a", "flange towards the transmission"),
             Flange("b", "outboard flange when the brake is inline", false)};
  auto& ps = t.parameters;
  ps.push_back(Param("max_dynamic_torque", "tauB_max", Torque(), "N*m", "maximum dynamic (sliding) brake torque")
                   .Nominal(550)
                   .Default(500, 700)
                   .Valid(0, 1e6)
                   .Source("domain.md s3/s6 (E): 1.5 x the larger of the wing's opposing torque (360 N m) and its "
                           "back-drive torque")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(Param("static_capacity", "tauB_lim", Torque(), "N*m", "maximum static (holding) brake torque after the halt")
                   .Nominal(700)
                   .Default(550, 900)
                   .Valid(0, 1e6)
                   .Source("domain.md s3 (E): static capacity at least 550 N m")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(Param("time_to_max_torque", "t_B", Time(), "ms", "time from engagement to the maximum dynamic torque")
                   .Nominal(30)
                   .Default(10, 60)
                   .Valid(0, 1e4)
                   .Source("estimate: friction packs close in tens of ms"));
  ps.push_back(Param("engagement_latency", "t_lat", Time(), "ms", "delay from the monitor trigger to brake engagement")
                   .Nominal(100)
                   .Default(50, 150)
                   .Valid(0, 1e4)
                   .Source("domain.md s3/s6 (E): 50-150 ms"));
  ps.push_back(Inertia(5e-4, 2e-4, 1e-3, "inertia of the brake rotor", "domain.md s3 (E): brake rotor 5e-4 kg m2",
                       ReferenceSide::kShaft));
  ps.push_back(SpanPosition());
  t.roles = {.tip_brake = true, .lumps_inertia = true};
  t.relations = {{"max_dynamic_torque", "static_capacity", 1.0, "its static capacity",
                  "a friction brake holds at least the torque it passes while sliding (paper, shaft brake)"}};
  return t;
}

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
