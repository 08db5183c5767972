// componentdb::ParseTubeSizes and the shipped table (data/tube_sizes.csv): the ISO 3 R20 sizes
// with 10 <= D/t <= 40, units from the header, and messages that name the file, the line and what
// is valid.
#include "highlift/componentdb/tube_sizes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "highlift/core/error.h"

namespace highlift::componentdb {
namespace {

std::string MessageOf(const std::string& text) {
  try {
    ParseTubeSizes(text, "stock.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(TubeSizes, StandardTableIsR20WithinTheThinTubeRange) {
  const TubeSizeTable& t = StandardTubeSizes();
  EXPECT_EQ(t.name, "standard");
  const double r20_d[] = {20, 22.4, 25, 28, 31.5, 35.5, 40, 45, 50, 56, 63, 71, 80, 90, 100, 112, 125};
  const double r20_t[] = {0.8, 0.9, 1.0, 1.12, 1.25, 1.4, 1.6, 1.8, 2.0, 2.24, 2.5, 2.8, 3.15, 3.55, 4.0, 4.5, 5.0};
  std::size_t expected = 0;
  for (double D : r20_d)
    for (double w : r20_t) expected += D / w >= 10 && D / w <= 40;
  EXPECT_EQ(t.sizes.size(), expected);
  for (const TubeSize& s : t.sizes) {
    const double D = s.outer_diameter * 1e3, w = s.wall_thickness * 1e3;
    EXPECT_TRUE(std::any_of(std::begin(r20_d), std::end(r20_d), [&](double v) { return std::fabs(v - D) < 1e-9; })) << s.designation;
    EXPECT_TRUE(std::any_of(std::begin(r20_t), std::end(r20_t), [&](double v) { return std::fabs(v - w) < 1e-9; })) << s.designation;
    EXPECT_GE(D / w, 10 - 1e-9) << s.designation;
    EXPECT_LE(D / w, 40 + 1e-9) << s.designation;
  }
  // The database's A380-class tubes are R20 sizes.
  for (const char* name : {"45x1.8", "50x2"}) {
    const auto it = std::find_if(t.sizes.begin(), t.sizes.end(), [&](const TubeSize& s) { return s.designation == name; });
    ASSERT_NE(it, t.sizes.end()) << name;
  }
  const auto it = std::find_if(t.sizes.begin(), t.sizes.end(), [](const TubeSize& s) { return s.designation == "45x1.8"; });
  EXPECT_DOUBLE_EQ(it->outer_diameter, 0.045);
  EXPECT_DOUBLE_EQ(it->wall_thickness, 0.0018);
}

TEST(TubeSizes, UnitsComeFromTheHeaderAndCommentsAreSkipped) {
  const TubeSizeTable t = ParseTubeSizes(
      "# my stock\ndesignation,outer_diameter [in],wall_thickness [mm]\n# inch tubes, metric walls\n\n"
      "2in x 1.6,2,1.6\r\n\"1.5in, thick\",1.5,3\n",
      "stock.csv");
  ASSERT_EQ(t.sizes.size(), 2u);
  EXPECT_EQ(t.name, "stock.csv");
  EXPECT_NEAR(t.sizes[0].outer_diameter, 0.0508, 1e-12);
  EXPECT_NEAR(t.sizes[0].wall_thickness, 0.0016, 1e-12);
  EXPECT_EQ(t.sizes[1].designation, "1.5in, thick");
  EXPECT_EQ(t.sizes[1].origin, "stock.csv line 6");
}

TEST(TubeSizes, MalformedCsvIsNamedWithFileLineAndWhatIsValid) {
  const std::string header = "designation,outer_diameter [mm],wall_thickness [mm]\n";
  EXPECT_NE(MessageOf("").find("stock.csv: no header"), std::string::npos);
  EXPECT_NE(MessageOf("designation,outer_diameter,wall_thickness [mm]\n")
                .find("stock.csv line 1: column 'outer_diameter' must be 'outer_diameter [UNIT]'"),
            std::string::npos);
  EXPECT_NE(MessageOf("designation,outer_diameter [kg],wall_thickness [mm]\n").find("expected a length"),
            std::string::npos);
  EXPECT_NE(MessageOf("designation,outer_diameter [furlongs per],wall_thickness [mm]\n").find("stock.csv line 1"),
            std::string::npos);
  EXPECT_NE(MessageOf("name,outer_diameter [mm],wall_thickness [mm]\n").find("the header must be designation,"),
            std::string::npos);
  EXPECT_NE(MessageOf(header).find("stock.csv: no size after the header"), std::string::npos);
  EXPECT_NE(MessageOf(header + "45x1.8,45,1.8\n\n50x2,50\n").find("stock.csv line 4: 2 fields"), std::string::npos);
  EXPECT_NE(MessageOf(header + "45x1.8,45,abc\n").find("stock.csv line 2: wall_thickness 'abc' must be a finite number > 0"),
            std::string::npos);
  EXPECT_NE(MessageOf(header + "45x1.8,-45,1.8\n").find("outer_diameter '-45' must be a finite number > 0"),
            std::string::npos);
  EXPECT_NE(MessageOf(header + ",45,1.8\n").find("stock.csv line 2: the designation is empty"), std::string::npos);
  EXPECT_NE(MessageOf(header + "a,45,1.8\na,50,2\n").find("stock.csv line 3: designation 'a' is repeated (line 2)"),
            std::string::npos);
  EXPECT_NE(MessageOf(header + "bar,10,6\n").find("wall of 6 mm above half its diameter of 10 mm"), std::string::npos);
}

TEST(TubeSizes, UnreadableFileIsNamed) {
  try {
    LoadTubeSizes("/nonexistent/stock.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'/nonexistent/stock.csv': cannot read the file"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'standard'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(LoadTubeSizes("standard").sizes.size(), StandardTubeSizes().sizes.size());
}

}  // namespace
}  // namespace highlift::componentdb
