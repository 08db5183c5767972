// `highlift simulate`: CSV with time + instance-path columns, --signals, --json summary,
// errors with exit code 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/run_cli.h"

namespace {

/// A file for the running test, removed when the test passed.
std::filesystem::path TempCsv(const std::string& name) {
  return highlift::testing::RemoveAfterTheTest(std::filesystem::temp_directory_path() /
                                               ("highlift_sim_" + std::to_string(::getpid()) + "_" + name));
}

TEST(SimulateCli, WritesSelectedColumnsAndJsonSummary) {
  const auto csv = TempCsv("friction.csv");
  const auto r = highlift::testing::RunCli({"simulate", "tests/sim/msl/Friction.json", "--scenario", "msl",
                                            "--out", csv.string(), "--signals", "clutch.w_rel,brake.mode",
                                            "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "success");
  EXPECT_EQ(j["output"]["columns"], 2);
  EXPECT_GT(j["output"]["rows"].get<long>(), 6000);
  // Brake engages at the step (time event at 0.5 s) and holds 800 N*m (cgeo*fn_max*mu).
  bool brake_event = false;
  for (const auto& e : j["events"])
    if (e["element"] == "brake" && e["kind"] == "time") brake_event = std::abs(e["time"].get<double>() - 0.5) < 1e-12;
  EXPECT_TRUE(brake_event) << j["events"].dump();
  bool brake_peak = false;
  for (const auto& p : j["peak_torques"])
    if (p["element"] == "brake") brake_peak = std::abs(p["abs_tau"].get<double>() - 800) < 1e-6;
  EXPECT_TRUE(brake_peak) << j["peak_torques"].dump();
  // The passivity monitor: MSL's Friction example (brake, clutch, bearing friction) dissipates.
  EXPECT_EQ(j["passivity"]["passive"], true) << j["passivity"].dump();
  EXPECT_TRUE(j["passivity"]["violations"].empty()) << j["passivity"].dump();
  EXPECT_GT(j["passivity"]["power_scale"].get<double>(), 0.0);
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "\"time\",\"clutch.w_rel\",\"brake.mode\"");
}

TEST(SimulateCli, UnknownSignalIsInvalidInputWithSuggestion) {
  const auto csv = TempCsv("bad.csv");
  const auto r = highlift::testing::RunCli({"simulate", "tests/sim/msl/First.json", "--out", csv.string(),
                                            "--signals", "inertia3.ww"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("signal 'inertia3.ww' is not an output of this network; closest: inertia3.w"),
            std::string::npos)
      << r.err;
}

TEST(SimulateCli, UnknownScenarioListsTheScenarios) {
  const auto r = highlift::testing::RunCli({"simulate", "tests/sim/msl/First.json", "--scenario", "nope"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("scenario 'nope' is not in the project; choose one of: msl"), std::string::npos) << r.err;
}

TEST(SimulateCli, ModelOptionsApplyOnlyToDriveSystemProjects) {
  const auto r = highlift::testing::RunCli({"simulate", "tests/sim/msl/First.json", "--model", "reduced"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--model and --elements apply to drive-system projects"), std::string::npos) << r.err;
}

TEST(SimulateCli, DriveSystemProjectRejectsAnUnknownResolution) {
  const auto r = highlift::testing::RunCli(
      {"simulate", "examples/a380_class_flaps.json", "--scenario", "extension", "--model", "fine"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("model 'fine' is not a model resolution; choose 'full'"), std::string::npos) << r.err;
}

TEST(SimulateCli, DriveSystemProjectWithSeveralScenariosNeedsOne) {
  const auto r = highlift::testing::RunCli({"simulate", "examples/a380_class_flaps.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("choose one with --scenario NAME (extension, jam_l1"), std::string::npos) << r.err;
}

TEST(SimulateCli, DriveSystemProjectRejectsZeroElements) {
  const auto r = highlift::testing::RunCli(
      {"simulate", "examples/a380_class_flaps.json", "--scenario", "jam_l1", "--elements", "0"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--elements: '0' is out of range; give a number from 1 to 1000"), std::string::npos) << r.err;
}

}  // namespace

// `highlift peak --transient`: a sizing case simulated under the single-DOF conditions, the
// transient peak beside the estimate. The rupture of shaft_l1 is the project's scenario
// rupture_wtb, which extends against opposing loads; the sizing case retracts with the airload
// aiding (a made-up scenario on that load case), and the report says so.
TEST(PeakTransientCli, RuptureSimulatedWhileRetractingBelowTheSingleDofEstimate) {
  const auto r = highlift::testing::RunCli(
      {"peak", "examples/a380_class_flaps.json", "--transient", "--case", "rupture_wtb", "--no-intervals", "--json"});
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;  // 1: negative margins of the example
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["transient"].size(), 1u) << j["transient"].dump();
  const auto& c = j["transient"][0];
  EXPECT_EQ(c["case"], "rupture_wtb");
  EXPECT_EQ(c["kind"], "rupture");
  EXPECT_EQ(c["scenario"], "rupture_shaft_l1");
  EXPECT_EQ(c["load_case"], "retract_aiding");
  EXPECT_TRUE(c["ok"].get<bool>()) << c.dump();
  // The outboard part is stopped by the WTB, which slips: the largest torque is at the tip, above
  // the WTB's dynamic capacity (550 N*m), at its static capacity (600 N*m), where the single-DOF
  // estimate caps the case. The shaft next to the brake also accelerates the brake rotor
  // (5e-4 kg*m^2) when it slips, so the simulation may exceed the cap by that inertial torque.
  const std::string at = c["at"];
  EXPECT_TRUE(at == "shaft_l7" || at == "wtb_left") << at;
  const double ratio = c["ratio"];
  EXPECT_GT(ratio, 0.9);
  EXPECT_LT(ratio, 1.01);
  EXPECT_GT(c["transient"].get<double>(), 500.0);
  EXPECT_GT(c["time"].get<double>(), 1.0);  // after the rupture at 1 s
}

TEST(PeakTransientCli, ElementsWithoutTransientIsAUsageError) {
  const auto r = highlift::testing::RunCli({"peak", "examples/a380_class_flaps.json", "--elements", "6"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("give --transient as well"), std::string::npos) << r.err;
}

namespace {

// An element network's experiment block sets the run as a Modelica experiment annotation does;
// --rtol and --atol override the tolerances.
TEST(SimulateCli, ExperimentBlockAndToleranceOptions) {
  auto r = highlift::testing::RunCli({"simulate", "tests/sim/msl/SeriesSprings.json", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["scenario"], "experiment");
  EXPECT_DOUBLE_EQ(j["stop_time"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(j["relative_tolerance"].get<double>(), 1e-8);
  EXPECT_GE(j["output"]["rows"].get<long>(), 501);  // 0 .. 1 s every 2 ms
  EXPECT_LE(j["output"]["rows"].get<long>(), 502);
  r = highlift::testing::RunCli(
      {"simulate", "tests/sim/msl/SeriesSprings.json", "--rtol", "1e-5", "--atol", "1e-9", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["relative_tolerance"].get<double>(), 1e-5);
  EXPECT_DOUBLE_EQ(j["absolute_tolerance"].get<double>(), 1e-9);
  r = highlift::testing::RunCli({"simulate", "tests/sim/msl/SeriesSprings.json", "--rtol", "2"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("relative_tolerance"), std::string::npos) << r.err;
}

// --start steady-state: the free start values solved for a = 0 (and constant spring twists);
// a start value that contradicts it is named.
TEST(SimulateCli, SteadyStateStart) {
  auto r = highlift::testing::RunCli(
      {"simulate", "tests/sim/msl/InitialConditions.json", "--start", "steady-state", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["start"], "steady_state");
  bool solved = false;
  for (const auto& e : j["events"])
    solved = solved || e["what"].get<std::string>().find("steady-state start: 4 equations on 2 free start values "
                                                         "(m3.s, m4.s)") != std::string::npos;
  EXPECT_TRUE(solved) << j["events"].dump();
  r = highlift::testing::RunCli({"simulate", "tests/sim/msl/TranslationalDamper.json", "--start", "steady-state"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("the steady-state start: der(mass1.v) = 0 does not hold at the start: a = -250"),
            std::string::npos)
      << r.err;
  r = highlift::testing::RunCli({"simulate", "tests/sim/msl/First.json", "--start", "rest"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown start 'rest'; choose \"given\""), std::string::npos) << r.err;
}

// The steady-state start from the project file (settings "initial"); --start overrides it; a
// value other than "given" or "steady_state" is an input error naming the key.
TEST(SimulateCli, SteadyStateStartFromTheProjectFile) {
  std::ifstream in(std::string(HIGHLIFT_SOURCE_DIR) + "/tests/sim/msl/InitialConditions.json");
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["settings"]["initial"] = "steady_state";
  const auto dir = std::filesystem::path(HIGHLIFT_BINARY_DIR) / "tests" / "sim";
  std::filesystem::create_directories(dir);
  const auto file = dir / "InitialConditionsSteady.json";
  std::ofstream(file) << doc.dump(1);
  auto r = highlift::testing::RunCli({"simulate", file.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["start"], "steady_state");
  r = highlift::testing::RunCli({"simulate", file.string(), "--start", "given", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["start"], "given");
  doc["settings"]["initial"] = "steady";
  std::ofstream(file) << doc.dump(1);
  r = highlift::testing::RunCli({"simulate", file.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("settings 'initial' must be \"given\" (the start values) or \"steady_state\""),
            std::string::npos)
      << r.err;
}

// validate and simulate apply one structural check: they accept and reject the same networks
// (a massless node between springs and an IdealPlanetary with an open ring are valid; a torque
// on a massless node is not, nor a torque sensor between two springs or an acceleration sensor on
// a massless node), with the same message.
// Every example and structure network under tests/sim/msl and tests/sim/structure is run
// through both.
TEST(ValidateAndSimulate, AgreeOnEveryExampleAndStructureNetwork) {
  // The networks that both must reject, with the message.
  const std::map<std::string, std::string> invalid{
      {"MasslessDrivenNode.json", "element 'torque' (ConstantTorque) acts on it"},
      {"AccSensorOnMasslessNode.json",
       "element 'accSensor' (AccSensor) measures the acceleration of flange 'spring1.flange_b', which has no "
       "inertia"},
      {"SensorBetweenSprings.json",
       "element 'torqueSensor' (TorqueSensor) joins flanges spring1.flange_b, torqueSensor.flange_b rigidly"},
      {"OverDeterminedAStart.json",
       "element 'inertia' (Inertia): the initial equation a = a_start = 1 rad/s^2 does not hold at the start: "
       "a = 4 rad/s^2"}};
  std::vector<std::filesystem::path> files;
  for (const char* dir : {"tests/sim/msl", "tests/sim/structure"})
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / dir))
      if (entry.path().extension() == ".json") files.push_back(std::filesystem::path(dir) / entry.path().filename());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 19u);
  std::size_t rejected = 0;
  for (const auto& path : files) {
    const std::string file = path.string();
    const auto v = highlift::testing::RunCli({"validate", file});
    const auto s = highlift::testing::RunCli({"simulate", file});
    EXPECT_EQ(v.exit_code, s.exit_code) << file << "\nvalidate: " << v.err << "\nsimulate: " << s.err;
    const auto it = invalid.find(path.filename().string());
    EXPECT_EQ(v.exit_code, it == invalid.end() ? 0 : 2) << file << ": " << v.err;
    if (it == invalid.end()) continue;
    ++rejected;
    EXPECT_NE(v.err.find(it->second), std::string::npos) << v.err;
    EXPECT_NE(s.err.find(it->second), std::string::npos) << s.err;
  }
  EXPECT_EQ(rejected, invalid.size());
}

}  // namespace
