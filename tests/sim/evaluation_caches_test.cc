// The evaluation caches and shortcuts of the simulator's internals (sim/src/model.h): Memo
// recognises the arguments of the last call bit for bit; ConstraintEntries keeps up to four
// entries inside the constraint and spills more, in order; LossyGear's law is reused only within
// one evaluation point (Eval::point), mode and quadrant; a table read near its last interval
// reads what a search from the start reads; SmoothSign is tanh within two ulps; the Stribeck peak
// and SpringDamper's direct law are the products they replace. The simulator's results do not
// depend on either (the campaign and peak tests compare them); these pin down the cases the
// models rarely reach.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "brake_elements.h"
#include "highlift/sim/network.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {
namespace {

TEST(Memo, SameOnlyForBitIdenticalArguments) {
  Memo<2> memo;
  EXPECT_FALSE(memo.Same({1.0, 2.0}));  // the first call
  EXPECT_TRUE(memo.Same({1.0, 2.0}));
  EXPECT_FALSE(memo.Same({1.0, std::nextafter(2.0, 3.0)}));
  EXPECT_FALSE(memo.Same({1.0, 2.0}));  // only the last arguments are remembered
  EXPECT_FALSE(memo.Same({0.0, 2.0}));
  EXPECT_FALSE(memo.Same({-0.0, 2.0}));  // equal, but tanh(-0) = -0: not the same call
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(memo.Same({nan, 2.0}));
  EXPECT_TRUE(memo.Same({nan, 2.0}));  // the same bits give the same value of a pure function
}

// A table read from the interval of its last read finds the interval InterpolatePoints finds
// from the start, so the same value bit for bit: along a sweep up and down, with jumps, at the
// knots, outside the table on both sides, at infinities and NaN, also on a table with a repeated
// abscissa (nondecreasing) and on tables of one and two points.
TEST(InterpolatePointsNear, ReadsTheValueInterpolatePointsReads) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<double>> abscissae{
      {0.0}, {0.0, 1.0}, {-2.0, -1.0, 0.5, 3.0, 4.0, 10.0}, {0.0, 1.0, 1.0, 2.0, 5.0}};
  for (const std::vector<double>& xs : abscissae) {
    std::vector<double> ys;
    for (std::size_t i = 0; i < xs.size(); ++i) ys.push_back(std::sin(3.0 * static_cast<double>(i) + 0.3));
    std::vector<double> queries;
    for (int k = 0; k <= 60; ++k) queries.push_back(-4.0 + 0.25 * k);  // up, across every knot
    for (int k = 60; k >= 0; --k) queries.push_back(-4.0 + 0.25 * k + 0.01);  // and down
    for (double x : {11.0, -3.0, 4.0, 1.0, 1.0, 0.5, -inf, inf, nan, 2.0, nan, -2.0, 10.0, 3.0}) queries.push_back(x);
    for (double x : xs) queries.push_back(x);
    std::size_t hint = 0;
    auto x_at = [&](std::size_t i) { return xs[i]; };
    auto y_at = [&](std::size_t i) { return ys[i]; };
    for (double x : queries) {
      const double expected = InterpolatePoints(xs.size(), x_at, y_at, x);
      const double near = InterpolatePointsNear(xs.size(), x_at, y_at, x, hint);
      EXPECT_EQ(std::bit_cast<std::uint64_t>(near), std::bit_cast<std::uint64_t>(expected))
          << xs.size() << " points, x = " << x;
      EXPECT_LT(hint + 1, std::max<std::size_t>(xs.size(), 2));
    }
  }
}

// SmoothSign is tanh by Cody and Waite's formulas, inline: within two ulps of std::tanh
// everywhere it computes (odd, the sign of a zero kept, NaN for NaN), +-1 beyond |x| = 20, and
// monotone across the switches between its formulas (a friction law that dips where the formula
// changes would have a speed of negative slope).
TEST(SmoothSign, IsTanhWithinTwoUlps) {
  auto ulps = [](double a, double b) {
    if (a == b) return 0.0;
    return std::abs(a - b) / std::abs(std::nextafter(b, 2.0 * b) - b);
  };
  std::vector<double> xs = {0x1p-60, 0x1p-27, std::nextafter(0x1p-27, 0.0), 1e-9, 0.3, 0.54930614433405484570,
                            std::nextafter(0.54930614433405484570, 1.0), 1.0, 1.5, 7.0, 19.99, 20.0,
                            std::numeric_limits<double>::denorm_min()};
  for (double x = 1e-9; x < 20.0; x *= 1.001) xs.push_back(x);
  double worst = 0.0;
  for (double x : xs)
    for (double v : {x, -x}) {
      worst = std::max(worst, ulps(SmoothSign(v), std::tanh(v)));
      EXPECT_EQ(SmoothSign(-v), -SmoothSign(v)) << v;
    }
  EXPECT_LE(worst, 2.0);
  EXPECT_GT(worst, 0.0);  // (not the library's function: the test would pass by itself)
  for (double edge : {0x1p-27, 0.54930614433405484570, 20.0}) {
    double x = edge;
    for (int k = 0; k < 1000; ++k) x = std::nextafter(x, 0.0);
    double before = SmoothSign(x);
    for (int k = 0; k < 2000; ++k) {
      x = std::nextafter(x, 100.0);
      const double now = SmoothSign(x);
      EXPECT_GE(now, before) << "x = " << x;
      before = now;
    }
  }
  EXPECT_EQ(SmoothSign(25.0), 1.0);
  EXPECT_EQ(SmoothSign(-25.0), -1.0);
  EXPECT_FALSE(std::signbit(SmoothSign(0.0)));
  EXPECT_TRUE(std::signbit(SmoothSign(-0.0)));
  EXPECT_TRUE(std::isnan(SmoothSign(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_GT(SmoothSign(0.5), 0.0);
  EXPECT_LT(SmoothSign(-0.5), 0.0);
}

TEST(ConstraintEntries, InlineAndSpilledEntriesKeepTheirOrder) {
  ConstraintEntries entries = {{1, 1.0}, {2, -2.0}, {3, 0.5}};
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[1], (std::pair<int, double>{2, -2.0}));
  for (int node = 4; node <= 6; ++node) entries.push_back({node, node * 1.0});  // beyond the inline four
  ASSERT_EQ(entries.size(), 6u);
  int expected = 1;
  for (const auto& [node, coef] : entries) EXPECT_EQ(node, expected++);
  EXPECT_EQ(entries[4].second, 5.0);
  const ConstraintEntries copy = entries;
  ASSERT_EQ(copy.size(), 6u);
  EXPECT_EQ(copy[5], (std::pair<int, double>{6, 6.0}));

  entries.clear();
  EXPECT_TRUE(entries.empty());
  entries = {{7, 7.0}};
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries.begin()->first, 7);
  entries.assign({{1, 1.0}, {2, 2.0}, {3, 3.0}, {4, 4.0}, {5, 5.0}});  // spilled at once
  ASSERT_EQ(entries.size(), 5u);
  EXPECT_EQ(entries[4].first, 5);
  entries.clear();  // inline again; a later spill starts from the inline entries
  for (int node = 1; node <= 5; ++node) entries.push_back({10 + node, 0.0});
  ASSERT_EQ(entries.size(), 5u);
  expected = 11;
  for (const auto& [node, coef] : entries) EXPECT_EQ(node, expected++);
}

// A LossyGear on nodes 0 (flange_a), 1 (flange_b) and 2 (support) whose loss table differs
// between |w_a| = 0 and 10 (efficiencies 0.9/0.8 to 0.5/0.4, bearing friction 2/1 to 4/3 N*m).
std::unique_ptr<msl::LossyGear> TwoSpeedLossyGear() {
  model::NetworkElement element;
  element.id = "gear";
  element.type = "LossyGear";
  element.parameters = {{{"ratio", 2.0}}, {{"lossTable", {{0, 0.9, 0.8, 2, 1}, {10, 0.5, 0.4, 4, 3}}}}};
  auto gear = std::make_unique<msl::LossyGear>(element);
  gear->Bind([](const std::string& port) { return port == "flange_a" ? 0 : (port == "flange_b" ? 1 : 2); },
             [](const std::string&) { return -1; });
  return gear;
}

// The phases of one evaluation (forces, constraint, loss after the solve) share the law of a
// point; a new point, another quadrant or mode computes it afresh, and an Eval set up by hand
// (point 0) never reuses it. (System does not change the speeds within a point; the test does,
// to see which law is returned.)
TEST(LossyGearLaw, ReusedOnlyAtTheSamePointModeAndQuadrant) {
  const auto owned = TwoSpeedLossyGear();
  msl::LossyGear& gear = *owned;
  gear.mode = msl::kForward;
  gear.quadrant = 1;
  Eval e;
  e.phi = {0.0, 0.0, 0.0};
  e.w = {1.0, 0.5, 0.0};
  auto law = [&] {
    double k = 0.0, c0 = 0.0;
    gear.Law(e, k, c0);
    return std::pair{k, c0};
  };
  auto fresh = [&] {
    double k = 0.0, c0 = 0.0;
    gear.LawAt(e, k, c0);
    return std::pair{k, c0};
  };
  const auto slow = law();
  e.w[0] = 5.0;
  const auto fast = fresh();
  ASSERT_NE(fast, slow);   // the loss table differs at the two speeds
  EXPECT_EQ(law(), fast);  // point 0: computed afresh

  e.point = 1;
  EXPECT_EQ(law(), fast);
  e.w[0] = 1.0;
  EXPECT_EQ(law(), fast);  // the same point: the law of its first phase
  gear.quadrant = -1;
  EXPECT_EQ(law(), fresh());  // a pass after Reassume flipped the quadrant
  EXPECT_NE(law(), slow);
  gear.mode = msl::kBackward;
  EXPECT_EQ(law(), fresh());
  gear.mode = msl::kForward;
  gear.quadrant = 1;
  e.point = 2;
  EXPECT_EQ(law(), slow);  // a new point
}

// Reassume, after the solve, reads the quadrant boundary bf_a that the law read at the same
// point and mode (LawAt) instead of the coefficients again; at a new point, at point 0 (an Eval
// set up by hand) or in another mode it reads them afresh. The loss table's boundary is
// bf_a = (bf1 - bf2) / (eta1 - 1/eta2): -2.19 N*m at |w_a| = 1, -1.03 N*m at 5, so with
// tau_a = -1.5 N*m the forward quadrant holds at 1 (tau_a - bf_a = +0.69) and not at 5 (-0.47).
// (System does not change the speeds within a point; the test does, to see which is read.)
TEST(LossyGearLaw, ReassumeReadsTheBoundaryOfTheLawAtItsPoint) {
  const auto owned = TwoSpeedLossyGear();
  msl::LossyGear& gear = *owned;
  gear.w_small = 1e-3;  // regularised: the quadrant is assumed and checked after the solve
  ASSERT_TRUE(gear.HasAssumptions());
  gear.mode = msl::kForward;
  gear.tau_a = -1.5;
  Eval e;
  e.phi = {0.0, 0.0, 0.0};
  e.w = {1.0, 0.5, 0.0};
  auto law_at_point = [&](std::uint64_t point) {
    e.point = point;
    e.w[0] = 1.0;
    double k = 0.0, c0 = 0.0;
    gear.Law(e, k, c0);
    e.w[0] = 5.0;
  };
  gear.quadrant = 1;
  law_at_point(1);
  EXPECT_FALSE(gear.Reassume(e));  // the boundary the law read at |w_a| = 1
  EXPECT_EQ(gear.quadrant, 1);
  e.point = 2;
  EXPECT_TRUE(gear.Reassume(e));  // a new point: the boundary at 5
  EXPECT_EQ(gear.quadrant, -1);

  gear.quadrant = 1;
  law_at_point(0);
  EXPECT_TRUE(gear.Reassume(e));  // point 0 reuses nothing
  gear.quadrant = 1;
  law_at_point(3);
  gear.mode = msl::kBackward;  // another mode at the same point: afresh (w_a > 0 still rolls forward)
  EXPECT_TRUE(gear.Reassume(e));
}

// A regularised StribeckFriction on one node (flange_a = flange_b) applies the smooth law
// tanh(w/w_small)*(tau_C + tau_S*exp(-f_exp*|w|)) + d_vis*w computed afresh for every new w (the
// same doubles, a -0 law too), sets tau (+0.0 as after the solve) in Forces, and leaves its
// phase after the solve to the system; with the load loss (two nodes) it keeps that phase.
TEST(StribeckFrictionLaw, OneNodeRegularisedTakesTauInForces) {
  auto element = [](double eta_GE) {
    Network scratch;
    scratch.AddElement("StribeckFriction", "f",
                       ElementParameters{{{"tau_C", 2.0}, {"tau_S", 1.5}, {"f_exp", 3.0}, {"d_vis", 0.25},
                                          {"w_small", 0.1}, {"eta_GE", eta_GE}},
                                         {}});
    return scratch.elements().front();
  };
  StribeckFriction friction(element(1.0), false);
  ASSERT_TRUE(friction.regularized);
  ASSERT_FALSE(friction.split);
  // flange_a and flange_b on node 0 (as one node after RigidFlanges), the support on node 1.
  friction.Bind([](const std::string& port) { return port == "support" ? 1 : 0; },
                [](const std::string&) { return -1; });
  Eval e;
  e.phi = {0.0, 0.0};
  auto law = [](double w) {
    return SmoothSign(w / 0.1) * (2.0 + 1.5 * std::exp(-(3.0 * std::abs(w)))) + 0.25 * w;
  };
  for (double w : {0.03, -0.4, 0.03, 25.0, -0.0}) {
    e.w = {w, 0.0};
    e.force = {1.0, -1.0};
    friction.Forces(e);
    const double expected = law(w);
    EXPECT_EQ(e.force[0], 1.0 - expected) << "w = " << w;
    EXPECT_EQ(e.force[1], -1.0 + expected) << "w = " << w;
    EXPECT_EQ(friction.tau_stribeck, expected);
    EXPECT_EQ(friction.tau, expected + 0.0);
  }
  EXPECT_TRUE(std::signbit(friction.tau_stribeck));  // tanh(-0) = -0: the law keeps the sign
  EXPECT_FALSE(std::signbit(friction.tau));          // tau as after the solve: +0
  friction.AfterSolve(e);
  EXPECT_FALSE(std::signbit(friction.tau));
  EXPECT_TRUE(friction.unused_phases & Element::kAfterSolvePhase);

  StribeckFriction lossy(element(0.9), false);
  ASSERT_TRUE(lossy.split);
  lossy.Bind([](const std::string& port) { return port == "flange_a" ? 0 : (port == "flange_b" ? 1 : 2); },
             [](const std::string&) { return -1; });
  e.phi = {0.0, 0.0, 0.0};
  e.w = {0.2, 0.2, 0.0};
  e.force = {0.0, 0.0, 0.0};
  lossy.Forces(e);
  lossy.AfterSolve(e);
  EXPECT_FALSE(lossy.unused_phases & Element::kAfterSolvePhase);
}

// The Stribeck peak's share tau_S*exp(-x) leaves the library call out for a law without a peak
// (tau_S = 0: the drags of a drive model's shaft elements) and is the product bit for bit,
// including the sign of a zero; a regularised drag with tau_S = 0 is the law with that product.
TEST(StribeckFrictionLaw, NoPeakIsTheProductWithoutTheExponential) {
  for (double tau_S : {0.0, -0.0, 1.5, -2.0})
    for (double x : {0.0, 0.3, 12.0, 39.9, 40.5, std::numeric_limits<double>::infinity()}) {
      const double product = tau_S * Decay(x);
      EXPECT_EQ(StribeckPeak(tau_S, x), product) << "tau_S = " << tau_S << ", x = " << x;
      EXPECT_EQ(std::signbit(StribeckPeak(tau_S, x)), std::signbit(product)) << tau_S << ", " << x;
    }
  Network scratch;
  scratch.AddElement("LossyInertia", "drag",
                     ElementParameters{{{"J", 0.01}, {"tau_C", 0.8}, {"tau_S", 0.0}, {"f_exp", 3.0},
                                        {"d_vis", 0.0}, {"w_small", 0.1}},
                                       {}});
  StribeckFriction drag(scratch.elements().front(), true);
  ASSERT_TRUE(drag.regularized);
  drag.Bind([](const std::string& port) { return port == "support" ? 1 : 0; },
            [](const std::string&) { return -1; });
  Eval e;
  e.phi = {0.0, 0.0};
  for (double w : {0.03, -0.4, 25.0, -0.0}) {
    e.w = {w, 0.0};
    e.force = {0.0, 0.0};
    drag.Forces(e);
    const double expected = SmoothSign(w / 0.1) * (0.8 + 0.0 * std::exp(-(3.0 * std::abs(w)))) + 0.0 * w;
    EXPECT_EQ(drag.tau_stribeck, expected) << "w = " << w;
    EXPECT_EQ(e.force[0], -expected) << "w = " << w;
  }
}

// SpringDamper applies its law directly (not through Compliant's virtual Tau): the torque
// c*(phi_rel - phi_rel0) + d*w_rel on both flanges and the loss power d*w_rel^2 of the general
// Compliant formula (tau - spring torque)*w_rel, bit for bit.
TEST(SpringDamperLaw, DirectLawIsCompliantsLaw) {
  Network scratch;
  scratch.AddElement("SpringDamper", "k", ElementParameters{{{"c", 2.0e4}, {"d", 3.5}, {"phi_rel0", 0.01}}, {}});
  msl::SpringDamper spring(scratch.elements().front());
  spring.Bind([](const std::string& port) { return port == "flange_a" ? 0 : 1; },
              [](const std::string&) { return -1; });
  spring.state_offset = 0;
  for (auto [phi, wa, wb] : {std::tuple{0.02, 1.0, 1.5}, std::tuple{-0.3, 12.0, -4.0}, std::tuple{0.01, 0.0, 0.0}}) {
    const double y[] = {phi};
    Eval e;
    e.y = y;
    e.phi = {0.0, 0.0};
    e.w = {wa, wb};
    e.force = {0.25, -0.5};
    spring.Forces(e);
    const double tau = 2.0e4 * (phi - 0.01) + 3.5 * (wb - wa);
    EXPECT_EQ(spring.tau, tau);
    EXPECT_EQ(spring.tau, spring.Tau(phi, wb - wa));
    EXPECT_EQ(e.force[0], 0.25 + tau);
    EXPECT_EQ(e.force[1], -0.5 - tau);
    EXPECT_EQ(spring.LossPower(e), (tau - spring.SpringTorque(phi)) * (wb - wa));
    EXPECT_EQ(spring.PeakTorque(e), tau);
  }
}

}  // namespace
}  // namespace highlift::sim::detail
