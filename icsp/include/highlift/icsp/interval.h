// Sound interval arithmetic for the propagator: one wrapper around boost::numeric::interval<double>.
//
// - Rounding: the four operations and sqrt are rounded outward exactly (IEEE directed rounding);
//   exp, log, sin, cos (and asin, acos in the backward projections of sin and cos) come from the
//   C library, which does not guarantee its rounding, so their results are widened outward by
//   one ulp more (std::nextafter). n-th roots (Newton iterations on pow) are widened likewise.
// - Emptiness: an empty interval is an ordinary value (both bounds NaN); every operation on an
//   empty operand gives empty; nothing throws.
// - Backward projections: for every operation y = f(x1, x2) a function that narrows an argument
//   to the values compatible with y and the other argument (HC4's backward step). Each is a set
//   operation; the comment above it states it.
//
// Speed: every operation of `Interval` saves, sets and restores the rounding mode. Inner loops
// hold one `RoundingGuard` (sets upward rounding once) and compute on `FastInterval`, which
// assumes that mode (the Boost "unprotected" idiom). Functions below are templated on the type.
// Translation units doing interval arithmetic are compiled with -frounding-math.
#pragma once

#include <boost/numeric/interval.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace highlift::icsp {

namespace bi = boost::numeric::interval_lib;

/// Rounding: transcendental functions from the C library with the "opposite" trick (upward mode
/// only; down = -up(-x)); save_state restores the caller's mode. Checking: empty intervals are
/// values (NaN bounds), no exceptions.
using IntervalPolicies =
    bi::policies<bi::save_state<bi::rounded_transc_opp<double>>, bi::checking_base<double>>;
using Interval = boost::numeric::interval<double, IntervalPolicies>;
/// The same arithmetic without the per-operation rounding-mode switches: only valid while a
/// RoundingGuard is alive.
using FastInterval = bi::unprotect<Interval>::type;
/// Sets upward rounding for its lifetime and restores the previous mode afterwards.
using RoundingGuard = Interval::traits_type::rounding;

inline constexpr double kInf = std::numeric_limits<double>::infinity();

template <class I = Interval>
inline I Make(double lo, double hi) {
  return I(lo, hi);  // NaN or lo > hi gives the empty interval
}
template <class I = Interval>
inline I Empty() {
  return I::empty();
}
template <class I = Interval>
inline I Whole() {
  return I::whole();
}
template <class I>
inline bool IsEmpty(const I& x) {
  return boost::numeric::empty(x);
}
/// Intersection; empty when disjoint or either is empty.
template <class I>
inline I Meet(const I& a, const I& b) {
  if (IsEmpty(a) || IsEmpty(b)) return I::empty();
  const double lo = std::max(a.lower(), b.lower());
  const double hi = std::min(a.upper(), b.upper());
  if (!(lo <= hi)) return I::empty();
  return I(lo, hi, true);
}
/// Convex hull of the union.
template <class I>
inline I Join(const I& a, const I& b) {
  if (IsEmpty(a)) return b;
  if (IsEmpty(b)) return a;
  return I(std::min(a.lower(), b.lower()), std::max(a.upper(), b.upper()), true);
}
template <class I>
inline bool ZeroIn(const I& x) {
  return x.lower() <= 0.0 && 0.0 <= x.upper();
}
/// Widens a result of an operation without guaranteed rounding by one ulp on each side.
template <class I>
inline I WidenUlp(const I& x) {
  if (IsEmpty(x)) return x;
  return I(std::nextafter(x.lower(), -kInf), std::nextafter(x.upper(), kInf), true);
}
/// "[lo, hi]" with 17 significant digits, "[empty]".
std::string ToString(const Interval& x, int significant = 17);

// ---------------------------------------------------------------------------------------------
// Forward functions that need more than Boost gives.

/// exp, log, sin, cos widened by one ulp (C library rounding is not guaranteed).
template <class I>
inline I Exp(const I& x) {
  if (IsEmpty(x)) return x;
  I r = WidenUlp(boost::numeric::exp(x));
  return Meet(r, I(0.0, kInf, true));
}
template <class I>
inline I Log(const I& x) {
  if (IsEmpty(x) || x.upper() < 0.0) return I::empty();
  if (x.upper() == 0.0) return I::empty();  // log(0) = -inf is not a real value
  return WidenUlp(boost::numeric::log(x));
}
template <class I>
inline I Sin(const I& x) {
  if (IsEmpty(x)) return x;
  if (!std::isfinite(x.lower()) || !std::isfinite(x.upper())) return I(-1.0, 1.0, true);
  return Meet(WidenUlp(boost::numeric::sin(x)), I(-1.0, 1.0, true));
}
template <class I>
inline I Cos(const I& x) {
  if (IsEmpty(x)) return x;
  if (!std::isfinite(x.lower()) || !std::isfinite(x.upper())) return I(-1.0, 1.0, true);
  return Meet(WidenUlp(boost::numeric::cos(x)), I(-1.0, 1.0, true));
}
/// sqrt over the non-negative part (exact directed rounding); empty when x < 0.
template <class I>
inline I Sqrt(const I& x) {
  if (IsEmpty(x) || x.upper() < 0.0) return I::empty();
  return boost::numeric::sqrt(x);
}
template <class I>
inline I Sqr(const I& x) {
  if (IsEmpty(x)) return x;
  return boost::numeric::square(x);
}
/// x^n for an integer n (negative n: 1/x^-n, whole when 0 is inside).
template <class I>
inline I PowInt(const I& x, int n) {
  if (IsEmpty(x)) return x;
  if (n == 0) return I(1.0, 1.0, true);
  if (n == 1) return x;
  if (n == 2) return boost::numeric::square(x);
  if (n > 0) return boost::numeric::pow(x, n);
  const I d = PowInt(x, -n);
  if (d.lower() == 0.0 && d.upper() == 0.0) return I::empty();
  return I(1.0, 1.0, true) / d;
}
/// x^p for a real p, defined on x >= 0 as exp(p * log(x)); x^p at x = 0 is 0 for p > 0.
template <class I>
inline I PowReal(const I& x, double p) {
  const I xp = Meet(x, I(0.0, kInf, true));
  if (IsEmpty(xp)) return xp;
  if (p == std::floor(p) && std::fabs(p) < 64) return PowInt(xp, static_cast<int>(p));
  if (p > 0.0) {
    I r = xp.upper() == 0.0 ? I(0.0, 0.0, true) : Exp(I(p, p, true) * Log(xp));
    if (xp.lower() == 0.0) r = Join(r, I(0.0, 0.0, true));
    return r;
  }
  if (xp.upper() == 0.0) return I::empty();
  return Exp(I(p, p, true) * Log(xp));
}
template <class I>
inline I Abs(const I& x) {
  if (IsEmpty(x)) return x;
  return boost::numeric::abs(x);
}
template <class I>
inline I Min(const I& a, const I& b) {
  if (IsEmpty(a) || IsEmpty(b)) return I::empty();
  return I(std::min(a.lower(), b.lower()), std::min(a.upper(), b.upper()), true);
}
template <class I>
inline I Max(const I& a, const I& b) {
  if (IsEmpty(a) || IsEmpty(b)) return I::empty();
  return I(std::max(a.lower(), b.lower()), std::max(a.upper(), b.upper()), true);
}
/// a / b with the hull of the extended division when 0 is inside b; empty when b = [0, 0].
template <class I>
inline I Div(const I& a, const I& b) {
  if (IsEmpty(a) || IsEmpty(b)) return I::empty();
  if (b.lower() == 0.0 && b.upper() == 0.0) return I::empty();
  return a / b;
}

// ---------------------------------------------------------------------------------------------
// Backward projections: each returns the narrowed argument (possibly empty).

/// x ∩ (y / d), where y / d is the extended division: when 0 is inside d the quotient is the
/// union of two half-lines, each met with x before taking the hull (keeps the gap's pruning).
template <class I>
inline I MeetQuotient(const I& x, const I& y, const I& d) {
  if (IsEmpty(x) || IsEmpty(y) || IsEmpty(d)) return I::empty();
  if (!ZeroIn(d)) return Meet(x, y / d);
  if (ZeroIn(y)) return x;  // 0 = y * 0 allows every x
  // 0 in d, 0 not in y: y / d = y / [d.lo, 0-] ∪ y / [0+, d.hi].
  I r = I::empty();
  if (d.lower() < 0.0) {
    bool unused = false;
    const I part = bi::division_part1(y, I(d.lower(), 0.0, true), unused);
    r = Join(r, Meet(x, part));
  }
  if (d.upper() > 0.0) {
    bool unused = false;
    const I part = bi::division_part1(y, I(0.0, d.upper(), true), unused);
    r = Join(r, Meet(x, part));
  }
  return r;
}
// y = a + b  =>  a in y - b
template <class I>
inline I AddBackward(const I& y, const I& a, const I& b) { return Meet(a, y - b); }
// y = a - b  =>  a in y + b
template <class I>
inline I SubBackwardLeft(const I& y, const I& a, const I& b) { return Meet(a, y + b); }
// y = a - b  =>  b in a - y
template <class I>
inline I SubBackwardRight(const I& y, const I& a, const I& b) { return Meet(b, a - y); }
// y = a * b  =>  a in y / b (extended division)
template <class I>
inline I MulBackward(const I& y, const I& a, const I& b) { return MeetQuotient(a, y, b); }
// y = a / b  =>  a in y * b
template <class I>
inline I DivBackwardLeft(const I& y, const I& a, const I& b) {
  if (IsEmpty(y) || IsEmpty(b)) return I::empty();
  return Meet(a, y * b);
}
// y = a / b  =>  b in a / y (extended division), and b != 0 is not representable: kept
template <class I>
inline I DivBackwardRight(const I& y, const I& a, const I& b) { return MeetQuotient(b, a, y); }
// y = -a  =>  a in -y
template <class I>
inline I NegBackward(const I& y, const I& a) { return Meet(a, -y); }
// y = a^2  =>  a in sqrt(y) ∪ -sqrt(y)
template <class I>
inline I SqrBackward(const I& y, const I& a) {
  const I r = Sqrt(y);
  if (IsEmpty(r)) return r;
  return Join(Meet(a, r), Meet(a, -r));
}
// y = sqrt(a)  =>  a in (y ∩ [0, inf))^2
template <class I>
inline I SqrtBackward(const I& y, const I& a) {
  const I yp = Meet(y, I(0.0, kInf, true));
  if (IsEmpty(yp)) return yp;
  return Meet(a, boost::numeric::square(yp));
}
/// n-th root (n >= 2) of the non-negative part of x, rounded outward; empty when x < 0.
template <class I>
inline I Root(const I& x, int n) {
  const I xp = Meet(x, I(0.0, kInf, true));
  if (IsEmpty(xp)) return xp;
  const bool inf = !std::isfinite(xp.upper());
  const I r = boost::numeric::nth_root(I(xp.lower(), inf ? std::max(xp.lower(), 1.0) : xp.upper(), true), n);
  const double lo = r.lower() == 0.0 ? 0.0 : std::max(0.0, std::nextafter(r.lower(), 0.0));
  return I(lo, inf ? kInf : std::nextafter(r.upper(), kInf), true);
}
// y = a^n  =>  a in the n-th root of y (both signs for even n; for negative n, a^-n in 1/y,
// split in two half-lines when 0 is inside y)
template <class I>
inline I PowIntBackward(const I& y, const I& a, int n) {
  if (IsEmpty(y) || IsEmpty(a)) return I::empty();
  if (n == 0) return (y.lower() <= 1.0 && 1.0 <= y.upper()) ? a : I::empty();
  if (n == 1) return Meet(a, y);
  if (n == 2) return SqrBackward(y, a);
  if (n < 0) {
    const I one(1.0, 1.0, true);
    if (!ZeroIn(y)) return PowIntBackward(one / y, a, -n);
    I r = I::empty();
    bool unused = false;
    if (y.lower() < 0.0) r = Join(r, PowIntBackward(bi::division_part1(one, I(y.lower(), 0.0, true), unused), a, -n));
    if (y.upper() > 0.0) r = Join(r, PowIntBackward(bi::division_part1(one, I(0.0, y.upper(), true), unused), a, -n));
    return r;
  }
  if (n % 2 == 0) {
    const I r = Root(y, n);
    if (IsEmpty(r)) return r;
    return Join(Meet(a, r), Meet(a, -r));
  }
  // odd n: a = sign(y) * |y|^(1/n), monotone
  I r = I::empty();
  const I pos = Root(y, n);
  const I neg = Root(-y, n);
  if (!IsEmpty(pos)) r = Join(r, pos);
  if (!IsEmpty(neg)) r = Join(r, -neg);
  return Meet(a, r);
}
// y = a^p (real p, a >= 0)  =>  a in y^(1/p) = exp((1/p) log(y)) over a >= 0, with 1/p enclosed
// (the double nearest 1/p is off by up to half an ulp, which y^(1/p) magnifies by log(y))
template <class I>
inline I PowRealBackward(const I& y, const I& a, double p) {
  if (p == std::floor(p) && std::fabs(p) < 64) {
    return Meet(PowIntBackward(y, a, static_cast<int>(p)), I(0.0, kInf, true));
  }
  const I ap = Meet(a, I(0.0, kInf, true));
  const I yp = Meet(y, I(0.0, kInf, true));
  if (IsEmpty(ap) || IsEmpty(yp)) return I::empty();
  if (yp.upper() == 0.0) return p > 0.0 ? Meet(ap, I(0.0, 0.0, true)) : I::empty();  // 0^p = 0 (p > 0)
  const I inverse = I(1.0, 1.0, true) / I(p, p, true);
  return Meet(ap, Exp(inverse * Log(yp)));  // y = 0 maps to a = 0 (p > 0) or a = inf (p < 0)
}
// y = exp(a)  =>  a in log(y)
template <class I>
inline I ExpBackward(const I& y, const I& a) {
  const I yp = Meet(y, I(0.0, kInf, true));
  if (IsEmpty(yp) || yp.upper() == 0.0) return I::empty();
  return Meet(a, WidenUlp(boost::numeric::log(yp)));
}
// y = log(a)  =>  a in exp(y)
template <class I>
inline I LogBackward(const I& y, const I& a) {
  if (IsEmpty(y)) return y;
  return Meet(a, Exp(y));
}
// y = |a|  =>  a in (a ∩ [0, inf) ∩ y) ∪ (a ∩ (-inf, 0] ∩ -y)
template <class I>
inline I AbsBackward(const I& y, const I& a) {
  const I yp = Meet(y, I(0.0, kInf, true));
  if (IsEmpty(yp)) return yp;
  return Join(Meet(a, yp), Meet(a, -yp));
}
// y = min(a, b)  =>  a >= y.lo; and a in y when b cannot be the minimum (b.lo > y.hi)
template <class I>
inline I MinBackward(const I& y, const I& a, const I& b) {
  if (IsEmpty(y) || IsEmpty(b)) return I::empty();
  if (b.lower() > y.upper()) return Meet(a, y);
  return Meet(a, I(y.lower(), kInf, true));
}
// y = max(a, b)  =>  a <= y.hi; and a in y when b cannot be the maximum (b.hi < y.lo)
template <class I>
inline I MaxBackward(const I& y, const I& a, const I& b) {
  if (IsEmpty(y) || IsEmpty(b)) return I::empty();
  if (b.upper() < y.lower()) return Meet(a, y);
  return Meet(a, I(-kInf, y.upper(), true));
}
/// a ∩ (the union over all integers k of branch_i + 2 k pi), as a hull. `branches` enclose the
/// branches of an inverse within one period (each an interval, empty ones skipped). The shifted
/// branches are enclosed with an outward enclosure of 2 pi, so the result is sound. A domain
/// beyond 1e9 rad (where a period is lost in the rounding of k 2 pi) is returned unchanged.
template <class I>
inline I PeriodicMeet(const I& a, const I (&branches)[2]) {
  if (IsEmpty(a)) return a;
  if (!(std::fabs(a.lower()) <= 1e9 && std::fabs(a.upper()) <= 1e9)) return a;
  const I two_pi(bi::constants::pi_twice_lower<double>(), bi::constants::pi_twice_upper<double>(), true);
  // Every branch lies within [-pi, 2 pi], so the shifts that can meet a are k in [k_first, k_last].
  const double period = bi::constants::pi_twice_lower<double>();
  const double k_first = std::floor(a.lower() / period) - 2.0, k_last = std::ceil(a.upper() / period) + 2.0;
  double lo = kInf, hi = -kInf;
  auto visit = [&](double k) {
    const I shift = I(k, k, true) * two_pi;
    for (const I& b : branches) {
      if (IsEmpty(b)) continue;
      const I m = Meet(a, b + shift);
      if (IsEmpty(m)) continue;
      lo = std::min(lo, m.lower());
      hi = std::max(hi, m.upper());
    }
  };
  if (k_last - k_first <= 16.0) {
    for (double k = k_first; k <= k_last; k += 1.0) visit(k);
  } else {
    // A wide domain (many periods): only its two ends can move, each within a period or two.
    for (double k = k_first; k <= k_first + 6.0; k += 1.0) visit(k);
    for (double k = k_last - 6.0; k <= k_last; k += 1.0) visit(k);
    if (!(lo <= hi)) return I::empty();
    return I(lo, hi, true);
  }
  if (!(lo <= hi)) return I::empty();
  return I(lo, hi, true);
}
// y = sin(a)  =>  a in (asin(y) + 2k pi) ∪ (pi - asin(y) + 2k pi), met with a
template <class I>
inline I SinBackward(const I& y, const I& a) {
  const I yy = Meet(y, I(-1.0, 1.0, true));
  if (IsEmpty(yy) || IsEmpty(a)) return I::empty();
  const I pi(bi::constants::pi_lower<double>(), bi::constants::pi_upper<double>(), true);
  const I half_pi(bi::constants::pi_half_lower<double>(), bi::constants::pi_half_upper<double>(), true);
  // asin from the C library (rounding not guaranteed): widened by one ulp, kept in [-pi/2, pi/2].
  const I asin_y = Meet(WidenUlp(boost::numeric::asin(yy)), I(-half_pi.upper(), half_pi.upper(), true));
  const I branches[2] = {asin_y, pi - asin_y};
  return PeriodicMeet(a, branches);
}
// y = cos(a)  =>  a in (acos(y) + 2k pi) ∪ (-acos(y) + 2k pi), met with a
template <class I>
inline I CosBackward(const I& y, const I& a) {
  const I yy = Meet(y, I(-1.0, 1.0, true));
  if (IsEmpty(yy) || IsEmpty(a)) return I::empty();
  const I acos_y = Meet(WidenUlp(boost::numeric::acos(yy)), I(0.0, bi::constants::pi_upper<double>(), true));
  const I branches[2] = {acos_y, -acos_y};
  return PeriodicMeet(a, branches);
}

}  // namespace highlift::icsp
