// geared_rotary_actuator: a rotary actuator at a flap or slat station (actuator.h); its travel
// is the output angle travel_angle.
#include "actuator.h"
#include "gear_scaling.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec GearedRotaryActuatorDeclaration() {
  ComponentTypeSpec t;
  t.name = "geared_rotary_actuator";
  t.display_name = "geared rotary actuator";
  t.description =
      "Geared rotary actuator (GRA, compound planetary) driving a flap track; load-dependent "
      "efficiency that differs for opposing and aiding loads and settles over an input angle "
      "after a reversal (paper eq. 4 and fig. 7).";
  t.ports = {Flange("input", "input flange from the station gearbox or limiter")};
  auto& ps = t.parameters;
  ps.push_back(Param("ratio", "ratio", Dimensionless(), "1", "gear ratio, input speed / output speed")
                   .Nominal(200)
                   .Default(100, 300)
                   .Valid(1, 10000)
                   .Source("domain.md s3 (E): GRA 200:1; s6 100-300:1"));
  ps.push_back(Efficiency("eta_opposing", "eta_op", 0.85, 0.80, 0.90, "efficiency driving against an opposing load",
                          "domain.md s3/s6 (E): 0.85 [0.80, 0.90]"));
  ps.push_back(AidingEfficiency("eta_aiding", "eta_ai", 0.70, 0.60, 0.80, "efficiency with an aiding (back-driving) load",
                          "domain.md s3/s6 (E): 0.70 [0.60, 0.80]"));
  ps.push_back(Param("input_inertia", "J_in", dimensions::Inertia(), "kg*m^2", "inertia of the actuator referred to its input")
                   .Nominal(1e-3)
                   .Default(5e-4, 2e-3)
                   .Valid(0, 100)
                   .Source("domain.md s6 (E): input J about 1e-3 kg m2")
                   .Side(ReferenceSide::kActuatorInput));
  ps.push_back(Param("load_inertia", "J_load", dimensions::Inertia(), "kg*m^2", "flap inertia reflected to the actuator input")
                   .Nominal(3.88e-2)
                   .Default(2e-2, 6e-2)
                   .Valid(0, 100)
                   .Source("domain.md s3 (E): reflected flap 9.7e-3 kg m2 at the shaft = 4 x 9.7e-3 at the input of an "
                           "actuator behind the default 2:1 station gearbox")
                   .Side(ReferenceSide::kActuatorInput));
  ps.push_back(Param("output_torque_rating", "tau_out_max", Torque(), "kN*m", "rated output torque")
                   .Nominal(20)
                   .Default(15, 30)
                   .Valid(0, 1e4)
                   .Source("domain.md s3 (E): station output torque about 20 kN m")
                   .Side(ReferenceSide::kActuatorOutput));
  ps.push_back(Param("limit_output_torque", "tau_out_lim", Torque(), "kN*m",
                     "limit (jam) output torque: the structural load it takes without damage when a jam puts the "
                     "station limiter's end-stop torque through it")
                   .Nominal(50)
                   .Default(45, 75)
                   .Valid(0, 1e5)
                   .Source("estimate: 2.5 x the rated output torque; a jam passes the station limiter's end stop, up to "
                           "1.6 x 1.25 x 1.1 = 2.2 x the operating torque (domain.md s6 trip 1.3-1.6 x, +-10 %)")
                   .Side(ReferenceSide::kActuatorOutput));
  ps.push_back(Param("travel_angle", "phi_travel", Dimensionless(), "rad", "output rotation for full travel")
                   .Nominal(2.2)
                   .Default(1.5, 3)
                   .Valid(0, 100)
                   .Source("domain.md s3 (E): 2.2 rad GRA output rotation")
                   .Side(ReferenceSide::kActuatorOutput));
  ps.push_back(Param("eta_settle_angle", "phi_eta", Dimensionless(), "rev",
                     "input angle over which the efficiency settles to its final value after a start or reversal, paper fig. 7")
                   .Nominal(0.5)
                   .Default(0.1, 2)
                   .Valid(0, 1000)
                   .Source("estimate: teeth of the planetary stages come into contact within about half an input revolution")
                   .Side(ReferenceSide::kActuatorInput));
  ps.push_back(Param("eta_speed_threshold", "w_eta", AngularVelocity(), "rad/s",
                     "input speed below which the efficiency rises linearly to 1 when stopping, paper fig. 7")
                   .Nominal(0.1)
                   .Default(0.05, 0.2)
                   .Valid(0, 1e3)
                   .Source("estimate: like the Stribeck speed, domain.md s6 w_brk 0.05-0.2 rad/s")
                   .Side(ReferenceSide::kActuatorInput));
  ps.push_back(Backlash("total backlash referred to the input", ReferenceSide::kActuatorInput));
  ps.push_back(OptionalStiffness("torsional stiffness referred to the input", ReferenceSide::kActuatorInput));
  AddStribeck(ps, 0.2, 0.1, 0.4, "estimate: about twice a steady bearing", ReferenceSide::kActuatorInput);
  ps.push_back(SpanPosition());
  t.roles = {.actuator = true, .jammable = true, .lumps_inertia = true};
  return t;
}

namespace {

/// A flap panel moving along its track, seen as an inertia at the actuator input: the panel of
/// mass m [kg] travels a stroke s [m] while the actuator output turns through phi_travel [rad],
/// so its speed is v = (s/phi_travel) w_out and, with w_in = ratio w_out,
/// J = m (s / phi_travel)^2 / ratio^2 [kg*m^2]. Example: 1200 kg, 2.5 m over 2.2 rad, station
/// ratio 400: 9.7e-3 kg*m^2 at the shaft (domain.md s3).
template <class T>
T FlapInertiaAtInput(const T& m, const T& s, const T& phi_travel, const T& ratio) {
  const T lever = s / phi_travel;
  return m * lever * lever / (ratio * ratio);
}

/// Actuator mass from its output torque rating tau_out [N*m]: m = 20 kg (tau_out / 20 kN*m)^0.8
/// (an estimate for a 20 kN*m GRA, 1 kN*m/kg; housing overhead makes mass grow slower than
/// torque, volume ~ tau).
template <class T>
T MassFromTorque(const T& tau_out) {
  using std::exp;
  using std::log;
  return T(20.0) * exp(T(0.8) * log(tau_out / T(20e3)));
}

class GearedRotaryActuatorModel final : public ActuatorModel {
 public:
  GearedRotaryActuatorModel() : ActuatorModel("geared_rotary_actuator") {}
  double TravelAngle(const Component& c) const override { return Require(c, "travel_angle"); }
  Sym OutputTravel(const ParameterReader<Sym>& p) const override { return p("travel_angle"); }

  /// Input side plus the surface's inertia referred to the input.
  template <class T>
  Lumped<T> Law(const ParameterReader<T>& p) const {
    Lumped<T> out = DefaultLumped(p);
    out.J = p("input_inertia") + p("load_inertia");
    return out;
  }
  HIGHLIFT_LUMPED_LAW

  /// Against the peak loads at its input: the input torque that puts its limit (jam) torque on
  /// the output when it drives against the stop, limit / (ratio eta_opposing). The rated output
  /// torque is an operating rating and is checked by the steady-state sizing, not here: a jam
  /// puts the station limiter's end-stop torque through the actuator, which its limit torque
  /// must take.
  template <class T>
  std::optional<Allowable<T>> PeakLaw(const ParameterReader<T>& p) const {
    if (!p.Has("limit_output_torque")) return std::nullopt;
    return Allowable<T>{"limit output torque / (ratio eta_opposing)",
                        p("limit_output_torque") / (p("ratio") * p("eta_opposing"))};
  }
  HIGHLIFT_PEAK_ALLOWABLE_LAW
  /// In the steady state its rated output torque against its output load.
  std::optional<Allowable<Interval>> SteadyAllowable(const ParameterReader<Interval>& p) const override {
    if (!p.Has("output_torque_rating")) return std::nullopt;
    return Allowable<Interval>{"rated output torque", p("output_torque_rating"), true};
  }
  /// Input inertia by gear scaling at the input torque of its rating, the surface's inertia from
  /// labels "flap_mass" and "flap_stroke", its limit torque from its rating, its mass by gear
  /// scaling.
  std::vector<EstimationLaw> EstimationLaws() const override {
    const LawInput tau_out = FromParameter("output_torque_rating"), ratio = FromParameter("ratio");
    return {
        EstimateParameter(
            "input_inertia", {tau_out, ratio, FromParameter("eta_opposing")},
            "physics: gear scaling J_in = 3e-4 + 7e-4 (tau_out/(ratio eta) / 117.6 N m)^(5/3) kg m2 (domain.md s6)",
            [](const auto& v) { return GearboxInertiaFromTorque(v[0] / (v[1] * v[2])); }),
        EstimateParameter("load_inertia",
                          {FromLabel("flap_mass", dimensions::Mass()), FromLabel("flap_stroke", dimensions::Length()),
                           FromParameter("travel_angle"), ratio},
                          "physics: J = m (s/phi_travel)^2 / ratio^2 from labels flap_mass, flap_stroke",
                          [](const auto& v) { return FlapInertiaAtInput(v[0], v[1], v[2], v[3]); }),
        EstimateParameter("limit_output_torque", {tau_out},
                          "estimate: 2.5 x the rated output torque, above the station limiter's end stop on the "
                          "output (up to 2.2 x the operating torque, domain.md s6)",
                          [](const auto& v) { return 2.5 * v[0]; }),
        DeriveQuantity("mass", "kg", {tau_out}, "gear scaling m = 20 kg (tau_out/20 kN m)^0.8 (estimate)",
                       [](const auto& v) { return MassFromTorque(v[0]); })};
  }
  std::vector<FitRule> FitRules() const override { return {{"input_inertia", "output_torque_rating"}}; }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(GearedRotaryActuator, GearedRotaryActuatorModel)
