// The sparse Jacobian's colouring on the pattern of the current mode (System::ModeJacobianPattern,
// SimulationOptions::mode_colouring): the columns of one colour share no row, the mode's pattern
// lies inside the superset of every mode and needs fewer colours, and a drive-system run gives
// the same steps, Newton iterations, events and peaks to the last bit as with the superset's
// colouring, from fewer evaluations.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "highlift/core/project_io.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"
#include "system.h"

namespace highlift::sim::detail {
namespace {


// Every column in exactly one colour, and no two columns of a colour with an entry in one row.
void ExpectValidColouring(const std::vector<int>& colptr, const std::vector<int>& rows,
                          const std::vector<char>* entry, const std::vector<std::vector<int>>& colours) {
  const int n = static_cast<int>(colptr.size()) - 1;
  std::vector<int> seen(static_cast<std::size_t>(n), 0);
  for (const auto& colour : colours) {
    std::set<int> rows_taken;
    for (int j : colour) {
      ++seen[static_cast<std::size_t>(j)];
      for (int k = colptr[j]; k < colptr[j + 1]; ++k) {
        if (entry != nullptr && !(*entry)[static_cast<std::size_t>(k)]) continue;
        EXPECT_TRUE(rows_taken.insert(rows[k]).second) << "row " << rows[k] << " twice in a colour";
      }
    }
  }
  for (int j = 0; j < n; ++j) EXPECT_EQ(seen[static_cast<std::size_t>(j)], 1) << "column " << j;
}

TEST(ColourColumns, ColumnsOfAColourShareNoRowOfAnUnsymmetricPattern) {
  // 4 x 4: column 0 has rows {0, 3}, column 1 {1}, column 2 {2, 3}, column 3 {3}. Columns 0, 2
  // and 3 meet in row 3 (the pattern is not symmetric: row 0 holds column 0 only).
  const std::vector<int> colptr = {0, 2, 3, 5, 6}, rows = {0, 3, 1, 2, 3, 3};
  const auto colours = ColourColumns(colptr, rows);
  ExpectValidColouring(colptr, rows, nullptr, colours);
  EXPECT_EQ(colours.size(), 3u);
  // Without the entries in row 3 every column fits one colour.
  const std::vector<char> entry = {1, 0, 1, 1, 0, 1};
  const auto masked = ColourColumns(colptr, rows, &entry);
  ExpectValidColouring(colptr, rows, &entry, masked);
  EXPECT_EQ(masked.size(), 1u);
}

TEST(ModeJacobianPattern, LiesInsideTheSupersetAndNeedsFewerColours) {
  const Project project =
      LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a380_class_flaps.json");
  const DriveModel model = BuildDriveNetwork(project, {.scenario = "extension"});
  System sys(model.network);
  std::vector<double> y = sys.InitialState(0.0);
  std::vector<std::string> changes, who;
  ASSERT_TRUE(sys.HandleEvent(0.0, y.data(), true, &changes, &who)) << sys.error();
  std::vector<double> ydot(y.size());
  ASSERT_TRUE(sys.Evaluate(0.0, y.data(), ydot.data())) << sys.error();
  const System::ModePattern* mode = sys.ModeJacobianPattern();
  ASSERT_NE(mode, nullptr);
  EXPECT_TRUE(sys.InMode(*mode));
  ASSERT_EQ(mode->entry.size(), sys.jacobian_rows().size());
  const auto superset = ColourColumns(sys.jacobian_colptr(), sys.jacobian_rows());
  ExpectValidColouring(sys.jacobian_colptr(), sys.jacobian_rows(), &mode->entry, mode->colours);
  EXPECT_LT(mode->colours.size(), superset.size());
  // Every diagonal entry is in the mode's pattern; the same mode gives the same pattern back.
  for (int j = 0; j < sys.NumStates(); ++j) {
    bool diagonal = false;
    for (int k = sys.jacobian_colptr()[j]; k < sys.jacobian_colptr()[j + 1]; ++k)
      if (sys.jacobian_rows()[k] == j) diagonal = mode->entry[static_cast<std::size_t>(k)] != 0;
    EXPECT_TRUE(diagonal) << sys.StateNames()[j];
  }
  EXPECT_EQ(sys.ModeJacobianPattern(), mode);
}

// A jam and a rupture of the bundled example: brakes and limiters stick, slide and release, so
// the mode changes many times. The run with the mode's colouring is the run with the
// superset's, bit for bit, from fewer right-hand sides.
TEST(ModeColouring, ADriveRunIsTheSameAsWithTheSupersetsColouring) {
  const Project project =
      LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a380_class_flaps.json");
  for (const std::string scenario : {"jam_l4", "rupture_wtb"}) {
    const DriveModel model = BuildDriveNetwork(project, {.scenario = scenario});
    SimulationOptions options = model.Options(project);
    DiscardSink sink_mode, sink_superset;
    const SimulationReport mode = Simulator(model.network).Run(options, sink_mode);
    options.mode_colouring = false;
    const SimulationReport superset = Simulator(model.network).Run(options, sink_superset);
    ASSERT_TRUE(mode.ok()) << mode.FullReport();
    ASSERT_TRUE(superset.ok()) << superset.FullReport();
    EXPECT_EQ(mode.statistics.steps, superset.statistics.steps) << scenario;
    EXPECT_EQ(mode.statistics.nonlinear_iterations, superset.statistics.nonlinear_iterations) << scenario;
    EXPECT_EQ(mode.statistics.jacobian_evaluations, superset.statistics.jacobian_evaluations) << scenario;
    EXPECT_LT(mode.statistics.rhs_evaluations, superset.statistics.rhs_evaluations) << scenario;
    ASSERT_EQ(mode.events.size(), superset.events.size()) << scenario;
    for (std::size_t i = 0; i < mode.events.size(); ++i) EXPECT_EQ(mode.events[i].time, superset.events[i].time) << i;
    ASSERT_EQ(mode.peak_torques.size(), superset.peak_torques.size());
    for (std::size_t i = 0; i < mode.peak_torques.size(); ++i) {
      EXPECT_EQ(mode.peak_torques[i].tau, superset.peak_torques[i].tau) << mode.peak_torques[i].element;
      EXPECT_EQ(mode.peak_torques[i].time, superset.peak_torques[i].time) << mode.peak_torques[i].element;
    }
  }
}

}  // namespace
}  // namespace highlift::sim::detail
