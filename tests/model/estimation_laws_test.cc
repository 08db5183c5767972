// The estimation laws the component models declare (ComponentModel::EstimationLaws, FitRules):
// against hand-computed values of domain.md s3/s4, the same law on intervals enclosing the
// point results, and every parameter a law or fit names declared by the type's catalogue entry.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "highlift/core/catalogue.h"
#include "highlift/model/component_model.h"
#include "highlift/model/laws.h"

namespace highlift::model {
namespace {

constexpr double kG = 44e9;    // Pa, Ti-6Al-4V (domain.md s3)
constexpr double kRho = 4420;  // kg/m^3

const EstimationLaw& LawOf(const std::string& type, const std::string& output) {
  static std::map<std::string, std::vector<EstimationLaw>> laws;
  auto it = laws.find(type);
  if (it == laws.end()) it = laws.emplace(type, FindComponentModel(type)->EstimationLaws()).first;
  for (const auto& law : it->second)
    if (law.output == output) return law;
  throw std::runtime_error("no estimation law for " + type + "." + output);
}

double At(const std::string& type, const std::string& output, std::vector<double> inputs) {
  const EstimationLaw& law = LawOf(type, output);
  EXPECT_EQ(law.inputs.size(), inputs.size()) << type << "." << output;
  return law.nominal(inputs);
}

Interval On(const std::string& type, const std::string& output, std::vector<Interval> inputs) {
  return LawOf(type, output).enclosure(inputs);
}

TEST(TubeLaws, TitaniumTube50x2Over4MetresIs1914) {
  // GJ = 44e9 * pi/32 * (0.05^4 - 0.046^4) = 7657 N m^2; c = GJ / 4 m = 1914 N m/rad.
  EXPECT_NEAR(kG * TubePolarMoment(0.05, 0.002), 7657.0, 1.0);
  EXPECT_NEAR(At("torque_shaft", "stiffness", {kG, 0.05, 0.002, 4.0}), 1914.0, 0.5);
  // The other segments of the A380-class table.
  EXPECT_NEAR(At("torque_shaft", "stiffness", {kG, 0.05, 0.002, 3.0}), 2552.0, 0.5);
  EXPECT_NEAR(At("torque_shaft", "stiffness", {kG, 0.045, 0.0018, 3.5}), 1435.0, 0.5);
  EXPECT_NEAR(At("torque_shaft", "stiffness", {kG, 0.045, 0.0018, 1.5}), 3349.0, 0.5);
  // A320-class 38 x 1.5 mm: GJ = 2525 N m^2.
  EXPECT_NEAR(At("torque_shaft", "stiffness", {kG, 0.038, 0.0015, 1.0}), 2525.0, 1.0);
}

TEST(TubeLaws, FactoredPolarMomentAgreesWithTheDifferenceOfFourthPowers) {
  // pi/8 (D^2 + d^2)(D - t) t = pi/32 (D^4 - d^4) to round-off.
  for (double D : {0.03, 0.038, 0.05, 0.06})
    for (double t : {0.001, 0.0015, 0.002}) {
      const double d = D - 2 * t;
      EXPECT_NEAR(TubePolarMoment(D, t), std::numbers::pi / 32 * (std::pow(D, 4) - std::pow(d, 4)), 1e-14 * std::pow(D, 4));
    }
}

TEST(TubeLaws, MassInertiaAndTorqueCapacityOfTitaniumTubes) {
  EXPECT_NEAR(At("torque_shaft", "linear_density", {kRho, 0.05, 0.002}), 1.333, 0.001);
  EXPECT_NEAR(At("torque_shaft", "linear_density", {kRho, 0.045, 0.0018}), 1.08, 0.005);
  EXPECT_NEAR(At("torque_shaft", "linear_density", {kRho, 0.038, 0.0015}), 0.76, 0.005);
  EXPECT_NEAR(At("torque_shaft", "mass", {kRho, 0.05, 0.002, 4.0}), 4 * 1.333, 0.005);
  // J = rho Ip L = 4420 * 1.7403e-7 * 4 = 3.077e-3 kg m^2 for the 4 m PCU-RGB segment.
  EXPECT_NEAR(At("torque_shaft", "inertia", {kRho, 0.05, 0.002, 4.0}), 3.077e-3, 2e-6);
  // The capacity at the lesser of tau_allow and the torsional buckling stress (inputs tau_allow,
  // D, t, G, nu, gamma, L): a 50 x 2 mm titanium tube buckles at 485 MPa (G 44 GPa, nu 0.33,
  // knock-down 0.67; D/t 25), so it carries 3.37 kN*m, not the 3.83 kN*m of 550 MPa; without the
  // knock-down (gamma 1) the shear allowable governs.
  EXPECT_NEAR(At("torque_shaft", "torque_capacity", {550e6, 0.05, 0.002, 44e9, 0.33, 0.67, 4.0}), 3374.5, 0.5);
  EXPECT_NEAR(At("torque_shaft", "torque_capacity", {550e6, 0.05, 0.002, 44e9, 0.33, 1.0, 4.0}), 3828.0, 5.0);
  EXPECT_NEAR(At("torque_shaft", "torque_capacity", {550e6, 0.045, 0.0018, 44e9, 0.33, 0.67, 4.0}), 2460.0, 0.5);
  EXPECT_NEAR(At("torque_shaft", "torque_capacity", {550e6, 0.038, 0.0015, 44e9, 0.33, 0.67, 1.4}), 1434.2, 0.5);
  const EstimationLaw& mass = LawOf("torque_shaft", "mass");
  EXPECT_TRUE(mass.derived);
  EXPECT_EQ(mass.unit, "kg");
}

TEST(TubeLaws, BearingDragPerLengthDividesTheDragOfOneBearingByTheLabelSpacing) {
  const EstimationLaw& law = LawOf("torque_shaft", "drag_per_length");
  ASSERT_EQ(law.inputs.size(), 2u);
  EXPECT_EQ(law.inputs[0].kind, LawInput::Kind::kConstant);
  EXPECT_EQ(law.inputs[0].range.lo, 0.05);  // domain.md s6: 0.05-0.2 N m each
  EXPECT_EQ(law.inputs[0].range.hi, 0.2);
  EXPECT_EQ(law.inputs[1].kind, LawInput::Kind::kLabel);
  EXPECT_EQ(law.inputs[1].name, "bearing_spacing");
  EXPECT_EQ(law.inputs[1].dimension, dimensions::Length());
  EXPECT_DOUBLE_EQ(law.nominal(std::vector<double>{0.1, 0.5}), 0.2);
}

TEST(TubeLaws, OnIntervalsEnclosesEveryPointResult) {
  const Interval G(43e9, 51e9), D(0.0499, 0.0501), t(0.0019, 0.0021), L(4.0);
  const Interval c = On("torque_shaft", "stiffness", {G, D, t, L});
  for (double g : {43e9, 47e9, 51e9})
    for (double dd : {0.0499, 0.05, 0.0501})
      for (double tt : {0.0019, 0.002, 0.0021}) {
        const double v = At("torque_shaft", "stiffness", {g, dd, tt, 4.0});
        EXPECT_LE(c.lo, v);
        EXPECT_GE(c.hi, v);
      }
  // The exact range, [1777, 2330] at the corners (the estimation law uses the monotonicity of
  // the tube law, MonotoneLaw): the factored law on the box gives [1755, 2358], pi/32 (D^4 - d^4)
  // with d = D - 2t [1694, 2426].
  const double lo = At("torque_shaft", "stiffness", {43e9, 0.0499, 0.0019, 4.0});
  const double hi = At("torque_shaft", "stiffness", {51e9, 0.0501, 0.0021, 4.0});
  EXPECT_NEAR(lo, 1777.0, 0.5);
  EXPECT_NEAR(hi, 2330.0, 0.5);
  EXPECT_NEAR(c.lo, lo, 1e-12 * lo);
  EXPECT_NEAR(c.hi, hi, 1e-12 * hi);
  const Interval box = ShaftStiffness(G, D, t, L);
  EXPECT_LT(box.lo, c.lo - 20.0);
  EXPECT_GT(box.hi, c.hi + 20.0);
  // Outside the monotone region (t > D/2: no tube) the law on the box, which still encloses.
  const Interval odd = On("torque_shaft", "stiffness", {G, Interval(0.01, 0.02), Interval(0.004, 0.006), L});
  for (double dd : {0.01, 0.015, 0.02})
    for (double tt : {0.004, 0.005, 0.006})
      EXPECT_TRUE(odd.contains(At("torque_shaft", "stiffness", {47e9, dd, tt, 4.0}))) << dd << " " << tt;
}

TEST(GearedRotaryActuator, FlapInertiaOfTheA380ClassPanelIsTheStationValue) {
  // 1200 kg over 2.5 m stroke and 2.2 rad GRA travel, station ratio 400: 9.7e-3 kg m^2 (s3).
  EXPECT_NEAR(At("geared_rotary_actuator", "load_inertia", {1200.0, 2.5, 2.2, 400.0}), 9.7e-3, 0.05e-3);
  const EstimationLaw& law = LawOf("geared_rotary_actuator", "load_inertia");
  EXPECT_EQ(law.inputs[0].name, "flap_mass");
  EXPECT_EQ(law.inputs[0].dimension, dimensions::Mass());
  EXPECT_EQ(law.inputs[1].name, "flap_stroke");
}

TEST(GearedRotaryActuator, GearScalingOfInertiaAndMass) {
  // The reference GRA: 20 kN m at 200:1, eta 0.85: 1e-3 kg m^2.
  EXPECT_NEAR(At("geared_rotary_actuator", "input_inertia", {20e3, 200.0, 0.85}), 1e-3, 1e-12);
  // 8^(5/3) = 32 on the part above the floor of 3e-4.
  EXPECT_NEAR(At("geared_rotary_actuator", "input_inertia", {8 * 20e3, 200.0, 0.85}), 3e-4 + 7e-4 * 32.0, 1e-9);
  // A320-class flap GRA, 6 kN m at 300:1 (domain.md s4): 3.5e-4 kg m^2.
  EXPECT_NEAR(At("geared_rotary_actuator", "input_inertia", {6e3, 300.0, 0.85}), 3.48e-4, 0.01e-4);
  EXPECT_NEAR(At("geared_rotary_actuator", "mass", {20e3}), 20.0, 1e-12);
  EXPECT_NEAR(At("geared_rotary_actuator", "mass", {40e3}), 20.0 * std::pow(2.0, 0.8), 1e-9);
  // On intervals (exp and log of model::Interval): an enclosure of the monotone law.
  const Interval J = On("geared_rotary_actuator", "input_inertia", {Interval(15e3, 30e3), Interval(200.0), Interval(0.85)});
  EXPECT_LE(J.lo, At("geared_rotary_actuator", "input_inertia", {15e3, 200.0, 0.85}));
  EXPECT_GE(J.hi, At("geared_rotary_actuator", "input_inertia", {30e3, 200.0, 0.85}));
  EXPECT_LT(J.hi - J.lo, 1.1 * (At("geared_rotary_actuator", "input_inertia", {30e3, 200.0, 0.85}) -
                                At("geared_rotary_actuator", "input_inertia", {15e3, 200.0, 0.85})));
}

TEST(Pdu, OutputInertiaIsItsLumpedLaw) {
  EXPECT_NEAR(At("pdu", "output_inertia", {3e-4, 2.0, 20.0, 0.02}), 0.26, 1e-12);     // A380 class
  EXPECT_NEAR(At("pdu", "output_inertia", {1.5e-4, 2.0, 16.0, 0.01}), 0.0868, 1e-12);  // A320 class
}

TEST(FitRules, TheActuatorLimitersAndBrakeFitTheirInertiaAgainstARating) {
  const auto rules = [](const std::string& type) {
    std::vector<std::string> out;
    for (const auto& r : FindComponentModel(type)->FitRules()) out.push_back(r.parameter + "/" + r.rating);
    return out;
  };
  EXPECT_EQ(rules("geared_rotary_actuator"), std::vector<std::string>{"input_inertia/output_torque_rating"});
  EXPECT_EQ(rules("system_torque_limiter"), std::vector<std::string>{"inertia/lockout_torque_extend"});
  EXPECT_EQ(rules("station_torque_limiter"), std::vector<std::string>{"inertia/lockout_torque_extend"});
  EXPECT_EQ(rules("wing_tip_brake"), std::vector<std::string>{"inertia/max_dynamic_torque"});
  EXPECT_TRUE(rules("torque_shaft").empty());
}

// Every parameter an estimation law or fit names is declared by the type, except the gearboxes'
// torque rating: their law is dormant until the catalogue declares it (gearbox.h).
TEST(EstimationLaws, NameOnlyParametersTheCatalogueDeclares) {
  std::set<std::string> missing;
  for (const ComponentModel* m : ComponentModels()) {
    const ComponentTypeSpec* type = FindComponentType(m->type());
    ASSERT_NE(type, nullptr);
    const std::string t(m->type());
    for (const EstimationLaw& law : m->EstimationLaws()) {
      ASSERT_TRUE(law.nominal && law.enclosure) << t << "." << law.output;
      EXPECT_FALSE(law.note.empty()) << t << "." << law.output;
      if (law.derived) {
        EXPECT_FALSE(law.unit.empty()) << t << "." << law.output;
      } else {
        EXPECT_NE(type->FindParameter(law.output), nullptr) << t << "." << law.output;
      }
      for (const LawInput& in : law.inputs)
        if (in.kind == LawInput::Kind::kParameter && !type->FindParameter(in.name)) missing.insert(t + "." + in.name);
    }
    for (const FitRule& r : m->FitRules()) {
      EXPECT_NE(type->FindParameter(r.parameter), nullptr) << t << "." << r.parameter;
      EXPECT_NE(type->FindParameter(r.rating), nullptr) << t << "." << r.rating;
    }
  }
  EXPECT_EQ(missing, (std::set<std::string>{"angle_gearbox.torque_rating", "branch_gearbox.torque_rating"}));
}

}  // namespace
}  // namespace highlift::model
