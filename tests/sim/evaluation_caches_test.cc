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

}  // namespace
}  // namespace highlift::sim::detail
