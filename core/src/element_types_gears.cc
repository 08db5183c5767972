// Gears and failure elements of the HighLift library, as element types: GearedRotaryActuator,
// BranchGearbox, GeneralRotationalElement, Disconnector, Jam. Names, parameters (names,
// defaults, ranges) and ports are those of the classes in export/modelica/HighLift/Mechanical/,
// so that an element network exports one-to-one. The laws are in sim/src/gear_elements.cc.
#include <cmath>

#include "element_type_builders.h"

namespace highlift::element_types {
namespace {

const char* const kSource = "HighLift library (export/modelica/HighLift/Mechanical)";

ParameterSpec HighLift(ParameterSpec p) {
  p.source = kSource;
  return p;
}

/// A parameter whose Modelica declaration has only a start value (no default): required.
ParameterSpec Required(std::string name, Dimension dimension, std::string unit, Domain valid,
                       std::string description) {
  return HighLift(Scalar(std::move(name), dimension, std::move(unit), std::nullopt, valid,
                         std::move(description)));
}

/// A parameter with a default.
ParameterSpec Default(std::string name, Dimension dimension, std::string unit, double nominal,
                      Domain valid, std::string description) {
  return HighLift(
      Scalar(std::move(name), dimension, std::move(unit), nominal, valid, std::move(description)));
}

/// A parameter that may be left out (a time that defaults to "never", a stiffness needed only
/// with elastic = true).
ParameterSpec Optional(std::string name, Dimension dimension, std::string unit, Domain valid,
                       std::string description) {
  ParameterSpec p = Required(std::move(name), dimension, std::move(unit), valid,
                             std::move(description));
  p.optional = true;
  return p;
}

ParameterSpec HighLiftFlag(std::string name, bool nominal, std::string description) {
  return HighLift(Flag(std::move(name), nominal, std::move(description)));
}

}  // namespace

void AppendGearTypes(std::vector<ComponentTypeSpec>& types) {
  using namespace dimensions;
  const Domain any = Domain::Whole();
  const Domain non_negative{0.0, kInf};
  const Domain positive{std::nextafter(0.0, 1.0), kInf};
  const Domain efficiency{std::nextafter(0.0, 1.0), 1.0};
  const Domain fraction{0.0, 1.0};
  const Dimension angle = Dimensionless();

  auto flange_a = [] { return Flange("flange_a", "input flange (transmission side)"); };
  auto flange_b = [] { return Flange("flange_b", "output flange"); };
  // Equation (3) of the paper: tau_fric,S = tau_C + d_vis*|w| + tau_S*exp(-f_exp*|w|).
  auto stribeck = [&](bool with_peak) {
    std::vector<ParameterSpec> p{
        Default("tau_C", Torque(), "N*m", 0.0, non_negative,
                "Coulomb friction torque, equation (3), referred to the input"),
        Default("d_vis", RotationalDamping(), "N*m*s/rad", 0.0, non_negative,
                "viscous friction coefficient, equation (3)"),
        Default("tau_S", Torque(), "N*m", 0.0, non_negative,
                "Stribeck torque at standstill, equation (3)"),
        Default("f_exp", Time(), "s/rad", 10.0, non_negative,
                "decay of the Stribeck torque with speed, equation (3)")};
    if (with_peak)
      p.push_back(Default("peak", Dimensionless(), "1", 1.0, {1.0, kInf},
                          "breakaway factor: static friction at standstill = peak*(tau_C + tau_S)"));
    p.push_back(Default("w_small", AngularVelocity(), "rad/s", 0.0, non_negative,
                        "regularisation speed: 0 = exact stick/slip; > 0 = friction and "
                        "load-dependent loss scaled by tanh(w/w_small), no stick/slip events"));
    return p;
  };
  // ElastoBacklash in front of the element (elastic = true).
  auto elasticity = [&](bool elastic_default, const std::string& what) {
    return std::vector<ParameterSpec>{
        HighLiftFlag("elastic", elastic_default,
                     "true: the " + what + " has a stiffness c, damping d and backlash b "
                     "(ElastoBacklash in front); false: rigid"),
        Optional("c", Torque(), "N*m/rad", positive,
                 "torsional stiffness referred to the input (required when elastic = true)"),
        Default("d", RotationalDamping(), "N*m*s/rad", 0.0, non_negative,
                "damping referred to the input (elastic = true)"),
        Default("b", angle, "rad", 0.0, non_negative,
                "total backlash referred to the input (elastic = true)")};
  };
  auto append = [](std::vector<ParameterSpec>& to, std::vector<ParameterSpec> more) {
    for (auto& p : more) to.push_back(std::move(p));
  };

  // --- GearedRotaryActuator ---------------------------------------------------------------
  {
    std::vector<ParameterSpec> p{
        Required("ratio", Dimensionless(), "1", any, "gear ratio, input speed / output speed (not 0)"),
        Default("eta_op", Dimensionless(), "1", 0.85, efficiency,
                "efficiency driving against an opposing load (power flows input -> output)"),
        Default("eta_ai", Dimensionless(), "1", 0.70, efficiency,
                "efficiency with an aiding (back-driving) load (power flows output -> input)"),
        Default("phi_eta", angle, "rad", 3.14, positive,
                "input angle over which the efficiency settles after a start or reversal "
                "(figure 7b)"),
        Default("w_eta", AngularVelocity(), "rad/s", 0.1, positive,
                "input speed below which the efficiency rises linearly to 1 when stopping "
                "(figure 7a)"),
        Required("J_in", Inertia(), "kg*m^2", non_negative, "inertia referred to the input"),
        Default("J_load", Inertia(), "kg*m^2", 0.0, non_negative,
                "flap inertia reflected to the input (J_load*ratio^2 at the output flange)")};
    append(p, elasticity(false, "actuator"));
    append(p, stribeck(true));
    types.push_back(Type(
        "GearedRotaryActuator",
        "geared rotary actuator: one gear stage whose efficiency depends on the direction of "
        "power flow (eta_op, eta_ai) and builds up over the input angle after a start or "
        "reversal (figure 7); Stribeck friction with stick-slip; output eta_GE",
        {flange_a(), flange_b(), Support(),
         SignalOutput("eta_GE", "gearbox efficiency in use (1 at standstill)")},
        std::move(p)));
  }

  // --- GeneralRotationalElement -----------------------------------------------------------
  {
    std::vector<ParameterSpec> p = elasticity(true, "element");
    p.push_back(Required("J", Inertia(), "kg*m^2", non_negative,
                         "moment of inertia (at the flange_a side of the gear)"));
    append(p, stribeck(true));
    p.push_back(Default("eta_GE", Dimensionless(), "1", 1.0, fraction,
                        "gearbox efficiency of the load-dependent loss, equation (4)"));
    p.push_back(Required("ratio", Dimensionless(), "1", any,
                         "gear ratio, speed of flange_a / speed of flange_b (not 0)"));
    types.push_back(Type(
        "GeneralRotationalElement",
        "general rotational element of the paper: ElastoBacklash, LossyInertia (Stribeck "
        "friction and load-dependent loss, equations 3 and 4) and IdealGear in series",
        {flange_a(), flange_b(), Support()}, std::move(p)));
  }

  // --- BranchGearbox ----------------------------------------------------------------------
  {
    std::vector<ParameterSpec> p{Required("ratio", Dimensionless(), "1", any,
                                          "gear ratio, input speed / branch speed (not 0)")};
    append(p, elasticity(false, "branch"));
    p.push_back(Required("J", Inertia(), "kg*m^2", non_negative,
                         "inertia of the branch referred to the input"));
    append(p, stribeck(false));
    p.push_back(Default("eta_GE", Dimensionless(), "1", 1.0, fraction,
                        "efficiency of the branch gear meshes, equation (4)"));
    types.push_back(Type(
        "BranchGearbox",
        "T-gearbox or down-drive: 1:1 through-drive from flange_a to flange_b and a geared "
        "branch (a GeneralRotationalElement) to flange_branch",
        {Flange("flange_a", "input flange, towards the PDU"),
         Flange("flange_b", "through-drive flange (rigidly tied to flange_a)", false),
         Flange("flange_branch", "down-drive flange to the station", false), Support()},
        std::move(p)));
  }

  // --- Disconnector -----------------------------------------------------------------------
  types.push_back(Type(
      "Disconnector",
      "failure element: a stiff coupling tau = c*phi_rel + d*w_rel that breaks for good "
      "(shaft rupture) at t_disconnect or when the input disconnect becomes true",
      {Flange("flange_a", "left flange (phi_rel = phi_b - phi_a)"), Flange("flange_b", "right flange"),
       Signal("disconnect", "rupture command, > 0.5 = true (latched; useDisconnectInput = true)",
              false)},
      {Default("c", Torque(), "N*m/rad", 1e6, positive, "stiffness of the intact coupling"),
       Default("d", RotationalDamping(), "N*m*s/rad", 100.0, non_negative,
               "damping of the intact coupling"),
       Optional("t_disconnect", Time(), "s", any, "time of the rupture (never when left out)"),
       HighLiftFlag("useDisconnectInput", false,
                    "true: the rupture is (also) commanded by the input disconnect"),
       HighLift(Start("phi_rel_start", angle, "rad",
                      "initial relative angle phi_b - phi_a (fixed when given)")),
       HighLift(Start("w_rel_start", AngularVelocity(), "rad/s",
                      "initial relative speed w_b - w_a (fixed when given)"))}));

  // --- Jam --------------------------------------------------------------------------------
  types.push_back(Type(
      "Jam",
      "failure element: from t_jam, or when the input jam becomes true, ties the flange to "
      "the housing at the angle it had then, through stiffness c and damping d (latched)",
      {Flange("flange", "the flange that jams"), Support(),
       Signal("jam", "jam command, > 0.5 = true (latched; useJamInput = true)", false)},
      {Default("c", Torque(), "N*m/rad", 1e5, positive,
               "stiffness of the jammed load path to the structure"),
       Default("d", RotationalDamping(), "N*m*s/rad", 0.0, non_negative,
               "damping of the jammed load path"),
       Optional("t_jam", Time(), "s", any, "time of the jam (never when left out)"),
       HighLiftFlag("useJamInput", false, "true: the jam is (also) commanded by the input jam")}));
}

}  // namespace highlift::element_types
