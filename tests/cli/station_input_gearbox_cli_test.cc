// The station input gearbox end to end: the two-station rig (tests/model/station_input_gearbox.json)
// through every command, and what its limiter in the down-drive means for the analyses: sizing sets
// it against the station's torque, a jam behind its branch gets what its brake does not ground, a
// jam at another station is not limited.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "common/run_cli.h"
#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sizing.h"

namespace highlift {
namespace {

using testing::RunCli;

const char* const kRig = "tests/model/station_input_gearbox.json";

Project Rig() { return LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / kRig); }

TEST(StationInputGearboxCli, ValidatesAndIsListedByInfo) {
  const auto validate = RunCli({"validate", kRig});
  EXPECT_EQ(validate.exit_code, 0) << validate.out << validate.err;
  const auto types = RunCli({"info", "--types", "--json"});
  ASSERT_EQ(types.exit_code, 0) << types.err;
  EXPECT_NE(types.out.find("\"station_input_gearbox\""), std::string::npos);
  const auto info = RunCli({"info", kRig, "--json"});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto j = nlohmann::json::parse(info.out);
  EXPECT_NE(j.dump().find("\"sig_1\""), std::string::npos);
}

TEST(StationInputGearboxCli, RunsInEveryAnalysis) {
  // Each command with what its output shows of the rig.
  const std::vector<std::pair<std::vector<std::string>, std::string>> runs = {
      {{"estimate", kRig, "--no-db"}, "gra_1      input_inertia"},
      {{"check", kRig}, "feasible"},
      {{"size", kRig}, "sig_1      lockout_torque_extend"},
      {{"modes", kRig}, "first"},
      {{"peak", kRig}, "sig_2"}};
  for (const auto& [args, shown] : runs) {
    const auto r = RunCli(args);
    EXPECT_EQ(r.exit_code, args[0] == "peak" ? 1 : 0) << args[0] << "\n" << r.out << r.err;  // peak: negative margins
    EXPECT_NE(r.out.find(shown), std::string::npos) << args[0] << ":\n" << r.out;
  }
}

TEST(StationInputGearboxCli, CheckDefinesTheLimiterMarginOnTheStationTorque) {
  const auto r = RunCli({"check", kRig, "--all"});
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.out << r.err;
  EXPECT_NE(r.out.find("sig_1.margin"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sig_2.torque_through_retract"), std::string::npos) << r.out;
}

TEST(StationInputGearboxCli, SimulatesTheJamAndExportsTheSameNetwork) {
  const auto dir = std::filesystem::temp_directory_path() / ("highlift_sig_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  testing::RemoveAfterTheTest(dir);
  const auto csv = dir / "jam.csv";
  const auto sim = RunCli({"simulate", kRig, "--scenario", "jam_gra_1", "--output", csv.string()});
  ASSERT_EQ(sim.exit_code, 0) << sim.out << sim.err;
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_NE(header.find("sig_1.limiter."), std::string::npos) << header.substr(0, 400);
  const auto exported = RunCli({"export", kRig, "--modelica", (dir / "mo").string(), "--scenario", "jam_gra_1"});
  ASSERT_EQ(exported.exit_code, 0) << exported.out << exported.err;
  std::string text;
  for (const auto& f : std::filesystem::recursive_directory_iterator(dir / "mo")) {
    std::stringstream s;
    s << std::ifstream(f.path()).rdbuf();
    text += s.str();
  }
  EXPECT_NE(text.find("HighLift.Mechanical.TorqueLimiter sig_1_limiter"), std::string::npos);
  EXPECT_NE(text.find("HighLift.Mechanical.BranchGearbox sig_1"), std::string::npos);
  EXPECT_NE(text.find("connect(sig_1.flange_branch, sig_1_limiter.flange_a)"), std::string::npos);
}

/// The rig with each station input gearbox replaced by a branch_gearbox and a separate
/// station_torque_limiter on its branch, with the same parameters.
nlohmann::json SeparateRig() {
  std::ifstream in(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / kRig);
  nlohmann::json rig = nlohmann::json::parse(in);
  nlohmann::json components = nlohmann::json::array(), connections = nlohmann::json::array();
  for (const auto& c : rig["components"]) {
    if (c["type"] != "station_input_gearbox") {
      components.push_back(c);
      continue;
    }
    nlohmann::json gearbox = {{"id", c["id"]}, {"type", "branch_gearbox"}, {"parameters", nlohmann::json::object()}};
    nlohmann::json limiter = {{"id", c["id"].get<std::string>() + "_stl"}, {"type", "station_torque_limiter"},
                              {"parameters", nlohmann::json::object()}};
    for (const auto& [name, value] : c["parameters"].items())
      (name.rfind("lockout_", 0) == 0 ? limiter : gearbox)["parameters"][name] = value;
    components.push_back(gearbox);
    components.push_back(limiter);
  }
  for (const auto& k : rig["connections"]) {
    const std::string a = k[0];
    if (a.size() > 7 && a.substr(a.size() - 7) == ".branch") {
      const std::string id = a.substr(0, a.size() - 7);
      connections.push_back({a, id + "_stl.input"});
      connections.push_back({id + "_stl.output", k[1]});
    } else {
      connections.push_back(k);
    }
  }
  rig["components"] = components;
  rig["connections"] = connections;
  return rig;
}

std::map<std::string, double> PeakTorques(const std::string& project) {
  const auto r = RunCli({"simulate", project, "--scenario", "jam_gra_1", "--json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  std::map<std::string, double> peaks;
  for (const auto& p : doc.at("component_peaks")) peaks[p.at("component").get<std::string>()] = p.at("abs_tau").get<double>();
  return peaks;
}

// The unit is a branch gearbox with a station limiter on its branch: the jam of station 1 loads
// every component as the two separate components do (the defaults of the limiter's inertia and
// the gear stage's agree between the types; the element order differs, so the integrator's
// steps do: 0.5 %).
TEST(StationInputGearboxCli, SimulatesAsABranchGearboxWithASeparateLimiter) {
  const auto file = testing::RemoveAfterTheTest(std::filesystem::temp_directory_path() /
                                                ("highlift_sig_separate_" + std::to_string(::getpid()) + ".json"));
  std::ofstream(file) << SeparateRig().dump(1);
  const auto unit = PeakTorques(kRig), separate = PeakTorques(file.string());
  for (const char* id : {"pdu", "shaft_1", "sig_1", "gra_1", "shaft_2", "sig_2", "gra_2"}) {
    ASSERT_TRUE(unit.count(id) && separate.count(id)) << id;
    EXPECT_NEAR(unit.at(id), separate.at(id), 5e-3 * separate.at(id)) << id;
  }
  // The limiter of station 1 locks out: its actuator sees more than the lock-out torque (the
  // loop above: as behind the separate limiter), and no more than the limiter carries.
  EXPECT_GT(unit.at("gra_1"), 180.0);
  EXPECT_LE(unit.at("gra_1"), separate.at("sig_1_stl") * (1 + 5e-3));
}

TEST(StationInputGearbox, SizingSetsItsLimiterAgainstTheStationTorque) {
  const reduced_models::SizingReport report = reduced_models::Size(Rig());
  auto torque = [&](const std::string& id, const std::string& direction) {
    double best = 0.0;
    for (const auto& s : report.cases)
      if (s.direction == direction)
        for (const auto& t : s.components)
          if (t.component == id) best = std::max(best, std::abs(t.torque.nominal));
    return best;
  };
  int found = 0;
  int brakes = 0;
  for (const auto& s : report.settings) {
    if (s.component != "sig_1" && s.component != "sig_2") continue;
    if (s.parameter == "max_brake_torque") {
      // The brake grounds what the drive can put into a jammed station above the end stop: the
      // STL passes its end stop of 200 N*m (its brake of 900 N*m grounds the rest of the PDU's
      // 1000 N*m stall torque), 400 N*m behind the 2:1 stage, minus the default end stop
      // 1.25 x 180 N*m.
      EXPECT_DOUBLE_EQ(s.operating.nominal, 200.0 * 2.0 - 1.25 * 180.0) << s.component;
      ++brakes;
      continue;
    }
    const std::string station = s.component == "sig_1" ? "gra_1" : "gra_2";
    const std::string direction = s.parameter == "lockout_torque_extend" ? "extend" : "retract";
    // The torque through the limiter is the actuator's input torque, not the unit's own input
    // torque, which carries the outboard stations too.
    EXPECT_DOUBLE_EQ(s.operating.nominal, torque(station, direction)) << s.component << " " << s.parameter;
    EXPECT_GT(std::abs(s.operating.nominal - torque(s.component, direction)), 1.0) << s.component;
    ++found;
  }
  EXPECT_EQ(found, 4);
  EXPECT_EQ(brakes, 2);
  // domain.md s3: the opposing 20 kN*m through 200:1 at 0.85 is 117.6 N*m at the actuator input.
  EXPECT_NEAR(torque("gra_1", "extend"), 20e3 / (200 * 0.85), 0.5);
}

// Issue 26 item 3: behind its branch a jammed actuator gets what the limiter's brake does not
// ground, min(tau_in, max(tau_2, tau_in - tau_B_max)) (docs/reduced_models.md); the through shaft
// to the other stations is not limited.
TEST(StationInputGearbox, JamPassesWhatTheLimiterBrakeDoesNotGroundBehindItsBranchOnly) {
  const double end_stop_at_shaft = 1.25 * 180.0 / 2.0;  // default end stop 1.25 x tau1, behind 2:1
  const double brake_at_shaft = 2.0 * 180.0 / 2.0;      // default max_brake_torque 2 x tau1, behind 2:1
  auto passed = [&](double total) { return std::min(total, std::max(end_stop_at_shaft, total - brake_at_shaft)); };
  auto jam = [&](const Project& project, const std::string& name) {
    reduced_models::PeakOptions options;
    options.intervals = false;
    options.only_case = name;
    return reduced_models::AnalysePeaks(project, options);
  };
  auto worst = [](const reduced_models::PeakReport& report, const std::string& id) {
    for (const auto& w : report.worst)
      if (w.component == id) return w.torque.nominal;
    ADD_FAILURE() << id << " is not on the load path";
    return 0.0;
  };
  // A jam at station 1: the brake grounds 180 N*m (at the shaft), gra_1 gets the rest.
  const auto first = jam(Rig(), "jam_gra_1");
  ASSERT_EQ(first.cases.size(), 1u);
  const double total_1 = first.cases[0].tau_total.nominal;
  EXPECT_GT(total_1, end_stop_at_shaft + brake_at_shaft);
  EXPECT_DOUBLE_EQ(worst(first, "gra_1"), passed(total_1));
  EXPECT_DOUBLE_EQ(worst(first, "gra_1"), total_1 - brake_at_shaft);
  EXPECT_DOUBLE_EQ(worst(first, "sig_1"), total_1);
  // A jam at station 2 passes sig_1 on its through shaft: sig_1's limiter limits nothing there,
  // sig_2's limits gra_2.
  const auto second = jam(Rig(), "jam_gra_2");
  ASSERT_EQ(second.cases.size(), 1u);
  const double total = second.cases[0].tau_total.nominal;
  EXPECT_GT(total, end_stop_at_shaft + brake_at_shaft);
  for (const char* id : {"shaft_1", "sig_1", "shaft_2", "sig_2"}) EXPECT_DOUBLE_EQ(worst(second, id), total) << id;
  EXPECT_DOUBLE_EQ(worst(second, "gra_2"), passed(total));
  // A brake that grounds the whole jam leaves the actuator at the end-stop torque.
  Project strong = Rig();
  strong.FindComponent("sig_1")->parameters["max_brake_torque"].nominal = 2.0 * total_1;  // N*m at the branch
  EXPECT_DOUBLE_EQ(worst(jam(strong, "jam_gra_1"), "gra_1"), end_stop_at_shaft);
}

}  // namespace
}  // namespace highlift
