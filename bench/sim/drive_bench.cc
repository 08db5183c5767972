// Benchmarks of the drive-system scenarios (sim/src/drive_network.cc): the A380-class flap
// transmission of examples/a380_class_flaps.json, both wings, full resolution (every torque shaft
// split into 4 spring-dampers), the 40 s `extension` and the 3 s `rupture_wtb` scenario, with the project's output interval (1 ms) into a sink that keeps nothing.
// Targets (issue 7): under 0.5 s wall each on one core, peak memory under 100 MB
// (docs/performance.md). The counters give the model size and the solver work.
//
//   build/bench/sim/drive_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>

#include "highlift/core/project_io.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"

namespace {

using namespace highlift;

class NullSink : public sim::OutputSink {
 public:
  void Begin(const std::vector<std::string>&) override {}
  void Row(double, const std::vector<double>&) override {}
};

const Project& Example() {
  static const Project project = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json");
  return project;
}

void RunScenario(benchmark::State& state, const std::string& scenario, sim::DriveResolution resolution) {
  sim::DriveNetworkOptions options;
  options.scenario = scenario;
  options.resolution = resolution;
  const sim::DriveModel model = sim::BuildDriveNetwork(Example(), options);
  const sim::SimulationOptions run = model.Options(Example());  // the scenario's stop time
  sim::SimulationReport report;
  for (auto _ : state) {
    sim::Simulator simulator(model.network);  // assembly is part of the cost
    NullSink sink;
    report = simulator.Run(run, sink);
    if (!report.ok()) state.SkipWithError(report.message.c_str());
  }
  state.counters["elements"] = static_cast<double>(model.network.elements().size());
  state.counters["states"] = report.statistics.states;
  state.counters["steps"] = static_cast<double>(report.statistics.steps);
  state.counters["rhs"] = static_cast<double>(report.statistics.rhs_evaluations);
  state.counters["events"] = static_cast<double>(report.events.size());
}

void BM_ExtensionFull(benchmark::State& state) { RunScenario(state, "extension", sim::DriveResolution::kFull); }
void BM_RuptureWtbFull(benchmark::State& state) { RunScenario(state, "rupture_wtb", sim::DriveResolution::kFull); }
void BM_ExtensionReduced(benchmark::State& state) {
  RunScenario(state, "extension", sim::DriveResolution::kReduced);
}

}  // namespace

BENCHMARK(BM_ExtensionFull)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RuptureWtbFull)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ExtensionReduced)->Unit(benchmark::kMillisecond)->Iterations(1);
