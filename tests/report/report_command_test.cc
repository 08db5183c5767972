// `highlift report` and the answer-first terminal output of `highlift check`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/run_cli.h"

namespace {

std::string FirstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(ReportCommand, WritesOneSelfContainedFileAndLeadsWithTheVerdict) {
  const auto out = std::filesystem::path(HIGHLIFT_BINARY_DIR) / "tests" / "report" / "command_report.html";
  std::filesystem::remove(out);
  const auto r = highlift::testing::RunCli(
      {"report", "examples/a380_class_flaps.json", "--no-transient", "--no-scenarios", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(FirstLine(r.out), "feasible: the nominal design meets all 32 requirements of the project") << r.out;
  EXPECT_NE(r.out.find("wrote " + out.string()), std::string::npos) << r.out;
  ASSERT_TRUE(std::filesystem::exists(out));
  EXPECT_LT(std::filesystem::file_size(out), 5u * 1024 * 1024);
}

TEST(ReportCommand, InfeasibleProjectExitsOneAndStillWritesTheReport) {
  const auto out = std::filesystem::path(HIGHLIFT_BINARY_DIR) / "tests" / "report" / "command_infeasible.html";
  const auto r = highlift::testing::RunCli({"report", "examples/a380_class_flaps_infeasible.json", "--no-transient",
                                            "--no-scenarios", "--out", out.string(), "--json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["verdict"]["status"], "infeasible");
  EXPECT_EQ(doc["all_requirements_met"], false);
  EXPECT_GT(doc["bytes"].get<std::size_t>(), 50000u);
  EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(ReportCommand, UnwritableOutputIsNamed) {
  const auto r = highlift::testing::RunCli({"report", "examples/a380_class_flaps.json", "--no-transient",
                                            "--no-scenarios", "--out", "/nonexistent-folder/report.html"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cannot write the report file '/nonexistent-folder/report.html': cannot create a file in the "
                       "folder '/nonexistent-folder' (No such file or directory); check that it exists and is writable"),
            std::string::npos)
      << r.err;
}

// --campaign: the envelope of the project's own campaign is in the page's data; a campaign of
// another project is refused (exit 2, naming both) and no file is written.
TEST(ReportCommand, CampaignOfTheProjectIsShownAndAnotherProjectsIsRefused) {
  const auto dir = std::filesystem::path(HIGHLIFT_BINARY_DIR) / "tests" / "report" / "command_campaign";
  std::filesystem::remove_all(dir);
  const auto run = highlift::testing::RunCli({"campaign", "examples/a320_class_flaps.json", "--cases", "rupture_*",
                                              "--model", "reduced", "--jobs", "2", "--out", dir.string()});
  ASSERT_LE(run.exit_code, 1) << run.err;

  const auto out = dir / "report.html";
  const auto r = highlift::testing::RunCli({"report", "examples/a320_class_flaps.json", "--campaign", dir.string(),
                                            "--no-transient", "--no-scenarios", "--out", out.string(), "--json"});
  ASSERT_LE(r.exit_code, 1) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["campaign_ok"].get<bool>(), run.exit_code == 0);
  std::ifstream in(out);
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("\"envelope\":[{\"capacity_N_m\""), std::string::npos) << "no envelope in the page's data";
  EXPECT_NE(html.find("\"campaign\":{\"at\""), std::string::npos) << "no peak case carries its campaign peak";

  const auto other = dir / "other.html";
  const auto refused = highlift::testing::RunCli({"report", "examples/a380_class_flaps.json", "--campaign", dir.string(),
                                                  "--no-transient", "--no-scenarios", "--out", other.string()});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("the campaign was run on project 'A320-class flap transmission (both wings)'"),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("run `highlift campaign` on this project again"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(other));

  const auto missing = highlift::testing::RunCli({"report", "examples/a320_class_flaps.json", "--campaign",
                                                  (dir / "nothing-here").string(), "--no-transient", "--no-scenarios",
                                                  "--out", other.string()});
  EXPECT_EQ(missing.exit_code, 2) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(other));
}

TEST(CheckOutput, VerdictComesFirstAndTheTableOnlyWithAll) {
  const auto r = highlift::testing::RunCli({"check", "examples/a380_class_flaps.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(FirstLine(r.out), "feasible: the nominal design meets all 32 requirements of the project");
  EXPECT_NE(r.out.find("\nParameter domains: all "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nNominal design (every parameter at its nominal value): meets all 32 requirements."),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("narrowed %"), std::string::npos) << "the parameter table needs --all";
  EXPECT_NE(r.out.find("parameter domains, initial and final: --all, or --json)"), std::string::npos);
  // Short: the answer, the why, the counters; not ~900 rows.
  EXPECT_LT(std::count(r.out.begin(), r.out.end(), '\n'), 80) << r.out;

  const auto all = highlift::testing::RunCli({"check", "examples/a380_class_flaps.json", "--all"});
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_EQ(FirstLine(all.out), FirstLine(r.out));
  EXPECT_NE(all.out.find("narrowed %"), std::string::npos);
  EXPECT_NE(all.out.find("shaft_l0a.c"), std::string::npos);
  EXPECT_GT(all.out.find("narrowed %"), all.out.find("Parameter domains:"));  // the table after the answer
}

}  // namespace
