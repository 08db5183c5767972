// The one translation of a drive-system project (catalogue components, load cases, scenarios)
// into an element network of HighLift and MSL element types, built automatically from the
// component graph. The simulator integrates this network (highlift/sim/drive_network.h adds the
// simulation options) and `highlift export` writes the same network as a Modelica model, so a
// simulated model and an exported one are the same object by construction.
//
//   const Project project = LoadProject("examples/a380_class_flaps.json");
//   highlift::model::DriveModel model = highlift::model::BuildDriveModel(project, {.scenario = "rupture_wtb"});
//   for (const auto& e : model.network.elements()) ...
//
// Instance names follow the component ids: a PDU with id pdu gives pdu.w, pdu.phi, pdu.tau,
// a torque limiter "stl_left" (stl_left.y, stl_left.tau), a wing-tip brake "wtb_left", an
// actuator "gra_l3". A torque shaft of the full model is the chain of spring-dampers
// "shaft_l3.e1" .. "shaft_l3.eN" (e1 at port a) between the shaft inertias "shaft_l3.m0" ..
// "shaft_l3.mN"; the reduced model lumps a chain of shafts, bearings and joints into
// "<chain>.mass_a", the spring-damper "<chain>.spring" and "<chain>.mass_b". In both,
// `<shaft>.tau` is a derived column: the torque the shaft receives at its port a, positive when
// the port-a side drives the shaft in the positive (extend) direction
// (= -tau of the spring-damper next to port a, MSL sign convention).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "highlift/core/project.h"
#include "highlift/model/network.h"

namespace highlift::model {

/// Resolution of the model of the transmission.
enum class DriveResolution {
  kFull,     ///< every torque shaft split into shaft_elements spring-dampers between inertias
  kReduced,  ///< inertias lumped at gearboxes and stations (chains of shafts, bearings, joints
             ///< become one spring-damper with their series stiffness)
};
std::string ToString(DriveResolution resolution);
/// "full" or "reduced"; throws InputError naming the value and the choices otherwise.
DriveResolution ParseDriveResolution(const std::string& text);

struct DriveNetworkOptions {
  /// Model resolution, see DriveResolution.
  DriveResolution resolution = DriveResolution::kFull;
  /// Spring-dampers per torque shaft in the full model; 0: the project's
  /// settings.shaft_elements, but at least kMinShaftElements.
  int shaft_elements = 0;
  /// The scenario to apply (its load case, failure and stop time); empty: the only scenario of
  /// the project, or none (the drive at rest) when the project has no scenario.
  std::string scenario;
  /// Regularisation speed of the bearing, gear and actuator friction, rad/s (the element
  /// parameter w_small): the friction and load-dependent losses are scaled by
  /// tanh(w/friction_speed), so the many bearings and gears of a transmission do not switch
  /// between stuck and sliding (each switch an integrator restart). 0: the exact stick/slip
  /// law of the HighLift classes. Brakes (pressure-off brakes, wing-tip brakes, the brakes of
  /// the torque limiters) always keep their exact stick/slip law: they must hold.
  double friction_speed = 0.1;

  static constexpr int kMinShaftElements = 4;  ///< default lower bound of the split
  /// Upper bound of shaft_elements: the one range of --elements of simulate, peak, report and
  /// campaign (a model of 1000 elements per shaft has about 10^5 states).
  static constexpr int kMaxShaftElements = 1000;

  /// Throws InputError naming the option when a value is invalid.
  void Validate() const;
};

/// A column computed from another one: name = factor * source.
struct DerivedColumn {
  std::string name;    ///< e.g. "shaft_l3.tau"
  std::string source;  ///< e.g. "shaft_l3.e1.tau"
  double factor = 1.0;
};

/// The simulation model of a drive-system project.
struct DriveModel {
  Network network;
  DriveResolution resolution = DriveResolution::kFull;
  int shaft_elements = 0;            ///< spring-dampers per shaft (full model)
  std::optional<Scenario> scenario;  ///< the scenario applied, if any
  std::string load_case;             ///< its load case, if any
  double stop_time = 10.0;           ///< s, the scenario's stop time
  /// Component-level columns added by DerivedColumnSink (shaft torques).
  std::vector<DerivedColumn> derived;
  /// Element id -> the project component it belongs to ("" for scenario parts such as the
  /// monitor or the load tables).
  std::map<std::string, std::string> component_of;
  /// Speed of each component relative to the PDU output (through the gear ratios).
  std::map<std::string, double> speed_factor;
  /// Reduced model: the lumped chains, "chain: member, member, ...".
  std::vector<std::string> notes;
  /// Components whose elements report their torque with the opposite sign (torque shafts: the
  /// torque received at port a is -tau of the spring-damper next to it), by component id.
  std::map<std::string, double> torque_sign;
  /// Components whose torque is their own element's only (actuators: their airload and jam
  /// elements are scenario parts, not the actuator's torque).
  std::set<std::string> own_element_torque;
  double relative_tolerance = 1e-6;  ///< the project's setting
  /// rad/s, the regularised friction speed the model was built with
  /// (DriveNetworkOptions::friction_speed; 0: the exact stick/slip law).
  double friction_speed = 0.0;
  double output_interval = 1e-3;     ///< s, the scenario's, else the project's
};

/// True when the project is a drive-system project (components, no element network).
bool IsDriveSystemProject(const Project& project);

/// Builds the model. Throws InputError naming the component, scenario or load case and the
/// remedy for anything it cannot translate (unknown scenario, a jam of a component that is no
/// actuator, a parameter without a value, ...).
DriveModel BuildDriveModel(const Project& project, const DriveNetworkOptions& options = {});
/// The same with a scenario given directly (for instance a sizing case made up on the fly).
DriveModel BuildDriveModel(const Project& project, const Scenario* scenario,
                             const DriveNetworkOptions& options);

/// The scenario of a sizing case of `highlift peak` (kind "jam" or "rupture" of `component`),
/// under the conditions the single-DOF estimate assumes: a jam while extending, a rupture while
/// retracting with the airload aiding the motion (when the project has such load cases). The
/// project's scenario of that kind and component if its load case is of that direction, else a
/// new one named "<kind>_<component>" on the first such load case, with the failure at 1 s and a
/// stop time of 2 s (jam) or 3 s (rupture, wing-tip brakes by the monitor).
Scenario SizingScenario(const Project& project, const std::string& kind, const std::string& component);

}  // namespace highlift::model
