// `highlift export`: writes the files, reports them (text and --json), and rejects bad usage
// with exit code 2 and a message that names the problem.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "common/run_cli.h"
#include "export_test_util.h"

namespace highlift {
namespace {

using testing::ReadText;
using testing::RunCli;

/// A folder for the running test, absent at first; removed when the test passed.
std::filesystem::path TempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("highlift_export_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return testing::RemoveAfterTheTest(dir);
}

TEST(ExportCli, ExportsAnElementNetworkWithAFlangeConnectedTwice) {
  // MSL First grounds several elements on fixed.flange; the CLI validates and exports it.
  const auto dir = TempDir("first");
  const auto r = RunCli({"export", "tests/export/first.json", "--modelica", dir.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ReadText(dir / "HighLift" / "Models" / "First.mo"), ReadText(testing::ExportTestDir() / "golden" / "First.mo"));
}

TEST(ExportCli, WritesLibraryAndModel) {
  // --start rest: the model as the library writes it without a start (the golden file).
  const auto dir = TempDir("rig");
  const auto r = RunCli({"export", "tests/export/small_drive.json", "--modelica", dir.string(), "--start", "rest"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Modelica model 'OneStationRig' (drive system, full, scenario 'rupture_wtb')"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("load HighLift/package.mo, simulate HighLift.Models.OneStationRig"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "HighLift" / "package.mo"));
  EXPECT_TRUE(std::filesystem::exists(dir / "HighLift" / "Mechanical" / "TorqueLimiter.mo"));
  EXPECT_EQ(ReadText(dir / "HighLift" / "Models" / "OneStationRig.mo"),
            ReadText(testing::ExportTestDir() / "golden" / "OneStationRig_full.mo"));
  // Only the package at the top of the folder: one file to load.
  for (const auto& entry : std::filesystem::directory_iterator(dir)) EXPECT_EQ(entry.path().filename(), "HighLift");
}

TEST(ExportCli, StartsWhereTheSimulatorStartsByDefault) {
  const auto dir = TempDir("start");
  const auto r = RunCli({"export", "tests/export/small_drive.json", "--modelica", dir.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("start: static equilibrium: loads balanced to"), std::string::npos) << r.out;
  const std::string model = ReadText(dir / "HighLift" / "Models" / "OneStationRig.mo");
  EXPECT_NE(model.find("fixed=true"), std::string::npos);
  EXPECT_NE(model.find("The model starts where <code>highlift simulate</code> starts"), std::string::npos);
  std::filesystem::remove_all(dir);
  const auto bad = RunCli({"export", "tests/export/small_drive.json", "--modelica", dir.string(), "--start", "settled"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--start"), std::string::npos) << bad.err;
}

TEST(ExportCli, JsonReportListsTheFiles) {
  const auto dir = TempDir("drive");
  const auto r = RunCli({"export", "tests/export/small_drive.json", "--modelica", dir.string(), "--model",
                         "reduced", "--scenario", "jam_gra_1", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["model"], "OneStationRig");
  EXPECT_EQ(doc["model_path"], "HighLift.Models.OneStationRig");
  EXPECT_EQ(doc["model_file"], "HighLift/Models/OneStationRig.mo");
  EXPECT_EQ(doc["scenario"], "jam_gra_1");
  EXPECT_EQ(doc["kind"], "drive system, reduced");
  bool has_model = false;
  for (const auto& f : doc["files"]) {
    EXPECT_TRUE(std::filesystem::exists(dir / f.get<std::string>())) << f;
    has_model = has_model || f == "HighLift/Models/OneStationRig.mo";
  }
  EXPECT_TRUE(has_model);
}

TEST(ExportCli, BadResolutionIsAUsageError) {
  const auto dir = TempDir("bad");
  const auto r = RunCli({"export", "tests/export/small_drive.json", "--modelica", dir.string(), "--model", "coarse"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown model resolution 'coarse'"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(ExportCli, UnknownScenarioIsAnInputError) {
  const auto dir = TempDir("scenario");
  const auto r = RunCli({"export", "tests/export/small_drive.json", "--modelica", dir.string(), "--scenario", "nope"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown scenario 'nope': use one of rupture_wtb, jam_gra_1"), std::string::npos) << r.err;
}

// Issue 27, item 13: a 300-character project name exports (the model name is cut at a word);
// a --model-name too long for a file name exits 2 before anything is written.
TEST(ExportCli, LongNamesExportOrFailBeforeWriting) {
  const auto dir = TempDir("long");
  std::string text = ReadText(testing::ExportTestDir() / "small_drive.json");
  const std::string old_name = "\"name\": \"one-station rig\"";
  ASSERT_NE(text.find(old_name), std::string::npos);
  std::string long_name;
  while (long_name.size() < 300) long_name += "wing ";
  long_name.resize(300);
  text.replace(text.find(old_name), old_name.size(), "\"name\": \"" + long_name + "\"");
  std::filesystem::create_directories(dir);
  const auto project = dir / "long.json";
  testing::WriteText(project, text);
  const auto out = dir / "out";
  const auto r = RunCli({"export", project.string(), "--modelica", out.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  const std::string model = doc["model"];
  EXPECT_LE(model.size(), 80u);
  EXPECT_TRUE(std::filesystem::exists(out / doc["model_file"].get<std::string>()));

  const auto none = dir / "none";
  const auto bad = RunCli({"export", project.string(), "--modelica", none.string(), "--model-name", "M" + std::string(299, 'x')});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("give a shorter model name with --model-name"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(none));
}

TEST(ExportCli, OutputFolderIsRequired) {
  const auto r = RunCli({"export", "tests/export/first.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--modelica"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace highlift
