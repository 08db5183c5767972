// Student t quantiles and the power-law fit.
#include <gtest/gtest.h>

#include <boost/math/distributions/students_t.hpp>
#include <random>

#include "highlift/estimation/statistics.h"

namespace highlift::estimation {
namespace {

TEST(StudentTQuantile, MatchesTableValues) {
  EXPECT_NEAR(StudentTQuantile(0.975, 10), 2.228138851986, 1e-10);
  EXPECT_NEAR(StudentTQuantile(0.95, 1), 6.313751514675, 1e-9);
  EXPECT_NEAR(StudentTQuantile(0.995, 30), 2.749995653567, 1e-10);
  EXPECT_NEAR(StudentTQuantile(0.95, 2), 2.919985580354, 1e-10);
  EXPECT_NEAR(StudentTQuantile(0.025, 10), -2.228138851986, 1e-10);
  EXPECT_EQ(StudentTQuantile(0.5, 7), 0.0);
}

TEST(StudentTQuantile, AgreesWithBoostMathOverAGrid) {
  for (double dof : {1.0, 2.0, 3.0, 5.0, 8.0, 20.0, 100.0, 1000.0})
    for (double p : {0.001, 0.05, 0.3, 0.6, 0.9, 0.95, 0.975, 0.999}) {
      const double expected = boost::math::quantile(boost::math::students_t(dof), p);
      EXPECT_NEAR(StudentTQuantile(p, dof), expected, 1e-9 * std::max(1.0, std::fabs(expected)))
          << "p " << p << " dof " << dof;
      EXPECT_NEAR(StudentTCdf(expected, dof), p, 1e-12);
    }
}

TEST(FitPowerLaw, RecoversAKnownExponentFromExactData) {
  std::vector<double> x, y;
  for (double v : {2e3, 3e3, 5e3, 8e3, 13e3, 21e3}) {
    x.push_back(v);
    y.push_back(3e-7 * std::pow(v, 1.7));
  }
  const PowerLawFit fit = FitPowerLaw(x, y);
  EXPECT_NEAR(fit.exponent, 1.7, 1e-10);
  EXPECT_NEAR(fit.coefficient, 3e-7, 3e-7 * 1e-9);
  EXPECT_NEAR(fit.residual_sigma, 0.0, 1e-10);
  EXPECT_NEAR(fit.r_squared, 1.0, 1e-12);
  EXPECT_NEAR(fit.Predict(10e3), 3e-7 * std::pow(10e3, 1.7), 1e-12);
}

TEST(FitPowerLaw, PredictionIntervalCoversNewPointsAtItsConfidence) {
  // Synthetic data with log-normal scatter (fixed seed): over many data sets, a 90 % prediction
  // interval must hold a new point about 90 % of the time.
  std::mt19937 random(12345);
  std::normal_distribution<double> noise(0.0, 0.2);
  std::uniform_real_distribution<double> rating(std::log(2e3), std::log(25e3));
  const int trials = 400;
  int covered = 0;
  double exponent_sum = 0;
  for (int k = 0; k < trials; ++k) {
    std::vector<double> x, y;
    for (int i = 0; i < 8; ++i) {
      const double xv = std::exp(rating(random));
      x.push_back(xv);
      y.push_back(5e-8 * std::pow(xv, 5.0 / 3.0) * std::exp(noise(random)));
    }
    const PowerLawFit fit = FitPowerLaw(x, y);
    exponent_sum += fit.exponent;
    const double x_new = std::exp(rating(random));
    const double y_new = 5e-8 * std::pow(x_new, 5.0 / 3.0) * std::exp(noise(random));
    double lo, hi;
    fit.PredictionInterval(x_new, 0.90, &lo, &hi);
    covered += (lo <= y_new && y_new <= hi) ? 1 : 0;
  }
  EXPECT_NEAR(exponent_sum / trials, 5.0 / 3.0, 0.03);
  EXPECT_NEAR(static_cast<double>(covered) / trials, 0.90, 0.04);
}

TEST(FitPowerLaw, RejectsTooFewPointsAndEqualRatings) {
  EXPECT_THROW(FitPowerLaw({1, 2}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(FitPowerLaw({2, 2, 2}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(FitPowerLaw({1, -2, 3}, {1, 2, 3}), std::invalid_argument);
}

}  // namespace
}  // namespace highlift::estimation
