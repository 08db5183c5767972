// The static equilibrium at the start of a drive-system run (System::SolveEquilibrium): its
// Jacobian perturbs the twists that share no row of the sparsity pattern together. Each row
// then reads one perturbed twist, so the difference quotients, the Gauss-Newton steps and the
// equilibrium are those of one twist at a time, to the last bit, from far fewer evaluations.
// A pattern that missed a dependency (a twist that moves a node it is not declared to reach)
// would mix two twists' quotients in one entry and move the equilibrium.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "highlift/core/project_io.h"
#include "highlift/sim/drive_network.h"
#include "system.h"

namespace highlift::sim::detail {
namespace {

struct Equilibrium {
  std::vector<double> y;
  double imbalance = 0.0;
  bool found = false;
  int evaluations = 0;
};

// The start of `scenario` of the bundled example as the simulator makes it (initial modes,
// then the equilibrium), with the twists perturbed together or alone.
Equilibrium Solve(const std::string& project_file, const std::string& scenario, bool group_twists,
                  model::DriveResolution resolution = model::DriveResolution::kFull) {
  const Project project = LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / project_file);
  const DriveModel model = BuildDriveNetwork(project, {.resolution = resolution, .scenario = scenario});
  System sys(model.network);
  Equilibrium out;
  out.y = sys.InitialState(0.0);
  std::vector<std::string> changes, who;
  EXPECT_TRUE(sys.HandleEvent(0.0, out.y.data(), true, &changes, &who)) << sys.error();
  out.imbalance = sys.SolveEquilibrium(0.0, out.y.data(), out.found, {.group_twists = group_twists});
  out.evaluations = sys.equilibrium_evaluations();
  return out;
}

void ExpectSameEquilibrium(const std::string& project_file, const std::string& scenario,
                           model::DriveResolution resolution = model::DriveResolution::kFull) {
  const Equilibrium alone = Solve(project_file, scenario, false, resolution);
  const Equilibrium grouped = Solve(project_file, scenario, true, resolution);
  ASSERT_TRUE(alone.found) << scenario;
  ASSERT_TRUE(grouped.found) << scenario;
  ASSERT_EQ(alone.y.size(), grouped.y.size());
  // Bit for bit: the start state, and the imbalance left.
  EXPECT_EQ(std::memcmp(alone.y.data(), grouped.y.data(), sizeof(double) * alone.y.size()), 0) << scenario;
  EXPECT_EQ(std::memcmp(&alone.imbalance, &grouped.imbalance, sizeof(double)), 0)
      << scenario << ": " << alone.imbalance << " against " << grouped.imbalance;
  // And the grouping is real: a few evaluations per Jacobian instead of one per twist.
  EXPECT_LT(2 * grouped.evaluations, alone.evaluations)
      << scenario << ": " << grouped.evaluations << " evaluations grouped, " << alone.evaluations << " alone";
}

TEST(StaticEquilibrium, GroupedTwistsGiveTheEquilibriumOfTwistsPerturbedAlone) {
  // The full model of both wings (118 twists): extending against the airload, and the WTB
  // scenario, whose brakes hold part of the load.
  ExpectSameEquilibrium("a380_class_flaps.json", "extension");
  ExpectSameEquilibrium("a380_class_flaps.json", "rupture_wtb");
}

TEST(StaticEquilibrium, GroupedTwistsOnTheReducedModelAndTheSlats) {
  ExpectSameEquilibrium("a380_class_flaps.json", "extension", model::DriveResolution::kReduced);
  ExpectSameEquilibrium("a320_class_slats.json", "extension");
}

}  // namespace
}  // namespace highlift::sim::detail
