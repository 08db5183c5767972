// Comparison of a simulation with a Modelica reference result (../shared/reference/msl):
// continuous signals pointwise against a band of 2e-3 x the signal's range (absolute floor
// 1e-9), with a time tube of +-1 ms around events; friction modes and start flags by their
// switching times (within 1 ms). Used by the msl.* tests and by the msl_report tool that
// writes the table of docs/validation.md.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "highlift/sim/simulator.h"

namespace highlift::testing {

struct Series {
  std::vector<double> t, y;
};

struct ReferenceCsv {
  std::vector<std::string> columns;  // including "time"
  std::vector<std::vector<double>> rows;
  Series Column(const std::string& name) const;
};
ReferenceCsv ReadReferenceCsv(const std::filesystem::path& file);
std::vector<std::string> ReadComparisonSignals(const std::filesystem::path& file);

struct SignalComparison {
  std::string name;
  bool discrete = false;      ///< mode or Boolean: compared by switching times
  bool informative = false;   ///< reported, not pass/fail (non-unique labels)
  double range = 0.0;         ///< reference range max - min
  double max_error = 0.0;     ///< largest |sim - ref| (continuous), or largest switch-time shift [s]
  double at_time = 0.0;       ///< where the largest error occurs
  double tolerance = 0.0;     ///< 2e-3 * range + 1e-9, or 1e-3 s
  bool passed = false;
  std::string note;           ///< e.g. a mismatch of the mode sequence
  double relative() const { return tolerance > 0 ? max_error / tolerance : 0.0; }
};

struct ExampleComparison {
  std::string example;
  highlift::sim::SimulationReport report;
  std::vector<SignalComparison> signals;
  bool passed() const;
};

/// Runs tests/sim/msl/<example>.json and compares with <reference_dir>/<csv_path>.
/// `informative` lists signals reported but not required to pass.
ExampleComparison CompareExample(const std::string& example, const std::filesystem::path& reference_dir,
                                 const std::string& csv_path,
                                 const std::vector<std::string>& informative = {});

/// The example list: name, CSV path relative to reference/msl, informative signals.
struct ExampleSpec {
  std::string name;
  std::string csv;
  std::vector<std::string> informative;
};
const std::vector<ExampleSpec>& MslExamples();

}  // namespace highlift::testing
