// The training run of the simulator's profile-guided build (HIGHLIFT_PGO, sim/CMakeLists.txt).
//
// Linked with an instrumented copy of the simulator's sources, it runs the kinds of simulation
// the tool runs (a scenario whose rows are read, as `highlift simulate` does; the sizing cases of
// `highlift peak --transient` and of the campaigns, whose rows are discarded) and writes the
// counts of every branch and call that GCC then uses to lay out and inline the simulator. The
// counts steer only the code's layout and inlining: the compiled arithmetic is the same, so the
// results are the same bit for bit with and without them (docs/performance.md).
//
//   highlift_sim_training [--results] <project.json> <run>...
//
// where each <run> is one of
//   scenario:<name>      the project's scenario, every column read
//   jam:<component>      the sizing case of `peak`: a jam of the actuator, rows discarded
//   rupture:<component>  the sizing case of `peak`: a rupture of the shaft, rows discarded
//   reduced:<name>       the project's scenario on the reduced model, rows discarded
//
// Prints one line per run and exits with 1 when a run fails: a training run that does not
// reach its end would train the build on a failure path. With --results it prints every result
// of each run to the last bit (the statistics, the events, every peak torque and its time, as
// hexadecimal floating point): the test `sim.profile_guided_build_same_results` compiles this
// file once more against the profile-guided simulator and requires the same text from both.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "highlift/core/project.h"
#include "highlift/core/validate.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"

namespace {

using namespace highlift;

/// Reads every value of every row, as a sink that writes them does (into a member, so the reads
/// are kept).
class ReadingSink : public sim::OutputSink {
 public:
  void Begin(const std::vector<std::string>&) override {}
  void Row(double time, const std::vector<double>& values) override {
    sum_ += time;
    for (double v : values) sum_ += v;
  }

 private:
  double sum_ = 0.0;
};

void PrintResults(const sim::SimulationReport& report) {
  const sim::SolverStatistics& s = report.statistics;
  std::printf("  status %d, t = %a, %ld steps, %ld right-hand sides, %ld Jacobians, %ld Newton iterations, "
              "%ld error test failures, %ld convergence failures\n",
              static_cast<int>(report.status), report.time, s.steps, s.rhs_evaluations, s.jacobian_evaluations,
              s.nonlinear_iterations, s.error_test_failures, s.nonlinear_convergence_failures);
  for (const sim::SimulationEvent& e : report.events)
    std::printf("  event %a %s %s %s\n", e.time, e.kind.c_str(), e.element.c_str(), e.what.c_str());
  for (const sim::PeakTorque& p : report.peak_torques)
    std::printf("  peak %s %a at %a\n", p.element.c_str(), p.tau, p.time);
}

bool Run(const Project& project, const std::string& run, bool results) {
  const std::size_t colon = run.find(':');
  if (colon == std::string::npos) {
    std::fprintf(stderr, "highlift_sim_training: '%s' is no run; write scenario:<name>, jam:<component>, "
                 "rupture:<component> or reduced:<name>\n", run.c_str());
    return false;
  }
  const std::string kind = run.substr(0, colon), name = run.substr(colon + 1);
  sim::DriveNetworkOptions options;
  Scenario scenario;
  if (kind == "jam" || kind == "rupture") {
    scenario = sim::SizingScenario(project, kind, name);
  } else if (kind == "scenario" || kind == "reduced") {
    const auto it = std::find_if(project.scenarios.begin(), project.scenarios.end(),
                                 [&](const Scenario& s) { return s.name == name; });
    if (it == project.scenarios.end()) {
      std::fprintf(stderr, "highlift_sim_training: the project has no scenario '%s'\n", name.c_str());
      return false;
    }
    scenario = *it;
    if (kind == "reduced") options.resolution = sim::DriveResolution::kReduced;
  } else {
    std::fprintf(stderr, "highlift_sim_training: unknown run kind '%s' in '%s' (scenario, jam, rupture, reduced)\n",
                 kind.c_str(), run.c_str());
    return false;
  }
  const sim::DriveModel model = sim::BuildDriveNetwork(project, &scenario, options);
  sim::Simulator simulator(model.network);
  sim::SimulationOptions o = model.Options(project);
  sim::SimulationReport report;
  if (kind == "scenario") {
    ReadingSink rows;
    sim::DerivedColumnSink sink(model.derived, rows);
    report = simulator.Run(o, sink);
  } else {
    o.output_interval = std::min(o.output_interval, 1e-3);  // as `peak --transient`
    sim::DiscardSink sink;  // as the peaks and the campaigns
    report = simulator.Run(o, sink);
  }
  std::printf("%-28s %-8s %7ld steps  %s\n", run.c_str(), report.ok() ? "ok" : "FAILED", report.statistics.steps,
              report.ok() ? "" : report.message.c_str());
  if (results) PrintResults(report);
  return report.ok();
}

}  // namespace

int main(int argc, char** argv) {
  const bool results = argc > 1 && std::string(argv[1]) == "--results";
  const int first = results ? 2 : 1;
  if (argc < first + 2) {
    std::fprintf(stderr, "usage: highlift_sim_training [--results] <project.json> <run>...\n");
    return 2;
  }
  try {
    const highlift::Project project = highlift::LoadValidProject(argv[first]);
    bool ok = true;
    for (int i = first + 1; i < argc; ++i) ok = Run(project, argv[i], results) && ok;
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "highlift_sim_training: %s: %s\n", argv[first], e.what());
    return 1;
  }
}
