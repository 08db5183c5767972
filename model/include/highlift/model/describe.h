// A readable description of a project (`highlift info`): components by type, shaft length and
// mass per wing, the drive stations, the inertia reflected to the PDU output, and the parameters
// that are still unknown or only loosely known, with their provenance. The inertias and shaft
// masses come from the component models (component_model.h): each component's lumped law
// (LumpedAtInput) at nominal values and on the parameter domains, the segment mass law.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "highlift/core/domain.h"
#include "highlift/core/project.h"

namespace highlift::model {

/// Options of DescribeProject.
struct DescribeOptions {
  double wide_relative_width = 0.2;  ///< a domain is "wide" when (hi - lo) / |mid| exceeds this
};

/// Shaft totals for one side of the aircraft (component label "side": "left", "right", ...).
struct SideSummary {
  std::string side;          ///< label value; "(none)" for components without a side label
  int shaft_count = 0;       ///< torque shaft segments
  double shaft_length = 0;   ///< m, sum of the shaft lengths (nominal values)
  double shaft_mass = 0;     ///< kg, sum of the shaft masses (nominal values)
  int stations = 0;          ///< actuators (drive stations) on this side
};

/// One drive station: an actuator and the chain that drives it.
struct StationSummary {
  std::string actuator;      ///< actuator component id, e.g. "gra_l3"
  std::string type;          ///< its type (roles().actuator)
  std::string side;          ///< label "side", empty when absent
  std::string station;       ///< label "station", empty when absent
  double speed_ratio = 0;    ///< PDU output speed / actuator input speed (0 when not reachable)
  double total_ratio = 0;    ///< PDU output speed / actuator output speed (0 when unknown)
  std::vector<std::string> path;  ///< components from the PDU to the actuator
};

/// Contribution of one component to the inertia reflected to the PDU output.
struct InertiaContribution {
  std::string component;
  std::string type;
  double inertia = 0;        ///< kg*m^2, the component's own inertia at its input (its lumped law)
  double speed_ratio = 0;    ///< PDU output speed / speed of that inertia
  double reflected = 0;      ///< kg*m^2, inertia / speed_ratio^2
};

/// A parameter whose value is not known to a point, or whose domain is wide.
struct ParameterConcern {
  enum class Kind { kUnknown, kWide };
  Kind kind = Kind::kUnknown;
  std::string component;
  std::string type;
  std::string parameter;
  std::string unit;          ///< display unit of the catalogue
  std::optional<double> nominal;  ///< SI
  Domain domain;             ///< SI
  double relative_width = 0;      ///< (hi - lo) / |mid|; infinite for unbounded domains
  Provenance provenance = Provenance::kDefault;
  std::string note;
};

/// "unknown", "wide".
std::string ToString(ParameterConcern::Kind kind);

/// Everything `highlift info` says about a project.
struct ProjectDescription {
  std::string name;
  std::string file;
  std::size_t components = 0;
  std::size_t connections = 0;
  std::size_t elements = 0;
  std::size_t requirements = 0;
  std::size_t load_cases = 0;
  std::size_t scenarios = 0;

  std::vector<std::pair<std::string, int>> components_by_type;  ///< catalogue order, count > 0
  std::vector<SideSummary> sides;   ///< one per "side" label, in order of first appearance
  int shaft_count = 0;
  double shaft_length = 0;          ///< m, all shafts
  double shaft_mass = 0;            ///< kg, all shafts
  std::vector<StationSummary> stations;

  double reflected_inertia = 0;     ///< kg*m^2 at the PDU output, sum of J / speed_ratio^2
  Domain reflected_inertia_domain;  ///< kg*m^2, the same from the lumped laws on the parameter domains
  std::vector<InertiaContribution> inertias;  ///< per component, in project order
  std::vector<std::string> unreachable;       ///< components with inertia not reached from the PDU

  std::vector<ParameterConcern> concerns;     ///< unknown first, then wide; project order
  int parameters = 0;               ///< scalar parameters in all components

  /// Number of concerns of one kind.
  int CountConcerns(ParameterConcern::Kind kind) const;

  /// "A380-class ...: 95 components, 12 stations, 51 m of shaft (68 kg), J_PDU = 0.43 kg*m^2".
  std::string BriefReport() const;
  /// Aligned tables of all of the above.
  std::string FullReport() const;
  nlohmann::json ToJson() const;
};

/// Describes a loaded project. The graph should be valid (ValidateProject); components that are
/// not reached from the PDU are listed in `unreachable` instead of being reflected.
ProjectDescription DescribeProject(const Project& project, const DescribeOptions& options = {});

}  // namespace highlift::model
