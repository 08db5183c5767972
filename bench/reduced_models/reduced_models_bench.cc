// Speed targets of issue 5 (docs/performance.md, section reduced_models):
//   modal analysis of a 10^3-DOF chain           < 50 ms
//   steady-state sizing of the A380-class project < 1 ms
//   all sizing cases with interval enclosures     < 100 ms
#include <benchmark/benchmark.h>

#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/modal.h"
#include "highlift/reduced_models/sizing.h"

namespace {

using namespace highlift;
using namespace highlift::reduced_models;

const Project& A380() {
  static const Project project = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json");
  return project;
}

LumpedModel Chain(int n) {
  LumpedModel m;
  m.AddNode("pdu", 0.26);
  for (int i = 1; i < n; ++i) {
    m.AddNode("n", 0.013);
    m.AddSpring(i - 1, i, 2000.0, "s");
  }
  return m;
}

// All 1000 eigenfrequencies and the 6 lowest mode shapes, PDU clamped and free.
void BM_ModesChain1000(benchmark::State& state) {
  const LumpedModel m = Chain(1000);
  for (auto _ : state) {
    benchmark::DoNotOptimize(ComputeModes(m, {{}, 6}));
  }
}
BENCHMARK(BM_ModesChain1000)->Unit(benchmark::kMillisecond);

void BM_SizeA380Point(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(Size(A380(), {false}));
}
BENCHMARK(BM_SizeA380Point)->Unit(benchmark::kMicrosecond);

void BM_SizeA380Intervals(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(Size(A380(), {true}));
}
BENCHMARK(BM_SizeA380Intervals)->Unit(benchmark::kMicrosecond);

void BM_PeakA380AllCasesIntervals(benchmark::State& state) {
  PeakOptions options;
  options.rank = false;
  for (auto _ : state) benchmark::DoNotOptimize(AnalysePeaks(A380(), options));
}
BENCHMARK(BM_PeakA380AllCasesIntervals)->Unit(benchmark::kMillisecond);

void BM_PeakA380AllCasesIntervalsAndRanking(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(AnalysePeaks(A380()));
}
BENCHMARK(BM_PeakA380AllCasesIntervalsAndRanking)->Unit(benchmark::kMillisecond);

void BM_ModesA380ThreeModels(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(AnalyseModes(A380()));
}
BENCHMARK(BM_ModesA380ThreeModels)->Unit(benchmark::kMillisecond);

}  // namespace
