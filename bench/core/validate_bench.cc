// `highlift validate` at scale (issue 19): reading and validating a drive system of 10^3..10^5
// components must take time and memory linear in the component count (it was quadratic: every
// component held a copy of its whole power path; 8000 components took 21 s and 3 GB).
// The project is one wing transmission as a long chain of stations (torque shaft, branch
// gearbox, geared rotary actuator on the branch): the deepest power paths there are.
// Counters: components, peak resident memory of the process during the benchmark (its
// high-water mark is reset before each one), bytes of project text.
//
//   validate_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <string>

#include "common/peak_rss.h"

#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"

namespace highlift {
namespace {

using bench::PeakRssMB;
using bench::ResetPeakRss;

/// A valid project of about `n` components: PDU, then stations of three components each.
std::string ChainProject(long n) {
  std::string components = R"({"id": "pdu", "type": "pdu"})";
  std::string connections;
  std::string previous = "pdu.left";
  for (long i = 0; 3 * i + 1 < n; ++i) {
    const std::string k = std::to_string(i);
    components += R"(, {"id": "s)" + k + R"(", "type": "torque_shaft", "parameters": {"length": "1 m"}})";
    components += R"(, {"id": "g)" + k + R"(", "type": "branch_gearbox"})";
    components += R"(, {"id": "a)" + k + R"(", "type": "geared_rotary_actuator"})";
    connections += std::string(connections.empty() ? "" : ", ") + "[\"" + previous + "\", \"s" + k + ".a\"], [\"s" + k +
                   ".b\", \"g" + k + ".input\"], [\"g" + k + ".branch\", \"a" + k + ".input\"]";
    previous = "g" + k + ".through";
  }
  return R"({"format": "highlift-project/1", "name": "chain", "components": [)" + components +
         R"(], "connections": [)" + connections + "]}";
}

void BM_ReadAndValidate(benchmark::State& state) {
  const std::string text = ChainProject(state.range(0));
  ResetPeakRss();
  std::size_t components = 0;
  for (auto _ : state) {
    const Project project = ParseProject(text, "chain.json");
    const ValidationReport report = ValidateProject(project);
    components = project.components.size();
    benchmark::DoNotOptimize(report);
    if (!report.ok()) state.SkipWithError(report.FullReport().substr(0, 300).c_str());
  }
  state.counters["components"] = static_cast<double>(components);
  state.counters["peak_rss_MB"] = PeakRssMB();
  state.counters["text_MB"] = static_cast<double>(text.size()) / 1e6;
}
BENCHMARK(BM_ReadAndValidate)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

}  // namespace
}  // namespace highlift

BENCHMARK_MAIN();
