// The elements of Modelica.Mechanics.Translational (MSL 4.0.0) that a ballscrew or a rack
// needs to meet a rotational network, and the two rotational-translational gears of
// Modelica.Mechanics.Rotational.Components. Types whose MSL name is also a rotational one
// carry the prefix "Translational." (Translational.Spring, Translational.Fixed, ...); Mass,
// IdealGearR2T and IdealRollingWheel keep their MSL names.
//
// The simulator has one kind of mechanical node; a translational flange is such a node read in
// SI translational units: position s in m, speed v in m/s, force f in N (the laws are the
// rotational ones, sim/src/msl_more_elements.cc).
#include "element_type_builders.h"

namespace highlift::element_types {

void AppendTranslationalTypes(std::vector<ComponentTypeSpec>& t) {
  using namespace dimensions;
  const Domain any = Domain::Whole();
  const Domain non_negative{0.0, kInf};
  const Domain positive{std::nextafter(0.0, 1.0), kInf};
  const Dimension velocity = Length() / Time();
  const Dimension stiffness = Force() / Length();
  const Dimension damping = Force() * Time() / Length();
  auto flange_a = [] { return Flange("flange_a", "left flange, translational (s_rel = s_b - s_a)"); };
  auto flange_b = [] { return Flange("flange_b", "right flange, translational"); };
  auto relative = [&](std::vector<ParameterSpec> p) {
    p.push_back(Start("s_rel_start", Length(), "m", "initial relative position s_b - s_a (fixed when given)"));
    p.push_back(Start("v_rel_start", velocity, "m/s", "initial relative speed v_b - v_a (fixed when given)"));
    p.push_back(Nominal("s_nominal", Length(), "m",
                        "nominal relative position: absolute tolerance of s_rel = absolute_tolerance * "
                        "s_nominal (absent: 1)"));
    return p;
  };
  auto c = [&] { return Scalar("c", stiffness, "N/m", std::nullopt, non_negative, "spring constant"); };
  auto d = [&] { return Scalar("d", damping, "N*s/m", std::nullopt, non_negative, "damping constant"); };
  auto s_rel0 = [&] { return Scalar("s_rel0", Length(), "m", 0.0, any, "unstretched spring length"); };
  auto rotational_translational = [&] {
    return std::vector<PortSpec>{
        Flange("flangeR", "rotational flange"), Flange("flangeT", "translational flange"),
        Flange("supportR", "rotational housing; grounded when left unconnected", false),
        Flange("supportT", "translational housing; grounded when left unconnected", false)};
  };

  t.push_back(Type("Mass", "translational mass: m * a = flange_a.f + flange_b.f",
                   {Flange("flange_a", "flange, translational (rigidly tied to flange_b)", false),
                    Flange("flange_b", "flange, translational (rigidly tied to flange_a)", false)},
                   {Scalar("m", Mass(), "kg", std::nullopt, non_negative, "mass"),
                    Start("s_start", Length(), "m", "initial position (fixed when given)"),
                    Start("v_start", velocity, "m/s", "initial speed (fixed when given)"),
                    Flag("s_fixed", true, "false: s_start is a guess (MSL fixed = false)"),
                    Flag("v_fixed", true, "false: v_start is a guess (MSL fixed = false)"),
                    Start("a_start", velocity / Time(), "m/s^2",
                          "initial acceleration (MSL a(start, fixed = true)): the initial equation "
                          "a = a_start determines start values that are not fixed"),
                    Flag("a_fixed", true, "false: a_start is ignored (a is not a state; MSL fixed = false)"),
                    Nominal("s_nominal", Length(), "m",
                            "nominal position: absolute tolerance of s = absolute_tolerance * s_nominal (absent: 1)"),
                    Nominal("v_nominal", velocity, "m/s",
                            "nominal speed: absolute tolerance of v = absolute_tolerance * v_nominal (absent: 1)")}));
  t.push_back(Type("Translational.Fixed", "translational flange fixed in the housing at position s0",
                   {Flange("flange", "the fixed flange")},
                   {Scalar("s0", Length(), "m", 0.0, any, "fixed position")}));
  t.push_back(Type("Translational.Spring", "linear spring: f = c * (s_rel - s_rel0)", {flange_a(), flange_b()},
                   relative({c(), s_rel0()})));
  t.push_back(Type("Translational.Damper", "linear damper: f = d * v_rel", {flange_a(), flange_b()},
                   relative({d()})));
  t.push_back(Type("Translational.SpringDamper", "spring and damper in parallel: f = c*(s_rel - s_rel0) + d*v_rel",
                   {flange_a(), flange_b()}, relative({c(), d(), s_rel0()})));
  t.push_back(Type("Translational.Force", "force from the signal input f accelerates the flange",
                   {Flange("flange", "driven flange"),
                    Flange("support", "housing; grounded when left unconnected", false),
                    Signal("f", "driving force [N]")},
                   {}));
  t.push_back(Type("Translational.PositionSensor", "ideal sensor: s = flange.s",
                   {Flange("flange", "measured flange"), SignalOutput("s", "position [m]")}, {}));
  t.push_back(Type("Translational.SpeedSensor", "ideal sensor: v = der(flange.s)",
                   {Flange("flange", "measured flange"), SignalOutput("v", "speed [m/s]")}, {}));
  t.push_back(Type("IdealGearR2T",
                   "rotational-translational gear: (phi_R - phi_supportR) = ratio * (s_T - s_supportT), "
                   "ratio * flangeR.tau + flangeT.f = 0",
                   rotational_translational(),
                   {Scalar("ratio", Dimensionless() / Length(), "rad/m", std::nullopt, positive,
                           "transmission ratio (flangeR.phi / flangeT.s), e.g. 2*pi/lead of a ballscrew")}));
  t.push_back(Type("IdealRollingWheel",
                   "wheel rolling without slip: (phi_R - phi_supportR) * radius = s_T - s_supportT, "
                   "radius * flangeT.f + flangeR.tau = 0",
                   rotational_translational(),
                   {Scalar("radius", Length(), "m", std::nullopt, positive, "wheel radius")}));
}

}  // namespace highlift::element_types
