// The interval constraint network of a drive-system project: every parameter of every component
// is a variable (its project domain, or its nominal value), every component type contributes its
// physics, derived quantities get names the requirements can use, and every requirement of the
// project is a constraint.
//
// Names: "<component>.<parameter>" for parameters; derived quantities:
//   <shaft>.polar_moment, .c (stiffness), .J (inertia), .mass, .torque_capacity, .drive_torque,
//   .shear_stress; <gra>.max_load, .input_torque_opposing, .input_torque_aiding,
//   .reflected_inertia; <branch gearbox>.station_torque; <limiter>.torque_through, .margin;
//   <wtb>.holding_torque, .holding_margin; pdu.reflected_inertia, pdu.output_torque,
//   pdu.required_power; travel_time.extension; peak.<scenario>.stiffness / .inertia / .speed /
//   .torque and peak.<scenario>.<component> for the components the peak load passes through
//   (the paper's equation (1), tau = w * sqrt(c* J*), with c* the series stiffness of the shafts
//   on the load path and J* the inertia that the stop must absorb).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "highlift/core/project.h"
#include "highlift/icsp/network.h"
#include "highlift/icsp/propagator.h"

namespace highlift::icsp {

struct DriveSystemNetwork {
  Network network;
  std::map<int, std::string> requirement_of;  ///< constraint index -> requirement id
  int physics_constraints = 0;
  int requirement_constraints = 0;
};

/// Builds the network. Throws InputError when a requirement does not parse or names an unknown
/// quantity (with the requirement's location and a "did you mean").
DriveSystemNetwork BuildDriveSystemNetwork(const Project& project);

/// One row of the check table.
struct ParameterResult {
  std::string name;
  std::string unit;        ///< display unit of the values below
  std::string provenance;
  Interval initial;        ///< in the display unit
  Interval final;          ///< in the display unit (empty when infeasible)
  double narrowing_percent = 0.0;  ///< 100 * (1 - final width / initial width); 0 for unbounded
};

struct CheckResult {
  PropagationReport report;
  std::vector<ParameterResult> parameters;
  bool feasible = true;
  Explanation explanation;     ///< when infeasible
};

/// Propagates the project network and, when infeasible, explains it.
CheckResult CheckDriveSystem(const DriveSystemNetwork& net, const PropagationOptions& options = {});

/// Value in SI converted to `unit` for display (SI when the unit is empty or not convertible).
double ToDisplay(double si, const std::string& unit);

}  // namespace highlift::icsp
