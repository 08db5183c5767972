// The interval constraint network of a drive-system project: every parameter of every component
// is a variable (its project domain, or its nominal value), every component type contributes its
// physics, derived quantities get names the requirements can use, and every requirement of the
// project is a constraint.
//
// Names: "<component>.<parameter>" for parameters; derived quantities:
//   <shaft>.polar_moment, .c (stiffness), .J (inertia), .mass, .buckling_stress (torsional
//   buckling), .torque_capacity (at the lesser of the allowable and the buckling stress: a
//   requirement on a tube's strength reads it, as the examples' jam requirements do),
//   .drive_torque, .shear_stress; <component>.reflected_inertia / .reflected_stiffness (at the PDU speed) and
//   .series_stiffness (the drive line from the PDU to it, in series); <actuator>.max_load,
//   .input_torque_opposing, .input_torque_aiding; <branch gearbox>.station_torque;
//   torque.<load case>.<component> (the steady-state torque flow of reduced_models' sizing, with
//   friction and the opposing/aiding efficiencies); <limiter>.torque_through, .margin,
//   .torque_through_retract, .margin_retract; <wtb>.holding_torque, .holding_margin;
//   pdu.output_torque, pdu.required_power, pdu.operating_speed; travel_time.<load case> and
//   travel_time.extension (with the ramps of the speed profile); and for the sizing cases of reduced_models (`highlift
//   peak`) that a scenario names or a requirement mentions: peak.<case>.speed / .omega (first
//   eigenfrequency, a monotone black box over reduced_models' lumped model) / .inertia (J*) /
//   .stiffness (c* = J* w1^2) / .torque (the paper's equation (1), w sqrt(c* J*)) /
//   .static_torque / .total_torque, and peak.<case>.<component> for the components the peak
//   passes through. docs/icsp.md describes the physics.
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
  std::vector<std::pair<int, double>> nominal;  ///< variable index -> the parameter's nominal value (SI)
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
  /// The nominal design: every parameter with a nominal value fixed at it. When the domains can
  /// meet the requirements but the nominal values cannot, this names what the nominal design
  /// violates (the domains were narrowed away from it).
  bool nominal_checked = false;
  bool nominal_feasible = true;
  Explanation nominal_explanation;  ///< when the nominal design is infeasible
};

/// Propagates the project network and, when infeasible, explains it; when feasible, also checks
/// the nominal design and explains what it violates.
CheckResult CheckDriveSystem(const DriveSystemNetwork& net, const PropagationOptions& options = {});

/// Value in SI converted to `unit` for display (SI when the unit is empty or not convertible).
double ToDisplay(double si, const std::string& unit);

}  // namespace highlift::icsp
