// CsvSink writes every number as the shortest text that reads back as the same double.
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

#include "common/scratch.h"
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
  const auto file = highlift::testing::RemoveAfterTheTest(std::filesystem::temp_directory_path() /
                                                          ("highlift_csv_sink_" + std::to_string(::getpid()) + ".csv"));
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

}  // namespace
}  // namespace highlift::sim
