// Single-DOF values against simulated peaks, per component: the one comparison behind the
// bound / NOT A BOUND flags of `highlift peak --transient` (table and JSON "transient_components"),
// of the design report and of the tests (issue 26, item 3).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "highlift/core/project.h"
#include "highlift/sim/simulator.h"

namespace highlift::reduced_models {
struct PeakReport;
}

namespace highlift::campaign {

/// Relative tolerance of the comparison: a simulated torque within this of the single-DOF value
/// counts as at the bound.
inline constexpr double kBoundTolerance = 1e-6;

/// The simulated peaks of one sizing case: per component its largest |torque| at its input flange
/// (its own speed), as ComponentTorquesAtInput gives them.
struct SimulatedCase {
  std::string name;  ///< the sizing case (PeakCase::name)
  bool ok = true;    ///< the simulation ran to its end
  std::map<std::string, double> components;
};

/// A component's single-DOF value beside the largest transient torque of any simulated case, both
/// at its own speed: the single-DOF value is a bound when the simulation stays at or below it.
struct ComponentBound {
  std::string component;
  double single_dof = 0;  ///< N*m, nominal, worst over the cases that load it
  std::string single_dof_case;
  double transient = 0;   ///< N*m, largest |torque| over every simulated case
  std::string transient_case;
  /// transient / single_dof - 1 when the simulation exceeds the single-DOF value (beyond
  /// kBoundTolerance), else 0; infinite when the single-DOF analysis gives it no load.
  double exceeded_by = 0;
  bool bound() const { return exceeded_by <= 0; }
  /// "bound" or "NOT A BOUND: the simulation exceeds it by x %".
  std::string Flag() const;
};

/// The torques of a simulation's per-component peaks (sim::ComponentPeakTorques) at each
/// component's input flange: a gear's element reports the torque at its geared flange (a branch
/// gearbox: the branch), the single-DOF table at its input: times w_geared / w_input (power
/// through an ideal gear). Actuators and every other component: as reported.
std::map<std::string, double> ComponentTorquesAtInput(const Project& project, const std::vector<sim::PeakTorque>& peaks);

/// Every component of the single-DOF report's worst-case table against the simulated cases.
std::vector<ComponentBound> CompareWithTransient(const reduced_models::PeakReport& report,
                                                 const std::vector<SimulatedCase>& simulated);

}  // namespace highlift::campaign
