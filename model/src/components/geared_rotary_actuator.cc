// geared_rotary_actuator: a rotary actuator at a flap or slat station (actuator.h); its travel
// is the output angle travel_angle.
#include "actuator.h"
#include "gear_scaling.h"

namespace highlift::model::components {
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
