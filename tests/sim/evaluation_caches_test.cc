// The evaluation caches of the simulator's internals (sim/src/model.h): Memo recognises the
// arguments of the last call bit for bit; ConstraintEntries keeps up to four entries inside the
// constraint and spills more, in order; LossyGear's law is reused only within one evaluation
// point (Eval::point), mode and quadrant. The simulator's results do not depend on either (the
// campaign and peak tests compare them); these pin down the cases the models rarely reach.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

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

// The phases of one evaluation (forces, constraint, loss after the solve) share the law of a
// point; a new point, another quadrant or mode computes it afresh, and an Eval set up by hand
// (point 0) never reuses it. (System does not change the speeds within a point; the test does,
// to see which law is returned.)
TEST(LossyGearLaw, ReusedOnlyAtTheSamePointModeAndQuadrant) {
  model::NetworkElement element;
  element.id = "gear";
  element.type = "LossyGear";
  element.parameters = {{{"ratio", 2.0}}, {{"lossTable", {{0, 0.9, 0.8, 2, 1}, {10, 0.5, 0.4, 4, 3}}}}};
  msl::LossyGear gear(element);
  gear.Bind([](const std::string& port) { return port == "flange_a" ? 0 : (port == "flange_b" ? 1 : 2); },
            [](const std::string&) { return -1; });
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
    return std::tanh(w / 0.1) * (2.0 + 1.5 * std::exp(-(3.0 * std::abs(w)))) + 0.25 * w;
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

}  // namespace
}  // namespace highlift::sim::detail
