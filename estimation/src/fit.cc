#include "highlift/estimation/fit.h"

#include <algorithm>
#include <cmath>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"

namespace highlift::estimation {

void FitOptions::Validate() const {
  if (!(confidence > 0 && confidence < 1))
    throw InputError("fit confidence " + FormatNumber(confidence) + " must lie strictly between 0 and 1 (e.g. 0.9)");
  if (min_parts < 3) throw InputError("fit min_parts " + std::to_string(min_parts) + " must be at least 3 (two coefficients and one degree of freedom)");
}

double EmpiricalFit::Predict(double rating_value) const {
  HIGHLIFT_CHECK(ok(), "EmpiricalFit::Predict without a fit");
  return law.Predict(rating_value);
}

Domain EmpiricalFit::PredictionInterval(const Domain& r) const {
  HIGHLIFT_CHECK(ok(), "EmpiricalFit::PredictionInterval without a fit");
  HIGHLIFT_CHECK(r.lo > 0 && std::isfinite(r.hi), "a fit needs a positive, bounded rating");
  double lo1, hi1, lo2, hi2;
  law.PredictionInterval(r.lo, confidence, &lo1, &hi1);
  law.PredictionInterval(r.hi, confidence, &lo2, &hi2);
  return {std::min(lo1, lo2), std::max(hi1, hi2)};
}

bool EmpiricalFit::Extrapolates(const Domain& r) const { return r.lo < rating_range.lo || r.hi > rating_range.hi; }

std::string EmpiricalFit::BriefReport() const {
  if (!ok()) return message;
  return parameter + " = " + FormatNumber(law.coefficient) + " * " + rating + "^" + FormatNumber(law.exponent, 3) +
         " (" + std::to_string(law.n) + " " + type + " parts, r^2 " + FormatNumber(law.r_squared, 3) +
         ", log sigma " + FormatNumber(law.residual_sigma, 3) + ", " + FormatNumber(100 * confidence, 3) +
         " % prediction interval)";
}

EmpiricalFit FitParameter(const std::vector<componentdb::Part>& parts, const std::string& type,
                          const std::string& parameter, const std::string& rating, const FitOptions& options) {
  options.Validate();
  EmpiricalFit fit;
  fit.type = type;
  fit.parameter = parameter;
  fit.rating = rating;
  fit.confidence = options.confidence;
  std::vector<double> x, y;
  for (const auto& p : parts) {
    if (p.type != type) continue;
    const auto* qx = p.Find(rating);
    const auto* qy = p.Find(parameter);
    if (!qx || !qy) continue;
    const double vx = qx->Representative(), vy = qy->Representative();
    if (!(vx > 0) || !(vy > 0) || !std::isfinite(vx) || !std::isfinite(vy)) continue;
    x.push_back(vx);
    y.push_back(vy);
    fit.parts_used.push_back(p.designation);
  }
  const std::size_t n = x.size();
  const bool spread = n > 0 && *std::min_element(x.begin(), x.end()) < *std::max_element(x.begin(), x.end());
  if (n < options.min_parts || !spread) {
    fit.status = EmpiricalFit::Status::kTooFewParts;
    fit.message = "no fit of " + type + "." + parameter + " against " + rating + ": " +
                  (n < options.min_parts ? "only " + std::to_string(n) + " database part" + (n == 1 ? "" : "s") +
                                               " of type " + type + " have both values, at least " +
                                               std::to_string(options.min_parts) + " are needed"
                                         : "all " + std::to_string(n) + " parts have the same " + rating) +
                  "; import more parts (highlift db import) or give the value";
    return fit;
  }
  fit.law = FitPowerLaw(x, y);
  fit.rating_range = {*std::min_element(x.begin(), x.end()), *std::max_element(x.begin(), x.end())};
  fit.status = EmpiricalFit::Status::kOk;
  fit.message = fit.BriefReport();
  return fit;
}

EmpiricalFit FitParameter(const componentdb::ComponentDatabase& database, const std::string& type,
                          const std::string& parameter, const std::string& rating, const FitOptions& options) {
  return FitParameter(database.Parts(type), type, parameter, rating, options);
}

}  // namespace highlift::estimation
