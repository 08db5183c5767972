// Hydraulic components of the HighLift library, as element types: the classes of
// export/modelica/HighLift/Hydraulics (same names, parameters, ports and defaults). The
// translational Mass a displacement cylinder needs is in element_types_translational.cc; the
// sensors and the Gain of a hydraulic PDU are the drive family's (element_types_drive.cc). The laws are in sim/src/hydraulic_elements.cc; docs/hydraulics.md
// describes the node law and the regularisation.
//
// The simulator has one kind of mechanical node; a translational flange (the rod of a
// DifferentialCylinder, a Mass) is such a node read in SI translational units: position in m,
// force in N, the "inertia" of a Mass in kg.
#include <cmath>

#include "element_type_builders.h"

namespace highlift::element_types {
namespace {

PortSpec Hydraulic(std::string name, std::string description, bool required = true) {
  return {std::move(name), PortKind::kHydraulic, required, std::move(description), false, {}};
}

}  // namespace

void AppendHydraulicTypes(std::vector<ComponentTypeSpec>& types) {
  using namespace dimensions;
  const std::size_t first = types.size();
  const Domain any = Domain::Whole();
  const Domain non_negative{0.0, kInf};
  const Domain positive{std::nextafter(0.0, 1.0), kInf};
  const Dimension velocity = Length() / Time();
  const Dimension conductance = VolumeFlowRate() / Pressure();
  auto oil = [&](std::vector<ParameterSpec> p) {
    p.push_back(Scalar("Cd", Dimensionless(), "1", 0.7, non_negative, "discharge coefficient"));
    p.push_back(Scalar("rho", Density(), "kg/m^3", 850.0, positive, "density of the oil"));
    p.push_back(Scalar("dp_small", Pressure(), "Pa", 1e4, positive,
                       "regularisation of the orifice law: below this pressure drop the flow is "
                       "nearly linear in dp"));
    return p;
  };

  types.push_back(Type("PressureSource",
                       "ideal pressure supply: port.p = p_supply whatever the flow "
                       "(HighLift.Hydraulics.PressureSource)",
                       {Hydraulic("port", "supply port")},
                       {Scalar("p_supply", Pressure(), "Pa", 345e5, non_negative,
                               "supply pressure (A320 207 bar, A380 345 bar)")}));
  types.push_back(Type("Tank",
                       "return line (reservoir) at constant pressure (HighLift.Hydraulics.Tank)",
                       {Hydraulic("port", "return port")},
                       {Scalar("p_return", Pressure(), "Pa", 5e5, non_negative, "return pressure")}));
  types.push_back(Type("TurbulentResistance",
                       "turbulent orifice V_flow = Cd*A*sqrt(2/rho)*dp/(dp^2 + dp_small^2)^(1/4), "
                       "dp = port_a.p - port_b.p (HighLift.Hydraulics.TurbulentResistance)",
                       {Hydraulic("port_a", "inlet (positive flow from port_a to port_b)"),
                        Hydraulic("port_b", "outlet")},
                       oil({Scalar("A", Area(), "m^2", 1e-5, non_negative, "opening area")})));
  types.push_back(Type(
      "ServoValve",
      "4/3-way closed-centre servo valve; spool x by `order`: 0 x = limit(u, -1, 1) (the "
      "command is the spool position), 1 T_v*der(x) = limit(u, -1, 1) - x, 2 der(x) = v_x, "
      "der(v_x) = w_v^2*(limit(u, -1, 1) - x) - 2*D_v*w_v*v_x; edges P-A and B-T open with "
      "x > 0, P-B and A-T with x < 0 (opening limited to full stroke, |x| <= 1), each a "
      "regularised turbulent orifice (HighLift.Hydraulics.ServoValve)",
      {Signal("u", "spool command (order 0: the spool position), -1 (P to B, A to T) ... 1 (P to A, B to T)"),
       Hydraulic("port_P", "supply"), Hydraulic("port_T", "return"),
       Hydraulic("port_A", "consumer port A"), Hydraulic("port_B", "consumer port B")},
      oil({Scalar("A_max", Area(), "m^2", 2e-6, non_negative,
                  "opening area of a metering edge at full spool stroke"),
           Scalar("leakage", Dimensionless(), "1", 1e-4, non_negative,
                  "leakage opening of a closed edge, as a fraction of A_max"),
           Integer("order", 1, {0, 2},
                   "spool dynamics: 0 = the command u is the spool position, 1 = first order "
                   "(T_v), 2 = second order (w_v, D_v)"),
           Scalar("T_v", Time(), "s", 0.005, positive, "time constant of the spool (order 1)"),
           Scalar("w_v", AngularVelocity(), "rad/s", 280.0, positive,
                  "natural frequency of the spool (order 2); the default gives the low-frequency "
                  "lag 2*D_v/w_v = 5 ms of the first-order default T_v"),
           Scalar("D_v", Dimensionless(), "1", 0.7, non_negative, "damping ratio of the spool (order 2)")})));
  types.push_back(Type(
      "DifferentialCylinder",
      "single-rod cylinder, grounded housing, compressible chambers: der(p_A) = E/(V0_A + A_A*s)*"
      "(V_flow_A - A_A*v), der(p_B) = E/(V0_B + A_B*(s_max - s))*(V_flow_B + A_B*v), force on the "
      "rod p_A*A_A - p_B*A_B - d*v - end stops (HighLift.Hydraulics.DifferentialCylinder); the "
      "rod end is a translational flange (m, N)",
      {Hydraulic("port_A", "chamber A (piston side)"), Hydraulic("port_B", "chamber B (rod side)"),
       Flange("flange", "rod end, translational: position s in m (0 retracted, s_max extended)")},
      {Scalar("A_A", Area(), "m^2", 1e-3, positive, "piston area (chamber A)"),
       Scalar("A_B", Area(), "m^2", 5e-4, positive, "annulus area (chamber B, rod side)"),
       Scalar("s_max", Length(), "m", 0.1, positive, "stroke"),
       Scalar("V0_A", Volume(), "m^3", 1e-5, positive, "dead volume of chamber A"),
       Scalar("V0_B", Volume(), "m^3", 1e-5, positive, "dead volume of chamber B"),
       Scalar("E", Pressure(), "Pa", 1.2e9, positive, "bulk modulus of the oil"),
       Scalar("d", Force() / velocity, "N*s/m", 1e3, non_negative, "viscous friction of the piston"),
       Scalar("c_stop", Force() / Length(), "N/m", 1e8, non_negative, "stiffness of the end stops"),
       Scalar("s_start", Length(), "m", 0.0, any, "initial rod position (at rest, chambers at 1 bar)")}));
  types.push_back(Type(
      "VariableDisplacementMotor",
      "variable-displacement hydraulic motor: V_flow = eps*D_max*w + G_leak*(p_A - p_B), tau_i = "
      "eps*D_max*(p_A - p_B), tau = eta_m*tau_i driving, tau_i/eta_m driven "
      "(HighLift.Hydraulics.VariableDisplacementMotor)",
      {Flange("flange", "output shaft"), Support(),
       Signal("eps", "normalized displacement (swash angle), -1 ... 1"),
       Hydraulic("port_A", "high-pressure port for positive rotation"),
       Hydraulic("port_B", "low-pressure port for positive rotation")},
      {Scalar("D_max", Volume(), "m^3/rad", 13.4e-6 / (2 * M_PI), non_negative,
              "displacement per radian at full swash angle"),
       Scalar("G_leak", conductance, "m^3/(s*Pa)", 1e-13, non_negative,
              "leakage conductance from A to B (volumetric efficiency)"),
       Scalar("eta_m", Dimensionless(), "1", 0.95, {std::nextafter(0.0, 1.0), 1.0},
              "mechanical efficiency (torque loss, in both directions of power flow)")}));
  {
    ParameterSpec p_start = Start("p_start", Pressure(), "Pa", "initial pressure (1 bar unless given)");
    types.push_back(Type("Volume",
                         "compressible oil volume of a line or a chamber: der(p) = E/V*port.V_flow "
                         "(HighLift.Hydraulics.Volume); gives a hydraulic node its pressure state",
                         {Hydraulic("port", "the node the volume belongs to")},
                         {Scalar("V", Volume(), "m^3", 1e-5, positive, "volume"),
                          Scalar("E", Pressure(), "Pa", 1.2e9, positive, "bulk modulus of the oil"),
                          p_start}));
  }
  types.push_back(Type(
      "MotorSpeedControl",
      "speed loop of one motor of a hydraulic PDU with secondary control: PI on the motor speed "
      "(reference ratio*w_ref) commands the normalized displacement eps_ref, a proportional position "
      "loop drives the servo valve of the displacement cylinder (u = k_s*(eps_ref - eps), eps = "
      "2*s/s_max - 1); active < 0.5 commands eps_ref = 0 (motor lost) (HighLift.Hydraulics."
      "MotorSpeedControl)",
      {Signal("w_ref", "commanded PDU output speed, rad/s"),
       Signal("active", "1: motor in operation, 0: motor lost (default 1 when unconnected)", false),
       Flange("flange_m", "motor shaft (speed sensed, no torque)"),
       Flange("flange_s", "rod of the displacement cylinder, translational (position sensed, no force)"),
       SignalOutput("u", "servo valve command, -1 ... 1"),
       SignalOutput("eps", "normalized motor displacement from the rod position, -1 ... 1")},
      {Scalar("ratio", Dimensionless(), "1", 20.0, positive, "motor speed / PDU output speed"),
       Scalar("k_w", Time(), "s/rad", 1e-3, non_negative,
              "displacement command per motor speed error (proportional gain)"),
       Scalar("T_i", Time(), "s", 0.1, positive, "integral time of the speed loop"),
       Scalar("k_s", Dimensionless(), "1", 1.0, non_negative,
              "valve command per displacement error (position loop gain)"),
       Scalar("s_max", Length(), "m", 0.02, positive, "stroke of the displacement cylinder"),
       Scalar("eps_max", Dimensionless(), "1", 1.0, {0.0, 1.0}, "limit of the displacement command")}));
  // Provenance: the HighLift library's classes.
  for (std::size_t k = first; k < types.size(); ++k)
    for (auto& p : types[k].parameters) p.source = "HighLift.Hydraulics." + types[k].name;
}

}  // namespace highlift::element_types
