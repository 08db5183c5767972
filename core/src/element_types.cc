// The element types of the element-level network: the simulation primitives of the Modelica
// Standard Library 4.0.0 (Modelica.Mechanics.Rotational and the Modelica.Blocks sources), with
// MSL names for the types, the ports (flange_a, flange_b, support, flange; signal ports u, y,
// tau, w_ref, f_normalized) and the parameters (J, c, d, b, ratio, mu_pos, peak, ...).
// The simulator (sim/) implements one law per type; its semantics are in
// docs/validation.md and ../shared/reference/msl/README.md.
//
// Initial conditions follow MSL's start values with fixed=true: a given `phi_start`, `w_start`,
// `phi_rel_start` or `w_rel_start` is fixed; an absent one is determined by the constraints
// (for instance an inertia behind a gear) or defaults to 0.
#include <cmath>
#include <limits>

#include "element_type_builders.h"
#include "highlift/core/catalogue.h"

namespace highlift {
namespace {

using namespace element_types;  // the builders of element_type_builders.h

std::vector<ComponentTypeSpec> MakeElementTypes() {
  using namespace dimensions;
  const Domain any = Domain::Whole();
  const Domain non_negative{0.0, kInf};
  const Domain positive{std::nextafter(0.0, 1.0), kInf};
  const Dimension angle = Dimensionless();
  auto flange_a = [] { return Flange("flange_a", "left flange (phi_rel = phi_b - phi_a)"); };
  auto flange_b = [] { return Flange("flange_b", "right flange"); };
  auto optional_a = [] { return Flange("flange_a", "flange (rigidly tied to flange_b)", false); };
  auto optional_b = [] { return Flange("flange_b", "flange (rigidly tied to flange_a)", false); };
  auto relative_starts = [&](std::vector<ParameterSpec> p) {
    p.push_back(Start("phi_rel_start", angle, "rad",
                      "initial relative angle phi_b - phi_a (fixed when given)"));
    p.push_back(Start("w_rel_start", AngularVelocity(), "rad/s",
                      "initial relative speed w_b - w_a (fixed when given)"));
    p.push_back(Nominal("phi_nominal", angle, "rad",
                        "nominal relative angle: the absolute tolerance of phi_rel is "
                        "absolute_tolerance * phi_nominal (absent: 1)"));
    return p;
  };
  auto friction_parameters = [&](std::string table, std::string table_description) {
    return std::vector<ParameterSpec>{
        TableParameter(std::move(table), std::move(table_description)),
        Scalar("peak", Dimensionless(), "1", 1.0, {1.0, kInf},
               "breakaway factor: static friction = peak * kinetic friction at zero speed"),
    };
  };
  auto clutch_parameters = [&](bool relative) {
    std::vector<ParameterSpec> p = friction_parameters(
        "mu_pos", "[w, mu]: friction coefficient against sliding speed |w| >= 0 (default [0, 0.5])");
    p.push_back(Scalar("cgeo", Length(), "m", 1.0, non_negative,
                       "geometry constant: tau = cgeo * mu * fn (number and radius of surfaces)"));
    p.push_back(Scalar("fn_max", Force(), "N", std::nullopt, non_negative,
                       "maximum normal force; fn = fn_max * f_normalized"));
    return relative ? relative_starts(std::move(p)) : p;
  };
  auto speed_torque = [&](std::string description) {
    return std::vector<ParameterSpec>{
        Scalar("tau_nominal", Torque(), "N*m", std::nullopt, any,
               "nominal torque (negative: braking)"),
        Flag("TorqueDirection", true, "true: same sign in both directions; false: odd in w"),
        Scalar("w_nominal", AngularVelocity(), "rad/s", std::nullopt, positive, description)};
  };
  auto source_ports = [&](std::vector<PortSpec> extra = {}) {
    std::vector<PortSpec> p{Flange("flange", "driven flange"), Support()};
    for (auto& e : extra) p.push_back(std::move(e));
    return p;
  };
  auto start_time = [&] {
    return Scalar("startTime", Time(), "s", 0.0, any, "output = offset for time < startTime");
  };
  auto offset = [&] { return Scalar("offset", Dimensionless(), "1", 0.0, any, "output offset"); };
  auto output = [] { return SignalOutput("y", "output signal"); };

  std::vector<ComponentTypeSpec> t;
  // --- Mechanical components -------------------------------------------------------------
  t.push_back(Type("Fixed", "flange fixed in the housing at angle phi0",
                   {Flange("flange", "the fixed flange")},
                   {Scalar("phi0", angle, "rad", 0.0, any, "fixed angle")}));
  t.push_back(Type("Inertia", "rigid rotating mass: J * a = flange_a.tau + flange_b.tau",
                   {optional_a(), optional_b()},
                   {Scalar("J", Inertia(), "kg*m^2", std::nullopt, non_negative,
                           "moment of inertia"),
                    Start("phi_start", angle, "rad", "initial angle (fixed when given)"),
                    Start("w_start", AngularVelocity(), "rad/s",
                          "initial speed (fixed when given)"),
                    Flag("phi_fixed", true,
                         "false: phi_start is a guess (MSL fixed = false), used where the initial "
                         "equations leave the angle free"),
                    Flag("w_fixed", true, "false: w_start is a guess (MSL fixed = false)"),
                    Start("a_start", AngularAcceleration(), "rad/s^2",
                          "initial acceleration (MSL a(start, fixed = true)): the initial equation "
                          "a = a_start determines start values that are not fixed"),
                    Flag("a_fixed", true, "false: a_start is ignored (a is not a state; MSL fixed = false)"),
                    Nominal("phi_nominal", angle, "rad",
                            "nominal angle (MSL phi(nominal)): absolute tolerance of phi = "
                            "absolute_tolerance * phi_nominal (absent: 1)"),
                    Nominal("w_nominal", AngularVelocity(), "rad/s",
                            "nominal speed (MSL w(nominal)): absolute tolerance of w = "
                            "absolute_tolerance * w_nominal (absent: 1)")}));
  t.push_back(Type("Spring", "linear spring: tau = c * (phi_rel - phi_rel0)", {flange_a(), flange_b()},
                   relative_starts({Scalar("c", Torque(), "N*m/rad", std::nullopt, non_negative,
                                           "spring constant"),
                                    Scalar("phi_rel0", angle, "rad", 0.0, any,
                                           "unstretched relative angle")})));
  t.push_back(Type("Damper", "linear damper: tau = d * w_rel", {flange_a(), flange_b()},
                   relative_starts({Scalar("d", RotationalDamping(), "N*m*s/rad", std::nullopt,
                                           non_negative, "damping constant")})));
  t.push_back(Type("SpringDamper", "spring and damper in parallel: tau = c*(phi_rel - phi_rel0) + d*w_rel",
                   {flange_a(), flange_b()},
                   relative_starts({Scalar("c", Torque(), "N*m/rad", std::nullopt, non_negative,
                                           "spring constant"),
                                    Scalar("d", RotationalDamping(), "N*m*s/rad", std::nullopt,
                                           non_negative, "damping constant"),
                                    Scalar("phi_rel0", angle, "rad", 0.0, any,
                                           "unstretched relative angle")})));
  auto backlash = [&] {
    return relative_starts({Scalar("c", Torque(), "N*m/rad", std::nullopt, positive, "spring constant in contact"),
                            Scalar("d", RotationalDamping(), "N*m*s/rad", std::nullopt, non_negative,
                                   "damping constant in contact"),
                            Scalar("b", angle, "rad", 0.0, non_negative, "total backlash"),
                            Scalar("phi_rel0", angle, "rad", 0.0, any, "unstretched relative angle")});
  };
  t.push_back(Type("ElastoBacklash",
                   "spring-damper with total backlash b; contact pushes only, damping limited to "
                   "the spring torque",
                   {flange_a(), flange_b()}, backlash()));
  t.push_back(Type("ElastoBacklash2",
                   "spring-damper with total backlash b; in contact tau = c*phi_contact + "
                   "d*w_rel (jumps at contact), set to 0 where it would pull",
                   {flange_a(), flange_b()}, backlash()));
  t.push_back(Type("Disc",
                   "rigid connection without inertia, flange_b turned by deltaPhi: phi_b = phi_a + "
                   "deltaPhi, flange_a.tau + flange_b.tau = 0",
                   {flange_a(), flange_b()},
                   {Scalar("deltaPhi", angle, "rad", 0.0, any,
                           "fixed rotation of flange_b with respect to flange_a (phi_b - phi_a)")}));
  t.push_back(Type("InitializeFlange",
                   "sets the flange's angle, speed and acceleration at the start time from the "
                   "inputs phi_start, w_start, a_start (each when enabled); no torque",
                   {Flange("flange", "the flange that is initialized"),
                    Signal("phi_start", "initial angle [rad] (use_phi_start)", false),
                    Signal("w_start", "initial speed [rad/s] (use_w_start)", false),
                    Signal("a_start", "initial acceleration [rad/s^2] (use_a_start)", false)},
                   {Flag("use_phi_start", true, "true: flange.phi = phi_start at the start"),
                    Flag("use_w_start", true, "true: der(flange.phi) = w_start at the start"),
                    Flag("use_a_start", true, "true: der(w) = a_start at the start")}));
  t.push_back(Type("AngleToTorqueAdaptor",
                   "moves the flange by the inputs phi, w, a (consistent: w = der(phi), a = der(w)) "
                   "and outputs the torque tau that takes",
                   {Flange("flange", "the driven flange"), Signal("phi", "angle [rad]"),
                    Signal("w", "speed [rad/s] (use_w or use_a)", false),
                    Signal("a", "acceleration [rad/s^2] (use_a)", false),
                    SignalOutput("tau", "torque needed to drive the flange [N*m]")},
                   {Flag("use_w", true, "true: the input w is enabled"),
                    Flag("use_a", true, "true: the input a is enabled (the flange follows phi, w, a); "
                                        "false: it follows phi exactly (phi differentiated)")}));
  t.push_back(Type("TorqueToAngleAdaptor",
                   "the input torque tau acts on the flange (flange.tau = tau); outputs its angle, "
                   "speed and acceleration",
                   {Flange("flange", "the flange"), Signal("tau", "torque acting on the flange [N*m]"),
                    SignalOutput("phi", "angle [rad]"), SignalOutput("w", "speed [rad/s] (use_w)"),
                    SignalOutput("a", "acceleration [rad/s^2] (use_a)")},
                   {Flag("use_w", true, "true: the output w is enabled"),
                    Flag("use_a", true, "true: the output a is enabled")}));
  t.push_back(Type("RelativeStates",
                   "relative angle and speed of two flanges as states of their own (no torque)",
                   {flange_a(), flange_b()}, relative_starts({})));
  t.push_back(Type("IdealGear",
                   "ideal gear: phi_a - phi_s = ratio * (phi_b - phi_s), ratio*tau_a + tau_b = 0",
                   {flange_a(), flange_b(), Support()},
                   {Scalar("ratio", Dimensionless(), "1", std::nullopt, any,
                           "transmission ratio w_a / w_b (not 0)")}));
  t.push_back(Type("IdealPlanetary",
                   "planetary gear: (1 + ratio) * phi_carrier = phi_sun + ratio * phi_ring",
                   // MSL: an open flange carries no torque (a free ring idles the gear).
                   {Flange("sun", "sun flange", false), Flange("carrier", "carrier flange", false),
                    Flange("ring", "ring flange", false)},
                   {Scalar("ratio", Dimensionless(), "1", std::nullopt, positive,
                           "number of ring teeth / number of sun teeth")}));
  t.push_back(Type("LossyGear",
                   "gear with load-dependent mesh efficiency and bearing friction; may stick",
                   {flange_a(), flange_b(), Support()},
                   {Scalar("ratio", Dimensionless(), "1", std::nullopt, any,
                           "transmission ratio w_a / w_b (not 0)"),
                    TableParameter("lossTable",
                                   "[|w_a|, eta_mf1, eta_mf2, tau_bf1, tau_bf2] rows; default "
                                   "[0, 1, 1, 0, 0] (ideal)")}));
  t.push_back(Type("Gearbox",
                   "realistic gearbox (MSL): LossyGear (ratio, lossTable) from flange_a in series "
                   "with ElastoBacklash (c, d, b) to flange_b; no inertia",
                   {flange_a(), flange_b(), Support()},
                   relative_starts({Scalar("ratio", Dimensionless(), "1", std::nullopt, any,
                                           "transmission ratio w_a / w_b (not 0)"),
                                    TableParameter("lossTable",
                                                   "[|w_a|, eta_mf1, eta_mf2, tau_bf1, tau_bf2] rows; "
                                                   "default [0, 1, 1, 0, 0] (ideal)"),
                                    Scalar("c", Torque(), "N*m/rad", std::nullopt, positive,
                                           "gear elasticity (spring constant)"),
                                    Scalar("d", RotationalDamping(), "N*m*s/rad", 0.0, non_negative,
                                           "gear damping"),
                                    Scalar("b", angle, "rad", 0.0, non_negative, "total backlash")})));
  t.push_back(Type("BearingFriction", "Coulomb friction in a bearing, stick-slip (MSL state machine)",
                   {optional_a(), optional_b(), Support()},
                   friction_parameters("tau_pos",
                                       "[w, tau]: friction torque against speed |w| >= 0 "
                                       "(default [0, 1])")));
  t.push_back(Type("Brake", "brake between the flange and the housing, normal force from f_normalized",
                   {optional_a(), optional_b(), Support(),
                    Signal("f_normalized", "normalized normal force in [0, 1]")},
                   clutch_parameters(false)));
  t.push_back(Type("Clutch", "clutch between flange_a and flange_b, normal force from f_normalized",
                   {flange_a(), flange_b(), Signal("f_normalized", "normalized normal force")},
                   clutch_parameters(true)));
  t.push_back(Type("OneWayClutch",
                   "freewheel (locks for w_rel -> 0) in parallel with a clutch",
                   {flange_a(), flange_b(), Signal("f_normalized", "normalized normal force")},
                   clutch_parameters(true)));
  // --- Torque and speed sources -----------------------------------------------------------
  t.push_back(Type("Torque", "torque from the signal input tau accelerates the flange",
                   source_ports({Signal("tau", "driving torque [N*m]")}), {}));
  t.push_back(Type("Torque2",
                   "torque from the signal input tau between two flanges: +tau accelerates flange_b, "
                   "-tau flange_a",
                   {flange_a(), flange_b(), Signal("tau", "torque between the flanges [N*m]")}, {}));
  t.push_back(Type("ConstantTorque", "constant torque, independent of speed", source_ports(),
                   {Scalar("tau_constant", Torque(), "N*m", std::nullopt, any,
                           "accelerating torque (negative: braking)")}));
  t.push_back(Type("TorqueStep", "torque = offsetTorque + (time < startTime ? 0 : stepTorque)",
                   source_ports(),
                   {Scalar("stepTorque", Torque(), "N*m", std::nullopt, any, "height of the step"),
                    Scalar("offsetTorque", Torque(), "N*m", 0.0, any, "offset"),
                    Scalar("startTime", Time(), "s", 0.0, any, "time of the step")}));
  t.push_back(Type("LinearSpeedDependentTorque",
                   "tau = tau_nominal * |w/w_nominal| (TorqueDirection) or tau_nominal * w/w_nominal",
                   source_ports(), speed_torque("speed at which |torque| = |tau_nominal|")));
  t.push_back(Type("QuadraticSpeedDependentTorque",
                   "tau = tau_nominal * (w/w_nominal)^2 (TorqueDirection) or tau_nominal*w*|w|/w_nominal^2",
                   source_ports(), speed_torque("speed at which |torque| = |tau_nominal|")));
  t.push_back(Type("InverseSpeedDependentTorque",
                   "tau = tau_nominal * w_nominal / max(|w|, w0) (TorqueDirection) or "
                   "tau_nominal * w / w0 below w0 and tau_nominal * w_nominal / w above (MSL after 4.0.0)",
                   source_ports(),
                   [&] {
                     auto p = speed_torque("speed at which |torque| = |tau_nominal|");
                     p.push_back(Scalar("w0", AngularVelocity(), "rad/s", 0.1, positive,
                                        "regularization below w0"));
                     return p;
                   }()));
  t.push_back(Type("SignTorque",
                   "tau = tau_nominal * (2 / (1 + exp(-w / (0.01 * w0))) - 1)", source_ports(),
                   {Scalar("tau_nominal", Torque(), "N*m", std::nullopt, any, "nominal torque"),
                    Scalar("w0", AngularVelocity(), "rad/s", std::nullopt, positive,
                           "regularization speed")}));
  t.push_back(Type(
      "EddyCurrentTorque",
      "eddy current brake: braking torque 2*tau_nominal*w_n/(1 + w_n^2), temperature-dependent",
      source_ports(),
      {Scalar("tau_nominal", Torque(), "N*m", std::nullopt, any,
              "maximum braking torque (at w = w_nominal)"),
       Scalar("w_nominal", AngularVelocity(), "rad/s", std::nullopt, positive,
              "speed of maximum torque at TRef"),
       Scalar("TRef", Temperature(), "K", 293.15, positive, "reference temperature"),
       Scalar("alpha20", PerKelvin(), "1/K", 0.0, any,
              "temperature coefficient of the resistance at 20 degC"),
       Flag("useHeatPort", false,
            "true: the loss heats a lumped heat capacitor (C_heatPort, T_heatPort_start); "
            "false: constant temperature T"),
       Scalar("T", Temperature(), "K", 293.15, positive, "fixed temperature (useHeatPort=false)"),
       Scalar("C_heatPort", HeatCapacity(), "J/K", 1.0, positive,
              "heat capacity on the heat port (useHeatPort=true)"),
       Scalar("T_heatPort_start", Temperature(), "K", 293.15, positive,
              "initial temperature of the heat capacity")}));
  auto f_crit = [&](std::string filter) {
    return Scalar("f_crit", AngularVelocity(), "Hz", 50.0, positive,
                  "critical frequency of the " + std::move(filter) + " of the input (exact = false)");
  };
  t.push_back(Type("Speed",
                   "speed source: w = w_ref (exact) or w_ref through a first-order filter of "
                   "f_crit; w = w_ref at the start",
                   source_ports({Signal("w_ref", "reference speed [rad/s]")}),
                   {Flag("exact", false,
                         "true: w = w_ref exactly (w_ref must be differentiable); false: filtered"),
                    f_crit("first-order filter"),
                    Start("phi_start", Dimensionless(), "rad", "initial flange angle")}));
  t.push_back(Type("Position",
                   "position source: phi = phi_ref (exact) or phi_ref through the second-order "
                   "Bessel filter of f_crit; phi = phi_ref at the start",
                   source_ports({Signal("phi_ref", "reference angle [rad]")}),
                   {Flag("exact", false,
                         "true: phi = phi_ref exactly (phi_ref must be differentiable twice); "
                         "false: filtered"),
                    f_crit("second-order Bessel filter")}));
  t.push_back(Type("Accelerate", "acceleration source: a = a_ref; phi and w integrate it",
                   source_ports({Signal("a_ref", "reference acceleration [rad/s^2]")}),
                   {Scalar("phi_start", angle, "rad", 0.0, any, "initial angle (fixed)"),
                    Scalar("w_start", AngularVelocity(), "rad/s", 0.0, any, "initial speed (fixed)")}));
  t.push_back(Type("Move",
                   "motion source: phi, w and a from the inputs u[1], u[2], u[3] (to be "
                   "consistent)",
                   source_ports({Signal("u[1]", "angle [rad]"), Signal("u[2]", "speed [rad/s]"),
                                 Signal("u[3]", "acceleration [rad/s^2]")}),
                   {}));
  t.push_back(Type("ConstantSpeed", "w = w_fixed, independent of the torque", source_ports(),
                   {Scalar("w_fixed", AngularVelocity(), "rad/s", std::nullopt, any, "fixed speed")}));
  // --- Signal sources (Modelica.Blocks) -------------------------------------------------
  t.push_back(Type("Constant", "y = k", {output()},
                   {Scalar("k", Dimensionless(), "1", std::nullopt, any, "constant output")}));
  t.push_back(Type("Step", "y = offset + (time < startTime ? 0 : height)", {output()},
                   {Scalar("height", Dimensionless(), "1", 1.0, any, "height of the step"),
                    offset(), start_time()}));
  t.push_back(Type("Ramp", "y = offset, then a linear ramp of `height` over `duration`", {output()},
                   {Scalar("height", Dimensionless(), "1", 1.0, any, "height of the ramp"),
                    Scalar("duration", Time(), "s", std::nullopt, positive, "duration of the ramp"),
                    offset(), start_time()}));
  t.push_back(Type("Sine", "y = offset + amplitude * sin(2*pi*f*(time - startTime) + phase)",
                   {output()},
                   {Scalar("amplitude", Dimensionless(), "1", 1.0, any, "amplitude"),
                    Scalar("f", AngularVelocity(), "Hz", 1.0, any, "frequency"),
                    Scalar("phase", Dimensionless(), "rad", 0.0, any, "phase"), offset(),
                    start_time()}));
  t.push_back(Type("Pulse", "y = offset + amplitude during the first width% of each period",
                   {output()},
                   {Scalar("amplitude", Dimensionless(), "1", 1.0, any, "amplitude"),
                    Scalar("width", Dimensionless(), "1", 50.0, {0.0, 100.0},
                           "width of the pulse in % of the period"),
                    Scalar("period", Time(), "s", std::nullopt, positive, "period"),
                    Integer("nperiod", -1, {-1, kInf}, "number of periods (< 0: infinite)"),
                    offset(), start_time()}));
  t.push_back(Type("TimeTable", "y = offset + linear interpolation of table [time, y] at time - startTime",
                   {output()},
                   {TableParameter("table", "[time, y] rows with non-decreasing time"), offset(),
                    start_time()}));
  t.push_back(Type("Product", "y = u1 * u2",
                   {Signal("u1", "first input"), Signal("u2", "second input"), output()}, {}));
  t.push_back(Type("Feedback", "y = u1 - u2",
                   {Signal("u1", "commanded input"), Signal("u2", "feedback input"), output()},
                   {}));
  AppendBrakeTypes(t);
  AppendGearTypes(t);
  AppendDriveTypes(t);
  AppendHydraulicTypes(t);
  AppendTranslationalTypes(t);
  return t;
}

}  // namespace

const std::vector<ComponentTypeSpec>& ElementTypes() {
  static const std::vector<ComponentTypeSpec> types = MakeElementTypes();
  return types;
}

const ComponentTypeSpec* FindElementType(std::string_view name) {
  for (const auto& t : ElementTypes())
    if (t.name == name) return &t;
  return nullptr;
}

}  // namespace highlift
