// The torsional buckling law of a thin-walled tube (laws.h TubeBucklingStress): a hand-computed
// value in each regime, the envelope of the two, the torque capacity at the lesser stress, and
// its interval enclosure (outward: contains every sampled point).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "highlift/model/interval.h"
#include "highlift/model/laws.h"

namespace highlift::model {
namespace {

// Ti-6Al-4V (G 44 GPa, nu 0.33), knock-down 0.67.
constexpr double kG = 44e9, kNu = 0.33, kGamma = 0.67;

// By hand: E = 2 G (1 + nu) = 117.04 GPa; a 38 x 1.5 mm tube, r = 18.25 mm, t/r = 0.0821918;
// long tube: 0.67 * 0.2357023 * 117.04e9 * 0.0821918^1.5 / 0.8911^0.75
//          = 0.67 * 0.2357023 * 117.04e9 * 0.0235636 / 0.917158 = 474.87 MPa;
// moderate length at L = 1.4 m: 0.747 * 0.67^0.75 * 117.04e9 * 0.0821918^1.25 * (0.01825/1.4)^0.5
//          / 0.8911^0.625 = 349.63 MPa, below the long-tube value: the long tube governs.
TEST(TubeBuckling, LongTubeStressMatchesAHandComputedValue) {
  const double tau = TubeBucklingStress(kG, kNu, kGamma, 0.038, 0.0015, 1.4);
  EXPECT_NEAR(tau, 474.87e6, 0.01e6);
}

// At L = 5 cm the moderate-length formula gives the larger stress: 0.747 * 0.67^0.75 * E *
// (t/r)^1.25 * (r/L)^0.5 / (1 - nu^2)^0.625 = 1850.07 MPa.
TEST(TubeBuckling, AShortTubeTakesTheModerateLengthFormula) {
  const double tau = TubeBucklingStress(kG, kNu, kGamma, 0.038, 0.0015, 0.05);
  EXPECT_NEAR(tau, 1850.07e6, 0.01e6);
  // Longer: falls as L^-1/2 until the long-tube value, then stays there.
  const double l1 = TubeBucklingStress(kG, kNu, kGamma, 0.038, 0.0015, 0.10);
  EXPECT_NEAR(l1, tau / std::sqrt(2.0), 1e-9 * tau);
  EXPECT_EQ(TubeBucklingStress(kG, kNu, kGamma, 0.038, 0.0015, 10.0), TubeBucklingStress(kG, kNu, kGamma, 0.038, 0.0015, 100.0));
}

// A thin tube (60 x 0.75 mm, D/t 80) buckles far below the 550 MPa allowable; a thick one
// (38 x 4 mm, D/t 9.5) reaches the allowable first.
TEST(TubeBuckling, TheCapacityIsAtTheLesserStress) {
  const double D = 0.060, t = 0.00075, Ip = TubePolarMoment(D, t);
  const double tau_cr = TubeBucklingStress(kG, kNu, kGamma, D, t, 2.0);
  EXPECT_LT(tau_cr, 100e6);
  EXPECT_GT(tau_cr, 70e6);
  EXPECT_DOUBLE_EQ(TubeTorqueCapacityWithBuckling(550e6, tau_cr, D, Ip), TubeTorqueCapacity(tau_cr, D, Ip));
  const double Dk = 0.038, tk = 0.004, Ipk = TubePolarMoment(Dk, tk);
  const double tau_k = TubeBucklingStress(kG, kNu, kGamma, Dk, tk, 2.0);
  EXPECT_GT(tau_k, 550e6);
  EXPECT_DOUBLE_EQ(TubeTorqueCapacityWithBuckling(550e6, tau_k, Dk, Ipk), TubeTorqueCapacity(550e6, Dk, Ipk));
}

// On intervals the law encloses every point of the box (G, nu, D, t, L uncertain, across the
// switch between the regimes), and the capacity grows with D and t (sampled along each).
TEST(TubeBuckling, TheIntervalLawEnclosesSampledPointsAndTheCapacityGrowsWithDAndT) {
  const Interval G(43e9, 51e9), nu(0.31, 0.34), gamma(0.67), D(0.030, 0.060), t(0.0006, 0.003), L(0.05, 3.0);
  const Interval tau = TubeBucklingStress(G, nu, gamma, D, t, L);
  std::mt19937 rng(7);
  auto in = [&](const Interval& x) { return std::uniform_real_distribution<double>(x.lo, x.hi)(rng); };
  for (int k = 0; k < 2000; ++k) {
    const double v = TubeBucklingStress(in(G), in(nu), 0.67, in(D), in(t), in(L));
    ASSERT_GE(v, tau.lo);
    ASSERT_LE(v, tau.hi);
  }
  for (double Lk : {0.05, 0.3, 3.0}) {
    double previous = 0.0;
    for (int i = 0; i <= 200; ++i) {
      const double d = 0.006 + i * (0.2 - 0.006) / 200;  // t = 3 mm: from the solid bar (D = 2t) up
      const double tc = TubeBucklingStress(kG, kNu, kGamma, d, 0.003, Lk);
      const double cap = TubeTorqueCapacityWithBuckling(550e6, tc, d, TubePolarMoment(d, 0.003));
      EXPECT_GE(cap, previous) << "D " << d << " L " << Lk;
      previous = cap;
    }
    previous = 0.0;
    for (int i = 0; i <= 200; ++i) {
      const double w = 0.0002 + i * (0.025 - 0.0002) / 200;  // D = 50 mm, up to the solid bar
      const double tc = TubeBucklingStress(kG, kNu, kGamma, 0.050, w, Lk);
      const double cap = TubeTorqueCapacityWithBuckling(550e6, tc, 0.050, TubePolarMoment(0.050, w));
      EXPECT_GE(cap, previous) << "t " << w << " L " << Lk;
      previous = cap;
    }
  }
}

}  // namespace
}  // namespace highlift::model
