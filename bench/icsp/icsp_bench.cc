// Build and propagation benchmarks on the dt and rnd families of ../shared/reference/icsp/README.md
// at 10^2..10^5 constraints, at the stopping ratio 0.01 and at the exact fixed point, and on the
// A380-class example project. Counters: revisions, build time (network and compiled propagator),
// heap taken by the network and the propagator, and the peak resident memory of the process
// during the benchmark (its high-water mark is reset before each one).
//
//   icsp_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <chrono>
#include <fstream>
#include <string>

#include "common/peak_rss.h"
#include "highlift/componentdb/database.h"
#include "highlift/core/project_io.h"
#include "highlift/estimation/estimator.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/icsp/propagator.h"
#include "highlift/icsp/reference_networks.h"

namespace highlift::icsp {
namespace {

using bench::PeakRssMB;
using bench::ResetPeakRss;

double HeapMB() { return static_cast<double>(mallinfo2().uordblks) / (1024.0 * 1024.0); }

ReferenceNetwork Make(bool rnd, int size) {
  return rnd ? MakeRandomNetwork(size) : MakeDriveTrainNetwork(size, false);
}

/// Building from the definition: the network (hash-consed DAG, topological orders, adjacency)
/// and the propagator (tapes, shared-subexpression table).
void BM_Build(benchmark::State& state, bool rnd) {
  const ReferenceNetwork ref = Make(rnd, static_cast<int>(state.range(0)));
  ResetPeakRss();
  double network_mb = 0, propagator_mb = 0;
  for (auto _ : state) {
    const double before = HeapMB();
    Network net = BuildNetwork(ref);
    const double after_network = HeapMB();
    Propagator propagator(net);
    network_mb = after_network - before;
    propagator_mb = HeapMB() - after_network;
    benchmark::DoNotOptimize(net);
    benchmark::DoNotOptimize(propagator);
  }
  state.counters["constraints"] = static_cast<double>(ref.constraints.size());
  state.counters["network_MB"] = network_mb;
  state.counters["propagator_MB"] = propagator_mb;
  state.counters["peak_rss_MB"] = PeakRssMB();
}

/// Propagation from the initial box to the fixed point (ratio 0) or the ratio-0.01 fixed point;
/// by default with the sweep schedule and shared subexpressions reused.
void BM_Propagate(benchmark::State& state, bool rnd, double ratio, Schedule schedule = Schedule::kSweep,
                  bool reuse = true) {
  const ReferenceNetwork ref = Make(rnd, static_cast<int>(state.range(0)));
  ResetPeakRss();
  const auto t0 = std::chrono::steady_clock::now();
  const Network net = BuildNetwork(ref);
  PropagationOptions options;
  options.ratio = ratio;
  options.record_reasons = false;
  options.schedule = schedule;
  options.reuse_shared_subexpressions = reuse;
  Propagator propagator(net, options);
  const double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  PropagationReport report;
  for (auto _ : state) {
    state.PauseTiming();
    Box box = net.InitialBox();
    state.ResumeTiming();
    report = propagator.Propagate(box);
    benchmark::DoNotOptimize(box);
  }
  if (report.status != Status::kFixedPoint) state.SkipWithError("no fixed point (rnd and dt are feasible): a bug");
  state.counters["constraints"] = static_cast<double>(ref.constraints.size());
  state.counters["revisions"] = static_cast<double>(report.revisions);
  state.counters["reused"] = static_cast<double>(report.reused_subexpressions);
  state.counters["build_s"] = build_s;
  state.counters["peak_rss_MB"] = PeakRssMB();
}

const std::string kA380 = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json";
const std::string kA380Infeasible = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps_infeasible.json";

/// The project as `highlift check` reads it: unknown parameters take the estimator's domains.
Project Estimated(const std::string& file) {
  Project project = LoadProject(file);
  componentdb::ComponentDatabase database =
      componentdb::OpenDatabase("", componentdb::ComponentDatabase::Mode::kReadOnly);
  estimation::EstimateProject(project, &database, {});
  return project;
}

/// The A380-class flap project (both wings): building its network and propagating it to the
/// exact fixed point. `estimated`: with the estimator's domains, as `highlift check` does.
void BM_A380Project(benchmark::State& state, bool estimated) {
  const Project project = estimated ? Estimated(kA380) : LoadProject(kA380);
  const auto t0 = std::chrono::steady_clock::now();
  const DriveSystemNetwork dn = BuildDriveSystemNetwork(project);
  PropagationOptions options;
  options.record_reasons = false;
  Propagator propagator(dn.network, options);
  const double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
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
BENCHMARK_CAPTURE(BM_A380Project, as_given, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_A380Project, estimated, true)->Unit(benchmark::kMillisecond);

/// What `highlift check` computes for the infeasible variant: propagation, the minimal conflict
/// by deletion filtering over its 33 requirements, and the chain.
void BM_A380InfeasibleCheck(benchmark::State& state) {
  const DriveSystemNetwork dn = BuildDriveSystemNetwork(Estimated(kA380Infeasible));
  CheckResult result;
  for (auto _ : state) {
    result = CheckDriveSystem(dn);
    benchmark::DoNotOptimize(result);
  }
  if (result.feasible) state.SkipWithError("the infeasible variant was not proved infeasible");
  state.counters["propagations"] = result.explanation.propagations;
}
BENCHMARK(BM_A380InfeasibleCheck)->Unit(benchmark::kMillisecond);

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
// For ratios within one run: the FIFO agenda (AC3, as IBEX's CtcPropag) on the dt chain, and
// propagation without reusing shared subexpressions.
BENCHMARK_CAPTURE(BM_Propagate, dt_exact_fifo, false, 0.0, Schedule::kFifo)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Propagate, rnd_exact_no_reuse, true, 0.0, Schedule::kSweep, false)
    ->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Propagate, rnd_ratio_0.01_no_reuse, true, 0.01, Schedule::kSweep, false)
    ->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace highlift::icsp
