// The output path: CsvSink writes every number as the shortest text that reads back as the same
// double; a sink that does not read the values (OutputSink::ReadsValues false) gets the same rows
// at the same times and leaves the run's results unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string field; std::getline(s, field, ',');) out.push_back(field);
  return out;
}

TEST(CsvSink, NumbersAreTheShortestTextThatReadsBackExactly) {
  const std::vector<double> values = {0.1,     1.0 / 3.0, -2.5e17, 3.0, 1e-300, std::numeric_limits<double>::denorm_min(),
                                      -0.0,    123456.789, std::nextafter(1.0, 2.0), std::numeric_limits<double>::max()};
  const auto file = std::filesystem::temp_directory_path() / ("highlift_csv_sink_" + std::to_string(::getpid()) + ".csv");
  {
    CsvSink sink(file);
    std::vector<std::string> columns;
    for (std::size_t i = 0; i < values.size(); ++i) columns.push_back("x" + std::to_string(i));
    sink.Begin(columns);
    sink.Row(0.25, values);
    sink.End();
  }
  std::ifstream in(file);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  in.close();
  std::filesystem::remove(file);
  const auto fields = Split(row);
  ASSERT_EQ(fields.size(), values.size() + 1) << row;
  EXPECT_EQ(fields[0], "0.25");
  EXPECT_EQ(fields[1], "0.1");  // not 0.10000000000000001
  EXPECT_EQ(fields[4], "3");
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double back = std::strtod(fields[i + 1].c_str(), nullptr);
    EXPECT_EQ(std::signbit(back), std::signbit(values[i])) << fields[i + 1];
    EXPECT_EQ(back, values[i]) << "column " << i << ": '" << fields[i + 1] << "'";
    EXPECT_LE(fields[i + 1].size(), 24u) << fields[i + 1];
  }
}

/// Counts the rows and their times; does not read the values.
class TimesOnlySink : public OutputSink {
 public:
  void Begin(const std::vector<std::string>& columns) override { columns_ = columns.size(); }
  void Row(double time, const std::vector<double>& values) override {
    times.push_back(time);
    sizes_match = sizes_match && values.size() == columns_;
  }
  bool ReadsValues() const override { return false; }
  std::vector<double> times;
  bool sizes_match = true;

 private:
  std::size_t columns_ = 0;
};

// A spring-damper chain with a friction brake: events (stick/slip) and rows at their limits.
Network FrictionChain() {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Sine", "drive", {{{"amplitude", 8}, {"f", 1.5}}, {}});
  net.AddElement("Torque", "torque");
  net.AddElement("Inertia", "inertia1", {{{"J", 1}, {"phi_start", 0}, {"w_start", 0}}, {}});
  net.AddElement("SpringDamper", "spring", {{{"c", 400}, {"d", 2}}, {}});
  net.AddElement("Inertia", "inertia2", {{{"J", 0.5}, {"phi_start", 0}, {"w_start", 0}}, {}});
  net.AddElement("BearingFriction", "bearing", {{{"peak", 1.2}}, {{"tau_pos", {{0, 1.0}, {10, 1.5}}}}});
  net.Connect("drive.y", "torque.tau");
  net.Connect("torque.flange", "inertia1.flange_a");
  net.Connect("inertia1.flange_b", "spring.flange_a");
  net.Connect("spring.flange_b", "inertia2.flange_a");
  net.Connect("inertia2.flange_b", "bearing.flange_a");
  net.Connect("bearing.support", "fixed.flange");
  net.Connect("torque.support", "fixed.flange");
  return net;
}

TEST(OutputSink, ASinkThatDoesNotReadTheValuesGetsTheSameRowsAndResults) {
  SimulationOptions o;
  o.stop_time = 2.0;
  o.output_interval = 1e-2;
  o.energy = true;
  MemorySink memory;
  TimesOnlySink times_only;
  const SimulationReport full = Simulator(FrictionChain()).Run(o, memory);
  const SimulationReport lean = Simulator(FrictionChain()).Run(o, times_only);
  ASSERT_TRUE(full.ok()) << full.FullReport();
  ASSERT_TRUE(lean.ok()) << lean.FullReport();
  EXPECT_GT(full.events.size(), 2u);  // stick/slip events: rows at their limits too
  EXPECT_EQ(times_only.times, memory.times());
  EXPECT_TRUE(times_only.sizes_match);
  EXPECT_EQ(lean.statistics.steps, full.statistics.steps);
  EXPECT_EQ(lean.events.size(), full.events.size());
  ASSERT_EQ(lean.peak_torques.size(), full.peak_torques.size());
  for (std::size_t i = 0; i < full.peak_torques.size(); ++i) {
    EXPECT_EQ(lean.peak_torques[i].tau, full.peak_torques[i].tau) << full.peak_torques[i].element;
    EXPECT_EQ(lean.peak_torques[i].time, full.peak_torques[i].time) << full.peak_torques[i].element;
  }
  EXPECT_EQ(lean.energy.dissipated, full.energy.dissipated);
  EXPECT_EQ(lean.energy.source_work, full.energy.source_work);
}

}  // namespace
}  // namespace highlift::sim
