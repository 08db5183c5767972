// Steady-state sizing of a drive-system project: the torque flow from the actuator loads up to
// the PDU for every load case, point values and guaranteed interval enclosures; recommended
// torque-limiter and brake settings; margins against the components' allowables.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "highlift/core/domain.h"
#include "highlift/core/project.h"

namespace highlift::reduced_models {

/// A point value (parameters at their nominal values) and a guaranteed enclosure (parameters
/// over their interval domains).
struct Bounded {
  double nominal = 0.0;
  Domain bounds = Domain::Point(0.0);
  /// Width of `bounds` over the width of the hull of the values at sampled points of the
  /// domains (the options' tightness_samples): 1 is exact, 2 twice as wide as what the samples
  /// reach. 0 when not measured. Widths under 1e-6 of the magnitude count as that floor (so a
  /// value no parameter moves reads 1, not a ratio of round-off widths).
  double tightness = 0.0;

  /// Sets `tightness` from the hull [lo, hi] of the sampled values.
  void SetTightness(double lo, double hi);
};

/// allowable / load - 1 rounded down: no exact quotient lies below it, and an exact result (a
/// load equal to its allowable gives 0) is not pushed below by rounding. `load` > 0.
double GuaranteedMargin(double allowable, double load);

/// {"nominal", "min", "max"} and, when measured, "tightness".
nlohmann::json ToJson(const Bounded& b);

/// Hull of sampled values of several enclosures, for Bounded::SetTightness.
struct SampledHull {
  std::vector<double> lo, hi;
  explicit SampledHull(std::size_t count);
  void Add(std::size_t i, double value);
};

struct ComponentTorque {
  std::string component;
  std::string type;
  double speed = 0.0;        ///< rad/s at the input flange
  Bounded torque;            ///< N*m at the input flange, at the component's own speed (positive resists motion)
};

struct LoadCaseSizing {
  std::string load_case;
  std::string direction;     ///< "extend" / "retract"
  double pdu_speed = 0.0;    ///< rad/s, the largest speed of the case's PDU profile
  std::vector<ComponentTorque> components;  ///< power-flow order, PDU first
  Bounded pdu_torque;        ///< N*m, PDU output torque, both sides
  Bounded pdu_power;         ///< W, output power: torque * speed
  Bounded pdu_input_power;   ///< W, divided by the PDU efficiency
};

/// A recommended setting: factor x operating torque, with the rule's range of factors.
struct SettingRecommendation {
  std::string component;
  std::string parameter;     ///< e.g. "lockout_torque_extend", "static_capacity"
  std::string rule;          ///< e.g. "1.2-1.4 x max operating wing torque (domain.md s6)"
  Bounded operating;         ///< N*m, the torque the rule refers to
  double factor = 0.0;       ///< recommended factor
  double factor_min = 0.0;
  double factor_max = 0.0;
  double recommended = 0.0;  ///< N*m = factor * nominal operating torque
  Domain recommended_robust; ///< N*m, settings within the rule over the whole enclosure
                             ///< [factor_min * op.hi, factor_max * op.lo] (empty when none)
  std::optional<double> current;  ///< N*m, the project's value
  double current_factor = 0.0;    ///< current / nominal operating torque
  bool ok = true;                 ///< current factor within [factor_min, factor_max]
  bool robust = true;             ///< current within the rule for every operating torque of the enclosure
};

struct AllowableMargin {
  std::string component;
  std::string allowable_name;  ///< e.g. "torque capacity (allowable shear stress)"
  double load = 0.0;           ///< N*m, the largest operating torque (upper bound), own speed
  double allowable = 0.0;      ///< N*m; with intervals the smallest value over the domains
  double margin = 0.0;         ///< allowable / load - 1, outward rounded: with intervals no point of
                               ///< the domains has a smaller margin
};

struct SizingReport {
  std::string project;
  std::vector<LoadCaseSizing> cases;
  std::vector<SettingRecommendation> settings;
  std::vector<AllowableMargin> margins;
  double shaft_mass = 0.0;     ///< kg, all torque shafts
  bool ok() const;             ///< every current setting within its rule and every margin >= 0
  std::string BriefReport() const;
  std::string FullReport() const;
  nlohmann::json ToJson() const;
};

struct SizingOptions {
  bool intervals = true;       ///< also compute enclosures over the parameter domains
  /// Points of the domains at which the sizing is evaluated to measure the tightness of the
  /// enclosures (Bounded::tightness); 0: not measured. Each costs one point evaluation.
  int tightness_samples = 0;
  std::uint64_t tightness_seed = 1;  ///< seed of the sampler (sampling.h)
};

/// Throws InputError when the project has no PDU, no load case, or a value the laws need.
SizingReport Size(const Project& project, const SizingOptions& options = {});
/// Fills the tightness of the enclosures of `report` (made by Size with intervals) from
/// options.tightness_samples point evaluations (Size calls it when that is > 0).
void MeasureTightness(const Project& project, const SizingOptions& options, SizingReport* report);

/// Total mass of the torque shafts [kg] (nominal values).
double ShaftMass(const Project& project);

}  // namespace highlift::reduced_models
