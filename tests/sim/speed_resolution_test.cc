// The speed resolution of drive-system runs (SimulationOptions::speed_resolution): a node's
// speed is resolved to at least the relative tolerance times the regularised friction speed,
// not to the absolute tolerance of 1e-8 rad/s. Below that speed the friction laws change sign;
// a stopped shaft resolved to 1e-8 rad/s rings at the limit of the error test and sets the step
// size long after the loads have peaked. The floor takes steps away without moving the peaks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/sim/drive_network.h"
#include "system.h"

namespace highlift::sim::detail {
namespace {

Project Example() {
  return LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a380_class_flaps.json");
}

TEST(SpeedResolution, FloorsTheNodeSpeedsAbsoluteToleranceAndNothingElse) {
  const DriveModel model =
      BuildDriveNetwork(Example(), {.resolution = model::DriveResolution::kReduced, .scenario = "jam_l3"});
  const System sys(model.network);
  const double floor = 1e-6;
  const std::vector<double> without = sys.AbsoluteTolerances(1e-8, 1e-3);
  const std::vector<double> with = sys.AbsoluteTolerances(1e-8, 1e-3, floor);
  ASSERT_EQ(without.size(), with.size());
  std::vector<char> speed(with.size(), 0);
  for (const Node& node : sys.nodes())
    if (!node.ground) speed[static_cast<std::size_t>(node.s_w)] = 1;
  int raised = 0;
  for (std::size_t i = 0; i < with.size(); ++i) {
    const std::string& name = sys.StateNames()[i];
    if (speed[i]) {
      EXPECT_EQ(with[i], std::max(without[i], floor)) << name;
      raised += without[i] < floor;
    } else {
      EXPECT_EQ(with[i], without[i]) << name << ": only the node speeds have the floor";
    }
  }
  EXPECT_GT(raised, 10) << "the speeds without a nominal value are resolved to 1e-8 rad/s without the floor";
}

TEST(SpeedResolution, DriveModelsResolveSpeedsToTheirFrictionSpeed) {
  const Project project = Example();
  const DriveModel model = BuildDriveNetwork(project, {.scenario = "jam_l3"});
  EXPECT_EQ(model.friction_speed, DriveNetworkOptions{}.friction_speed);
  EXPECT_EQ(model.Options(project).speed_resolution, 0.1);
  // The exact stick/slip law has no friction speed: the speeds keep the absolute tolerance.
  const DriveModel exact = BuildDriveNetwork(project, {.scenario = "jam_l3", .friction_speed = 0.0});
  EXPECT_EQ(exact.Options(project).speed_resolution, 0.0);
  SimulationOptions o = model.Options(project);
  EXPECT_NO_THROW(o.Validate());
  o.speed_resolution = -0.1;
  try {
    o.Validate();
    ADD_FAILURE() << "a negative speed resolution was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("speed_resolution must be >= 0 rad/s"), std::string::npos) << e.what();
  }
}


struct Outcome {
  SimulationReport report;
  std::map<std::string, double> peaks;  // |tau| of every element's peak
};

Outcome Simulate(const Project& project, const DriveModel& model, double rtol, double speed_resolution) {
  SimulationOptions o = model.Options(project);
  o.relative_tolerance = rtol;
  o.speed_resolution = speed_resolution;
  Simulator simulator(model.network);
  DiscardSink sink;
  Outcome run{simulator.Run(o, sink), {}};
  EXPECT_TRUE(run.report.ok()) << run.report.FullReport();
  for (const PeakTorque& p : run.report.peak_torques) run.peaks[p.element] = std::abs(p.tau);
  return run;
}

// The largest difference of the element peaks from the reference's, relative to its largest.
double PeakError(const Outcome& reference, const Outcome& run) {
  double largest = 0.0, error = 0.0;
  for (const auto& [element, tau] : reference.peaks) largest = std::max(largest, tau);
  for (const auto& [element, tau] : reference.peaks) {
    const auto it = run.peaks.find(element);
    EXPECT_NE(it, run.peaks.end()) << element;
    if (it != run.peaks.end()) error = std::max(error, std::abs(it->second - tau));
  }
  return error / largest;
}

// A jam of the A380-class example (reduced model, 2 s): the stopped outboard shafts ring for the
// rest of the run. With the floor the default tolerance takes at least a tenth fewer steps (3577
// against 4358), and its peaks stay as close to a tight run's as without it (about 1e-5 of the
// largest peak, 135 kN*m at the actuator). All 38 reference cases of the full model are judged
// by bench/sim/reference_check.py (docs/performance.md, issue 30, thirteenth pass): there a floor
// 100 times higher moves a rupture's component peak by 175 %.
TEST(SpeedResolution, AJamTakesFewerStepsToTheSamePeaks) {
  const Project project = Example();
  const DriveModel model =
      BuildDriveNetwork(project, {.resolution = model::DriveResolution::kReduced, .scenario = "jam_l3"});
  const double w_small = model.Options(project).speed_resolution;
  ASSERT_GT(w_small, 0.0);
  const Outcome reference = Simulate(project, model, 1e-9, w_small);
  const Outcome resolved = Simulate(project, model, model.relative_tolerance, w_small);
  const Outcome absolute = Simulate(project, model, model.relative_tolerance, 0.0);
  EXPECT_LT(resolved.report.statistics.steps, 0.9 * absolute.report.statistics.steps)
      << resolved.report.statistics.steps << " steps with the floor, " << absolute.report.statistics.steps
      << " without";
  const double error_resolved = PeakError(reference, resolved), error_absolute = PeakError(reference, absolute);
  EXPECT_LT(error_resolved, 1e-4) << "without the floor " << error_absolute;
  EXPECT_LT(error_absolute, 1e-4);
}

}  // namespace
}  // namespace highlift::sim::detail
