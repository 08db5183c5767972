#include "highlift/estimation/statistics.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "highlift/core/error.h"

namespace highlift::estimation {
namespace {

// Continued fraction of the incomplete beta function (modified Lentz).
double BetaContinuedFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  constexpr double kEpsilon = 1e-15;
  const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
  double c = 1.0;
  double d = 1.0 - qab * x / qap;
  if (std::fabs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 10000; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < kEpsilon) return h;
  }
  return h;  // converges in far fewer steps for the a, b used here
}

double StudentTDensity(double t, double dof) {
  const double log_norm = std::lgamma(0.5 * (dof + 1.0)) - std::lgamma(0.5 * dof) - 0.5 * std::log(dof * M_PI);
  return std::exp(log_norm - 0.5 * (dof + 1.0) * std::log1p(t * t / dof));
}

}  // namespace

double RegularizedIncompleteBeta(double a, double b, double x) {
  HIGHLIFT_CHECK(a > 0 && b > 0, "incomplete beta needs a, b > 0");
  HIGHLIFT_CHECK(x >= 0 && x <= 1, "incomplete beta needs 0 <= x <= 1");
  if (x == 0.0 || x == 1.0) return x;
  const double log_front =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  // The continued fraction converges fast for x < (a + 1)/(a + b + 2); use the symmetry
  // I_x(a, b) = 1 - I_{1-x}(b, a) otherwise.
  if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(log_front) * BetaContinuedFraction(a, b, x) / a;
  return 1.0 - std::exp(log_front) * BetaContinuedFraction(b, a, 1.0 - x) / b;
}

double StudentTCdf(double t, double dof) {
  HIGHLIFT_CHECK(dof > 0, "Student t needs dof > 0");
  if (std::isinf(t)) return t > 0 ? 1.0 : 0.0;
  // P(|T| > |t|) = I_{dof/(dof + t^2)}(dof/2, 1/2).
  const double tail = 0.5 * RegularizedIncompleteBeta(0.5 * dof, 0.5, dof / (dof + t * t));
  return t > 0 ? 1.0 - tail : tail;
}

double StudentTQuantile(double p, double dof) {
  HIGHLIFT_CHECK(p > 0 && p < 1, "Student t quantile needs 0 < p < 1");
  HIGHLIFT_CHECK(dof > 0, "Student t needs dof > 0");
  if (p == 0.5) return 0.0;
  if (p < 0.5) return -StudentTQuantile(1.0 - p, dof);
  // Bracket [lo, hi] with cdf(lo) <= p < cdf(hi), then safeguarded Newton.
  double lo = 0.0, hi = 1.0;
  while (StudentTCdf(hi, dof) < p) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e300) return hi;
  }
  double t = 0.5 * (lo + hi);
  for (int i = 0; i < 200; ++i) {
    const double f = StudentTCdf(t, dof) - p;
    if (f < 0) lo = t;
    else hi = t;
    const double density = StudentTDensity(t, dof);
    double next = density > 0 ? t - f / density : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - t) <= 1e-14 * std::fabs(next) || hi - lo <= 1e-14 * hi) return next;
    t = next;
  }
  return t;
}

double PowerLawFit::Predict(double x) const { return coefficient * std::pow(x, exponent); }

void PowerLawFit::PredictionInterval(double x, double confidence, double* lo, double* hi) const {
  HIGHLIFT_CHECK(n >= 3, "a prediction interval needs at least 3 points");
  HIGHLIFT_CHECK(confidence > 0 && confidence < 1, "confidence must lie in (0, 1)");
  const double u = std::log(x);
  const double yhat = std::log(coefficient) + exponent * u;
  const double t = StudentTQuantile(0.5 * (1.0 + confidence), static_cast<double>(n - 2));
  const double se = residual_sigma * std::sqrt(1.0 + 1.0 / static_cast<double>(n) +
                                               (u - mean_log_x) * (u - mean_log_x) / sxx);
  *lo = std::exp(yhat - t * se);
  *hi = std::exp(yhat + t * se);
}

PowerLawFit FitPowerLaw(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) throw std::invalid_argument("FitPowerLaw: x and y differ in length");
  const auto n = static_cast<Eigen::Index>(x.size());
  if (n < 3) throw std::invalid_argument("FitPowerLaw: at least 3 points are needed, got " + std::to_string(n));
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd logy(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!(x[k] > 0) || !(y[k] > 0)) throw std::invalid_argument("FitPowerLaw: x and y must be > 0");
    design(i, 0) = 1.0;
    design(i, 1) = std::log(x[k]);
    logy(i) = std::log(y[k]);
  }
  PowerLawFit fit;
  fit.n = x.size();
  fit.mean_log_x = design.col(1).mean();
  fit.sxx = (design.col(1).array() - fit.mean_log_x).square().sum();
  if (!(fit.sxx > 0)) throw std::invalid_argument("FitPowerLaw: all x are equal; no exponent can be fitted");
  const Eigen::Vector2d beta = design.colPivHouseholderQr().solve(logy);
  const Eigen::VectorXd residual = logy - design * beta;
  fit.coefficient = std::exp(beta(0));
  fit.exponent = beta(1);
  fit.residual_sigma = std::sqrt(residual.squaredNorm() / static_cast<double>(n - 2));
  const double syy = (logy.array() - logy.mean()).square().sum();
  fit.r_squared = syy > 0 ? 1.0 - residual.squaredNorm() / syy : 1.0;
  return fit;
}

}  // namespace highlift::estimation
