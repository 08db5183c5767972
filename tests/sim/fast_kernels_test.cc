// The simulator's own serial vector kernels (sim/src/fast_kernels.h) against SUNDIALS'
// nvector_serial operations, bit for bit: the kernels promise the same doubles operation by
// operation (CVODE's steps, and so every answer, depend on it). z = a*x + b*y for every
// special case of the coefficients (1, -1, a == b, a == -b, the general one, signed zeros),
// with z a third vector, x itself or y itself; the linear combinations and the weighted norm.
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

TEST(FastKernels, CombinationsAndNormGiveSundialsDoubles) {
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
    // The weighted RMS norm of finite values (weights: |x| + 1).
    v.Set(2, Values(8));
    std::vector<double> w = Values(9);
    for (double& x : w) x = std::isfinite(x) ? std::abs(x) + 1.0 : 1.0;
    std::vector<double> x = Values(8);
    for (double& value : x) value = std::isfinite(value) ? value : 1.0;
    v.Set(1, w);
    v.Set(2, x);
    norms[k] = N_VWrmsNorm(v[2], v[1]);
  }
  for (int k : {0, 1, 3}) EXPECT_TRUE(SameBits(sundials.Get(k), ours.Get(k))) << "vector " << k;
  EXPECT_TRUE(SameDouble(norms[0], norms[1])) << norms[0] << " against " << norms[1];
}

}  // namespace
}  // namespace highlift::sim::detail
