// pdu: the power drive unit. Speed-controlled (the HighLift.Drives.PDU element) or, with text
// parameter drive = "hydraulic", the hydraulic sub-network of hydraulic_pdu.cc.
#include "component_util.h"
#include "highlift/model/drive_network.h"
#include "highlift/model/hydraulic_pdu.h"

namespace highlift::model::components {
namespace {

/// The inertia at the output: n motors of rotor inertia J_m [kg*m^2] through the PDU ratio
/// (motor speed / output speed) plus the gears referred to the output J_g:
/// J = n J_m ratio^2 + J_g [kg*m^2]. Example: 2 x 3e-4 x 20^2 + 0.02 = 0.26 kg*m^2 (domain.md s3).
template <class T>
T OutputInertia(const T& J_m, const T& n, const T& ratio, const T& J_g) {
  return J_m * n * ratio * ratio + J_g;
}

class PduModel final : public NamedModel {
 public:
  PduModel() : NamedModel("pdu") {}

  std::vector<std::string> PowerPorts() const override { return {"left", "right"}; }

  /// Motors reflected through the PDU gearbox plus the gear inertia, at the output.
  template <class T>
  Lumped<T> Law(const ParameterReader<T>& p) const {
    Lumped<T> out = DefaultLumped(p);
    out.J = OutputInertia(p("motor_inertia"), T(p.Nominal("motor_count")), p("ratio"), p("gear_inertia"));
    return out;
  }
  HIGHLIFT_LUMPED_LAW

  /// In the steady state its stall torque against the operating torque at its output.
  std::optional<Allowable<Interval>> SteadyAllowable(const ParameterReader<Interval>& p) const override {
    if (!p.Has("stall_torque")) return std::nullopt;
    return Allowable<Interval>{"stall torque", p("stall_torque")};
  }

  void Expand(const Component& c, ExpansionContext& x) const override {
    std::optional<double> motor_lost_time;  // the scenario value, as t_motor_lost below
    if (const Scenario* s = x.scenario())
      if (auto it = s->values.find("motor_lost_time"); it != s->values.end()) motor_lost_time = it->second;
    if (detail::IsHydraulicPdu(c)) {
      // A shutdown input when the wing-tip brakes will be commanded (the monitor).
      const detail::PduPorts p = detail::AddHydraulicPdu(x.network(), c, motor_lost_time, x.HasTipBrakes());
      for (const auto& e : x.network().elements())
        if (!x.model().component_of.count(e.id)) x.model().component_of[e.id] = c.id;
      x.SetDriveUnit(c, {p.flange_left, p.flange_right, p.w_ref, p.phi, p.stop});
      return;
    }
    Scalars s = {{"n_m", ValueOr(c, "motor_count", 2)},
                 {"J_m", Require(c, "motor_inertia")},
                 {"ratio", Require(c, "ratio")},
                 {"J_g", Require(c, "gear_inertia")},
                 {"w_max", Require(c, "max_output_speed")},
                 {"tau_stall", Require(c, "stall_torque")},
                 {"P_max", Require(c, "power")},
                 {"t_ramp", Require(c, "speed_ramp_time")},
                 {"tauPOB", Require(c, "brake_torque")}};
    if (motor_lost_time) s["t_motor_lost"] = *motor_lost_time;
    x.Add("PDU", c.id, s, c.id);
    x.SetDriveUnit(c, {c.id + ".flange_left", c.id + ".flange_right", c.id + ".w_ref", c.id + ".phi", c.id + ".stop"});
  }

  /// Reported: the inertia at the output (its lumped law) over the domains of the motor count too.
  std::vector<EstimationLaw> EstimationLaws() const override {
    return {DeriveQuantity("output_inertia", "kg*m^2",
                           {FromParameter("motor_inertia"), FromParameter("motor_count"), FromParameter("ratio"),
                            FromParameter("gear_inertia")},
                           "n J_m ratio^2 + J_g", [](const auto& v) { return OutputInertia(v[0], v[1], v[2], v[3]); })};
  }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(Pdu, PduModel)
