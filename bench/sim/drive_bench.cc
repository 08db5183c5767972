// Benchmarks of the drive-system scenarios (sim/src/drive_network.cc): the A380-class flap
// transmission of examples/a380_class_flaps.json, both wings, full resolution (every torque shaft
// split into 4 spring-dampers, 443 states), the 40 s `extension` (rows every 10 ms), the 3 s
// `rupture_wtb` and the 2 s `jam_l3` scenario (rows every 1 ms) into a sink that keeps nothing;
// the reduced model of the extension; the hydraulic-PDU example's extension and rupture.
// Targets (issue 7): under 0.5 s wall each on one core, peak memory under 100 MB
// (docs/performance.md). The counters give the model size and the solver work.
//
//   build/bench/sim/drive_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include <sys/resource.h>

#include "highlift/core/project_io.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"

namespace {

using namespace highlift;

const Project& Example(const std::string& file = "a380_class_flaps.json") {
  static std::map<std::string, Project> projects;
  auto it = projects.find(file);
  if (it == projects.end())
    it = projects.emplace(file, LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/" + file)).first;
  return it->second;
}

/// Peak resident set size of the process so far, MB.
double PeakRssMB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

void RunScenario(benchmark::State& state, const std::string& scenario, sim::DriveResolution resolution,
                 const std::string& file = "a380_class_flaps.json") {
  sim::DriveNetworkOptions options;
  options.scenario = scenario;
  options.resolution = resolution;
  const sim::DriveModel model = sim::BuildDriveNetwork(Example(file), options);
  const sim::SimulationOptions run = model.Options(Example(file));  // the scenario's stop time, tolerance, rows
  sim::SimulationReport report;
  for (auto _ : state) {
    sim::Simulator simulator(model.network);  // assembly is part of the cost
    sim::DiscardSink sink;  // as the campaign's and the CLI's without --out
    report = simulator.Run(run, sink);
    if (!report.ok()) state.SkipWithError(report.message.c_str());
  }
  state.counters["elements"] = static_cast<double>(model.network.elements().size());
  state.counters["states"] = report.statistics.states;
  state.counters["steps"] = static_cast<double>(report.statistics.steps);
  state.counters["rhs"] = static_cast<double>(report.statistics.rhs_evaluations);
  state.counters["events"] = static_cast<double>(report.events.size());
  state.counters["peak_rss_MB"] = PeakRssMB();
}

void BM_ExtensionFull(benchmark::State& state) { RunScenario(state, "extension", sim::DriveResolution::kFull); }
void BM_RuptureWtbFull(benchmark::State& state) { RunScenario(state, "rupture_wtb", sim::DriveResolution::kFull); }
void BM_JamL3Full(benchmark::State& state) { RunScenario(state, "jam_l3", sim::DriveResolution::kFull); }
void BM_ExtensionReduced(benchmark::State& state) {
  RunScenario(state, "extension", sim::DriveResolution::kReduced);
}
void BM_HydraulicExtensionFull(benchmark::State& state) {
  RunScenario(state, "extension", sim::DriveResolution::kFull, "hydraulic_pdu_flaps.json");
}
void BM_HydraulicRuptureWtbFull(benchmark::State& state) {
  RunScenario(state, "rupture_wtb", sim::DriveResolution::kFull, "hydraulic_pdu_flaps.json");
}

}  // namespace

BENCHMARK(BM_ExtensionFull)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RuptureWtbFull)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_JamL3Full)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ExtensionReduced)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_HydraulicExtensionFull)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_HydraulicRuptureWtbFull)->Unit(benchmark::kMillisecond)->Iterations(1);
