// A minimal outward-rounded interval for the component laws (model/laws.h, the reduced models). Every operation computes the
// bounds in round-to-nearest and then widens each bound by one ulp (two for library functions),
// which encloses the exact result because IEEE operations are correctly rounded and glibc's exp,
// log, sqrt and tanh are accurate to within an ulp. Kept small on purpose: the laws here need
// +, -, *, / by positive intervals, exp, log, sqrt, tanh, abs and hull; nothing else.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

#include "highlift/core/domain.h"
#include "highlift/core/error.h"

namespace highlift::model {

struct Interval {
  double lo = 0.0;
  double hi = 0.0;

  Interval() = default;
  Interval(double value) : lo(value), hi(value) {}  // NOLINT: implicit from a point by design
  Interval(double l, double h) : lo(l), hi(h) {
    HIGHLIFT_CHECK(!(l > h), "interval lower bound above upper bound");
  }
  static Interval FromDomain(const Domain& d) { return {d.lo, d.hi}; }
  Domain ToDomain() const { return {lo, hi}; }
  double mid() const { return 0.5 * (lo + hi); }
  double width() const { return hi - lo; }
  bool contains(double v) const { return lo <= v && v <= hi; }
};

/// The next double above x: std::nextafter(x, +infinity), bit for bit, without the library call
/// (17 % of `highlift peak` went into it). IEEE doubles of one sign are ordered as their bit
/// patterns, so one step is one unit in the last place of the pattern.
inline double NextUp(double x) {
  if (std::isnan(x) || x == std::numeric_limits<double>::infinity()) return x;
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();  // from +0 and from -0
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0.0 ? bits + 1 : bits - 1);
}
/// The next double below x: std::nextafter(x, -infinity), bit for bit.
inline double NextDown(double x) { return std::isnan(x) ? x : -NextUp(-x); }

inline double Down(double x, int ulps = 1) {
  for (int i = 0; i < ulps; ++i) x = NextDown(x);
  return x;
}
inline double Up(double x, int ulps = 1) {
  for (int i = 0; i < ulps; ++i) x = NextUp(x);
  return x;
}
inline Interval Outward(double lo, double hi, int ulps = 1) { return {Down(lo, ulps), Up(hi, ulps)}; }

/// Outward rounding that keeps a sign the operands prove: the sum, product or quotient of
/// non-negative numbers is non-negative, so its lower bound never drops below zero (a zero
/// inertia times a speed ratio stays an exact zero, not -5e-324).
inline Interval OutwardNonNegative(bool non_negative, double lo, double hi) {
  Interval r = Outward(lo, hi);
  if (non_negative && r.lo < 0.0) r.lo = 0.0;
  return r;
}

inline Interval operator+(const Interval& a, const Interval& b) {
  return OutwardNonNegative(a.lo >= 0.0 && b.lo >= 0.0, a.lo + b.lo, a.hi + b.hi);
}
inline Interval operator-(const Interval& a, const Interval& b) { return Outward(a.lo - b.hi, a.hi - b.lo); }
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
inline Interval operator*(const Interval& a, const Interval& b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return OutwardNonNegative(a.lo >= 0.0 && b.lo >= 0.0, *std::min_element(p, p + 4), *std::max_element(p, p + 4));
}
/// y = a / b, defined for denominators that do not contain zero (ratios, efficiencies, J, c).
inline Interval operator/(const Interval& a, const Interval& b) {
  HIGHLIFT_CHECK(b.lo > 0.0 || b.hi < 0.0, "interval division by an interval containing zero");
  const double q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  return OutwardNonNegative(a.lo >= 0.0 && b.lo > 0.0, *std::min_element(q, q + 4), *std::max_element(q, q + 4));
}
inline Interval& operator+=(Interval& a, const Interval& b) { return a = a + b; }
inline Interval& operator-=(Interval& a, const Interval& b) { return a = a - b; }
inline Interval& operator*=(Interval& a, const Interval& b) { return a = a * b; }

inline Interval exp(const Interval& x) { return {std::max(0.0, Down(std::exp(x.lo), 2)), Up(std::exp(x.hi), 2)}; }
inline Interval log(const Interval& x) {
  HIGHLIFT_CHECK(x.lo > 0.0, "interval logarithm of a non-positive interval");
  return {Down(std::log(x.lo), 2), Up(std::log(x.hi), 2)};
}
inline Interval sqrt(const Interval& x) {
  HIGHLIFT_CHECK(x.lo >= 0.0, "interval square root of a negative interval");
  return {std::max(0.0, Down(std::sqrt(x.lo))), Up(std::sqrt(x.hi))};
}
inline Interval tanh(const Interval& x) {
  return {std::max(-1.0, Down(std::tanh(x.lo), 2)), std::min(1.0, Up(std::tanh(x.hi), 2))};
}
inline Interval abs(const Interval& x) {
  if (x.lo >= 0.0) return x;
  if (x.hi <= 0.0) return -x;
  return {0.0, std::max(-x.lo, x.hi)};
}
inline Interval Hull(const Interval& a, const Interval& b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }
/// The larger and the smaller of two quantities: exact, bound by bound.
inline Interval max(const Interval& a, const Interval& b) { return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)}; }
inline Interval min(const Interval& a, const Interval& b) { return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)}; }

/// The part of x at or above zero, and the part at or below; a side may be absent.
inline bool HasNonNegativePart(const Interval& x) { return x.hi >= 0.0; }
inline bool HasNonPositivePart(const Interval& x) { return x.lo <= 0.0; }

// Scalar helpers shared by the templated laws, so one law body serves double and Interval.
inline double Lower(double x) { return x; }
inline double Upper(double x) { return x; }
inline double Lower(const Interval& x) { return x.lo; }
inline double Upper(const Interval& x) { return x.hi; }

/// f applied to a value whose law changes at zero: f_pos for x >= 0, f_neg for x < 0. For an
/// interval straddling zero, the hull of both parts (each law is continuous at zero here).
/// `law` names the law in the messages of the symbolic scalar (symbolic.h).
template <class Pos, class Neg>
double BySign(double x, Pos f_pos, Neg f_neg, std::string_view /*law*/ = {}) {
  return x >= 0.0 ? f_pos(x) : f_neg(x);
}
template <class Pos, class Neg>
Interval BySign(const Interval& x, Pos f_pos, Neg f_neg, std::string_view /*law*/ = {}) {
  if (x.lo >= 0.0) return f_pos(x);
  if (x.hi < 0.0) return f_neg(x);
  return Hull(f_pos(Interval(0.0, x.hi)), f_neg(Interval(x.lo, 0.0)));
}

}  // namespace highlift::model
