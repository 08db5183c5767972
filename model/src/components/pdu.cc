// pdu: the power drive unit. Speed-controlled (the HighLift.Drives.PDU element) or, with text
// parameter drive = "hydraulic", the hydraulic sub-network of hydraulic_pdu.cc.
#include "declaration.h"
#include "highlift/model/drive_network.h"
#include "highlift/model/hydraulic_pdu.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec PduDeclaration() {
  ComponentTypeSpec t;
  t.name = "pdu";
  t.display_name = "power drive unit";
  t.description =
      "Power drive unit (PCU): two motors summed by a speed-summing differential, each with a "
      "pressure-off brake (POB), driving the left and right transmission. One motor lost: half "
      "speed, full torque. Parameters refer to the output shaft unless stated.";
  t.ports = {Flange("left", "output flange to the left wing transmission"),
             Flange("right", "output flange to the right wing transmission (optional for a one-wing rig)", false)};
  auto& ps = t.parameters;
  ps.push_back(Param::Integer("motor_count", "n_m", "number of motors summed by the differential")
                   .Nominal(2)
                   .Valid(1, 4)
                   .Source("domain.md s1 (P): A320 PCU has 2 motors"));
  ps.push_back(Param("motor_inertia", "J_m", dimensions::Inertia(), "kg*m^2", "rotor inertia of one motor")
                   .Nominal(3e-4)
                   .Default(2e-4, 4e-4)
                   .Valid(0, 10)
                   .Source("domain.md s3 (E): motor J [2, 4]e-4 kg m2")
                   .Side(ReferenceSide::kMotor));
  ps.push_back(Param("ratio", "i_PDU", Dimensionless(), "1", "PDU gear ratio, motor speed / output speed")
                   .Nominal(20)
                   .Default(16, 25)
                   .Valid(1, 1000)
                   .Source("domain.md s3 (E): i_PCU = 20 (A320-class 16, s4)"));
  ps.push_back(Param("gear_inertia", "J_g", dimensions::Inertia(), "kg*m^2",
                     "inertia of the differential and gears, referred to the output")
                   .Nominal(0.02)
                   .Default(0.01, 0.03)
                   .Valid(0, 100)
                   .Source("domain.md s3 (E): 0.02 kg m2 gears")
                   .Side(ReferenceSide::kPduOutput));
  ps.push_back(Efficiency("efficiency", "eta", 0.90, 0.85, 0.95, "efficiency of the PDU gearbox",
                          "domain.md s3 (E): PCU gearbox 0.90"));
  ps.push_back(Param("max_output_speed", "w_max", AngularVelocity(), "rpm", "maximum output speed, both motors")
                   .Nominal(242)
                   .Default(220, 265)
                   .Valid(0, 20000)
                   .Source("domain.md s3 (E): 25.3 rad/s = 242 rpm")
                   .Side(ReferenceSide::kPduOutput));
  ps.push_back(Param("stall_torque", "tau_stall", Torque(), "N*m",
                     "output torque at stall (reacted at a jammed station)")
                   .Nominal(1000)
                   .Default(850, 1200)
                   .Valid(0, 1e6)
                   .Source("estimate: 1.4 x the 720 N m operating torque for both wings of domain.md s3")
                   .Side(ReferenceSide::kPduOutput));
  ps.push_back(Param("power", "P", dimensions::Power(), "kW", "maximum output power")
                   .Nominal(18)
                   .Default(15, 22)
                   .Valid(0, 1e4)
                   .Source("domain.md s3 (E): about 18 kW for both wings"));
  ps.push_back(Param("brake_torque", "tau_POB", Torque(), "N*m",
                     "holding torque of the pressure-off brakes, referred to the output")
                   .Nominal(1100)
                   .Default(900, 1400)
                   .Valid(0, 1e6)
                   .Source("estimate: above the stall torque so the POBs hold the drive")
                   .Side(ReferenceSide::kPduOutput));
  ps.push_back(Param("speed_ramp_time", "t_ramp", Time(), "s", "time from 0 to the maximum output speed")
                   .Nominal(0.4)
                   .Default(0.3, 0.5)
                   .Valid(0, 100)
                   .Source("domain.md s3 (E): 0 -> w_max in 0.3-0.5 s"));
  ps.push_back(Param("brake_stop_time", "t_stop", Time(), "s", "time for the POBs to stop the drive")
                   .Nominal(0.1)
                   .Default(0.05, 0.2)
                   .Valid(0, 100)
                   .Source("domain.md s3 (E): stop with POB in about 0.1 s"));
  ps.push_back(Param("motor_displacement", "V_m", Volume(), "cm^3/rev", "displacement of one hydraulic motor")
                   .Valid(0, 1e4)
                   .Optional()
                   .Source("domain.md s6 (P/E): 4-13 cm3/rev"));
  ps.push_back(Param("supply_pressure", "p_s", Pressure(), "bar", "hydraulic supply pressure")
                   .Valid(0, 1000)
                   .Optional()
                   .Source("domain.md s1 (P-low): 207 bar (A320), 345 bar (A380)"));
  // The hydraulic drive (drive = "hydraulic", sim/src/hydraulic_pdu.cc, docs/hydraulics.md):
  // per motor a servo valve strokes a differential cylinder that sets the displacement of a
  // variable-displacement motor on constant supply pressure (secondary control).
  ps.push_back(Param::Text("drive", "'speed_controlled' (default: ideal speed-controlled motors) or "
                                    "'hydraulic' (valve, cylinder and variable-displacement motors)")
                   .Optional()
                   .Source("domain.md s1 (P): A320 PCU has 2 hydraulic motors"));
  ps.push_back(Param("return_pressure", "p_r", Pressure(), "bar", "hydraulic return pressure (hydraulic drive)")
                   .Nominal(5)
                   .Default(3, 8)
                   .Valid(0, 1000)
                   .Source("estimate: typical aircraft return line 3-8 bar"));
  ps.push_back(Param("supply_line_area", "A_line", Area(), "mm^2",
                     "orifice area equivalent to the supply line and filters (hydraulic drive)")
                   .Nominal(30)
                   .Default(20, 45)
                   .Valid(0, 1e4)
                   .Source("estimate: about 10 bar drop at the 52 L/min of two motors at full speed"));
  ps.push_back(Param("supply_volume", "V_s", Volume(), "L", "compressible oil volume of the supply line (hydraulic drive)")
                   .Nominal(0.5)
                   .Default(0.2, 1.0)
                   .Valid(1e-6, 1e3)
                   .Source("estimate: a few metres of 12 mm line"));
  ps.push_back(Efficiency("motor_mechanical_efficiency", "eta_m", 0.95, 0.92, 0.97,
                          "mechanical (torque) efficiency of one hydraulic motor (hydraulic drive)",
                          "estimate: axial-piston motors 0.92-0.97"));
  ps.push_back(Param("motor_leakage", "G_leak", VolumeFlowRate() / Pressure(), "m^3/(s*Pa)",
                     "leakage conductance of one motor (hydraulic drive)")
                   .Nominal(3e-13)
                   .Default(1e-13, 6e-13)
                   .Valid(0, 1e-9)
                   .Source("estimate: volumetric efficiency about 0.97 at full speed and 345 bar"));
  ps.push_back(Param("valve_area", "A_max", Area(), "mm^2", "metering edge area of the displacement servo valve at full stroke")
                   .Nominal(1)
                   .Default(0.5, 2)
                   .Valid(0, 1e3)
                   .Source("estimate: strokes the displacement cylinder in about 15 ms"));
  ps.push_back(Param("valve_time_constant", "T_v", Time(), "ms", "time constant of the servo valve spool")
                   .Nominal(5)
                   .Default(3, 10)
                   .Valid(1e-3, 1e4)
                   .Source("estimate: servo valves 3-10 ms"));
  ps.push_back(Param("cylinder_area", "A_A", Area(), "mm^2", "piston area of the displacement cylinder")
                   .Nominal(100)
                   .Default(60, 150)
                   .Valid(1e-3, 1e5)
                   .Source("estimate: 11 mm bore"));
  ps.push_back(Param("cylinder_annulus_area", "A_B", Area(), "mm^2", "annulus (rod side) area of the displacement cylinder")
                   .Nominal(50)
                   .Default(30, 75)
                   .Valid(1e-3, 1e5)
                   .Source("estimate: half the piston area"));
  ps.push_back(Param("cylinder_stroke", "s_max", Length(), "mm", "stroke of the displacement cylinder (eps from -1 to 1)")
                   .Nominal(20)
                   .Default(15, 30)
                   .Valid(1e-3, 1e4)
                   .Source("estimate: swash-plate actuators 15-30 mm"));
  ps.push_back(Param("cylinder_dead_volume", "V0", Volume(), "cm^3", "dead volume of each chamber of the displacement cylinder")
                   .Nominal(1)
                   .Default(0.5, 2)
                   .Valid(1e-6, 1e6)
                   .Source("estimate"));
  ps.push_back(Param("cylinder_mass", "m_c", Mass(), "kg", "piston, rod and swash plate reflected to the rod")
                   .Nominal(0.1)
                   .Default(0.05, 0.2)
                   .Valid(1e-6, 1e3)
                   .Source("estimate"));
  ps.push_back(Param("cylinder_damping", "d_c", Force() / (Length() / Time()), "N*s/m", "viscous friction of the displacement piston")
                   .Nominal(1000)
                   .Default(500, 2000)
                   .Valid(0, 1e7)
                   .Source("estimate: damping ratio about 0.5 with the oil stiffness"));
  ps.push_back(Param("speed_gain", "k_w", Time(), "s/rad", "displacement command per motor speed error (speed loop)")
                   .Nominal(5e-4)
                   .Default(2.5e-4, 1e-3)
                   .Valid(0, 1)
                   .Source("estimate: speed loop about 40 rad/s with the PDU's own 0.26 kg m2 (the transmission is compliant)")
                   .Side(ReferenceSide::kMotor));
  ps.push_back(Param("speed_integral_time", "T_i", Time(), "s", "integral time of the speed loop")
                   .Nominal(0.05)
                   .Default(0.03, 0.1)
                   .Valid(1e-4, 100)
                   .Source("estimate: 2 x the speed-loop time constant"));
  ps.push_back(Param("position_gain", "k_s", Dimensionless(), "1", "servo valve command per displacement error (position loop)")
                   .Nominal(1.5)
                   .Default(1, 2)
                   .Valid(0, 100)
                   .Source("estimate: position loop about 200 rad/s, at the valve's 200 rad/s"));
  ps.push_back(SpanPosition());
  t.roles = {.drive_unit = true, .lumps_inertia = true};
  return t;
}

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
