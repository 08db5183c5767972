// The soundness property at scale: random chain projects, each sampled at many points of its
// parameter domains; every point value of size and peak must lie in the enclosure.
//
//   build/bench/soundness/soundness_stress --points=1000000 --seed=1 [--per-project=200]
//
// Prints the counts and every violation (with the seed and point that reproduce it) and exits 1
// when there is one. Google Benchmark's counters give the rate: the benchmark "Soundness" runs
// one project per iteration with `per-project` points.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include "highlift/core/error.h"
#include "soundness/soundness.h"

namespace {

long g_points = 1000000;
std::uint64_t g_seed = 1;
int g_per_project = 200;
highlift::testing::SoundnessResult g_total;

void Soundness(benchmark::State& state) {
  std::uint64_t project = 0;
  for (auto _ : state) {
    highlift::testing::SoundnessOptions options;
    options.points = g_per_project;
    options.seed = g_seed + project;
    const auto project_under_test = highlift::testing::RandomChainProject(g_seed + project);
    g_total.Merge(highlift::testing::CheckEnclosures(project_under_test, options));
    ++project;
  }
  state.counters["points"] = static_cast<double>(g_total.points);
  state.counters["violations"] = static_cast<double>(g_total.violations.size());
  state.counters["points_per_s"] = benchmark::Counter(static_cast<double>(project) * g_per_project, benchmark::Counter::kIsRate);
}

bool Flag(const char* arg, const char* name, std::string* value) {
  const std::size_t n = std::strlen(name);
  if (std::strncmp(arg, name, n) != 0 || arg[n] != '=') return false;
  *value = arg + n + 1;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    std::string value;
    if (Flag(argv[i], "--points", &value)) g_points = std::stol(value);
    else if (Flag(argv[i], "--seed", &value)) g_seed = std::stoull(value);
    else if (Flag(argv[i], "--per-project", &value)) g_per_project = std::stoi(value);
    else rest.push_back(argv[i]);
  }
  if (g_points <= 0 || g_per_project <= 0) {
    std::cerr << "soundness_stress: --points and --per-project must be positive\n";
    return 2;
  }
  const long projects = (g_points + g_per_project - 1) / g_per_project;
  int rest_argc = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_argc, rest.data());
  benchmark::RegisterBenchmark("Soundness", Soundness)->Iterations(projects)->Unit(benchmark::kMillisecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::cout << "soundness: " << g_total.points << " points on " << projects << " random projects (seed " << g_seed
            << "), " << g_total.checks << " checks, " << g_total.violations.size() << " violations\n";
  for (const auto& v : g_total.violations) std::cout << "  " << v << "\n";
  return g_total.violations.empty() ? 0 : 1;
}
