// Brakes, torque limiters and friction of the HighLift library, as element types:
// StribeckFriction, LossyInertia, ShaftBrake, BrakeActuation, WingTipBrake, NonlinearSpring,
// TorqueLimiter. Names, parameters (names, defaults, ranges) and ports are those of the classes
// in export/modelica/HighLift/Mechanical/ and Control/BrakeActuation.mo, so that an element
// network exports one-to-one. The laws are in sim/src/brake_elements.cc; the equations are in
// docs/highlift_elements.md ("Brakes, torque limiters and friction").
#include <cmath>

#include "element_type_builders.h"

namespace highlift::element_types {
namespace {

const char* const kSource = "HighLift library (export/modelica/HighLift)";

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

/// A parameter whose default depends on another one (left out: the law derives it).
ParameterSpec Derived(std::string name, Dimension dimension, std::string unit, Domain valid,
                      std::string description) {
  ParameterSpec p = Required(std::move(name), dimension, std::move(unit), valid,
                             std::move(description));
  p.optional = true;
  return p;
}

}  // namespace

void AppendBrakeTypes(std::vector<ComponentTypeSpec>& types) {
  using namespace dimensions;
  const Domain non_negative{0.0, kInf};
  const Domain positive{std::nextafter(0.0, 1.0), kInf};
  const Domain unit_interval{0.0, 1.0};
  const Dimension angle = Dimensionless();

  // Stribeck law (3) and the load-dependent loss (4): shared by StribeckFriction and LossyInertia.
  auto stribeck = [&] {
    return std::vector<ParameterSpec>{
        Default("tau_C", Torque(), "N*m", 0.0, non_negative, "Coulomb friction torque, equation (3)"),
        Default("d_vis", RotationalDamping(), "N*m*s/rad", 0.0, non_negative,
                "viscous friction coefficient, equation (3)"),
        Default("tau_S", Torque(), "N*m", 0.0, non_negative,
                "Stribeck torque (excess of the breakaway torque at standstill), equation (3)"),
        Default("f_exp", Time(), "s/rad", 10.0, non_negative,
                "decay of the Stribeck torque with speed, equation (3)"),
        Default("peak", Dimensionless(), "1", 1.0, {1.0, kInf},
                "static friction at standstill = peak*(tau_C + tau_S)"),
        Default("w_small", AngularVelocity(), "rad/s", 0.0, non_negative,
                "regularisation speed: 0 = exact stick/slip; > 0 = friction and load loss "
                "scaled by tanh(w/w_small), continuous, no stick/slip events"),
    };
  };
  auto eta_ge = [&] {
    return Default("eta_GE", Dimensionless(), "1", 1.0, unit_interval,
                   "gearbox efficiency of the load-dependent loss (1 - eta_GE)*|tau_load| in "
                   "motion, equation (4)");
  };
  auto brake_torques = [&](std::string max_text, bool lim_derived) {
    std::vector<ParameterSpec> p{
        Required("tauB_max", Torque(), "N*m", non_negative, std::move(max_text))};
    if (lim_derived)
      p.push_back(Derived("tauB_lim", Torque(), "N*m", non_negative,
                          "maximum static (holding) brake torque at u = 1, >= tauB_max "
                          "(default tauB_max)"));
    else
      p.push_back(Required("tauB_lim", Torque(), "N*m", non_negative,
                           "maximum static (holding) brake torque at u = 1, >= tauB_max"));
    return p;
  };
  auto spring = [&](bool starts) {
    std::vector<ParameterSpec> p{
        Required("tau1_ext", Torque(), "N*m", non_negative,
                 "lock-out torque tau_1 for positive phi_rel (extend direction)"),
        Required("tau1_ret", Torque(), "N*m", non_negative,
                 "lock-out torque tau_1 for negative phi_rel (retract direction), magnitude"),
        Required("tau2_ext", Torque(), "N*m", non_negative,
                 "end-stop torque tau_2 for positive phi_rel (> tau1_ext)"),
        Required("tau2_ret", Torque(), "N*m", non_negative,
                 "end-stop torque tau_2 for negative phi_rel (> tau1_ret), magnitude"),
        Required("c1", Torque(), "N*m/rad", positive, "stiffness in normal operation (balls seated)"),
        Required("c2", Torque(), "N*m/rad", positive,
                 "stiffness during lock-out (balls running up the ramps)"),
        Required("c3", Torque(), "N*m/rad", positive, "stiffness at the end stop (device grounded)"),
        Default("d", RotationalDamping(), "N*m*s/rad", 0.0, non_negative, "damping constant"),
    };
    if (starts) {
      p.push_back(HighLift(Start("phi_rel_start", angle, "rad",
                                 "initial relative angle phi_b - phi_a (fixed when given)")));
      p.push_back(HighLift(Start("w_rel_start", AngularVelocity(), "rad/s",
                                 "initial relative speed w_b - w_a (fixed when given)")));
    }
    return p;
  };
  auto optional_a = [] { return Flange("flange_a", "flange (rigidly tied to flange_b)", false); };
  auto optional_b = [] { return Flange("flange_b", "flange (rigidly tied to flange_a)", false); };

  {
    std::vector<ParameterSpec> p = stribeck();
    p.push_back(Flag("useEfficiencyInput", false,
                     "true: the efficiency eta_GE of the load-dependent loss is the input eta"));
    p.back().source = kSource;
    p.push_back(eta_ge());
    types.push_back(Type(
        "StribeckFriction",
        "friction to the housing: Stribeck law (3) plus the load-dependent loss (1 - eta_GE)*"
        "|tau_load| of (4) in motion; sticks below peak*(tau_C + tau_S)",
        {Flange("flange_a", "input flange (rigidly tied to flange_b)"),
         Flange("flange_b", "output flange (rigidly tied to flange_a)", false), Support(),
         Signal("eta", "gearbox efficiency eta_GE in [0, 1] (when useEfficiencyInput)", false)},
        std::move(p)));
  }
  {
    std::vector<ParameterSpec> p{Required("J", Inertia(), "kg*m^2", non_negative, "moment of inertia")};
    for (auto& x : stribeck()) p.push_back(std::move(x));
    p.push_back(eta_ge());
    types.push_back(Type("LossyInertia",
                         "inertia J with Stribeck bearing friction (3) and the load-dependent "
                         "gear loss (4) to the housing; sticks at standstill",
                         {optional_a(), optional_b(), Support()}, std::move(p)));
  }
  types.push_back(Type(
      "ShaftBrake",
      "brake to the housing: sliding torque u*tauB_max against the motion, holds up to "
      "u*tauB_lim once stopped, free for u <= 0",
      {optional_a(), optional_b(), Support(),
       Signal("u", "normalized maximum dynamic brake torque, 0 (released) ... 1 (applied)")},
      brake_torques("maximum dynamic (sliding) brake torque, reached at u = 1", false)));
  types.push_back(Type(
      "BrakeActuation",
      "Boolean brake command (trigger > 0.5) to the normalized brake torque y: 0 until "
      "t_lat after the command, then a linear rise to 1 over t_rise; optionally latched",
      {Signal("trigger", "brake command, Boolean as 0/1 (> 0.5 is true)"),
       SignalOutput("y", "normalized brake torque in [0, 1]")},
      {Default("t_lat", Time(), "s", 0.0, non_negative, "delay from the command to engagement"),
       Default("t_rise", Time(), "s", 0.0, non_negative,
               "time of the rise from 0 to 1 after engagement"),
       HighLift(Flag("latch", false, "true: once commanded, the brake stays applied"))}));
  {
    std::vector<ParameterSpec> p = brake_torques("maximum dynamic (sliding) brake torque", false);
    p.push_back(Default("t_B", Time(), "s", 0.03, non_negative,
                        "time from engagement to the maximum dynamic brake torque"));
    p.push_back(Default("t_lat", Time(), "s", 0.1, non_negative,
                        "delay from the command to engagement"));
    p.push_back(Default("J", Inertia(), "kg*m^2", 5e-4, non_negative, "inertia of the brake rotor"));
    types.push_back(Type(
        "WingTipBrake",
        "wing-tip brake: rotor inertia J and a ShaftBrake applied by the latched Boolean `apply` "
        "after t_lat, dynamic torque rising to tauB_max over t_B, holding up to tauB_lim",
        {Flange("flange_a", "shaft flange (through the rotor to flange_b)"),
         Flange("flange_b", "shaft flange; may be left open at the shaft end", false), Support(),
         Signal("apply", "brake command, Boolean as 0/1 (> 0.5 is true); latched")},
        std::move(p)));
  }
  types.push_back(Type(
      "NonlinearSpring",
      "torque limiter spring (figure 4): stiffness c1 up to tau1, c2 during lock-out up to "
      "tau2, c3 at the end stop, asymmetric extend/retract; output y of equation (2)",
      {Flange("flange_a", "left flange (phi_rel = phi_b - phi_a)"),
       Flange("flange_b", "right flange"),
       SignalOutput("y", "normalized brake torque of the lock-out, equation (2)")},
      spring(true)));
  {
    std::vector<ParameterSpec> p = spring(false);
    for (auto& x : brake_torques("dynamic brake torque to the housing at the end stop (y = 1)", true))
      p.push_back(std::move(x));
    p.push_back(Default("J", Inertia(), "kg*m^2", 0.0, non_negative,
                        "inertia of the limiter, on the input side"));
    types.push_back(Type(
        "TorqueLimiter",
        "ball-ramp torque limiter (figure 5): NonlinearSpring whose output y drives a "
        "ShaftBrake from the input side to the housing",
        {Flange("flange_a", "input flange (braked to the housing at lock-out)"),
         Flange("flange_b", "output flange"), Support(),
         SignalOutput("y", "normalized lock-out brake torque (lock-out indicator)")},
        std::move(p)));
  }
}

}  // namespace highlift::element_types
