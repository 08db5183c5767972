// Empirical fits over database parts: a parameter against a rating (e.g. GRA input inertia
// against output torque rating) by least squares on logarithms, with a prediction interval.
#pragma once

#include <string>
#include <vector>

#include "highlift/componentdb/database.h"
#include "highlift/core/domain.h"
#include "highlift/estimation/statistics.h"

namespace highlift::estimation {

struct FitOptions {
  double confidence = 0.90;    // probability that a new part lies inside the prediction interval
  std::size_t min_parts = 4;   // fewer parts with both values: no fit (n - 2 >= 2 degrees of freedom)
  void Validate() const;       // throws InputError for a confidence outside (0, 1) or min_parts < 3
};

/// A fitted power law y = a x^b of `parameter` against `rating` over parts of `type`.
struct EmpiricalFit {
  enum class Status { kOk, kTooFewParts };
  Status status = Status::kTooFewParts;
  std::string message;           ///< why there is no fit ("only 2 parts ..."), or a summary
  std::string type;
  std::string parameter;         ///< fitted parameter (y)
  std::string rating;            ///< rating it is fitted against (x)
  double confidence = 0.90;
  PowerLawFit law;               ///< valid when status == kOk
  std::vector<std::string> parts_used;  ///< designations of the parts in the fit
  Domain rating_range;           ///< smallest and largest rating among the parts (SI)

  bool ok() const { return status == Status::kOk; }
  /// Nominal prediction at a rating value (SI).
  double Predict(double rating_value) const;
  /// Prediction interval at `confidence` for a rating interval: the hull of the intervals at
  /// its ends (a power law is monotonic). A point rating gives the ordinary prediction interval.
  Domain PredictionInterval(const Domain& rating_domain) const;
  /// True when the rating lies outside the range the parts cover (an extrapolation).
  bool Extrapolates(const Domain& rating_domain) const;
  /// "input_inertia = 3.5e-07 * output_torque_rating^1.62 (22 parts, r^2 0.91, s 0.12)".
  std::string BriefReport() const;
};

/// Fits `parameter` against `rating` over `parts` of `type` that have both values > 0 (the
/// representative value of each: its nominal value, else its interval midpoint). With fewer
/// than options.min_parts such parts the status is kTooFewParts and the message gives the count.
EmpiricalFit FitParameter(const std::vector<componentdb::Part>& parts, const std::string& type,
                          const std::string& parameter, const std::string& rating, const FitOptions& options = {});
/// The same over every part of `type` in a database.
EmpiricalFit FitParameter(const componentdb::ComponentDatabase& database, const std::string& type,
                          const std::string& parameter, const std::string& rating, const FitOptions& options = {});

}  // namespace highlift::estimation
