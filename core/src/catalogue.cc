// The catalogue of drive-system component types. Every port and parameter of every type is
// declared here exactly once; values are written in their display unit and converted to SI.
//
// Sources (the `source` of each parameter): "domain.md s3 (E)" etc. refer to sections and tags
// of ../shared/reference/domain.md; "paper fig. 4" etc. to highlift_paper.txt; "estimate" marks a
// catalogue estimate with its reasoning, to be treated as the centre of an interval.
#include "highlift/core/catalogue.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "highlift/core/error.h"

namespace highlift {

namespace {

constexpr std::pair<ReferenceSide, const char*> kSideNames[] = {
    {ReferenceSide::kNone, "none"},
    {ReferenceSide::kMotor, "motor"},
    {ReferenceSide::kPduOutput, "pdu_output"},
    {ReferenceSide::kShaft, "shaft"},
    {ReferenceSide::kActuatorInput, "actuator_input"},
    {ReferenceSide::kActuatorOutput, "actuator_output"},
};

}  // namespace

const char* ToString(ReferenceSide side) {
  for (const auto& [s, name] : kSideNames)
    if (s == side) return name;
  return "none";
}

std::optional<ReferenceSide> ParseReferenceSide(std::string_view name) {
  for (const auto& [s, n] : kSideNames)
    if (name == n) return s;
  return std::nullopt;
}

const char* ReferenceSideLabel(ReferenceSide side) {
  switch (side) {
    case ReferenceSide::kNone: return "";
    case ReferenceSide::kMotor: return "motor side";
    case ReferenceSide::kPduOutput: return "PDU output";
    case ReferenceSide::kShaft: return "shaft side";
    case ReferenceSide::kActuatorInput: return "actuator input";
    case ReferenceSide::kActuatorOutput: return "actuator output";
  }
  return "";
}

const PortSpec* ComponentTypeSpec::FindPort(std::string_view port) const {
  for (const auto& p : ports)
    if (p.name == port) return &p;
  return nullptr;
}

const PortSpec* ComponentTypeSpec::GearedPort() const {
  for (const auto& p : ports)
    if (!p.speed_ratio.empty()) return &p;
  return nullptr;
}

const ParameterSpec* ComponentTypeSpec::FindParameter(std::string_view parameter) const {
  for (const auto& p : parameters)
    if (p.name == parameter) return &p;
  return nullptr;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using namespace dimensions;

// Builder of a ParameterSpec; numbers are in the display unit.
class Param {
 public:
  Param(std::string name, std::string symbol, Dimension dimension, std::string unit, std::string description) {
    spec_.name = std::move(name);
    spec_.symbol = std::move(symbol);
    spec_.dimension = dimension;
    spec_.unit = std::move(unit);
    spec_.description = std::move(description);
  }
  static Param Integer(std::string name, std::string symbol, std::string description) {
    Param p(std::move(name), std::move(symbol), Dimensionless(), "1", std::move(description));
    p.spec_.kind = ParameterKind::kInteger;
    return p;
  }
  static Param Text(std::string name, std::string description) {
    Param p(std::move(name), "", Dimensionless(), "", std::move(description));
    p.spec_.kind = ParameterKind::kText;
    return p;
  }
  Param& Nominal(double v) {
    nominal_ = v;
    return *this;
  }
  Param& Default(double lo, double hi) {
    default_ = Domain{lo, hi};
    return *this;
  }
  Param& Valid(double lo, double hi) {
    valid_ = Domain{lo, hi};
    return *this;
  }
  Param& Source(std::string s) {
    spec_.source = std::move(s);
    return *this;
  }
  Param& Optional() {
    spec_.optional = true;
    return *this;
  }
  Param& Side(ReferenceSide side) {  // the gear side the value counts on
    spec_.referred_to = side;
    return *this;
  }
  operator ParameterSpec() const {  // NOLINT: implicit by design, for the declaration lists
    ParameterSpec s = spec_;
    const std::string unit = spec_.kind == ParameterKind::kText ? "1" : spec_.unit;
    auto si = [&](double v) { return std::isinf(v) ? v : ToSI(v, unit, spec_.dimension); };
    auto si_domain = [&](const Domain& d) { return Domain{si(d.lo), si(d.hi)}; };
    s.valid_range = si_domain(valid_);
    if (nominal_) s.nominal = si(*nominal_);
    if (default_) {
      s.default_domain = si_domain(*default_);
    } else if (s.nominal) {
      s.default_domain = Domain::Point(*s.nominal);
    } else {
      s.default_domain = s.valid_range;
    }
    return s;
  }

 private:
  ParameterSpec spec_;
  std::optional<double> nominal_;
  std::optional<Domain> default_;
  Domain valid_{0.0, kInf};
};

PortSpec Flange(std::string name, std::string description, bool required = true) {
  return PortSpec{std::move(name), PortKind::kFlange, required, std::move(description), false, {}};
}

/// A gear's flange turning 1/ratio as fast as its flange "input".
PortSpec GearedFlange(std::string name, std::string description, bool required = true) {
  PortSpec p = Flange(std::move(name), std::move(description), required);
  p.speed_ratio = "ratio";
  return p;
}

// Parameters shared by several types ---------------------------------------------------------

ParameterSpec SpanPosition() {
  return Param("span_position", "x", Length(), "m",
               "position along the span from the aircraft centre line (stations, reports)")
      .Valid(-100, 100)
      .Optional()
      .Source("domain.md s3 (E) gives x per node");
}

ParameterSpec Inertia(double nominal, double lo, double hi, std::string description, std::string source,
                      ReferenceSide side) {
  return Param("inertia", "J", dimensions::Inertia(), "kg*m^2", std::move(description))
      .Nominal(nominal)
      .Default(lo, hi)
      .Valid(0, 1e3)
      .Source(std::move(source))
      .Side(side);
}

ParameterSpec OptionalStiffness(std::string description, ReferenceSide side,
                                std::string source = "none: rigid unless given") {
  return Param("stiffness", "c", Torque(), "N*m/rad", std::move(description))
      .Valid(0, 1e9)
      .Optional()
      .Source(std::move(source))
      .Side(side);
}

ParameterSpec Backlash(std::string description, ReferenceSide side) {
  return Param("backlash", "b", Dimensionless(), "deg", std::move(description))
      .Nominal(0)
      .Default(0, 0.5)
      .Valid(0, 30)
      .Source("estimate: 0 (ideal); up to 0.5 deg for worn splines")
      .Side(side);
}

// Stribeck friction of the paper's eq. (3): tau = tau_C + d_vis*|w| + tau_S*exp(-f_exp*|w|).
// domain.md s6: T_brk = tau_C + tau_S = 1.2-1.5 x tau_C, w_brk 0.05-0.2 rad/s (f_exp = 1/w_brk).
void AddStribeck(std::vector<ParameterSpec>& ps, double tau_C, double tau_C_lo, double tau_C_hi,
                 const std::string& tau_C_source, ReferenceSide side) {
  ps.push_back(Param("coulomb_torque", "tau_C", Torque(), "N*m", "Coulomb friction (drag) torque, paper eq. (3)")
                   .Nominal(tau_C)
                   .Default(tau_C_lo, tau_C_hi)
                   .Valid(0, 1e4)
                   .Source(tau_C_source)
                   .Side(side));
  ps.push_back(Param("viscous_coefficient", "d_vis", RotationalDamping(), "N*m*s/rad",
                     "viscous friction coefficient, paper eq. (3)")
                   .Nominal(1e-4 * tau_C / 0.1)
                   .Default(0, 1e-3 * tau_C / 0.1)
                   .Valid(0, 1e3)
                   .Source("estimate: small; viscous drag at 25 rad/s below 3 % of tau_C")
                   .Side(side));
  ps.push_back(Param("stribeck_torque", "tau_S", Torque(), "N*m",
                     "Stribeck (break-away excess) torque at standstill, paper eq. (3)")
                   .Nominal(0.35 * tau_C)
                   .Default(0.2 * tau_C, 0.5 * tau_C)
                   .Valid(0, 1e4)
                   .Source("domain.md s6 (E): T_brk 1.2-1.5 x T_C")
                   .Side(side));
  ps.push_back(Param("stribeck_decay", "f_exp", Time(), "s/rad", "decay of the Stribeck torque with speed, paper eq. (3)")
                   .Nominal(10)
                   .Default(5, 20)
                   .Valid(0, 1e4)
                   .Source("domain.md s6 (E): w_brk 0.05-0.2 rad/s, f_exp = 1/w_brk")
                   .Side(side));
}

ParameterSpec Efficiency(std::string name, std::string symbol, double nominal, double lo, double hi,
                         std::string description, std::string source) {
  return Param(std::move(name), std::move(symbol), Dimensionless(), "1", std::move(description))
      .Nominal(nominal)
      .Default(lo, hi)
      .Valid(0, 1)
      .Source(std::move(source));
}

// Torque limiter settings and the three stiffnesses of the paper's figure 4, all on `side`.
void AddTorqueLimiter(std::vector<ParameterSpec>& ps, double tau1, double retract_factor, double c1,
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

// The types ----------------------------------------------------------------------------------

ComponentTypeSpec Pdu() {
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

ComponentTypeSpec SystemTorqueLimiter() {
  ComponentTypeSpec t;
  t.name = "system_torque_limiter";
  t.display_name = "system torque limiter";
  t.description =
      "System torque limiter (STL) at a PDU output: a ball-ramp coupling that locks the "
      "transmission to structure above its lock-out torque (paper fig. 4 and 5).";
  t.ports = {Flange("input", "flange towards the PDU"), Flange("output", "flange towards the wing")};
  AddTorqueLimiter(t.parameters, 470, 1.0, 2e4, "domain.md s3 (E): 1.3 x 360 N m root torque",
                   "estimate: about 10 x the adjacent shaft stiffness (domain.md s3 c = 1.4-3.3 kN*m/rad)",
                   ReferenceSide::kShaft);
  t.parameters.push_back(Inertia(1e-3, 5e-4, 2e-3, "inertia of the limiter", "estimate: comparable to a station gearbox",
                                 ReferenceSide::kShaft));
  t.parameters.push_back(SpanPosition());
  t.roles = {.lumps_inertia = true, .wing_limiter = true};
  return t;
}

ComponentTypeSpec TorqueShaft() {
  ComponentTypeSpec t;
  t.name = "torque_shaft";
  t.display_name = "torque shaft";
  t.description =
      "Torque shaft segment: a tube (length, outer diameter, wall thickness, material) or given "
      "directly by stiffness and inertia. c = G*pi/32*(D^4 - d^4)/L, J = rho*pi/32*(D^4 - d^4)*L.";
  t.ports = {Flange("a", "flange nearer the PDU"), Flange("b", "flange farther from the PDU")};
  auto& ps = t.parameters;
  ps.push_back(Param("length", "L", Length(), "m", "length of the segment")
                   .Valid(0.01, 100)
                   .Source("none: given per segment (domain.md s3 lists 1.5-4 m)"));
  ps.push_back(Param("outer_diameter", "D", Length(), "mm", "outer diameter of the tube")
                   .Nominal(50)
                   .Default(38, 60)
                   .Valid(5, 500)
                   .Source("domain.md s3 (E): 50 mm inboard, 45 mm outboard; s4: 38 mm"));
  ps.push_back(Param("wall_thickness", "t", Length(), "mm", "wall thickness of the tube")
                   .Nominal(2.0)
                   .Default(1.4, 2.1)
                   .Valid(0.1, 100)
                   .Source("domain.md s3 (E): 2.0 mm inboard, 1.8 mm outboard, +-0.1 mm"));
  ps.push_back(Param("shear_modulus", "G", Pressure(), "GPa", "shear modulus of the tube material")
                   .Nominal(44)
                   .Default(43, 51)
                   .Valid(1, 300)
                   .Source("domain.md s6 (P-low): Ti-6Al-4V G 44 [43, 51] GPa"));
  ps.push_back(Param("density", "rho", Density(), "kg/m^3", "density of the tube material")
                   .Nominal(4420)
                   .Valid(100, 30000)
                   .Source("domain.md s1 (P): Ti-6Al-4V 4420 kg/m3"));
  ps.push_back(Param("allowable_shear_stress", "tau_allow", Pressure(), "MPa", "allowable (ultimate) shear stress of the material")
                   .Nominal(550)
                   .Default(500, 600)
                   .Valid(1, 5000)
                   .Source("domain.md s6 (E): Ti-6Al-4V ultimate shear about 550 MPa"));
  ps.push_back(OptionalStiffness("torsional stiffness of the whole segment; overrides the tube geometry",
                                 ReferenceSide::kShaft, "none: from the tube geometry unless given"));
  ps.push_back(Param("inertia", "J", dimensions::Inertia(), "kg*m^2", "inertia of the whole segment; overrides the tube geometry")
                   .Valid(0, 1e3)
                   .Optional()
                   .Source("none: from the tube geometry unless given")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(Param("linear_density", "m_l", LinearDensity(), "kg/m", "mass per length (for a composite tube whose density is not known)")
                   .Valid(0, 1e3)
                   .Optional()
                   .Source("domain.md s1 (P): Ti 1.2 kg/m, CFRP 0.28 kg/m"));
  ps.push_back(Param("damping", "d", RotationalDamping(), "N*m*s/rad", "structural damping of the segment")
                   .Valid(0, 1e6)
                   .Optional()
                   .Source("none")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(Param("drag_per_length", "tau_d", TorquePerLength(), "N*m/m",
                     "drag torque of the bearings and joints along the segment, per metre of shaft")
                   .Nominal(0.25)
                   .Default(0.1, 0.5)
                   .Valid(0, 100)
                   .Source("domain.md s3 (E): 0.2-0.3 N m per metre, domain [0.1, 0.5]")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(SpanPosition());
  t.relations = {{"wall_thickness", "outer_diameter", 2.0, "the radius", "equal: a solid shaft"}};
  t.roles = {.chain_member = true, .rupturable = true, .segment = true};
  return t;
}

ComponentTypeSpec SteadyBearing() {
  ComponentTypeSpec t;
  t.name = "steady_bearing";
  t.display_name = "steady bearing";
  t.description = "Steady bearing supporting the shaft; Stribeck friction (paper eq. 3).";
  t.ports = {Flange("a", "flange nearer the PDU"), Flange("b", "flange farther from the PDU")};
  AddStribeck(t.parameters, 0.1, 0.05, 0.2, "domain.md s6 (E): drag 0.05-0.2 N m each", ReferenceSide::kShaft);
  t.parameters.push_back(
      Inertia(5e-5, 1e-5, 1e-4, "inertia of the bearing's rotating parts", "estimate: small", ReferenceSide::kShaft));
  t.parameters.push_back(SpanPosition());
  t.roles = {.chain_member = true};
  return t;
}

ComponentTypeSpec UniversalJoint() {
  ComponentTypeSpec t;
  t.name = "universal_joint";
  t.display_name = "universal joint";
  t.description = "Universal (Cardan) joint compensating a change in shaft direction.";
  t.ports = {Flange("a", "flange nearer the PDU"), Flange("b", "flange farther from the PDU")};
  auto& ps = t.parameters;
  ps.push_back(Efficiency("efficiency", "eta", 0.985, 0.98, 0.99, "efficiency of the joint", "domain.md s6 (E): 0.98-0.99"));
  ps.push_back(Inertia(2e-4, 1e-4, 3e-4, "inertia of the joint", "domain.md s6 (E): 1e-4 to 3e-4 kg m2", ReferenceSide::kShaft));
  ps.push_back(Param("joint_angle", "beta", Dimensionless(), "deg", "bend angle of the joint")
                   .Valid(0, 45)
                   .Optional()
                   .Source("none: from the installation"));
  ps.push_back(Backlash("total backlash of the joint", ReferenceSide::kShaft));
  ps.push_back(OptionalStiffness("torsional stiffness of the joint", ReferenceSide::kShaft));
  ps.push_back(SpanPosition());
  t.roles = {.chain_member = true};
  return t;
}

void AddGearbox(std::vector<ParameterSpec>& ps, const std::string& ratio_meaning, double ratio,
                double ratio_lo, double ratio_hi, const std::string& ratio_source, double J, const std::string& J_source) {
  ps.push_back(Param("ratio", "ratio", Dimensionless(), "1", ratio_meaning)
                   .Nominal(ratio)
                   .Default(ratio_lo, ratio_hi)
                   .Valid(0.01, 100)
                   .Source(ratio_source));
  ps.push_back(Efficiency("eta_mesh", "eta", 0.97, 0.96, 0.98, "efficiency per gear mesh",
                          "domain.md s6 (E): 0.96-0.98 per mesh"));
  ps.push_back(Param::Integer("meshes", "n_mesh", "number of gear meshes in the power path")
                   .Nominal(1)
                   .Valid(1, 10)
                   .Source("estimate: one bevel mesh"));
  // The input flange is on the transmission shaft (root gearbox, station down-drive).
  ps.push_back(Inertia(J, 0.5 * J, 2 * J, "inertia referred to the input", J_source, ReferenceSide::kShaft));
  ps.push_back(Backlash("total backlash referred to the input", ReferenceSide::kShaft));
  ps.push_back(OptionalStiffness("torsional stiffness referred to the input", ReferenceSide::kShaft));
  AddStribeck(ps, 0.1, 0.05, 0.2, "estimate: like a steady bearing, domain.md s6 (E) 0.05-0.2 N m", ReferenceSide::kShaft);
}

ComponentTypeSpec AngleGearbox() {
  ComponentTypeSpec t;
  t.name = "angle_gearbox";
  t.display_name = "angle gearbox";
  t.description = "Angle, bevel, offset or kink gearbox (root gearbox) changing the shaft direction.";
  t.ports = {Flange("input", "flange nearer the PDU"), GearedFlange("output", "flange farther from the PDU")};
  AddGearbox(t.parameters, "gear ratio, input speed / output speed (MSL IdealGear)", 1, 1, 2,
             "domain.md s6 (E): 1:1 to 2:1", 2e-3, "domain.md s3 (E): root gearbox 2e-3 kg m2");
  t.parameters.push_back(Param("shaft_angle", "alpha", Dimensionless(), "deg", "angle between input and output shafts")
                             .Valid(0, 180)
                             .Optional()
                             .Source("domain.md s1 (P): e.g. 19 deg, 63.5 deg (A320 slats)"));
  t.parameters.push_back(SpanPosition());
  t.roles = {.lumps_inertia = true};
  return t;
}

ComponentTypeSpec BranchGearbox() {
  ComponentTypeSpec t;
  t.name = "branch_gearbox";
  t.display_name = "branch gearbox";
  t.description =
      "T-gearbox or down-drive (station gearbox): the shaft passes through 1:1 and a branch "
      "drives the station. ratio = input speed / branch speed.";
  t.ports = {Flange("input", "flange nearer the PDU"),
             Flange("through", "through-drive flange, 1:1 with the input (open at the last station)", false),
             GearedFlange("branch", "down-drive flange to the station")};
  AddGearbox(t.parameters, "gear ratio, input speed / branch speed", 2, 1, 2,
             "domain.md s3 (E): station gearbox 2:1; s6 1:1 to 2:1", 6.25e-4,
             "domain.md s3 (E): station input 1e-3 kg m2 at the shaft in all = this 6.25e-4 + (limiter 5e-4 + "
             "actuator input 1e-3) / 2^2 behind the default 2:1");
  t.parameters.push_back(SpanPosition());
  t.roles = {.lumps_inertia = true};
  return t;
}

ComponentTypeSpec StationTorqueLimiter() {
  ComponentTypeSpec t;
  t.name = "station_torque_limiter";
  t.display_name = "station torque limiter";
  t.description =
      "Bi-directional station torque limiter before an actuator (ball ramp, friction discs, "
      "lock-out indicator), asymmetric: lower trip torque in retract. Paper fig. 4 and 5.";
  t.ports = {Flange("input", "flange towards the transmission"), Flange("output", "flange towards the actuator")};
  AddTorqueLimiter(t.parameters, 180, 0.7, 2e4,
                   "domain.md s3 (E): 1.5 x 58.8 N m station input torque = 90 N m at the shaft, x 2 behind the "
                   "default 2:1 station gearbox",
                   "estimate: 2e4 at the actuator input = 5e3 at the shaft behind the default 2:1 station gearbox, "
                   "2-3 x the adjacent shaft segments (domain.md s3 c = 1.4-3.3 kN*m/rad)",
                   ReferenceSide::kActuatorInput);
  t.parameters.push_back(Inertia(5e-4, 2e-4, 1e-3, "inertia of the limiter", "estimate: half a station gearbox",
                                 ReferenceSide::kActuatorInput));
  t.parameters.push_back(SpanPosition());
  t.roles = {.lumps_inertia = true, .station_limiter = true};
  return t;
}

ComponentTypeSpec GearedRotaryActuator() {
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
  ps.push_back(Efficiency("eta_aiding", "eta_ai", 0.70, 0.60, 0.80, "efficiency with an aiding (back-driving) load",
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

ComponentTypeSpec BallscrewActuator() {
  ComponentTypeSpec t;
  t.name = "ballscrew_actuator";
  t.display_name = "ballscrew actuator";
  t.description = "Ballscrew actuator: input gear and a ball screw turning rotation into stroke.";
  t.ports = {Flange("input", "input flange from the station gearbox or limiter")};
  auto& ps = t.parameters;
  ps.push_back(Param("ratio", "ratio", Dimensionless(), "1", "input gear ratio, input speed / screw speed")
                   .Nominal(1)
                   .Default(1, 3)
                   .Valid(0.01, 1000)
                   .Source("estimate"));
  ps.push_back(Param("lead", "l", Length(), "mm/rev", "screw lead, stroke per screw revolution")
                   .Nominal(10)
                   .Default(5, 20)
                   .Valid(0.1, 1000)
                   .Source("estimate"));
  ps.push_back(Efficiency("eta_opposing", "eta_op", 0.90, 0.85, 0.95, "efficiency driving against an opposing load",
                          "estimate: ball screws are more efficient than planetary GRAs"));
  ps.push_back(Efficiency("eta_aiding", "eta_ai", 0.80, 0.70, 0.90, "efficiency with an aiding (back-driving) load", "estimate"));
  ps.push_back(Param("input_inertia", "J_in", dimensions::Inertia(), "kg*m^2", "inertia referred to the input")
                   .Nominal(5e-4)
                   .Default(2e-4, 1e-3)
                   .Valid(0, 100)
                   .Source("estimate")
                   .Side(ReferenceSide::kActuatorInput));
  ps.push_back(Param("output_force_rating", "F_max", Force(), "kN", "rated output force")
                   .Valid(0, 1e4)
                   .Optional()
                   .Source("none")
                   .Side(ReferenceSide::kActuatorOutput));
  ps.push_back(Param("stroke", "s", Length(), "mm", "stroke for full travel")
                   .Valid(0, 1e5)
                   .Optional()
                   .Source("none"));
  ps.push_back(Backlash("total backlash referred to the input", ReferenceSide::kActuatorInput));
  AddStribeck(ps, 0.2, 0.1, 0.4, "estimate: about twice a steady bearing", ReferenceSide::kActuatorInput);
  ps.push_back(SpanPosition());
  t.roles = {.actuator = true, .jammable = true, .lumps_inertia = true};
  return t;
}

ComponentTypeSpec WingTipBrake() {
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
  return t;
}

ComponentTypeSpec PositionSensor() {
  ComponentTypeSpec t;
  t.name = "position_sensor";
  t.display_name = "position sensor";
  t.description =
      "Position pick-off unit (APPU at the shaft end, FPPU at the PDU) feeding the monitor that "
      "fires the wing-tip brakes on asymmetry or overspeed.";
  t.ports = {Flange("a", "flange on the transmission"), Flange("b", "through flange when inline", false)};
  auto& ps = t.parameters;
  ps.push_back(Param::Text("role", "'appu' (asymmetry position pick-off) or 'fppu' (feedback at the PDU)")
                   .Optional()
                   .Source("domain.md s1 (P)"));
  ps.push_back(Param("latency", "t_s", Time(), "ms", "delay of the sensor and monitor chain")
                   .Nominal(10)
                   .Default(5, 30)
                   .Valid(0, 1e4)
                   .Source("estimate"));
  ps.push_back(Param("asymmetry_threshold", "dphi_asym", Dimensionless(), "rev",
                     "shaft angle difference (left/right or sensor/command) that triggers the WTBs")
                   .Nominal(2)
                   .Default(1, 3)
                   .Valid(0, 1000)
                   .Source("domain.md s3 (E): 1-3 shaft revolutions")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(Param("overspeed_factor", "k_os", Dimensionless(), "1", "overspeed trigger, multiple of the maximum shaft speed")
                   .Nominal(1.3)
                   .Default(1.2, 1.4)
                   .Valid(1, 10)
                   .Source("domain.md s3 (E): 1.3 x w_max"));
  ps.push_back(Inertia(1e-5, 0, 5e-5, "inertia of the sensor shaft", "estimate: small", ReferenceSide::kShaft));
  ps.push_back(SpanPosition());
  t.roles = {.tip_sensor = true};
  return t;
}

ComponentTypeSpec Disconnector() {
  ComponentTypeSpec t;
  t.name = "disconnector";
  t.display_name = "disconnector";
  t.description = "Failure element: a rigid (or elastic) coupling that breaks at the scenario's rupture time (shaft rupture).";
  t.ports = {Flange("a", "flange nearer the PDU"), Flange("b", "flange farther from the PDU")};
  t.parameters.push_back(OptionalStiffness("torsional stiffness before the rupture", ReferenceSide::kShaft));
  t.parameters.push_back(SpanPosition());
  t.roles = {.rupturable = true};
  return t;
}

ComponentTypeSpec Jam() {
  ComponentTypeSpec t;
  t.name = "jam";
  t.display_name = "jam";
  t.description = "Failure element: locks its flange to structure at the scenario's jam time.";
  t.ports = {Flange("a", "flange on the transmission (usually an actuator input)")};
  t.parameters.push_back(Param("stiffness", "c", Torque(), "N*m/rad", "stiffness of the jammed load path to structure, at the flange it locks (an actuator input)")
                             .Nominal(1e5)
                             .Default(2e4, 5e5)
                             .Valid(0, 1e12)
                             .Source("estimate: stiff compared with the shaft segments (1.4-3.3 kN*m/rad)")
                             .Side(ReferenceSide::kActuatorInput));
  t.parameters.push_back(SpanPosition());
  t.roles = {.jammable = true, .lumps_inertia = true};
  return t;
}

std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string Lower(std::string_view s) {
  std::string r(s);
  for (char& ch : r) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return r;
}

}  // namespace

const std::vector<ComponentTypeSpec>& ComponentTypes() {
  static const std::vector<ComponentTypeSpec> types = {
      Pdu(),           SystemTorqueLimiter(),  TorqueShaft(),          SteadyBearing(), UniversalJoint(),
      AngleGearbox(),  BranchGearbox(),        StationTorqueLimiter(), GearedRotaryActuator(),
      BallscrewActuator(), WingTipBrake(),     PositionSensor(),       Disconnector(), Jam()};
  return types;
}

const ComponentTypeSpec* FindComponentType(std::string_view name) {
  for (const auto& t : ComponentTypes())
    if (t.name == name) return &t;
  return nullptr;
}

std::vector<std::string> ComponentTypesWith(bool ComponentRoles::*role) {
  std::vector<std::string> names;
  for (const auto& t : ComponentTypes())
    if (t.roles.*role) names.push_back(t.name);
  return names;
}

ComponentRoles RolesOf(std::string_view type) {
  const ComponentTypeSpec* spec = FindComponentType(type);
  return spec ? spec->roles : ComponentRoles{};
}

std::vector<std::string> ComponentTypeNames() {
  std::vector<std::string> names;
  for (const auto& t : ComponentTypes()) names.push_back(t.name);
  return names;
}

std::vector<std::string> Suggest(std::string_view name, const std::vector<std::string>& candidates,
                                 std::size_t max_results) {
  // Close in edit distance (case-insensitive), or one contains the other ("gra" -> "geared_...").
  const std::string lower = Lower(name);
  const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const auto& c : candidates) {
    std::size_t d = EditDistance(name, c);
    const std::string lc = Lower(c);
    if (d > limit && lower.size() >= 3 && (lc.find(lower) != std::string::npos || lower.find(lc) != std::string::npos))
      d = limit;
    if (d <= limit) scored.emplace_back(d, c);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (const auto& s : scored) {
    if (out.size() >= max_results) break;
    if (std::find(out.begin(), out.end(), s.second) == out.end()) out.push_back(s.second);
  }
  return out;
}

std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  const auto close = Suggest(name, candidates);
  if (close.empty()) return "";
  std::string out = "; did you mean ";
  for (std::size_t i = 0; i < close.size(); ++i) {
    if (i > 0) out += (i + 1 == close.size()) ? " or " : ", ";
    out += "'" + close[i] + "'";
  }
  return out + "?";
}

std::string SuggestionHint(std::string_view name, const std::vector<std::string>& candidates,
                           const std::string& label) {
  std::string list;
  for (std::size_t i = 0; i < candidates.size(); ++i) list += (i ? ", " : "") + candidates[i];
  if (candidates.empty()) list = "(none)";
  const std::string suggestion = DidYouMean(name, candidates);
  if (suggestion.empty()) return "; " + label + ": " + list;
  std::string capital = label;
  capital[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(capital[0])));
  return suggestion + " " + capital + ": " + list;
}

}  // namespace highlift
