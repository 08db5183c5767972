// The outward rounding of model::Interval steps each bound by one unit in the last place with
// its own bit arithmetic (NextUp, NextDown): it must be std::nextafter bit for bit, including
// at zero, the subnormals, the largest finite doubles, the infinities and NaN.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "highlift/model/interval.h"

namespace highlift::model {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::uint64_t Bits(double x) { return std::bit_cast<std::uint64_t>(x); }

void ExpectSameAsLibrary(double x) {
  EXPECT_EQ(Bits(NextUp(x)), Bits(std::nextafter(x, kInf))) << "NextUp(" << x << ")";
  EXPECT_EQ(Bits(NextDown(x)), Bits(std::nextafter(x, -kInf))) << "NextDown(" << x << ")";
}

TEST(IntervalRounding, OneStepIsNextafterAtTheSpecialValues) {
  const double max = std::numeric_limits<double>::max(), min = std::numeric_limits<double>::min(),
               tiny = std::numeric_limits<double>::denorm_min();
  for (double x : {0.0, -0.0, tiny, -tiny, 2 * tiny, -2 * tiny, min, -min, min - tiny, -(min - tiny), max, -max,
                   kInf, -kInf, 1.0, -1.0, 0.1, -0.1, 1e300, -1e-300})
    ExpectSameAsLibrary(x);
  // NaN stays NaN, as std::nextafter's does.
  EXPECT_TRUE(std::isnan(NextUp(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(NextDown(std::numeric_limits<double>::quiet_NaN())));
}

TEST(IntervalRounding, OneStepIsNextafterOverRandomBitPatterns) {
  std::mt19937_64 random(20261206);
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    const double x = std::bit_cast<double>(random());
    if (std::isnan(x)) continue;
    ExpectSameAsLibrary(x);
    ++checked;
  }
  EXPECT_GT(checked, 199000);
}

TEST(IntervalRounding, TheBoundsEncloseTheExactSumAndKeepTheirSign) {
  // The doubles 0.1 and 0.2 add up exactly to 0.30000000000000001665..., rounded up to
  // 0.30000000000000004441...; the enclosure reaches one step below the rounded sum.
  const Interval s = Interval(0.1) + Interval(0.2);
  EXPECT_LT(s.lo, 0.1 + 0.2);
  EXPECT_GT(s.hi, 0.1 + 0.2);
  EXPECT_EQ(s.hi, NextUp(0.1 + 0.2));
  EXPECT_EQ(s.lo, NextDown(0.1 + 0.2));
  // A product of non-negative operands never reaches below zero.
  EXPECT_EQ((Interval(0.0) * Interval(2.0, 3.0)).lo, 0.0);
  EXPECT_EQ(Down(1.0, 2), NextDown(NextDown(1.0)));
}

}  // namespace
}  // namespace highlift::model
