// The simulator's own serial vector kernels (sim/src/fast_kernels.h) against SUNDIALS'
// nvector_serial operations, bit for bit: the kernels promise the same doubles operation by
// operation (CVODE's steps, and so every answer, depend on it). z = a*x + b*y for every
// special case of the coefficients (1, -1, a == b, a == -b, the general one, signed zeros),
// with z a third vector, x itself or y itself; the linear combinations. The weighted norms add
// their squares in eight partial sums (element i to sum i mod 8, the sums pairwise), not in
// SUNDIALS' one running sum: the same doubles as that order written out, within a few ulps of
// SUNDIALS' norm.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "fast_kernels.h"
#include "sundials_compat.h"

namespace highlift::sim::detail {
namespace {

constexpr int kLength = 37;  // not a multiple of the vector width: the loops' tails run too

// Values with every sign, magnitudes far apart, zeros of both signs, subnormals and infinities:
// a*(x + y) and a*x + b*y round differently on them.
std::vector<double> Values(int seed) {
  std::vector<double> v(kLength);
  for (int i = 0; i < kLength; ++i) {
    const double s = ((i * 7 + seed * 13) % 11) - 5.0;
    v[i] = s * std::pow(10.0, ((i + seed) % 9) - 4) / 3.0;
  }
  v[3] = 0.0;
  v[4] = -0.0;
  v[5] = std::numeric_limits<double>::denorm_min() * (seed + 1);
  v[6] = seed % 2 ? std::numeric_limits<double>::infinity() : 1e308;
  return v;
}

class Vectors {
 public:
  explicit Vectors(bool fast) {
    for (N_Vector& v : v_) {
      v = N_VNew_Serial(kLength, ctx_);
      if (fast) InstallFastVectorOps(v);
    }
  }
  ~Vectors() {
    for (N_Vector v : v_) N_VDestroy(v);
  }
  Vectors(const Vectors&) = delete;
  Vectors& operator=(const Vectors&) = delete;
  N_Vector operator[](int k) const { return v_[k]; }
  void Set(int k, const std::vector<double>& values) const {
    std::memcpy(N_VGetArrayPointer(v_[k]), values.data(), sizeof(double) * kLength);
  }
  std::vector<double> Get(int k) const {
    const double* d = N_VGetArrayPointer(v_[k]);
    return std::vector<double>(d, d + kLength);
  }

 private:
  SundialsContext ctx_;
  N_Vector v_[4] = {nullptr, nullptr, nullptr, nullptr};
};

// The same doubles, bit for bit; a NaN matches any NaN (the sign and payload of a NaN depend on
// the order in which a compiler puts the operands of a commutative operation, and nothing reads
// them: a NaN fails the step).
bool SameDouble(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof(double)) == 0;
}

bool SameBits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!SameDouble(a[i], b[i])) return false;
  return true;
}

std::string Show(const std::vector<double>& a, const std::vector<double>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!SameDouble(a[i], b[i]))
      return "first difference at " + std::to_string(i) + ": " + std::to_string(a[i]) + " against " +
             std::to_string(b[i]);
  return "";
}

TEST(FastKernels, LinearSumGivesSundialsDoublesInEveryCase) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> coefficients = {1.0, -1.0, 2.5, -2.5, 0.0, -0.0, 1e-300, -3.0, nan};
  const Vectors sundials(false), ours(true);
  int cases = 0;
  for (double a : coefficients)
    for (double b : coefficients)
      for (int target : {2, 0, 1}) {  // z: a third vector, x, y
        for (const Vectors* v : {&sundials, &ours}) {
          v->Set(0, Values(1));
          v->Set(1, Values(2));
          v->Set(2, Values(3));
          N_VLinearSum(a, (*v)[0], b, (*v)[1], (*v)[target]);
        }
        const std::vector<double> want = sundials.Get(target), got = ours.Get(target);
        EXPECT_TRUE(SameBits(want, got)) << "a = " << a << ", b = " << b << ", z = vector " << target << ": "
                                         << Show(want, got);
        ++cases;
      }
  EXPECT_EQ(cases, 9 * 9 * 3);
}

TEST(FastKernels, CombinationsGiveSundialsDoublesAndTheNormItsOwnOrder) {
  const Vectors sundials(false), ours(true);
  double norms[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    const Vectors& v = k == 0 ? sundials : ours;
    v.Set(0, Values(4));
    v.Set(1, Values(5));
    v.Set(2, Values(6));
    v.Set(3, Values(7));
    // z = 1*z + c1*x1 + c2*x2 (CVODE's corrector update), then z = c0*x0 + c1*x1.
    N_Vector in_place[3] = {v[3], v[0], v[1]};
    double c3[3] = {1.0, -0.75, 1.0 / 3.0};
    N_VLinearCombination(3, c3, in_place, v[3]);
    N_Vector two[2] = {v[0], v[1]};
    double c2[2] = {0.5, -2.0};
    N_VLinearCombination(2, c2, two, v[2]);
    // Z[k] = a[k]*x + Y[k].
    N_Vector Y[2] = {v[0], v[1]}, Z[2] = {v[0], v[1]};
    double a[2] = {-1.25, 3.0};
    N_VScaleAddMulti(2, a, v[2], Y, Z);
    // The weighted RMS norm of finite values whose squares are finite (weights: |x| + 1).
    v.Set(2, Values(8));
    std::vector<double> w = Values(9);
    for (double& x : w) x = std::isfinite(x) ? std::abs(x) + 1.0 : 1.0;
    std::vector<double> x = Values(8);
    for (double& value : x) value = std::abs(value) < 1e100 ? value : 1.0;  // (squares that do not overflow)
    v.Set(1, w);
    v.Set(2, x);
    norms[k] = N_VWrmsNorm(v[2], v[1]);
  }
  for (int k : {0, 1, 3}) EXPECT_TRUE(SameBits(sundials.Get(k), ours.Get(k))) << "vector " << k;
  // The norm in the partial sums' order, written out.
  const std::vector<double> x = ours.Get(2), w = ours.Get(1);
  double partial[8] = {};
  for (int i = 0; i < kLength; ++i) partial[i % 8] += (x[i] * w[i]) * (x[i] * w[i]);
  const double in_order =
      std::sqrt((((partial[0] + partial[4]) + (partial[1] + partial[5])) +
                 ((partial[2] + partial[6]) + (partial[3] + partial[7]))) / kLength);
  EXPECT_TRUE(SameDouble(in_order, norms[1])) << in_order << " against " << norms[1];
  EXPECT_NE(norms[0], 0.0);
  EXPECT_LE(std::abs(norms[1] - norms[0]), 4.0 * std::numeric_limits<double>::epsilon() * norms[0])
      << norms[0] << " against " << norms[1];
}

// Data on which the order of the additions shows: one running sum, eight partial sums added
// pairwise, the same eight added in a row, and four partial sums each give another double. The
// norm is the pairwise one's.
TEST(FastKernels, NormAddsInItsOwnOrder) {
  const Vectors ours(true);
  std::vector<double> x(kLength), w(kLength);
  for (int i = 0; i < kLength; ++i) {
    x[i] = std::sin(44.0 * i + 1.0) * std::pow(10.0, (44 * i) % 7 - 3);
    w[i] = 1.0 / (1.0 + 0.1 * i);
  }
  ours.Set(0, x);
  ours.Set(1, w);
  double running = 0.0, eight[8] = {}, four[4] = {};
  for (int i = 0; i < kLength; ++i) {
    const double p = x[i] * w[i];
    running += p * p;
    eight[i % 8] += p * p;
    four[i % 4] += p * p;
  }
  const double pairwise = ((eight[0] + eight[4]) + (eight[1] + eight[5])) + ((eight[2] + eight[6]) + (eight[3] + eight[7]));
  double in_a_row = 0.0;
  for (double e : eight) in_a_row += e;
  const double by_four = (four[0] + four[2]) + (four[1] + four[3]);
  ASSERT_NE(pairwise, running);
  ASSERT_NE(pairwise, in_a_row);
  ASSERT_NE(pairwise, by_four);
  EXPECT_TRUE(SameDouble(std::sqrt(pairwise / kLength), N_VWrmsNorm(ours[0], ours[1])));
}

// The masked norm (N_VWrmsNormMask) adds only the elements whose id is positive, in the same
// partial sums: an element masked out counts for nothing, even where it is not finite.
TEST(FastKernels, MaskedNormLeavesTheMaskedElementsOut) {
  const Vectors ours(true);
  std::vector<double> x = Values(3), w(kLength), id(kLength);
  for (int i = 0; i < kLength; ++i) {
    w[i] = 1.0 + 0.1 * i;
    id[i] = i % 3 == 0 ? 0.0 : 1.0;
    if (i % 3 == 0) x[i] = std::numeric_limits<double>::quiet_NaN();
  }
  for (double& value : x)
    if (!std::isnan(value) && !std::isfinite(value)) value = 2.0;
  ours.Set(0, x);
  ours.Set(1, w);
  ours.Set(2, id);
  double partial[8] = {};
  for (int i = 0; i < kLength; ++i)
    if (id[i] > 0.0) partial[i % 8] += (x[i] * w[i]) * (x[i] * w[i]);
  const double expected =
      std::sqrt((((partial[0] + partial[4]) + (partial[1] + partial[5])) +
                 ((partial[2] + partial[6]) + (partial[3] + partial[7]))) / kLength);
  const double got = N_VWrmsNormMask(ours[0], ours[1], ours[2]);
  EXPECT_TRUE(SameDouble(expected, got)) << expected << " against " << got;
  EXPECT_TRUE(std::isfinite(got));
}

// CVODE's error weights for a vector of absolute tolerances, as its cvEwtSetSV forms them with
// SUNDIALS' own operations (N_VAbs, N_VLinearSum(rtol, |y|, 1, atol), N_VInv), against
// ErrorWeights' one pass: the same doubles for every value of y (signed zeros, subnormals,
// infinities) and for relative tolerances of 1 (N_VLinearSum's x + y case) and others.
TEST(FastKernels, ErrorWeightsAreCvodesThreePasses) {
  const Vectors sundials(false);
  int cases = 0;
  for (double rtol : {1e-6, 1e-8, 0.3, 1.0}) {
    for (int seed = 0; seed < 4; ++seed) {
      std::vector<double> y = Values(seed), atol(kLength);
      for (int i = 0; i < kLength; ++i) atol[i] = 1e-9 * (1.0 + (i * 5 + seed) % 7) + (i % 4 == 0 ? 1e-300 : 0.0);
      sundials.Set(0, y);
      sundials.Set(1, atol);
      N_VAbs(sundials[0], sundials[2]);
      N_VLinearSum(rtol, sundials[2], 1.0, sundials[1], sundials[2]);
      N_VInv(sundials[2], sundials[3]);
      std::vector<double> ewt(kLength);
      for (bool has_zero : {false, true}) {
        ASSERT_TRUE(ErrorWeights(kLength, rtol, atol.data(), has_zero, y.data(), ewt.data()));
        EXPECT_TRUE(SameBits(sundials.Get(3), ewt)) << "rtol " << rtol << ", seed " << seed << ": "
                                                     << Show(sundials.Get(3), ewt);
        ++cases;
      }
    }
  }
  EXPECT_EQ(cases, 4 * 4 * 2);
}

// With an absolute tolerance of 0, a state at 0 has no weight: CVODE then fails (N_VMin of
// rtol |y| + atol not positive), and so does ErrorWeights; a nonzero state keeps it defined.
TEST(FastKernels, ErrorWeightsFailWhereAZeroToleranceMeetsAZeroState) {
  std::vector<double> atol(kLength, 1e-6), y(kLength, 0.5), ewt(kLength);
  atol[9] = 0.0;
  EXPECT_TRUE(ErrorWeights(kLength, 1e-6, atol.data(), true, y.data(), ewt.data()));
  EXPECT_EQ(ewt[9], 1.0 / (1e-6 * 0.5));
  y[9] = -0.0;
  EXPECT_FALSE(ErrorWeights(kLength, 1e-6, atol.data(), true, y.data(), ewt.data()));
  y[9] = 0.0;
  y[10] = 0.0;
  EXPECT_FALSE(ErrorWeights(kLength, 1e-6, atol.data(), true, y.data(), ewt.data()));
}

}  // namespace
}  // namespace highlift::sim::detail
