// The reduced models on the A380-class example (examples/a380_class_flaps.json, domain.md s3)
// and the size / modes / peak commands of the CLI.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/run_cli.h"
#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sizing.h"

namespace highlift::reduced_models {
namespace {

const std::string kExample = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json";

TEST(A380Example, SizingMatchesTheDomainEstimates) {
  const Project project = LoadProject(kExample);
  const SizingReport r = Size(project);
  const LoadCaseSizing* extend = nullptr;
  for (const auto& c : r.cases)
    if (c.direction == "extend") extend = &c;
  ASSERT_NE(extend, nullptr);
  // domain.md s3 (E): PCU about 720 N*m and 18 kW for both wings (within 25 %: drags and
  // efficiencies of the example's components differ from the round figures).
  EXPECT_NEAR(extend->pdu_torque.nominal, 720.0, 0.25 * 720.0);
  EXPECT_NEAR(extend->pdu_power.nominal / 1e3, 18.0, 0.25 * 18.0);
  EXPECT_TRUE(extend->pdu_torque.bounds.contains(extend->pdu_torque.nominal));
  EXPECT_NEAR(r.shaft_mass, 51.0 * 1.2, 0.2 * 51.0 * 1.2);  // about 51 m of 1.08-1.33 kg/m tube
}

TEST(A380Example, ReducedModelsFirstModeErrorIsSmall) {
  const ModesReport r = AnalyseModes(LoadProject(kExample));
  for (const auto& m : r.models) EXPECT_LT(std::abs(m.first_clamped_error), 0.05) << ToString(m.reduction);
}

TEST(A380Example, PeakListsEveryJamAndRupture) {
  const PeakReport r = AnalysePeaks(LoadProject(kExample));
  int jams = 0;
  for (const auto& c : r.cases) {
    jams += c.kind == "jam";
    EXPECT_TRUE(c.tau_dynamic.bounds.contains(c.tau_dynamic.nominal)) << c.name;
  }
  EXPECT_EQ(jams, 12);
  EXPECT_GT(r.cases.size(), 12u);
}

TEST(ReducedModelsCli, SizeModesAndPeakPrintOneJsonDocument) {
  for (const char* command : {"size", "modes", "peak"}) {
    const highlift::testing::CliResult r = highlift::testing::RunCli({command, "examples/a380_class_flaps.json", "--json"});
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << command << ": " << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j.contains("project")) << command;
  }
}

TEST(ReducedModelsCli, PeakUnknownCaseExitsTwoAndListsTheCases) {
  const highlift::testing::CliResult r = highlift::testing::RunCli({"peak", "examples/a380_class_flaps.json", "--case", "jam_nowhere"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("peak case 'jam_nowhere' does not exist; the cases are:"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace highlift::reduced_models
