// The soundness property of every interval the tool reports: for points drawn from the
// parameter domains (corners, interior points, points one ulp inside a bound), the value the
// point code path computes lies inside the enclosure computed over the domains.
//
// Checked: `size` (per load case the PDU torque, power and input power and every component
// torque; the operating torque of every setting rule; the margins, which are guaranteed lower
// bounds) and `peak` (per case w_max, tau_dynamic, tau_static and tau_total; per component the
// worst torque and the margin). `check` has its own property (the propagator never removes a
// feasible point): CheckDomainSoundness.
//
// Used by tests/soundness/soundness_test.cc (10^4 points in CI) and by
// bench/soundness/soundness_stress.cc (10^6 points, seed on the command line).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "highlift/core/project.h"

namespace highlift::testing {

struct SoundnessOptions {
  int points = 100;             ///< sampled points per project
  std::uint64_t seed = 1;       ///< sampler seed (a failure names it, so it reproduces)
  bool size = true;             ///< check the sizing enclosures
  bool peak = true;             ///< check the peak-load enclosures
  /// A point value may exceed its enclosure by this much relative to its magnitude: the point
  /// code path rounds to nearest (a few ulps), the enclosure is outward rounded around the exact
  /// value. 1e-12 is about 4500 ulps, far below any physical significance and far below the
  /// defects this test exists to catch (a nominal term in a bound moves it by percents).
  double relative_slack = 1e-12;
};

struct SoundnessResult {
  int points = 0;                        ///< points evaluated
  long checks = 0;                       ///< containments checked
  std::vector<std::string> violations;   ///< one line each: project, seed, point, what, value, enclosure
  void Merge(const SoundnessResult& other);
};

/// Draws options.points points of the project's uncertain parameters and checks every enclosure
/// of `size` and `peak` against the point values.
SoundnessResult CheckEnclosures(const Project& project, const SoundnessOptions& options);

/// The propagator keeps every feasible point: for drawn points at which the project's
/// constraint network (physics and requirements) is feasible, every parameter's value lies in
/// the domain `check` narrowed to, and every derived quantity's point enclosure meets its
/// narrowed domain.
SoundnessResult CheckDomainSoundness(const Project& project, const SoundnessOptions& options);

/// The slices of `highlift tradeoff` keep every feasible point: the domain of `parameter`
/// ("component.parameter", an uncertain variable of the network) split into `slices`, each
/// propagated from the initial box met with the slice (as the command does); for drawn points
/// whose `parameter` lies in the slice and at which the network is feasible, every variable's
/// point enclosure meets the slice's narrowed domain.
SoundnessResult CheckTradeoffSoundness(const Project& project, const std::string& parameter, int slices,
                                       const SoundnessOptions& options);

/// Options of a random one- or two-wing chain project.
struct RandomProjectOptions {
  int max_stations = 5;         ///< stations per wing, 1..max
  bool allow_two_wings = true;
};

/// A random drive system that the reduced models accept: PDU, optional system torque limiter,
/// shafts (random lengths, tube sizes and domains), optional bearings and joints, stations
/// (branch gearbox + station torque limiter + geared rotary actuator), a wing-tip brake and a
/// position sensor; load cases extend (opposing) and retract (aiding), with or without a PDU
/// speed profile (without one, the PDU's max_output_speed domain is the speed). The same seed
/// gives the same project.
Project RandomChainProject(std::uint64_t seed, const RandomProjectOptions& options = {});

}  // namespace highlift::testing
