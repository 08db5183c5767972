// `highlift estimate`: report, JSON, --write and reload.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/run_cli.h"
#include "highlift/componentdb/database.h"
#include "highlift/core/project_io.h"

namespace highlift {
namespace {

using highlift::testing::RunCli;

// ctest sets HIGHLIFT_DATA_DIR; run by hand, keep the default database out of the home directory,
// in a folder of this process that goes when every test passed.
const bool kDataDirectorySet = [] {
  if (!std::getenv("HIGHLIFT_DATA_DIR")) {
    const auto home = std::filesystem::temp_directory_path() /
                      ("highlift_estimate_cli_home_" + std::to_string(::getpid()));
    ::setenv("HIGHLIFT_DATA_DIR", testing::RemoveAtTheEnd(home).c_str(), 1);
  }
  return true;
}();

const char* kProject = R"({
  "format": "highlift-project/1",
  "name": "estimate test rig",
  "components": [
    {"id": "pdu", "type": "pdu"},
    {"id": "shaft_1", "type": "torque_shaft",
     "parameters": {"length": "4 m", "outer_diameter": "50 mm", "wall_thickness": "2.0 mm", "shear_modulus": "44 GPa"}},
    {"id": "gra_1", "type": "geared_rotary_actuator",
     "parameters": {"ratio": {"part": "GRA-200-A380C"}, "output_torque_rating": "20 kN*m"}}
  ],
  "connections": [["pdu.left", "shaft_1.a"], ["shaft_1.b", "gra_1.input"]]
})";

/// `name` in the folder the tests of this process share (with the seed database built once).
std::filesystem::path Scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("highlift_estimate_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return testing::RemoveAtTheEnd(dir) / name;
}

// A database made from this build's seed (the default database in the data directory may have
// been created by an older build and is never replaced behind the user's back).
std::string FreshSeedDatabase() {
  static const std::string path = [] {
    const auto file = Scratch("seed.sqlite");
    if (!std::filesystem::exists(file)) componentdb::CreateDatabaseFromSeed(file);
    return file.string();
  }();
  return path;
}

TEST(EstimateCli, ReportsValuesWithProvenanceAsJson) {
  const auto file = Scratch("rig.json");
  std::ofstream(file) << kProject;
  const auto r = RunCli({"estimate", file.string(), "--json", "--db", FreshSeedDatabase()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["status"], "ok");
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& p : doc["parameters"]) by_name[p["component"].get<std::string>() + "." + p["parameter"].get<std::string>()] = p;
  EXPECT_EQ(by_name["shaft_1.stiffness"]["provenance"], "estimated");
  EXPECT_NEAR(by_name["shaft_1.stiffness"]["value"].get<double>(), 1914.0, 0.5);
  EXPECT_EQ(by_name["gra_1.ratio"]["provenance"], "database");
  EXPECT_EQ(by_name["gra_1.ratio"]["value"].get<double>(), 200.0);
  EXPECT_EQ(by_name["gra_1.input_inertia"]["provenance"], "fit");
  EXPECT_EQ(by_name["shaft_1.length"]["provenance"], "user");
  ASSERT_FALSE(doc["fits"].empty());
  EXPECT_GE(doc["fits"][0]["parts"].size(), 4u);
}

TEST(EstimateCli, WrittenProjectLoadsAgainWithTheEstimates) {
  const auto file = Scratch("rig2.json");
  const auto out = Scratch("rig2_estimated.json");
  std::ofstream(file) << kProject;
  const auto r = RunCli({"estimate", file.string(), "--write", out.string(), "--db", FreshSeedDatabase()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("shaft_1"), std::string::npos);
  EXPECT_NE(r.out.find("estimated"), std::string::npos);
  const Project p = LoadProject(out);
  const Parameter& c = p.FindComponent("shaft_1")->parameters.at("stiffness");
  EXPECT_EQ(c.provenance, Provenance::kEstimated);
  ASSERT_TRUE(c.nominal.has_value());
  EXPECT_NEAR(*c.nominal, 1914.0, 0.5);
  EXPECT_EQ(p.FindComponent("gra_1")->parameters.at("input_inertia").provenance, Provenance::kFit);
  // Estimating the written project again changes nothing.
  const auto again = RunCli({"estimate", out.string(), "--json", "--db", FreshSeedDatabase()});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const auto again_doc = nlohmann::json::parse(again.out);
  for (const auto& q : again_doc["parameters"])
    EXPECT_FALSE(q["changed"].get<bool>()) << q.dump();
}

TEST(EstimateCli, ConflictExitsOneAndNamesBothSources) {
  const auto file = Scratch("rig3.json");
  std::string text = kProject;
  text.replace(text.find("\"shear_modulus\": \"44 GPa\""), std::string("\"shear_modulus\": \"44 GPa\"").size(),
               "\"shear_modulus\": \"44 GPa\", \"stiffness\": \"3000 N*m/rad\"");
  std::ofstream(file) << text;
  const auto r = RunCli({"estimate", file.string(), "--db", FreshSeedDatabase()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("conflict: component 'shaft_1' (torque_shaft): parameter 'stiffness': the user value 3000 N*m/rad"),
            std::string::npos)
      << r.err;
  const auto bad = RunCli({"estimate", file.string(), "--db", Scratch("missing.sqlite").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("does not exist"), std::string::npos);
}

}  // namespace
}  // namespace highlift

namespace highlift {
namespace {

// Regression: the shipped examples and the shipped seed database agree (both are domain.md
// estimates); a change to either that makes them conflict shows up here.
TEST(EstimateCli, ShippedExamplesEstimateWithoutConflicts) {
  for (const char* example : {"examples/a380_class_flaps.json", "examples/a320_class_flaps.json",
                              "examples/a320_class_slats.json"}) {
    if (!std::filesystem::exists(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / example)) continue;
    const auto r = highlift::testing::RunCli({"estimate", example, "--json", "--db", FreshSeedDatabase()});
    EXPECT_EQ(r.exit_code, 0) << example << "\n" << r.err.substr(0, 2000);
    if (r.exit_code != 0) continue;
    const auto doc = nlohmann::json::parse(r.out);
    EXPECT_EQ(doc["status"], "ok") << example;
    EXPECT_GT(doc["parameters"].size(), 100u) << example;
  }
}

}  // namespace
}  // namespace highlift
