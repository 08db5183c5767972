// A small outward-rounded interval type for evaluating the physics laws on parameter domains.
// Only what the laws need: + - * / with a positive or negative (not zero-straddling) divisor,
// exp and log. Each result is widened by one ulp on each side, which covers the rounding of
// one operation.
#pragma once

#include <algorithm>
#include <cmath>

#include "highlift/core/domain.h"
#include "highlift/core/error.h"

namespace highlift::estimation::detail {

struct Interval {
  double lo = 0.0, hi = 0.0;
  Interval() = default;
  Interval(double v) : lo(v), hi(v) {}  // NOLINT: implicit, so laws can write T(3.14)
  Interval(double l, double h) : lo(l), hi(h) {}
  static Interval Outward(double l, double h) {
    return {std::nextafter(l, -HUGE_VAL), std::nextafter(h, HUGE_VAL)};
  }
  Domain ToDomain() const { return {lo, hi}; }
};

inline Interval operator+(const Interval& a, const Interval& b) { return Interval::Outward(a.lo + b.lo, a.hi + b.hi); }
inline Interval operator-(const Interval& a, const Interval& b) { return Interval::Outward(a.lo - b.hi, a.hi - b.lo); }
inline Interval operator*(const Interval& a, const Interval& b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return Interval::Outward(*std::min_element(p, p + 4), *std::max_element(p, p + 4));
}
inline Interval operator/(const Interval& a, const Interval& b) {
  HIGHLIFT_CHECK(b.lo > 0 || b.hi < 0, "interval division by an interval containing zero");
  const double q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  return Interval::Outward(*std::min_element(q, q + 4), *std::max_element(q, q + 4));
}
inline Interval exp(const Interval& a) { return Interval::Outward(std::exp(a.lo), std::exp(a.hi)); }
inline Interval log(const Interval& a) {
  HIGHLIFT_CHECK(a.lo > 0, "interval log of a non-positive interval");
  return Interval::Outward(std::log(a.lo), std::log(a.hi));
}

}  // namespace highlift::estimation::detail
