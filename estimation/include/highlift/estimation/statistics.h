// Statistics for the empirical fits: the Student t distribution and log-log least squares.
#pragma once

#include <string>
#include <vector>

namespace highlift::estimation {

/// Regularised incomplete beta function I_x(a, b), a, b > 0, 0 <= x <= 1 (continued fraction,
/// relative accuracy about 1e-14).
double RegularizedIncompleteBeta(double a, double b, double x);

/// Cumulative distribution function of Student's t with `dof` > 0 degrees of freedom.
double StudentTCdf(double t, double dof);

/// Quantile of Student's t: the t with StudentTCdf(t, dof) = p, 0 < p < 1 (Newton steps on the
/// CDF from a bracketing bisection; |error| < 1e-12 relative). Example: p = 0.975, dof = 10:
/// 2.228138852.
double StudentTQuantile(double p, double dof);

/// Result of fitting y = a x^b by least squares on (log x, log y).
struct PowerLawFit {
  double coefficient = 0.0;     ///< a (in the SI units of y / x^b)
  double exponent = 0.0;        ///< b
  double residual_sigma = 0.0;  ///< s, standard deviation of the log residuals
  double r_squared = 0.0;       ///< coefficient of determination in log space
  std::size_t n = 0;            ///< number of points
  double mean_log_x = 0.0;      ///< for the prediction interval
  double sxx = 0.0;             ///< sum of (log x - mean)^2

  /// Nominal prediction a x^b.
  double Predict(double x) const;
  /// Prediction interval at x: exp(yhat +- t_{(1+confidence)/2, n-2} s sqrt(1 + 1/n + (u - ubar)^2/Sxx))
  /// with u = log x: the interval that holds a new part's value with probability `confidence`.
  void PredictionInterval(double x, double confidence, double* lo, double* hi) const;
};

/// Fits y = a x^b with Eigen (least squares on the logs). Needs at least 3 points with x, y > 0
/// and x not all equal; throws std::invalid_argument otherwise (callers check the count first).
PowerLawFit FitPowerLaw(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace highlift::estimation
