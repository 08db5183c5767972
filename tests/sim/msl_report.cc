// msl_report: runs every MSL reference example and prints the comparison table of
// docs/validation.md (Markdown). Usage: msl_report [REFERENCE_MSL_DIR]
#include <cstdio>
#include <iostream>

#include "common/shared_reference.h"
#include "msl_compare.h"

int main(int argc, char** argv) {
  using namespace highlift::testing;
  std::filesystem::path dir;
  if (argc > 1) {
    dir = argv[1];
  } else if (const SharedReferenceLookup found = LocateSharedReference("msl"); found.dir) {
    dir = *found.dir;
  } else {
    std::cerr << "msl_report: " << found.message << "; or pass the folder as the argument\n";
    return 2;
  }
  bool all = true;
  std::printf("| example | signal | range | largest error | at t [s] | tolerance | error/tolerance | result |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const auto& spec : MslExamples()) {
    const ExampleComparison c = CompareExample(spec.name, dir, spec.csv, spec.informative);
    if (!c.report.ok()) std::printf("| %s | (run failed: %s) | | | | | | FAIL |\n", spec.name.c_str(), c.report.message.c_str());
    for (const auto& s : c.signals) {
      const char* verdict = s.informative ? (s.passed ? "pass (informative)" : "differs (informative)")
                                          : (s.passed ? "pass" : "FAIL");
      if (s.discrete)
        std::printf("| %s | %s | | %.3g s | %.6g | 1 ms | %.3f | %s %s |\n", spec.name.c_str(), s.name.c_str(),
                    s.max_error, s.at_time, s.relative(), verdict, s.note.c_str());
      else
        std::printf("| %s | %s | %.4g | %.3g | %.6g | %.3g | %.3f | %s |\n", spec.name.c_str(), s.name.c_str(),
                    s.range, s.max_error, s.at_time, s.tolerance, s.relative(), verdict);
    }
    std::fprintf(stderr, "%s: %s\n", spec.name.c_str(), c.report.BriefReport().c_str());
    all = all && c.passed();
  }
  return all ? 0 : 1;
}
