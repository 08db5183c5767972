#include "highlift/reduced_models/lumped_model.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "highlift/core/error.h"
#include "highlift/reduced_models/modal.h"

namespace highlift::reduced_models {
namespace {

// A uniform shaft, clamped at one end and free at the other: w1 = pi/2 sqrt(c/J) for the
// continuous shaft with total stiffness c and total inertia J.
Transmission BareShaft(double c, double J) {
  Transmission t;
  const int root = t.AddPoint("root", 0.0);
  const int tip = t.AddPoint("tip", 0.0);
  t.AddLink(root, tip, c, J, "shaft");
  return t;
}

double FirstClampedOmega(const LumpedModel& m, int clamped_node) {
  return ComputeModes(m, {{clamped_node}, 0}).FirstElasticOmega();
}

TEST(LumpedModel, FullResolutionConvergesToTheContinuousShaft) {
  const double c = 2000.0, J = 0.01;
  const double exact = std::numbers::pi / 2.0 * std::sqrt(c / J);
  const Transmission t = BareShaft(c, J);
  double previous_error = 1.0;
  for (int n : {2, 4, 8, 16, 32}) {
    const LumpedModel m = BuildLumpedModel(t, Reduction::kFullResolution, n);
    EXPECT_EQ(m.nodes.size(), static_cast<std::size_t>(n + 1));
    const double error = std::abs(FirstClampedOmega(m, 0) / exact - 1.0);
    EXPECT_LT(error, previous_error / 3.0) << "n = " << n;  // second-order convergence
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-3);
}

TEST(LumpedModel, EveryRulePreservesTotalInertia) {
  Transmission t;
  const int pdu = t.AddPoint("pdu", 0.26);
  const int brg = t.AddPoint("brg", 5e-5, false);
  const int gbx = t.AddPoint("gbx", 1e-3);
  const int flap = t.AddPoint("flap", 1e-2);
  t.AddLink(pdu, brg, 3800.0, 0.002, "shaft_a");
  t.AddLink(brg, gbx, 3800.0, 0.002, "shaft_b");
  t.AddLink(gbx, flap, 5000.0, 0.0, "limiter");
  for (Reduction r : {Reduction::kFullResolution, Reduction::kAccumulated, Reduction::kTwoMassesPerSection}) {
    const LumpedModel m = BuildLumpedModel(t, r, 4);
    EXPECT_NEAR(m.TotalInertia(), t.TotalInertia(), 1e-15) << ToString(r);
  }
  // The bearing is merged away by the reduced rules: one series spring c/2 for the section.
  const LumpedModel accumulated = BuildLumpedModel(t, Reduction::kAccumulated);
  EXPECT_EQ(accumulated.nodes.size(), 3u);
  EXPECT_NEAR(accumulated.springs[0].c, 1900.0, 1e-9);
  EXPECT_EQ(accumulated.NodeOfPoint(brg), -1);
  const LumpedModel two = BuildLumpedModel(t, Reduction::kTwoMassesPerSection);
  EXPECT_EQ(two.nodes.size(), 5u);
}

TEST(LumpedModel, TwoMassesPerSectionBeatAccumulationOnAHeavyShaft) {
  // A station inertia at the tip of a shaft as heavy as the station: the accumulated rule
  // puts half the shaft at each end; Neumann's two masses keep more of the shaft's own mode.
  Transmission t;
  const int root = t.AddPoint("root", 0.0);
  const int station = t.AddPoint("station", 0.01);
  t.AddLink(root, station, 2000.0, 0.01, "shaft");
  const double reference = FirstClampedOmega(BuildLumpedModel(t, Reduction::kFullResolution, 64), 0);
  const double accumulated = FirstClampedOmega(BuildLumpedModel(t, Reduction::kAccumulated), 0);
  const double two_masses = FirstClampedOmega(BuildLumpedModel(t, Reduction::kTwoMassesPerSection), 0);
  EXPECT_LT(std::abs(two_masses / reference - 1.0), std::abs(accumulated / reference - 1.0));
  EXPECT_LT(std::abs(accumulated / reference - 1.0), 0.10);
  EXPECT_LT(std::abs(two_masses / reference - 1.0), 0.01);
}

TEST(LumpedModel, ReflectionScalesWithTheSquareOfTheSpeedRatio) {
  EXPECT_DOUBLE_EQ(Reflect(0.04, 0.5), 0.01);
  EXPECT_DOUBLE_EQ(Reflect(2e4, 0.5), 5e3);
}

TEST(LumpedModel, LoopIsAnInputErrorWithARemedy) {
  Transmission t;
  const int a = t.AddPoint("a", 1.0), b = t.AddPoint("b", 1.0);
  t.AddLink(a, b, 1.0, 0.0, "s1");
  t.AddLink(b, a, 1.0, 0.0, "s2");
  try {
    BuildLumpedModel(t, Reduction::kAccumulated);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("link 's2' closes a loop"), std::string::npos) << e.what();
  }
}

TEST(LumpedModel, NonPositiveStiffnessIsAnInputError) {
  Transmission t = BareShaft(0.0, 0.01);
  EXPECT_THROW(BuildLumpedModel(t, Reduction::kFullResolution), InputError);
}

TEST(LumpedModel, ReductionNamesRoundTrip) {
  for (Reduction r : {Reduction::kFullResolution, Reduction::kAccumulated, Reduction::kTwoMassesPerSection}) {
    Reduction back = Reduction::kFullResolution;
    ASSERT_TRUE(ReductionFromString(ToString(r), &back));
    EXPECT_EQ(back, r);
  }
  Reduction unused;
  EXPECT_FALSE(ReductionFromString("coarse", &unused));
}

}  // namespace
}  // namespace highlift::reduced_models
