// Build and propagation benchmarks on the dt and rnd families at 10^2..10^5 constraints, at the
// stopping ratio 0.01 and at the exact fixed point. Counters: revisions, build time, heap used by
// the network and peak resident memory of the process.
//
//   icsp_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <chrono>
#include <fstream>
#include <string>

#include "highlift/core/project_io.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/icsp/propagator.h"
#include "highlift/icsp/reference_networks.h"

namespace highlift::icsp {
namespace {

double PeakRssMB() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return 0.0;
}

ReferenceNetwork Make(bool rnd, int size) {
  return rnd ? MakeRandomNetwork(size) : MakeDriveTrainNetwork(size, false);
}

/// Building the network (hash-consed DAG, topological orders, adjacency) from its definition.
void BM_Build(benchmark::State& state, bool rnd) {
  const ReferenceNetwork ref = Make(rnd, static_cast<int>(state.range(0)));
  double heap_mb = 0;
  for (auto _ : state) {
    const std::size_t before = mallinfo2().uordblks;
    Network net = BuildNetwork(ref);
    heap_mb = static_cast<double>(mallinfo2().uordblks - before) / (1024.0 * 1024.0);
    benchmark::DoNotOptimize(net);
  }
  state.counters["constraints"] = static_cast<double>(ref.constraints.size());
  state.counters["network_MB"] = heap_mb;
  state.counters["peak_rss_MB"] = PeakRssMB();
}

/// Propagation from the initial box to the fixed point (ratio 0) or the ratio-0.01 fixed point.
void BM_Propagate(benchmark::State& state, bool rnd, double ratio) {
  const ReferenceNetwork ref = Make(rnd, static_cast<int>(state.range(0)));
  const auto t0 = std::chrono::steady_clock::now();
  const Network net = BuildNetwork(ref);
  const double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  PropagationOptions options;
  options.ratio = ratio;
  options.record_reasons = false;
  Propagator propagator(net, options);
  PropagationReport report;
  for (auto _ : state) {
    state.PauseTiming();
    Box box = net.InitialBox();
    state.ResumeTiming();
    report = propagator.Propagate(box);
    benchmark::DoNotOptimize(box);
  }
  if (report.status == Status::kInfeasible) state.SkipWithError("reported infeasible: a bug");
  state.counters["constraints"] = static_cast<double>(ref.constraints.size());
  state.counters["revisions"] = static_cast<double>(report.revisions);
  state.counters["build_s"] = build_s;
  state.counters["peak_rss_MB"] = PeakRssMB();
}

/// The A380-class flap project (both wings): building its network and propagating it exactly.
void BM_A380Project(benchmark::State& state) {
  const Project project = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json");
  const auto t0 = std::chrono::steady_clock::now();
  const DriveSystemNetwork dn = BuildDriveSystemNetwork(project);
  const double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  PropagationOptions options;
  options.record_reasons = false;
  Propagator propagator(dn.network, options);
  PropagationReport report;
  for (auto _ : state) {
    Box box = dn.network.InitialBox();
    report = propagator.Propagate(box);
    benchmark::DoNotOptimize(box);
  }
  if (report.status != Status::kFixedPoint) state.SkipWithError("the A380 project did not reach a fixed point");
  state.counters["constraints"] = dn.network.num_constraints();
  state.counters["revisions"] = static_cast<double>(report.revisions);
  state.counters["build_s"] = build_s;
}
BENCHMARK(BM_A380Project)->Unit(benchmark::kMillisecond);

void Sizes(benchmark::internal::Benchmark* b) {
  for (int n : {100, 1000, 10000, 100000}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK_CAPTURE(BM_Build, dt, false)->Apply(Sizes);
BENCHMARK_CAPTURE(BM_Build, rnd, true)->Apply(Sizes);
BENCHMARK_CAPTURE(BM_Propagate, dt_ratio_0.01, false, 0.01)->Apply(Sizes);
BENCHMARK_CAPTURE(BM_Propagate, dt_exact, false, 0.0)->Apply(Sizes);
BENCHMARK_CAPTURE(BM_Propagate, rnd_ratio_0.01, true, 0.01)->Apply(Sizes);
BENCHMARK_CAPTURE(BM_Propagate, rnd_exact, true, 0.0)->Apply(Sizes);

}  // namespace
}  // namespace highlift::icsp
