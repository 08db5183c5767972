// station_input_gearbox: the A330-style station input gearbox with its torque limiter built in
// (domain.md s1: "torque limiters in the station input gearboxes"). One unit on the transmission
// shaft: the shaft passes through 1:1 (ports input, through), a gear stage drives the station
// (ratio = w_input / w_branch) and a ball-ramp torque limiter (paper fig. 4) sits in that
// down-drive, between the gear stage and the port branch, which carries the actuator.
//
// It composes the laws of the branch gearbox (gearbox.h) and of the station torque limiter
// (torque_limiter.h): two elements, HighLift.Mechanical.BranchGearbox `<id>` and
// HighLift.Mechanical.TorqueLimiter `<id>.limiter`. The limiter's settings count on the branch
// side, the actuator input (LimitedPort "branch"): sizing sets them against the station's torque,
// and in a jam of that station what lies behind the branch sees at most the end-stop torque, while
// the through shaft to the other stations is not limited.
#include "gearbox.h"
#include "torque_limiter.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec StationInputGearboxDeclaration() {
  ComponentTypeSpec t;
  t.name = "station_input_gearbox";
  t.display_name = "station input gearbox";
  t.description =
      "Station input gearbox with an integrated station torque limiter (A330 flaps, domain.md s1): the "
      "shaft passes through 1:1 and a gear stage drives the station through a ball-ramp torque limiter "
      "(paper fig. 4). ratio = input speed / branch speed; the limiter's torques and stiffnesses refer to "
      "the branch (actuator input).";
  t.ports = {Flange("input", "flange nearer the PDU"),
             Flange("through", "through-drive flange, 1:1 with the input (open at the last station)", false),
             GearedFlange("branch", "down-drive flange to the actuator, behind the torque limiter")};
  auto& ps = t.parameters;
  AddGearbox(ps, "gear ratio, input speed / branch speed", 2, 1, 2,
             "domain.md s3 (E): station gear stage 2:1; s6 (E) 1:1 to 2:1", 6.25e-4,
             "estimate: the gear stage of a station gearbox, domain.md s3 (E) station input 1e-3 kg m2 at the shaft "
             "with limiter and actuator");
  AddTorqueLimiter(ps, 180, 0.7, 2e4,
                   "domain.md s3 (E): station limiter 1.5 x 58.8 N m at the shaft, referred to the branch of the "
                   "2:1 gear stage",
                   "estimate: as a separate station limiter, 2-3 x the adjacent shaft segments referred to the branch",
                   ReferenceSide::kActuatorInput);
  ps.push_back(Param("limiter_inertia", "J_lim", dimensions::Inertia(), "kg*m^2",
                     "inertia of the torque limiter, on the branch behind the gear stage")
                   .Nominal(5e-4)
                   .Default(2e-4, 1e-3)
                   .Valid(0, 1e3)
                   .Source("estimate: the limiter of domain.md s3's station, half a station gearbox")
                   .Side(ReferenceSide::kActuatorInput));
  ps.push_back(SpanPosition());
  t.roles = {.lumps_inertia = true, .station_limiter = true};
  t.relations = TorqueLimiterRelations();
  return t;
}

namespace {

class StationInputGearboxModel final : public NamedModel {
 public:
  StationInputGearboxModel() : NamedModel("station_input_gearbox") {}

  std::vector<std::string> PowerPorts() const override { return {"branch", "through"}; }  // the station first
  std::string_view LimitedPort() const override { return "branch"; }

  /// Steady state: a branch gearbox; the limiter passes the station's torque (its drag is the
  /// gear stage's Stribeck friction).
  template <class T>
  T SteadyLaw(const ParameterReader<T>& p, const SteadyFlow<T>& in) const {
    return BranchGearboxInputTorque(p, in);
  }
  HIGHLIFT_STEADY_LAW

  /// In the lumped models one point at the input speed: the gear stage's inertia plus the
  /// limiter's, referred across the stage (J_lim / ratio^2), and the stage's optional stiffness.
  /// The limiter's own stiffness c1 lies in the station's down-drive only, not in the through
  /// shaft, so one point cannot carry it: the unit is rigid there (a stiffer station: higher
  /// jam peaks and eigenfrequencies than with c1 in series).
  template <class T>
  Lumped<T> Law(const ParameterReader<T>& p) const {
    Lumped<T> out = DefaultLumped(p);
    const T ratio = p("ratio");
    out.J = out.J + p("limiter_inertia") / (ratio * ratio);
    return out;
  }
  HIGHLIFT_LUMPED_LAW

  /// Its limiter in a jam of the station: the law of every torque limiter (torque_limiter.h).
  template <class T>
  std::optional<T> PassLaw(const ParameterReader<T>& p, const T& tau_in, const T& n) const {
    return LimiterPassLaw(p, tau_in, n);
  }
  HIGHLIFT_JAM_PASSED_LAW

  std::vector<SettingRule> SettingRules() const override { return StationLimiterSettingRules(); }

  void Expand(const Component& c, ExpansionContext& x) const override {
    const std::string limiter = c.id + ".limiter";
    x.Add("BranchGearbox", c.id, GearboxScalars(c, x), c.id);
    x.Add("TorqueLimiter", limiter, TorqueLimiterScalars(c, x, "limiter_inertia"), c.id, {},
          "torque limiter in the down-drive of " + c.id);
    x.Connect(c.id + ".flange_branch", limiter + ".flange_a");
    x.MapPort(c, "input", c.id + ".flange_a");
    x.MapPort(c, "through", c.id + ".flange_b");
    x.MapPort(c, "branch", limiter + ".flange_b");
  }

  std::vector<FitRule> FitRules() const override { return {{"limiter_inertia", "lockout_torque_extend"}}; }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(StationInputGearbox, StationInputGearboxModel)
