// The interval domain of a parameter, and where its value came from.
#pragma once

#include <limits>
#include <optional>
#include <string>

namespace highlift {

/// A closed interval [lo, hi] of SI values; either side may be infinite. Empty when lo > hi.
/// This is the storage type of domains; the icsp module does sound arithmetic on it.
struct Domain {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();

  static Domain Point(double v) { return {v, v}; }
  static Domain Whole() { return {}; }
  static Domain Empty() { return {1.0, 0.0}; }
  bool empty() const { return !(lo <= hi); }
  bool bounded() const;
  bool is_point() const { return lo == hi; }
  bool contains(double v) const { return lo <= v && v <= hi; }
  double width() const { return hi - lo; }
  double mid() const;
  Domain intersect(const Domain& o) const;
  friend bool operator==(const Domain&, const Domain&) = default;
};

/// Where a parameter's value came from, in trust order (user first).
enum class Provenance { kUser, kDatabase, kFit, kEstimated, kDefault, kPropagated, kOptimized };

/// "user", "database", "fit", "estimated", "default", "propagated", "optimized" (a value chosen by
/// `highlift optimize`).
std::string ToString(Provenance p);
/// Inverse of ToString; nullopt for an unknown name.
std::optional<Provenance> ProvenanceFromString(const std::string& s);

}  // namespace highlift
