// The power drive unit and the failure monitoring of the HighLift library (HighLift.Drives.PDU,
// HighLift.Control.Monitoring), and the MSL sensors, tables and math blocks that drive models
// need (Modelica.Mechanics.Rotational.Sensors, Modelica.Blocks.Sources.CombiTimeTable,
// Modelica.Blocks.Tables.CombiTable1Ds, Modelica.Blocks.Math, Modelica.Blocks.Continuous):
// type, parameter and port names as in the Modelica classes, so that a network exports
// one-to-one. The laws are in sim/src/drive_elements.cc; docs/highlift_elements.md describes them.
//
// Modelica enumerations are Integer parameters holding the literal's position (1-based), as the
// MSL C tables do: Smoothness 1 = LinearSegments, 3 = ConstantSegments; Extrapolation
// 1 = HoldLastPoint, 2 = LastTwoPoints, 3 = Periodic; TimeEvents 1 = Always,
// 2 = AtDiscontinuities, 3 = NoTimeEvents.
#include <cmath>

#include "element_type_builders.h"

namespace highlift::element_types {

namespace {

/// A parameter that may be left out; absent means the Modelica default (e.g. Constants.inf).
ParameterSpec OptionalScalar(std::string name, Dimension dimension, std::string unit,
                             Domain valid, std::string description) {
  ParameterSpec p = Scalar(std::move(name), dimension, std::move(unit), std::nullopt, valid,
                           std::move(description));
  p.optional = true;
  return p;
}

ParameterSpec HighLift(ParameterSpec p) {
  p.source = "HighLift library (export/modelica/HighLift)";
  return p;
}

}  // namespace

void AppendDriveTypes(std::vector<ComponentTypeSpec>& t) {
  using namespace dimensions;
  const Domain any = Domain::Whole();
  const Domain non_negative{0.0, kInf};
  const Domain positive{std::nextafter(0.0, 1.0), kInf};
  const Dimension angle = Dimensionless();
  auto output = [] { return SignalOutput("y", "output signal"); };
  auto extrapolation = [] {
    return Integer("extrapolation", 2, {1, 3},
                   "outside the table: 1 = HoldLastPoint, 2 = LastTwoPoints (linear through the "
                   "first/last two points), 3 = Periodic (Modelica.Blocks.Types.Extrapolation)");
  };

  // --- HighLift.Drives.PDU ----------------------------------------------------------------
  auto pdu = [&](ParameterSpec p) { return HighLift(std::move(p)); };
  t.push_back(Type(
      "PDU",
      "speed-controlled power drive unit: n_m motors on a speed-summing differential, speed loop "
      "(T_w) with ramp, stall torque and power limit, pressure-off brakes, loss of one motor",
      {Signal("w_ref", "commanded output speed [rad/s]"),
       Signal("stop", "shutdown command, > 0.5 = true (a monitor's brake command): the motors are "
                      "depressurised and the pressure-off brakes applied at once (optional)",
              false),
       Flange("flange_left", "output to the left wing (rigidly tied to flange_right)", false),
       Flange("flange_right", "output to the right wing (rigidly tied to flange_left)", false),
       SignalOutput("phi", "output angle (FPPU) [rad]"), SignalOutput("w", "output speed [rad/s]")},
      {pdu(Integer("n_m", 2, {1, kInf}, "number of motors summed by the differential")),
       pdu(Scalar("J_m", Inertia(), "kg*m^2", 3e-4, non_negative, "rotor inertia of one motor")),
       pdu(Scalar("ratio", Dimensionless(), "1", 20, positive,
                  "PDU gear ratio, motor speed / output speed")),
       pdu(Scalar("J_g", Inertia(), "kg*m^2", 0.02, non_negative,
                  "inertia of the differential and gears, at the output")),
       pdu(Scalar("w_max", AngularVelocity(), "rad/s", 25.3, positive,
                  "maximum output speed with all motors")),
       pdu(Scalar("tau_stall", Torque(), "N*m", 1000, non_negative,
                  "maximum output torque (stall torque)")),
       pdu(Scalar("P_max", Power(), "W", 18000, positive, "maximum output power")),
       pdu(Scalar("t_ramp", Time(), "s", 0.4, positive,
                  "time from 0 to the maximum output speed (speed ramp)")),
       pdu(Scalar("T_w", Time(), "s", 0.02, positive, "time constant of the closed speed loop")),
       pdu(Scalar("T_i", Time(), "s", 0.08, non_negative,
                  "integral time of the speed loop (PI; 0 = proportional only)")),
       pdu(Scalar("tauPOB", Torque(), "N*m", 1100, non_negative,
                  "holding torque of the pressure-off brakes at the output")),
       pdu(Scalar("t_POB", Time(), "s", 0.05, non_negative,
                  "time for the pressure-off brakes to build up their torque")),
       pdu(Scalar("w_hold", AngularVelocity(), "rad/s", 1e-3, non_negative,
                  "speed command below which the pressure-off brakes are applied")),
       pdu(OptionalScalar("t_motor_lost", Time(), "s", any,
                          "time at which one motor is lost (absent: never)"))}));

  // --- HighLift.Control.Monitoring ----------------------------------------------------------
  t.push_back(Type(
      "Monitoring",
      "failure monitoring: asymmetry, overspeed and uncommanded movement, latched wing-tip "
      "brake command wtb after the detection latency t_detect",
      {Signal("phi_left", "shaft angle at the left tip (APPU) [rad]"),
       Signal("phi_right", "shaft angle at the right tip (APPU) [rad]"),
       Signal("phi_pdu", "shaft angle at the PDU output (FPPU) [rad]"),
       Signal("phi_cmd", "commanded shaft angle [rad]"),
       Signal("w_left", "shaft speed at the left tip [rad/s]"),
       Signal("w_right", "shaft speed at the right tip [rad/s]"),
       SignalOutput("asymmetry", "asymmetry detected (0/1)"),
       SignalOutput("overspeed", "overspeed detected (0/1)"),
       SignalOutput("uncommanded", "uncommanded movement detected (0/1)"),
       SignalOutput("wtb", "wing-tip brake command, latched (0/1)")},
      {HighLift(Scalar("phi_asym", angle, "rad", 12.57, non_negative,
                       "asymmetry threshold: shaft angle difference between the tips, or a tip "
                       "and the PDU")),
       HighLift(Scalar("w_over", AngularVelocity(), "rad/s", 33, non_negative,
                       "overspeed threshold of the transmission speed at the tips")),
       HighLift(Scalar("phi_unc", angle, "rad", 12.57, non_negative,
                       "uncommanded movement threshold: |phi_pdu - phi_cmd|")),
       HighLift(Scalar("t_detect", Time(), "s", 0.01, non_negative,
                       "detection latency from the first detection to the brake command")),
       HighLift(Flag("enableAsymmetry", true, "true: the asymmetry monitor is active")),
       HighLift(Flag("enableOverspeed", true, "true: the overspeed monitor is active")),
       HighLift(Flag("enableUncommanded", true,
                     "true: the uncommanded movement monitor is active"))}));

  // --- Modelica.Mechanics.Rotational.Sensors ------------------------------------------------
  t.push_back(Type("AngleSensor", "ideal sensor: phi = flange.phi (absolute angle)",
                   {Flange("flange", "measured flange"), SignalOutput("phi", "angle [rad]")}, {}));
  t.push_back(Type("SpeedSensor", "ideal sensor: w = der(flange.phi) (absolute speed)",
                   {Flange("flange", "measured flange"), SignalOutput("w", "speed [rad/s]")}, {}));
  t.push_back(Type("RelAngleSensor", "ideal sensor: phi_rel = flange_b.phi - flange_a.phi",
                   {Flange("flange_a", "first flange"), Flange("flange_b", "second flange"),
                    SignalOutput("phi_rel", "relative angle [rad]")},
                   {}));
  t.push_back(Type("RelSpeedSensor", "ideal sensor: w_rel = der(flange_b.phi - flange_a.phi)",
                   {Flange("flange_a", "first flange"), Flange("flange_b", "second flange"),
                    SignalOutput("w_rel", "relative speed [rad/s]")},
                   {}));
  t.push_back(Type("AccSensor", "ideal sensor: a = der(der(flange.phi)) (absolute acceleration)",
                   {Flange("flange", "measured flange"), SignalOutput("a", "acceleration [rad/s^2]")}, {}));
  t.push_back(Type("RelAccSensor", "ideal sensor: a_rel = der(w_b - w_a)",
                   {Flange("flange_a", "first flange"), Flange("flange_b", "second flange"),
                    SignalOutput("a_rel", "relative acceleration [rad/s^2]")},
                   {}));
  auto through = [](std::vector<PortSpec> outputs) {
    std::vector<PortSpec> p{Flange("flange_a", "flange (rigidly joined to flange_b)"),
                            Flange("flange_b", "flange (rigidly joined to flange_a)")};
    for (auto& o : outputs) p.push_back(std::move(o));
    return p;
  };
  t.push_back(Type("TorqueSensor", "ideal sensor: tau = flange_a.tau, the torque through a rigid joint",
                   through({SignalOutput("tau", "torque [N*m]")}), {}));
  t.push_back(Type("PowerSensor", "ideal sensor: power = flange_a.tau * der(flange_a.phi)",
                   through({SignalOutput("power", "power [W]")}), {}));
  t.push_back(Type("MultiSensor", "ideal sensor: tau = flange_a.tau, w = der(flange_a.phi), power = tau * w",
                   through({SignalOutput("power", "power [W]"), SignalOutput("w", "speed [rad/s]"),
                            SignalOutput("tau", "torque [N*m]")}),
                   {}));

  // --- Modelica.Blocks tables -------------------------------------------------------------
  t.push_back(Type(
      "CombiTimeTable",
      "y = offset + table(time - shiftTime)/timeScale) for time >= startTime, else offset; one "
      "output column (table column 2, Modelica y[1])",
      {output()},
      {TableParameter("table", "[time, y] rows, time non-decreasing (a repeated time is a jump)"),
       Integer("smoothness", 1, {1, 3},
               "1 = LinearSegments, 3 = ConstantSegments (Modelica.Blocks.Types.Smoothness)"),
       extrapolation(),
       Scalar("timeScale", Time(), "s", 1.0, positive, "time scale of the first table column"),
       Scalar("offset", Dimensionless(), "1", 0.0, any, "offset of the output"),
       Scalar("startTime", Time(), "s", 0.0, any, "output = offset for time < startTime"),
       OptionalScalar("shiftTime", Time(), "s", any,
                      "shift time of the first table column (absent: startTime)"),
       Integer("timeEvents", 1, {1, 3},
               "time events at table points: 1 = Always, 2 = AtDiscontinuities, "
               "3 = NoTimeEvents (Modelica.Blocks.Types.TimeEvents)")}));
  t.push_back(Type(
      "CombiTable1Ds",
      "y = table(u) by linear interpolation in the first column; one output column (table "
      "column 2, Modelica y[1])",
      {Signal("u", "table input (abscissa)"), output()},
      {TableParameter("table", "[u, y] rows, u strictly increasing"),
       Integer("smoothness", 1, {1, 1}, "1 = LinearSegments (the only supported option)"),
       extrapolation()}));

  // --- Modelica.Blocks.Math and Continuous --------------------------------------------------
  t.push_back(Type("Gain", "y = k * u", {Signal("u", "input"), output()},
                   {Scalar("k", Dimensionless(), "1", std::nullopt, any, "gain")}));
  t.push_back(Type("Add", "y = k1 * u1 + k2 * u2",
                   {Signal("u1", "first input"), Signal("u2", "second input"), output()},
                   {Scalar("k1", Dimensionless(), "1", 1.0, any, "gain of u1"),
                    Scalar("k2", Dimensionless(), "1", 1.0, any, "gain of u2")}));
  t.push_back(Type("Integrator", "der(y) = k * u, y(startTime) = y_start (initType InitialState)",
                   {Signal("u", "input"), output()},
                   {Scalar("k", Dimensionless(), "1", 1.0, any, "integrator gain"),
                    Scalar("y_start", Dimensionless(), "1", 0.0, any, "initial output")}));
}

}  // namespace highlift::element_types
