// Drive-system projects as simulation models. The translation of a project into an element
// network lives in the model layer (highlift/model/drive_network.h), shared with the Modelica
// export; this header adds what the simulator needs on top of it (simulation options, derived
// output columns, peak torques per component) and keeps the simulator's names for callers.
//
//   const Project project = LoadProject("examples/a380_class_flaps.json");
//   highlift::sim::DriveModel model = highlift::sim::BuildDriveNetwork(project, {.scenario = "rupture_wtb"});
//   highlift::sim::Simulator simulator(model.network);
//   highlift::sim::MemorySink memory;
//   highlift::sim::DerivedColumnSink sink(model.derived, memory);   // adds shaft_l1.tau, ...
//   simulator.Run(model.Options(project), sink);
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "highlift/core/project.h"
#include "highlift/model/drive_network.h"
#include "highlift/sim/network.h"
#include "highlift/sim/simulator.h"

namespace highlift::sim {

using model::DerivedColumn;
using model::DriveNetworkOptions;
using model::DriveResolution;
using model::IsDriveSystemProject;
using model::ParseDriveResolution;
using model::SizingScenario;
using model::ToString;

/// The simulation model of a drive-system project: the model layer's network and its scenario
/// data, with the simulation options.
struct DriveModel : model::DriveModel {
  /// Simulation options of the model: the scenario's stop time, the project's tolerance and
  /// output interval. (`project` is kept for the callers; the model carries its settings.)
  SimulationOptions Options(const Project& project) const;
};

/// model::BuildDriveNetwork, as the simulator's model.
DriveModel BuildDriveNetwork(const Project& project, const DriveNetworkOptions& options = {});
DriveModel BuildDriveNetwork(const Project& project, const Scenario* scenario,
                             const DriveNetworkOptions& options);

/// Forwards rows to `next` with the derived columns appended. A derived column whose source is
/// not among the columns is left out.
class DerivedColumnSink : public OutputSink {
 public:
  DerivedColumnSink(std::vector<DerivedColumn> derived, OutputSink& next);
  void Begin(const std::vector<std::string>& columns) override;
  void Row(double time, const std::vector<double>& values) override;
  void End() override;
  bool ReadsValues() const override { return next_.ReadsValues(); }

 private:
  std::vector<DerivedColumn> derived_;
  std::vector<std::pair<int, double>> sources_;  // column index, factor
  std::vector<double> row_;
  OutputSink& next_;
};

/// The peak torques of the report per project component: for each component the element with
/// the largest |tau| among the elements that belong to it (for a shaft, its spring-dampers),
/// named after the component, in project order.
std::vector<PeakTorque> ComponentPeakTorques(const DriveModel& model, const Project& project,
                                             const SimulationReport& report);

}  // namespace highlift::sim
