// The torque limiters (system_torque_limiter.cc, station_torque_limiter.cc): one
// HighLift.Mechanical.TorqueLimiter element, ports input and output.
#pragma once

#include "component_util.h"
#include "declaration.h"
#include "highlift/core/message_number.h"

namespace highlift::model::components {

// Torque limiter settings and the three stiffnesses of the paper's figure 4, all on `side`.
inline void AddTorqueLimiter(std::vector<ParameterSpec>& ps, double tau1, double retract_factor, double c1,
                      const std::string& tau1_source, const std::string& c1_source, ReferenceSide side) {
  ps.push_back(Param("lockout_torque_extend", "tau1_ext", Torque(), "N*m",
                     "lock-out (trip) torque tau_1 when driving in extend direction, paper fig. 4")
                   .Nominal(tau1)
                   .Default(0.9 * tau1, 1.1 * tau1)
                   .Valid(0, 1e5)
                   .Source(tau1_source + "; domain.md s3: trips +-10 %")
                   .Side(side));
  ps.push_back(Param("lockout_torque_retract", "tau1_ret", Torque(), "N*m",
                     "lock-out (trip) torque tau_1 when driving in retract direction, paper fig. 4")
                   .Nominal(retract_factor * tau1)
                   .Default(0.9 * retract_factor * tau1, 1.1 * retract_factor * tau1)
                   .Valid(0, 1e5)
                   .Source(retract_factor == 1.0 ? "estimate: symmetric (E)"
                                                 : "domain.md s3 (E): retract 0.7 x extend; EP4265931 (P)")
                   .Side(side));
  ps.push_back(Param("end_stop_torque", "tau2", Torque(), "N*m",
                     "torque tau_2 at which the balls reach their end stop and the device is grounded, paper fig. 4")
                   .Nominal(1.25 * tau1)
                   .Default(1.15 * tau1, 1.4 * tau1)
                   .Valid(0, 1e5)
                   .Source("estimate: 1.25 x tau_1 (lock-out travel a few degrees on the lock-out stiffness)")
                   .Side(side));
  ps.push_back(Param("stiffness_normal", "c1", Torque(), "N*m/rad",
                     "torsional stiffness in normal operation (balls seated), paper fig. 4")
                   .Nominal(c1)
                   .Default(0.5 * c1, 2 * c1)
                   .Valid(0, 1e9)
                   .Source(c1_source)
                   .Side(side));
  ps.push_back(Param("stiffness_lockout", "c2", Torque(), "N*m/rad",
                     "torsional stiffness while the balls run up the ramp (lock-out), paper fig. 4")
                   .Nominal(0.05 * c1)
                   .Default(0.02 * c1, 0.1 * c1)
                   .Valid(0, 1e9)
                   .Source("estimate: the paper says it 'decreases significantly': 5 % of c1")
                   .Side(side));
  ps.push_back(Param("stiffness_end_stop", "c3", Torque(), "N*m/rad",
                     "torsional stiffness with the balls at their end stop (grounded), paper fig. 4")
                   .Nominal(5 * c1)
                   .Default(2 * c1, 10 * c1)
                   .Valid(0, 1e9)
                   .Source("estimate: grounded to structure, 5 x c1")
                   .Side(side));
  ps.push_back(Param("max_brake_torque", "tau_B_max", Torque(), "N*m",
                     "friction brake torque to ground reached at the end stop (normalised output y = 1), paper eq. (2)")
                   .Nominal(2 * tau1)
                   .Default(1.5 * tau1, 3 * tau1)
                   .Valid(0, 1e6)
                   .Source("estimate: 2 x tau_1")
                   .Side(side));
}

/// The relations of a limiter's settings that their ranges cannot express: both lock-out
/// torques below the end-stop torque (paper fig. 4: the balls leave their seats at tau_1 and
/// reach the end stop at tau_2).
inline std::vector<ParameterRelation> TorqueLimiterRelations() {
  const std::string note = "the balls reach their end stop above the lock-out torque, paper fig. 4";
  return {{"lockout_torque_extend", "end_stop_torque", 1.0, "the end-stop torque", note, /*strict=*/true},
          {"lockout_torque_retract", "end_stop_torque", 1.0, "the end-stop torque", note, /*strict=*/true}};
}

/// The element parameters of a HighLift.Mechanical.TorqueLimiter from a component's limiter
/// settings and stiffnesses (AddTorqueLimiter) and its inertia parameter `inertia`. Throws
/// InputError when the end stop does not exceed both lock-out torques.
inline Scalars TorqueLimiterScalars(const Component& c, ExpansionContext& x, const std::string& inertia) {
  const double tau1_ext = Require(c, "lockout_torque_extend");
  const double tau1_ret = Require(c, "lockout_torque_retract");
  const double tau2 = Require(c, "end_stop_torque");
  if (!(tau2 > tau1_ext && tau2 > tau1_ret))
    throw InputError("component '" + c.id + "' (" + c.type + "): 'end_stop_torque' = " + FormatMessageNumber(tau2) +
                         " N*m must exceed both lock-out torques (" + FormatMessageNumber(tau1_ext) + ", " +
                         FormatMessageNumber(tau1_ret) + " N*m): raise it or lower the lock-out torques",
                     c.where);
  // The retract end stop keeps the extend ratio tau2/tau1.
  return {{"tau1_ext", tau1_ext},
          {"tau1_ret", tau1_ret},
          {"tau2_ext", tau2},
          {"tau2_ret", tau2 * tau1_ret / tau1_ext},
          {"c1", Require(c, "stiffness_normal")},
          {"d", x.beta() * Require(c, "stiffness_normal")},  // structural damping of the balls and ramps
          {"c2", Require(c, "stiffness_lockout")},
          {"c3", Require(c, "stiffness_end_stop")},
          {"tauB_max", Require(c, "max_brake_torque")},
          {"J", Require(c, inertia)}};
}

/// The torque a torque limiter passes on to a jammed output when `tau_in` arrives at its input
/// (every torque at one speed). The paper's limiter (fig. 5) is a shaft brake that grounds the
/// input side with y tau_B_max, y of eq. (2), in series with the nonlinear spring of fig. 4 that
/// carries the rest to the output. Below the end stop (y < 1) the spring carries less than tau_2;
/// at the end stop (y = 1) the brake, while it slides, grounds tau_B_max and the spring carries
/// tau_in - tau_B_max; once it holds, the output's twist and torque are frozen. So the jammed
/// output sees at most max(tau_2, tau_in - tau_B_max), and never more than arrives:
///   tau_out = min(tau_in, max(tau_2, tau_in - tau_B_max)).
/// A limiter whose brake (its lock-out into the housing) grounds what the drive can deliver
/// passes tau_2; one whose brake is weaker passes the excess (docs/reduced_models.md).
template <class T>
T LimiterPassedTorque(const T& tau_in, const T& tau2, const T& tauB_max) {
  using std::max;
  using std::min;
  return min(tau_in, max(tau2, tau_in - tauB_max));
}

/// LimiterPassedTorque with a limiter's parameters, every torque n x its own (n: the limiter's
/// speed over the reference speed); nullopt without the settings.
template <class T>
std::optional<T> LimiterPassLaw(const ParameterReader<T>& p, const T& tau_in, const T& n) {
  if (!p.Has("end_stop_torque") || !p.Has("max_brake_torque")) return std::nullopt;
  return LimiterPassedTorque(tau_in, p("end_stop_torque") * n, p("max_brake_torque") * n);
}

/// The setting rules of a limiter in front of one station: extend against the station's largest
/// extend torque; retract: the aiding airload leaves little drive torque, the rule applies to
/// what remains, and the project's asymmetric setting (domain.md s3: 0.7 x extend) is checked
/// against it (no upper bound).
inline std::vector<SettingRule> StationLimiterSettingRules() {
  const std::string rule = "1.3-1.6 x station max operating torque (domain.md s6)";
  return {{"lockout_torque_extend", rule, SettingRule::Against::kOperatingExtend, 1.5, 1.3, 1.6},
          {"lockout_torque_retract", rule, SettingRule::Against::kOperatingRetract, 1.5, 1.3, kInfinity},
          {"max_brake_torque",
           ">= the static jam torque it must ground (PDU stall torque through the system torque limiter, at its "
           "speed, minus its end-stop torque), so that a jammed actuator sees at most the end-stop torque "
           "(docs/reduced_models.md)",
           SettingRule::Against::kJamGrounding, 1.25, 1.0, kInfinity}};
}

class TorqueLimiterModel : public NamedModel {
 public:
  explicit TorqueLimiterModel(std::string_view type) : NamedModel(type) {}

  std::vector<std::string> PowerPorts() const override { return {"output"}; }

  /// In the lumped models the normal-operation stiffness c1 (the paper's figure 4).
  template <class T>
  Lumped<T> Law(const ParameterReader<T>& p) const {
    Lumped<T> out = DefaultLumped(p);
    out.c = p("stiffness_normal");
    return out;
  }
  HIGHLIFT_LUMPED_LAW

  template <class T>
  std::optional<T> PassLaw(const ParameterReader<T>& p, const T& tau_in, const T& n) const {
    return LimiterPassLaw(p, tau_in, n);
  }
  HIGHLIFT_JAM_PASSED_LAW

  void Expand(const Component& c, ExpansionContext& x) const override {
    x.Add("TorqueLimiter", c.id, TorqueLimiterScalars(c, x, "inertia"), c.id);
    x.MapPort(c, "input", c.id + ".flange_a");
    x.MapPort(c, "output", c.id + ".flange_b");
  }

  std::vector<FitRule> FitRules() const override { return {{"inertia", "lockout_torque_extend"}}; }
};

}  // namespace highlift::model::components
