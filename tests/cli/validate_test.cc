// `highlift validate`: every kind of bad input named in issue 2 gives exit code 2 and a message
// that names the thing, the problem and the remedy; --json prints one document either way.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/run_cli.h"

namespace highlift {
namespace {

using testing::RunCli;

/// A small valid one-wing rig: PDU -> STL -> shaft -> station 1 (gearbox, limiter, GRA) ->
/// shaft -> station 2. Each test breaks one thing by replacing a marked piece of text.
const char* const kRig = R"json({
  "format": "highlift-project/1",
  "name": "two-station rig",
  "components": [
    {"id": "pdu", "type": "pdu"},
    {"id": "stl", "type": "system_torque_limiter"},
    {"id": "shaft_1", "type": "torque_shaft",
     "parameters": {"length": "3 m", "outer_diameter": "50 mm", "wall_thickness": "2 mm"}},
    {"id": "rgb", "type": "angle_gearbox", "parameters": {"ratio": 1.5}},
    {"id": "tgb_1", "type": "branch_gearbox", "parameters": {"ratio": 2}},
    {"id": "lim_1", "type": "station_torque_limiter"},
    {"id": "gra_1", "type": "geared_rotary_actuator"},
    {"id": "shaft_2", "type": "torque_shaft", "parameters": {"length": "3.5 m"}},
    {"id": "tgb_2", "type": "branch_gearbox"},
    {"id": "lim_2", "type": "station_torque_limiter"},
    {"id": "gra_2", "type": "geared_rotary_actuator"}/*EXTRA_COMPONENT*/
  ],
  "connections": [
    ["pdu.left", "stl.input"],
    ["stl.output", "shaft_1.a"],
    ["shaft_1.b", "rgb.input"],
    ["rgb.output", "tgb_1.input"],
    ["tgb_1.branch", "lim_1.input"],
    ["lim_1.output", "gra_1.input"],
    ["tgb_1.through", "shaft_2.a"],
    ["shaft_2.b", "tgb_2.input"],
    ["tgb_2.branch", "lim_2.input"],
    ["lim_2.output", "gra_2.input"]/*EXTRA_CONNECTION*/
  ]
})json";

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("highlift_validate_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    testing::RemoveAfterTheTest(dir_);
  }

  /// Writes `text` to <dir>/<name> and returns the path.
  std::string Write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }

  /// The rig with each `from` replaced by its `to` (each must occur once).
  static std::string Rig(const std::vector<std::pair<std::string, std::string>>& edits = {}) {
    std::string text = kRig;
    for (const auto& [from, to] : edits) {
      const auto at = text.find(from);
      EXPECT_NE(at, std::string::npos) << from;
      if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    for (const std::string marker : {"/*EXTRA_COMPONENT*/", "/*EXTRA_CONNECTION*/"}) {
      const auto at = text.find(marker);
      if (at != std::string::npos) text.erase(at, marker.size());
    }
    return text;
  }
  static std::string Rig(const std::string& from, const std::string& to) { return Rig({{from, to}}); }

  /// Runs validate in text and in --json mode; checks exit code 2 for both, that --json prints
  /// one JSON document with ok = false, and returns stderr of the text run.
  std::string ExpectInvalid(const std::string& file) {
    const auto r = RunCli({"validate", file});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;  // messages go to stderr
    const auto j = RunCli({"validate", file, "--json"});
    EXPECT_EQ(j.exit_code, 2) << j.out << j.err;
    nlohmann::json doc;
    EXPECT_NO_THROW(doc = nlohmann::json::parse(j.out)) << j.out;
    if (doc.is_object()) {
      EXPECT_FALSE(doc.at("ok").get<bool>());
      EXPECT_FALSE(doc.at("issues").empty());
    }
    EXPECT_FALSE(j.err.empty());
    return r.err;
  }

  std::filesystem::path dir_;
};

TEST_F(BadInput, TheRigItselfIsValid) {
  const auto r = RunCli({"validate", Write("rig.json", Rig())});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ok: "), std::string::npos);
  EXPECT_NE(r.out.find("11 components, 10 connections"), std::string::npos) << r.out;
}

TEST_F(BadInput, MalformedJsonNamesFileLineAndColumn) {
  // Line 3 lacks the comma after "two-station rig"; the parser stumbles on line 4.
  const std::string file = Write("malformed.json", Rig("\"two-station rig\",", "\"two-station rig\""));
  const std::string err = ExpectInvalid(file);
  EXPECT_TRUE(std::regex_search(err, std::regex("malformed\\.json:4:\\d+"))) << err;
}

TEST_F(BadInput, MissingFileSaysSo) {
  const auto r = RunCli({"validate", (dir_ / "nowhere.json").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nowhere.json"), std::string::npos) << r.err;
}

TEST_F(BadInput, UnknownKeySuggestsTheClosest) {
  const std::string file = Write("key.json", Rig("\"connections\":", "\"conections\":"));
  const std::string err = ExpectInvalid(file);
  EXPECT_NE(err.find("unknown key 'conections'"), std::string::npos) << err;
  EXPECT_NE(err.find("did you mean 'connections'"), std::string::npos) << err;
  EXPECT_TRUE(std::regex_search(err, std::regex("key\\.json:\\d+:\\d+"))) << err;
}

TEST_F(BadInput, UnknownParameterSuggestsTheClosest) {
  const std::string file = Write("param.json", Rig("\"length\": \"3 m\"", "\"lenght\": \"3 m\""));
  const std::string err = ExpectInvalid(file);
  EXPECT_NE(err.find("shaft_1"), std::string::npos) << err;
  EXPECT_NE(err.find("'lenght'"), std::string::npos) << err;
  EXPECT_NE(err.find("did you mean 'length'"), std::string::npos) << err;
  EXPECT_NE(err.find("/components/2/parameters/lenght"), std::string::npos) << err;
}

TEST_F(BadInput, UnknownComponentTypeListsTheValidTypes) {
  const std::string file =
      Write("type.json", Rig("{\"id\": \"gra_2\", \"type\": \"geared_rotary_actuator\"}",
                             "{\"id\": \"gra_2\", \"type\": \"geared_rotary_actuatr\"}"));
  const std::string err = ExpectInvalid(file);
  EXPECT_NE(err.find("gra_2"), std::string::npos) << err;
  EXPECT_NE(err.find("'geared_rotary_actuatr'"), std::string::npos) << err;
  EXPECT_NE(err.find("did you mean 'geared_rotary_actuator'"), std::string::npos) << err;
  for (const char* type : {"pdu", "system_torque_limiter", "torque_shaft", "wing_tip_brake", "jam"})
    EXPECT_NE(err.find(type), std::string::npos) << type << " missing from: " << err;
}

TEST_F(BadInput, UnitOfTheWrongDimensionNamesTheExpectedOne) {
  const std::string file = Write("unit.json", Rig("\"length\": \"3 m\"", "\"length\": \"5 N*m\""));
  const std::string err = ExpectInvalid(file);
  EXPECT_NE(err.find("shaft_1"), std::string::npos) << err;
  EXPECT_NE(err.find("expected a length"), std::string::npos) << err;
  EXPECT_NE(err.find("5 N*m"), std::string::npos) << err;
  EXPECT_TRUE(std::regex_search(err, std::regex("unit\\.json:\\d+:\\d+ at /components/2/parameters/length"))) << err;
}

TEST_F(BadInput, PortConnectedTwice) {
  // A wing-tip brake on the PDU flange that already drives the STL.
  const std::string text = Rig({{"/*EXTRA_COMPONENT*/", ",\n    {\"id\": \"wtb\", \"type\": \"wing_tip_brake\"}"},
                                {"/*EXTRA_CONNECTION*/", ",\n    [\"pdu.left\", \"wtb.a\"]"}});
  const std::string err = ExpectInvalid(Write("twice.json", text));
  EXPECT_NE(err.find("pdu"), std::string::npos) << err;
  EXPECT_NE(err.find("left"), std::string::npos) << err;
  EXPECT_NE(err.find("connected"), std::string::npos) << err;
  EXPECT_NE(err.find("twice"), std::string::npos) << err;
}

TEST_F(BadInput, RequiredPortLeftOpen) {
  // Station 2 loses its limiter and actuator: the branch flange of tgb_2 (required) is open.
  const std::string text =
      Rig({{",\n    {\"id\": \"lim_2\", \"type\": \"station_torque_limiter\"}", ""},
           {",\n    {\"id\": \"gra_2\", \"type\": \"geared_rotary_actuator\"}", ""},
           {",\n    [\"tgb_2.branch\", \"lim_2.input\"]", ""},
           {",\n    [\"lim_2.output\", \"gra_2.input\"]", ""}});
  const std::string err = ExpectInvalid(Write("open.json", text));
  EXPECT_NE(err.find("tgb_2"), std::string::npos) << err;
  EXPECT_NE(err.find("branch"), std::string::npos) << err;
  EXPECT_NE(err.find("open"), std::string::npos) << err;
}

TEST_F(BadInput, DisconnectedSubSystem) {
  const std::string text =
      Rig({{"/*EXTRA_COMPONENT*/",
            ",\n    {\"id\": \"shaft_x\", \"type\": \"torque_shaft\", \"parameters\": {\"length\": \"1 m\"}},\n"
            "    {\"id\": \"wtb_x\", \"type\": \"wing_tip_brake\"}"},
           {"/*EXTRA_CONNECTION*/", ",\n    [\"shaft_x.b\", \"wtb_x.a\"]"}});
  const std::string err = ExpectInvalid(Write("island.json", text));
  EXPECT_NE(err.find("shaft_x"), std::string::npos) << err;
  EXPECT_TRUE(err.find("not reachable") != std::string::npos || err.find("disconnected") != std::string::npos)
      << err;
}

TEST_F(BadInput, UnknownPortSuggestsTheClosest) {
  const std::string file = Write("port.json", Rig("[\"stl.output\", \"shaft_1.a\"]", "[\"stl.outptu\", \"shaft_1.a\"]"));
  const std::string err = ExpectInvalid(file);
  EXPECT_NE(err.find("stl"), std::string::npos) << err;
  EXPECT_NE(err.find("'outptu'"), std::string::npos) << err;
  EXPECT_NE(err.find("did you mean 'output'"), std::string::npos) << err;
}

TEST_F(BadInput, GearboxReachedThroughItsOutputIsAnInconsistentRatioConvention) {
  // The root gearbox is built in the wrong way round: the PDU reaches its output first.
  const std::string text = Rig({{"[\"shaft_1.b\", \"rgb.input\"]", "[\"shaft_1.b\", \"rgb.output\"]"},
                                {"[\"rgb.output\", \"tgb_1.input\"]", "[\"rgb.input\", \"tgb_1.input\"]"}});
  const std::string err = ExpectInvalid(Write("ratio.json", text));
  EXPECT_NE(err.find("rgb"), std::string::npos) << err;
  EXPECT_NE(err.find("ratio"), std::string::npos) << err;
}

TEST_F(BadInput, JsonErrorDocumentCarriesTheLocation) {
  const std::string file = Write("unit.json", Rig("\"length\": \"3 m\"", "\"length\": \"5 N*m\""));
  const auto r = RunCli({"validate", file, "--json"});
  EXPECT_EQ(r.exit_code, 2);
  const auto doc = nlohmann::json::parse(r.out);
  const auto& issue = doc.at("issues").at(0);
  EXPECT_EQ(issue.at("severity"), "error");
  EXPECT_EQ(issue.at("location").at("json_pointer"), "/components/2/parameters/length");
  EXPECT_GT(issue.at("location").at("line").get<int>(), 0);
  EXPECT_NE(issue.at("message").get<std::string>().find("expected a length"), std::string::npos);
}

TEST_F(BadInput, UsageErrorsExitWithTwo) {
  EXPECT_EQ(RunCli({"validate"}).exit_code, 2);             // no project file
  EXPECT_EQ(RunCli({"validate", "--frobnicate"}).exit_code, 2);
}

}  // namespace
}  // namespace highlift
