// Soundness of every forward operation and backward projection of interval.h: points sampled
// with a fixed seed inside the argument boxes, whose image lies in y, are never excluded.
#include "highlift/icsp/interval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

namespace highlift::icsp {
namespace {

constexpr int kTrials = 4000;

/// A random interval from a mix of signs, zero-touching and wide/narrow shapes.
Interval RandomInterval(std::mt19937_64& rng, double scale = 10.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  std::uniform_int_distribution<int> shape(0, 5);
  double a = u(rng), b = u(rng);
  switch (shape(rng)) {
    case 0: a = 0.0; break;                  // touches zero
    case 1: b = a + 1e-6 * std::fabs(a); break;  // narrow
    case 2: a = std::fabs(a); b = std::fabs(b); break;  // positive
    case 3: a = -std::fabs(a); b = -std::fabs(b); break;  // negative
    default: break;
  }
  return Interval(std::min(a, b), std::max(a, b));
}
double PointIn(std::mt19937_64& rng, const Interval& x) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double t = u(rng);
  if (t < 0.05) return x.lower();
  if (t > 0.95) return x.upper();
  return std::clamp(x.lower() + (x.upper() - x.lower()) * u(rng), x.lower(), x.upper());
}
/// An interval around a computed value, wide enough (>= 4 ulps) to contain the exact value.
Interval Around(std::mt19937_64& rng, double y) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double lo = y, hi = y;
  for (int k = 0; k < 4; ++k) {
    lo = std::nextafter(lo, -kInf);
    hi = std::nextafter(hi, kInf);
  }
  const double spread = std::fabs(y) * 0.3 + 0.1;
  return Interval(lo - spread * u(rng) * (u(rng) < 0.5), hi + spread * u(rng) * (u(rng) < 0.5));
}
bool Contains(const Interval& x, double v) { return !IsEmpty(x) && x.lower() <= v && v <= x.upper(); }

using Binary = std::function<double(double, double)>;
using BinaryForward = std::function<Interval(const Interval&, const Interval&)>;
using BinaryBackward = std::function<Interval(const Interval&, const Interval&, const Interval&)>;

void CheckBinary(const char* name, Binary f, BinaryForward fwd, BinaryBackward back_a, BinaryBackward back_b,
                 bool positive_b = false) {
  std::mt19937_64 rng(20240601);
  int checked = 0;
  for (int t = 0; t < kTrials; ++t) {
    const Interval a = RandomInterval(rng);
    Interval b = RandomInterval(rng);
    if (positive_b) b = Interval(std::fabs(b.lower()) + 0.5, std::fabs(b.lower()) + 0.5 + b.upper() - b.lower());
    const double pa = PointIn(rng, a), pb = PointIn(rng, b);
    const double y = f(pa, pb);
    if (!std::isfinite(y)) continue;
    ++checked;
    EXPECT_TRUE(Contains(fwd(a, b), y)) << name << " forward " << ToString(a) << ", " << ToString(b) << " at " << pa << ", " << pb;
    const Interval yy = Around(rng, y);
    EXPECT_TRUE(Contains(back_a(yy, a, b), pa)) << name << " backward a: y " << ToString(yy) << " a " << ToString(a) << " b " << ToString(b) << " pa " << pa;
    EXPECT_TRUE(Contains(back_b(yy, a, b), pb)) << name << " backward b: y " << ToString(yy) << " a " << ToString(a) << " b " << ToString(b) << " pb " << pb;
  }
  EXPECT_GT(checked, kTrials / 3) << name;
}

TEST(IntervalProjection, AddSubMulDivAreSound) {
  CheckBinary("add", [](double a, double b) { return a + b; }, [](auto& a, auto& b) { return a + b; },
              [](auto& y, auto& a, auto& b) { return AddBackward(y, a, b); },
              [](auto& y, auto& a, auto& b) { return AddBackward(y, b, a); });
  CheckBinary("sub", [](double a, double b) { return a - b; }, [](auto& a, auto& b) { return a - b; },
              [](auto& y, auto& a, auto& b) { return SubBackwardLeft(y, a, b); },
              [](auto& y, auto& a, auto& b) { return SubBackwardRight(y, a, b); });
  CheckBinary("mul", [](double a, double b) { return a * b; }, [](auto& a, auto& b) { return a * b; },
              [](auto& y, auto& a, auto& b) { return MulBackward(y, a, b); },
              [](auto& y, auto& a, auto& b) { return MulBackward(y, b, a); });
  CheckBinary("div", [](double a, double b) { return b == 0.0 ? NAN : a / b; },
              [](auto& a, auto& b) { return Div(a, b); },
              [](auto& y, auto& a, auto& b) { return DivBackwardLeft(y, a, b); },
              [](auto& y, auto& a, auto& b) { return DivBackwardRight(y, a, b); });
  CheckBinary("min", [](double a, double b) { return std::min(a, b); }, [](auto& a, auto& b) { return Min(a, b); },
              [](auto& y, auto& a, auto& b) { return MinBackward(y, a, b); },
              [](auto& y, auto& a, auto& b) { return MinBackward(y, b, a); });
  CheckBinary("max", [](double a, double b) { return std::max(a, b); }, [](auto& a, auto& b) { return Max(a, b); },
              [](auto& y, auto& a, auto& b) { return MaxBackward(y, a, b); },
              [](auto& y, auto& a, auto& b) { return MaxBackward(y, b, a); });
}

TEST(IntervalProjection, PowersAreSound) {
  for (int n : {-3, -2, -1, 2, 3, 4, 5}) {
    CheckBinary("powint", [n](double a, double) { return (n < 0 && a == 0.0) ? NAN : std::pow(a, n); },
                [n](auto& a, auto&) { return PowInt(a, n); },
                [n](auto& y, auto& a, auto&) { return PowIntBackward(y, a, n); },
                [](auto&, auto&, auto& b) { return b; });
  }
  for (double p : {0.5, 1.5, 2.7, -0.5}) {
    CheckBinary("powreal", [p](double a, double) { return (a < 0 || (p < 0 && a == 0)) ? NAN : std::pow(a, p); },
                [p](auto& a, auto&) { return PowReal(a, p); },
                [p](auto& y, auto& a, auto&) { return PowRealBackward(y, a, p); },
                [](auto&, auto&, auto& b) { return b; });
  }
}

TEST(IntervalProjection, UnaryFunctionsAreSound) {
  struct Case {
    const char* name;
    std::function<double(double)> f;
    std::function<Interval(const Interval&)> fwd;
    std::function<Interval(const Interval&, const Interval&)> back;
  };
  const std::vector<Case> cases = {
      {"sqr", [](double a) { return a * a; }, [](auto& a) { return Sqr(a); }, [](auto& y, auto& a) { return SqrBackward(y, a); }},
      {"sqrt", [](double a) { return a < 0 ? NAN : std::sqrt(a); }, [](auto& a) { return Sqrt(a); }, [](auto& y, auto& a) { return SqrtBackward(y, a); }},
      {"exp", [](double a) { return std::exp(a); }, [](auto& a) { return Exp(a); }, [](auto& y, auto& a) { return ExpBackward(y, a); }},
      {"log", [](double a) { return a <= 0 ? NAN : std::log(a); }, [](auto& a) { return Log(a); }, [](auto& y, auto& a) { return LogBackward(y, a); }},
      {"abs", [](double a) { return std::fabs(a); }, [](auto& a) { return Abs(a); }, [](auto& y, auto& a) { return AbsBackward(y, a); }},
      {"neg", [](double a) { return -a; }, [](auto& a) { return -a; }, [](auto& y, auto& a) { return NegBackward(y, a); }},
      {"sin", [](double a) { return std::sin(a); }, [](auto& a) { return Sin(a); }, [](auto& y, auto& a) { return SinBackward(y, a); }},
      {"cos", [](double a) { return std::cos(a); }, [](auto& a) { return Cos(a); }, [](auto& y, auto& a) { return CosBackward(y, a); }},
  };
  for (const Case& c : cases) {
    CheckBinary(c.name, [&](double a, double) { return c.f(a); }, [&](auto& a, auto&) { return c.fwd(a); },
                [&](auto& y, auto& a, auto&) { return c.back(y, a); }, [](auto&, auto&, auto& b) { return b; });
  }
}

TEST(IntervalProjection, RealPowerBackwardEnclosesTheRoundingOfOneOverP) {
  // a^p = y  =>  a = y^(1/p). The double nearest 1/p is off by up to half an ulp, an error that
  // y^(1/p) magnifies by log(y); the projection encloses 1/p instead of counting on the one-ulp
  // widening of log to cover it. Point values y (fixed seed) from 1e-300 to 1e300, and the true
  // a = y^(1/p) computed in long double (64-bit mantissa).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  int checked = 0;
  for (double p : {0.3, 0.7, 1.1, 2.3, 3.7, -0.3, -1.7}) {
    for (int t = 0; t < 500; ++t) {
      const double y = std::pow(10.0, exponent(rng));
      const long double a = std::pow(static_cast<long double>(y), 1.0L / static_cast<long double>(p));
      if (!(a > 1e-300L && a < 1e300L)) continue;
      const Interval back = PowRealBackward(Interval(y), Interval(0.0, kInf), p);
      EXPECT_TRUE(!IsEmpty(back) && back.lower() <= a && a <= back.upper())
          << "p " << p << " y " << y << " back " << ToString(back);
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000);
  // And it still narrows: a^0.5 in [2, 3] gives a in [4, 9] up to rounding; a^-0.5 in [0.5, 1]
  // gives a in [1, 4]; a^0.5 = 0 gives a = 0.
  Interval a = PowRealBackward(Interval(2, 3), Interval(0, 100), 0.5);
  EXPECT_NEAR(a.lower(), 4.0, 1e-12);
  EXPECT_NEAR(a.upper(), 9.0, 1e-12);
  a = PowRealBackward(Interval(0.5, 1), Interval(0, 100), -0.5);
  EXPECT_NEAR(a.lower(), 1.0, 1e-12);
  EXPECT_NEAR(a.upper(), 4.0, 1e-12);
  a = PowRealBackward(Interval(0, 0), Interval(0, 100), 0.5);
  EXPECT_EQ(a.lower(), 0.0);
  EXPECT_EQ(a.upper(), 0.0);
}

TEST(IntervalProjection, SineAndCosineProjectOntoTheirBranches) {
  // sin(a) in [0.5, 1] with a in [0, 3]: a in [pi/6, 5 pi/6].
  const Interval s = SinBackward(Interval(0.5, 1.0), Interval(0.0, 3.0));
  EXPECT_NEAR(s.lower(), M_PI / 6, 1e-12);
  EXPECT_NEAR(s.upper(), 5 * M_PI / 6, 1e-12);
  EXPECT_LE(s.lower(), M_PI / 6);
  EXPECT_GE(s.upper(), 5 * M_PI / 6);
  // cos(a) in [-1, -0.5] with a in [-1, 10]: a in [2 pi/3, 4 pi/3] or [8 pi/3, 10]; the hull.
  const Interval c = CosBackward(Interval(-1.0, -0.5), Interval(-1.0, 10.0));
  EXPECT_NEAR(c.lower(), 2 * M_PI / 3, 1e-12);
  EXPECT_EQ(c.upper(), 10.0);
  // A period away: cos(a) = 1 with a in [0.5, 6] leaves nothing.
  EXPECT_TRUE(IsEmpty(CosBackward(Interval(1.0, 1.0), Interval(0.5, 6.0))));
  EXPECT_TRUE(IsEmpty(SinBackward(Interval(2.0, 3.0), Interval(0.0, 1.0))));
  // Wide domains move only at their ends: sin(a) = 1 with a in [-1000, 1000].
  const Interval w = SinBackward(Interval(1.0, 1.0), Interval(-1000.0, 1000.0));
  EXPECT_GT(w.lower(), -1000.0);
  EXPECT_NEAR(std::sin(w.lower()), 1.0, 1e-9);
  EXPECT_NEAR(std::sin(w.upper()), 1.0, 1e-9);
  // Soundness over many periods (fixed seed): a point whose sine or cosine lies in y survives.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-300.0, 300.0), width(0.0, 40.0);
  for (int t = 0; t < 4000; ++t) {
    const double lo = u(rng);
    const Interval a(lo, lo + width(rng) * (t % 3 == 0 ? 0.01 : 1.0));
    const double x = PointIn(rng, a);
    const Interval ys = Around(rng, std::sin(x)), yc = Around(rng, std::cos(x));
    EXPECT_TRUE(Contains(SinBackward(ys, a), x)) << "sin: a " << ToString(a) << " x " << x << " y " << ToString(ys);
    EXPECT_TRUE(Contains(CosBackward(yc, a), x)) << "cos: a " << ToString(a) << " x " << x << " y " << ToString(yc);
  }
}

TEST(IntervalProjection, MultiplicationByZeroIntervalKeepsTheGap) {
  // y = a * b with y in [1, 2] and b in [-1, 1]: a in (-inf, -1] U [1, inf), met with [-0.5, 3].
  const Interval a = MulBackward(Interval(1, 2), Interval(-0.5, 3), Interval(-1, 1));
  EXPECT_EQ(a.lower(), 1.0);
  EXPECT_EQ(a.upper(), 3.0);
  // 0 in y and in b: nothing follows for a.
  const Interval whole = MulBackward(Interval(-1, 2), Interval(-5, 5), Interval(-1, 1));
  EXPECT_EQ(whole.lower(), -5.0);
  EXPECT_EQ(whole.upper(), 5.0);
}

TEST(Interval, EmptyIsAValueAndNeverThrows) {
  const Interval e = Empty();
  EXPECT_TRUE(IsEmpty(e));
  EXPECT_TRUE(IsEmpty(e + Interval(1, 2)));
  EXPECT_TRUE(IsEmpty(e * Interval(1, 2)));
  EXPECT_TRUE(IsEmpty(Sqrt(Interval(-3, -1))));
  EXPECT_TRUE(IsEmpty(Log(Interval(-3, -1))));
  EXPECT_TRUE(IsEmpty(Meet(Interval(0, 1), Interval(2, 3))));
  EXPECT_TRUE(IsEmpty(Make(2.0, 1.0)));
  EXPECT_TRUE(IsEmpty(MulBackward(e, Interval(1, 2), Interval(1, 2))));
  EXPECT_EQ(ToString(e), "[empty]");
}

TEST(Interval, ArithmeticRoundsOutward) {
  const Interval third = Interval(1.0) / Interval(3.0);
  EXPECT_LT(third.lower(), third.upper());
  EXPECT_EQ(std::nextafter(third.lower(), 1.0), third.upper());
  const Interval tenth = Interval(1.0) / Interval(10.0);
  EXPECT_LE(tenth.lower() * 10.0, 1.0);
  // exp is widened by one ulp beyond the library's result.
  const Interval e1 = Exp(Interval(1.0));
  EXPECT_LT(e1.lower(), std::exp(1.0));
  EXPECT_GT(e1.upper(), std::exp(1.0));
  // sqrt of an exact square stays exact.
  const Interval s = Sqrt(Interval(4.0));
  EXPECT_EQ(s.lower(), 2.0);
  EXPECT_EQ(s.upper(), 2.0);
}

TEST(Interval, FastIntervalUnderGuardMatchesProtectedArithmetic) {
  const Interval a(0.1, 0.3), b(1.0 / 3.0, 7.0);
  Interval slow = a * b / (a + b);
  FastInterval fast_result;
  {
    RoundingGuard guard;
    const FastInterval fa(a.lower(), a.upper(), true), fb(b.lower(), b.upper(), true);
    fast_result = fa * fb / (fa + fb);
  }
  EXPECT_EQ(slow.lower(), fast_result.lower());
  EXPECT_EQ(slow.upper(), fast_result.upper());
}

}  // namespace
}  // namespace highlift::icsp
