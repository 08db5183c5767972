#include "highlift/core/domain.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace highlift {

bool Domain::bounded() const { return std::isfinite(lo) && std::isfinite(hi); }

double Domain::mid() const {
  if (empty()) return std::numeric_limits<double>::quiet_NaN();
  if (bounded()) return lo + 0.5 * (hi - lo);
  if (std::isfinite(lo)) return lo;  // [lo, inf): the finite end is the best guess
  if (std::isfinite(hi)) return hi;
  return 0.0;
}

Domain Domain::intersect(const Domain& o) const { return {std::max(lo, o.lo), std::min(hi, o.hi)}; }

namespace {
constexpr std::array<std::pair<Provenance, const char*>, 7> kProvenanceNames = {{
    {Provenance::kUser, "user"},
    {Provenance::kDatabase, "database"},
    {Provenance::kFit, "fit"},
    {Provenance::kEstimated, "estimated"},
    {Provenance::kDefault, "default"},
    {Provenance::kPropagated, "propagated"},
    {Provenance::kOptimized, "optimized"},
}};
}  // namespace

std::string ToString(Provenance p) {
  for (const auto& [value, name] : kProvenanceNames)
    if (value == p) return name;
  return "unknown";
}

std::optional<Provenance> ProvenanceFromString(const std::string& s) {
  for (const auto& [value, name] : kProvenanceNames)
    if (s == name) return value;
  return std::nullopt;
}

}  // namespace highlift
