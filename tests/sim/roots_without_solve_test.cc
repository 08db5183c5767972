// The root functions without the solve (System::RootsWithoutSolve): inside a step longer than
// the output interval the simulator checks the roots at the output points, and where no
// element's roots read a result of the solve in its present mode (Element::RootsNeedSolve) it
// evaluates only the angles, speeds and the signals computed before the solve. The values are
// those of the full evaluation to the last bit, an element whose roots read a constraint torque
// (a stuck brake) makes the simulator evaluate in full, and a drive-system run is the same
// whether its output points are evaluated in full (a sink that reads them) or not.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "highlift/core/project_io.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"
#include "system.h"

namespace highlift::sim::detail {
namespace {

ElementParameters P(std::map<std::string, double> s) { return {std::move(s), {}}; }

// A rotor on a shaft brake commanded from `command` (a ramp that rises by 1 per second),
// coupled through an elastic backlash to a second rotor: the brake's roots read the slip speed
// and the command (sliding, free) or the holding torque (stuck); the backlash's roots read the
// twist.
Network BrakeAndBacklash(double w_start, double command) {
  Network net;
  net.AddElement("Inertia", "rotor", P({{"J", 0.5}, {"phi_start", 0}, {"w_start", w_start}}));
  net.AddElement("ShaftBrake", "brake", P({{"tauB_max", 100}, {"tauB_lim", 150}}));
  net.AddElement("Ramp", "command", P({{"height", 1}, {"duration", 1}, {"offset", command}, {"startTime", 0}}));
  net.AddElement("ElastoBacklash", "backlash", P({{"c", 1e4}, {"d", 5}, {"b", 0.01}, {"phi_rel0", 0}}));
  net.AddElement("Inertia", "load", P({{"J", 0.2}, {"phi_start", 0.002}, {"w_start", w_start}}));
  net.Connect("rotor.flange_b", "brake.flange_a");
  net.Connect("command.y", "brake.u");
  net.Connect("rotor.flange_a", "backlash.flange_a");
  net.Connect("backlash.flange_b", "load.flange_a");
  return net;
}

// The state after the initial event, with the speeds and angles moved a little (a point of a
// step's interpolant, not the event's own).
std::vector<double> Started(System& sys) {
  std::vector<double> y = sys.InitialState(0.0);
  std::vector<std::string> changes, who;
  EXPECT_TRUE(sys.HandleEvent(0.0, y.data(), true, &changes, &who)) << sys.error();
  for (const Node& node : sys.nodes())
    if (!node.ground) {
      y[static_cast<std::size_t>(node.s_phi)] += 1e-4;
      y[static_cast<std::size_t>(node.s_w)] *= 0.999;
    }
  return y;
}

TEST(RootsWithoutSolve, SlidingAndFreeRootsAreThoseOfTheFullEvaluation) {
  for (const double command : {0.5, -0.5}) {  // applied (the rotor slides), released (free)
    System sys(BrakeAndBacklash(20.0, command));
    ASSERT_GT(sys.NumRoots(), 0);
    const std::vector<double> y = Started(sys);
    // Last evaluated elsewhere (another time: another command), as at the previous output point.
    ASSERT_TRUE(sys.Evaluate(0.001, y.data(), nullptr)) << sys.error();
    const double t = 0.01;
    std::vector<double> part(static_cast<std::size_t>(sys.NumRoots()), -7.0);
    ASSERT_TRUE(sys.RootsWithoutSolve(t, y.data(), part.data())) << "command " << command;
    EXPECT_FALSE(sys.IsEvaluatedAt(0.001, y.data())) << "the last full evaluation is no longer current";
    std::vector<double> full(part.size(), 7.0);
    ASSERT_TRUE(sys.Evaluate(t, y.data(), nullptr)) << sys.error();
    sys.Roots(full.data());
    for (std::size_t k = 0; k < full.size(); ++k)
      EXPECT_EQ(std::memcmp(&full[k], &part[k], sizeof(double)), 0)
          << "command " << command << ", root " << k << ": " << part[k] << " against " << full[k];
  }
}

TEST(RootsWithoutSolve, AStuckBrakeNeedsTheSolve) {
  System sys(BrakeAndBacklash(0.0, 0.5));  // at rest and applied: stuck, its root reads the torque
  const std::vector<double> y = Started(sys);
  std::vector<double> g(static_cast<std::size_t>(sys.NumRoots()), 7.0);
  ASSERT_TRUE(sys.Evaluate(0.01, y.data(), nullptr)) << sys.error();
  EXPECT_FALSE(sys.RootsWithoutSolve(0.02, y.data(), g.data()));
  for (double v : g) EXPECT_EQ(v, 7.0) << "g is left alone";
  EXPECT_TRUE(sys.IsEvaluatedAt(0.01, y.data())) << "and so is the evaluation";
}

// A sink that takes the rows, reading the values or not.
class CountingSink : public OutputSink {
 public:
  explicit CountingSink(bool reads) : reads_(reads) {}
  void Begin(const std::vector<std::string>&) override {}
  void Row(double, const std::vector<double>&) override { ++rows; }
  bool ReadsValues() const override { return reads_; }
  long rows = 0;

 private:
  bool reads_;
};

// The extension of the bundled example steps far beyond the output interval while the flaps
// run at constant speed; its output points are checked for roots without the solve when the
// sink does not read them. Steps, events and peaks are those of the run that evaluates every
// output point in full.
TEST(RootsWithoutSolve, ADriveRunIsTheSameWhetherTheOutputPointsAreEvaluatedOrNot) {
  const Project project =
      LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a380_class_flaps.json");
  const DriveModel model = BuildDriveNetwork(project, {.scenario = "extension"});
  const SimulationOptions options = model.Options(project);
  CountingSink reading(true), discarding(false);
  const SimulationReport full = Simulator(model.network).Run(options, reading);
  const SimulationReport part = Simulator(model.network).Run(options, discarding);
  ASSERT_TRUE(full.ok()) << full.FullReport();
  ASSERT_TRUE(part.ok()) << part.FullReport();
  EXPECT_EQ(reading.rows, discarding.rows);
  EXPECT_EQ(full.statistics.steps, part.statistics.steps);
  EXPECT_EQ(full.statistics.rhs_evaluations, part.statistics.rhs_evaluations);
  ASSERT_EQ(full.events.size(), part.events.size());
  for (std::size_t i = 0; i < full.events.size(); ++i) {
    EXPECT_EQ(full.events[i].time, part.events[i].time) << i;
    EXPECT_EQ(full.events[i].element + full.events[i].what, part.events[i].element + part.events[i].what) << i;
  }
  ASSERT_EQ(full.peak_torques.size(), part.peak_torques.size());
  for (std::size_t i = 0; i < full.peak_torques.size(); ++i) {
    EXPECT_EQ(full.peak_torques[i].tau, part.peak_torques[i].tau) << full.peak_torques[i].element;
    EXPECT_EQ(full.peak_torques[i].time, part.peak_torques[i].time) << full.peak_torques[i].element;
  }
}

}  // namespace
}  // namespace highlift::sim::detail
