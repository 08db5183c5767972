// Estimation of a project's parameters from everything known, in trust order:
//   user value > database part > fit over database parts > physics estimate > catalogue default.
// Each estimate is intersected with what is already known about the parameter; an empty
// intersection is a conflict naming both sources, and the more trusted value is kept.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "highlift/componentdb/database.h"
#include "highlift/core/domain.h"
#include "highlift/core/project.h"
#include "highlift/estimation/fit.h"

namespace highlift::estimation {

struct EstimationOptions {
  double confidence = 0.90;       // prediction-interval confidence of the empirical fits
  std::size_t min_fit_parts = 4;  // a fit needs at least this many database parts
  bool use_database = true;       // resolve database parts and materials
  bool use_fits = true;           // fit parameters against ratings over database parts
  bool use_physics = true;        // physics laws (shaft stiffness, reflected inertia, ...)
  void Validate() const;          // throws InputError naming the bad option
};

/// What the estimator did to one parameter of one component (every scalar parameter is listed).
struct ParameterEstimate {
  std::string component;
  std::string type;
  std::string parameter;
  std::string unit;               ///< display unit (catalogue)
  std::optional<double> nominal;  ///< SI
  Domain domain;                  ///< SI
  Provenance provenance = Provenance::kDefault;
  std::string note;
  bool changed = false;           ///< the estimator changed the value, domain or provenance
};

/// Two sources whose values do not overlap. The more trusted one is kept.
struct EstimationConflict {
  std::string component;
  std::string parameter;
  Provenance kept = Provenance::kUser;
  Domain kept_domain;
  Provenance rejected = Provenance::kDefault;
  Domain rejected_domain;
  std::string message;  ///< names the thing, both sources with their values, and the remedy
};

/// A quantity computed for information (not a catalogue parameter): PDU output inertia,
/// shaft torque capacity and mass.
struct DerivedQuantity {
  std::string component;
  std::string name;
  std::string unit;
  std::optional<double> nominal;  ///< SI
  Domain domain;                  ///< SI
  std::string note;
};

struct EstimationReport {
  enum class Status {
    kOk,         ///< every estimate fitted what was known
    kConflicts,  ///< at least one conflict: the more trusted value was kept, see `conflicts`
  };
  Status status = Status::kOk;
  std::vector<ParameterEstimate> parameters;
  std::vector<EstimationConflict> conflicts;
  std::vector<DerivedQuantity> derived;
  std::vector<EmpiricalFit> fits;      ///< every fit tried (with its parts, or why there is none)
  std::vector<std::string> messages;   ///< notes: missing inputs for a law, extrapolated fits
  std::size_t from_database = 0, from_fit = 0, from_physics = 0;
  double seconds = 0.0;

  /// "estimated 37 parameters (database 12, fit 3, physics 22), 0 conflicts".
  std::string BriefReport() const;
  /// Tables of the changed parameters, conflicts, derived quantities and fits. With
  /// `all_parameters`, every parameter is listed.
  std::string FullReport(bool all_parameters = false) const;
  nlohmann::json ToJson() const;
};

std::string ToString(EstimationReport::Status status);

/// Fills in the parameters of `project` that have no user value, from the database (parts
/// referenced by {"part": ...} or by a component label "part", materials by a label
/// "material"), fits over database parts and physics laws, and narrows user intervals by them.
/// `database` may be null (then only physics laws apply). Throws InputError when the project
/// references a database part that does not exist or has the wrong type.
EstimationReport EstimateProject(Project& project, const componentdb::ComponentDatabase* database,
                                 const EstimationOptions& options = {});

}  // namespace highlift::estimation
