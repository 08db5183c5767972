// Monotone black-box constraints: y = f(x1, x2) enclosed by corner evaluation, projected back.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "highlift/icsp/parser.h"
#include "highlift/icsp/propagator.h"

namespace highlift::icsp {
namespace {

/// The first eigenfrequency of a two-mass chain is a black box here: w = sqrt(c / J) rises with
/// the stiffness and falls with the inertia.
MonotoneFunction Frequency(int* calls = nullptr) {
  MonotoneFunction f;
  f.f = [calls](std::span<const double> x) {
    if (calls) ++*calls;
    return std::sqrt(x[0] / x[1]);
  };
  f.monotonicity = {Monotonicity::kIncreasing, Monotonicity::kDecreasing};
  return f;
}

TEST(Monotone, ForwardEnclosureUsesTheRightCorners) {
  Network net;
  const VariableId w = net.AddVariable("w", Whole());
  const VariableId c = net.AddVariable("c", Interval(100, 400));
  const VariableId J = net.AddVariable("J", Interval(1, 4));
  int calls = 0;
  net.AddMonotone(w, {c, J}, Frequency(&calls), {"f1", "first eigenfrequency", ConstraintRole::kPhysics});
  Box box = net.InitialBox();
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  EXPECT_NEAR(box[w.value].lower(), 5.0, 1e-9);   // sqrt(100 / 4)
  EXPECT_NEAR(box[w.value].upper(), 20.0, 1e-9);  // sqrt(400 / 1)
  EXPECT_LE(box[w.value].lower(), 5.0);
  EXPECT_GE(box[w.value].upper(), 20.0);
  EXPECT_GT(calls, 0);
}

TEST(Monotone, BackwardProjectionNarrowsArguments) {
  Network net;
  const VariableId w = net.AddVariable("w", Interval(15, 30));
  const VariableId c = net.AddVariable("c", Interval(100, 400));
  const VariableId J = net.AddVariable("J", Interval(1, 4));
  net.AddMonotone(w, {c, J}, Frequency(), {"f1", "", ConstraintRole::kPhysics});
  Box box = net.InitialBox();
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  // w >= 15 needs c >= 225 at J = 1 and J <= 400/225 = 1.777... at c = 400.
  EXPECT_NEAR(box[c.value].lower(), 225.0, 1e-6);
  EXPECT_LE(box[c.value].lower(), 225.0);
  EXPECT_NEAR(box[J.value].upper(), 400.0 / 225.0, 1e-6);
  EXPECT_GE(box[J.value].upper(), 400.0 / 225.0);
}

TEST(Monotone, SatisfyingPointsAreNeverExcluded) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double c0 = 50 + 500 * u(rng), J0 = 0.5 + 5 * u(rng);
    const double w0 = std::sqrt(c0 / J0);
    Network net;
    const VariableId w = net.AddVariable("w", Interval(w0 * (1 - 0.3 * u(rng)), w0 * (1 + 0.3 * u(rng))));
    const VariableId c = net.AddVariable("c", Interval(c0 * (1 - u(rng)), c0 * (1 + u(rng))));
    const VariableId J = net.AddVariable("J", Interval(J0 * (1 - 0.9 * u(rng)), J0 * (1 + u(rng))));
    net.AddMonotone(w, {c, J}, Frequency(), {"f1", "", ConstraintRole::kPhysics});
    Box box = net.InitialBox();
    ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint) << trial;
    EXPECT_TRUE(box[c.value].lower() <= c0 && c0 <= box[c.value].upper()) << trial;
    EXPECT_TRUE(box[J.value].lower() <= J0 && J0 <= box[J.value].upper()) << trial;
    EXPECT_TRUE(box[w.value].lower() <= w0 && w0 <= box[w.value].upper()) << trial;
  }
}

TEST(Monotone, ConflictWithAFormulaIsProved) {
  Network net;
  const VariableId w = net.AddVariable("w", Whole());
  const VariableId c = net.AddVariable("c", Interval(100, 400));
  const VariableId J = net.AddVariable("J", Interval(1, 4));
  net.AddMonotone(w, {c, J}, Frequency(), {"f1", "", ConstraintRole::kPhysics});
  AddConstraintText(net, "w >= 25", {"R1", "", ConstraintRole::kRequirement});
  Box box = net.InitialBox();
  EXPECT_EQ(Propagate(net, box).status, Status::kInfeasible);
}

TEST(Monotone, CostlyFunctionIsEvaluatedOnlyAtNewCorners) {
  // A black box such as an eigenvalue is costly: a revision whose corners did not move reuses the
  // last values, and a y that the box's image already fits needs no backward projection.
  Network net;
  const VariableId w = net.AddVariable("w", Whole());
  const VariableId c = net.AddVariable("c", Interval(100, 400));
  const VariableId J = net.AddVariable("J", Interval(1, 4));
  const VariableId k = net.AddVariable("k", Interval(0, 1000));
  int calls = 0;
  net.AddMonotone(w, {c, J}, Frequency(&calls), {"f1", "", ConstraintRole::kPhysics});
  AddConstraintText(net, "w <= 100", {"R1", "", ConstraintRole::kRequirement});  // never cuts [5, 20]
  AddConstraintText(net, "k == 2 * w", {"R2", "", ConstraintRole::kRequirement});  // revisits w
  Box box = net.InitialBox();
  const PropagationReport report = Propagate(net, box);
  ASSERT_EQ(report.status, Status::kFixedPoint);
  EXPECT_EQ(calls, 2);  // the two corners, once each
  EXPECT_NEAR(box[k.value].upper(), 40.0, 1e-9);
  // A y that cuts into the image still projects back (and evaluates more).
  AddConstraintText(net, "w >= 15", {"R3", "", ConstraintRole::kRequirement});
  box = net.InitialBox();
  calls = 0;
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  EXPECT_GT(calls, 2);
  EXPECT_NEAR(box[c.value].lower(), 225.0, 1e-6);
}

}  // namespace
}  // namespace highlift::icsp
