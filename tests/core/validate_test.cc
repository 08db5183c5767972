#include "highlift/core/validate.h"

#include <gtest/gtest.h>

#include "highlift/core/project_io.h"

namespace highlift {
namespace {

const char* kValid = R"json({
  "format": "highlift-project/1", "name": "validate",
  "components": [
    {"id": "pdu", "type": "pdu"},
    {"id": "stl", "type": "system_torque_limiter"},
    {"id": "shaft_1", "type": "torque_shaft", "parameters": {"length": "4 m"}},
    {"id": "rgb", "type": "angle_gearbox", "parameters": {"ratio": 1.5}},
    {"id": "sgb", "type": "branch_gearbox"},
    {"id": "gra", "type": "geared_rotary_actuator"},
    {"id": "disc", "type": "disconnector"},
    {"id": "wtb", "type": "wing_tip_brake"}
  ],
  "connections": [
    ["pdu.left", "stl.input"], ["stl.output", "shaft_1.a"], ["shaft_1.b", "rgb.input"],
    ["rgb.output", "disc.a"], ["disc.b", "sgb.input"], ["sgb.branch", "gra.input"], ["sgb.through", "wtb.a"]
  ],
  "load_cases": [{"name": "lc", "actuator_loads": {"gra": {"points": [[0, 100]]}}}],
  "scenarios": [
    {"name": "jam", "kind": "jam", "load_case": "lc", "jam": {"component": "gra", "time": 1}},
    {"name": "rupture", "kind": "rupture", "load_case": "lc", "rupture": {"component": "disc", "time": 1}}
  ]
})json";

std::string Edit(const std::string& from, const std::string& to) {
  std::string s = kValid;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// All issue messages, one per line, errors and warnings marked.
std::string Issues(const std::string& text) {
  const ValidationReport r = ValidateProject(ParseProject(text, "v.json"));
  std::string out;
  for (const auto& i : r.issues)
    out += std::string(i.severity == ValidationIssue::Severity::kError ? "E " : "W ") + "[" + i.component + "." +
           i.port + "] " + i.message + "\n";
  return out;
}

TEST(Validate, AValidProjectHasNoIssues) {
  const ValidationReport r = ValidateProject(ParseProject(kValid));
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.issues.empty()) << r.FullReport();
  EXPECT_EQ(r.BriefReport(), "valid: 0 errors, 0 warnings");
}

TEST(Validate, UnknownPortSuggestsTheClosest) {
  const std::string issues = Issues(Edit("\"stl.input\"", "\"stl.inptu\""));
  EXPECT_NE(issues.find("E [stl.inptu] component 'stl' (system_torque_limiter) has no port 'inptu'; did you mean "
                        "'input'? Ports: input, output\n"),
            std::string::npos)
      << issues;
  EXPECT_NE(issues.find("E [stl.input] component 'stl' (system_torque_limiter): required port 'input' is not "
                        "connected; connect it (flange towards the PDU) or remove the component\n"),
            std::string::npos)
      << issues;
}

TEST(Validate, UnknownComponentInAConnection) {
  const std::string issues = Issues(Edit("\"disc.b\"", "\"dics.b\""));
  EXPECT_NE(issues.find("E [dics.b] component connection dics.b - sgb.input: unknown component 'dics'; did you mean "
                        "'disc'?\n"),
            std::string::npos)
      << issues;
}

TEST(Validate, PortConnectedTwice) {
  const std::string issues = Issues(Edit("[\"sgb.through\", \"wtb.a\"]", "[\"sgb.through\", \"wtb.a\"], [\"gra.input\", \"wtb.b\"]"));
  EXPECT_NE(issues.find("E [gra.input] component 'gra' (geared_rotary_actuator): port 'input' is connected 2 times "
                        "(to 'sgb.branch', 'wtb.b'); a flange takes one connection, branch the shaft with a "
                        "branch_gearbox\n"),
            std::string::npos)
      << issues;
}

TEST(Validate, RequiredPortLeftOpen) {
  EXPECT_EQ(Issues(Edit("[\"sgb.branch\", \"gra.input\"], ", "")),
            "E [sgb.branch] component 'sgb' (branch_gearbox): required port 'branch' is not connected; connect it "
            "(down-drive flange to the station) or remove the component\n"
            "E [gra.input] component 'gra' (geared_rotary_actuator): required port 'input' is not connected; connect "
            "it (input flange from the station gearbox or limiter) or remove the component\n"
            "E [gra.] component 'gra' (geared_rotary_actuator) is not connected to the PDU 'pdu' (disconnected "
            "sub-system: 'gra'); connect it to the transmission or remove it\n");
}

TEST(Validate, DisconnectedSubSystem) {
  const std::string text = Edit("[\"disc.b\", \"sgb.input\"], ", "");
  const std::string issues = Issues(text);
  EXPECT_NE(issues.find("E [sgb.] component 'sgb' (branch_gearbox) is not connected to the PDU 'pdu' (disconnected "
                        "sub-system: 'sgb', 'gra', 'wtb'); connect it to the transmission or remove it\n"),
            std::string::npos)
      << issues;
  EXPECT_NE(issues.find("E [wtb.] component 'wtb'"), std::string::npos);
  EXPECT_FALSE(ValidateProject(ParseProject(text)).ok());
}

TEST(Validate, GearboxReachedThroughItsOutput) {
  std::string text = Edit("[\"shaft_1.b\", \"rgb.input\"]", "[\"shaft_1.b\", \"rgb.output\"]");
  text.replace(text.find("[\"rgb.output\", \"disc.a\"]"), 24, "[\"rgb.input\", \"disc.a\"]");
  const std::string issues = Issues(text);
  EXPECT_EQ(issues,
            "E [rgb.output] component 'rgb' (angle_gearbox): inconsistent gear-ratio convention: the gearbox is "
            "reached from the PDU through its port 'output' (from 'shaft_1'), but 'input' must be the flange nearer "
            "the PDU (ratio = input speed / output speed); swap the connections of its ports\n");
}

TEST(Validate, TorqueLimiterTheWrongWayRoundIsAWarning) {
  std::string text = Edit("[\"pdu.left\", \"stl.input\"], [\"stl.output\", \"shaft_1.a\"]",
                          "[\"pdu.left\", \"stl.output\"], [\"stl.input\", \"shaft_1.a\"]");
  EXPECT_EQ(Issues(text),
            "W [stl.output] component 'stl' (system_torque_limiter): reached from the PDU through its port 'output'; "
            "its extend and retract lock-out torques refer to power flowing from 'input' to 'output', so swap the "
            "connections of its ports\n");
  EXPECT_TRUE(ValidateProject(ParseProject(text)).ok());
}

TEST(Validate, PduMissingOrTwice) {
  EXPECT_NE(Issues(Edit("{\"id\": \"wtb\", \"type\": \"wing_tip_brake\"}",
                        "{\"id\": \"wtb\", \"type\": \"wing_tip_brake\"}, {\"id\": \"pdu2\", \"type\": \"pdu\"}"))
                .find("E [pdu2.] component 'pdu2' is a second pdu (the first is 'pdu'); a project has one PDU "
                      "driving both wings\n"),
            std::string::npos);
  Project p = ParseProject(kValid);
  p.components.erase(p.components.begin());
  const ValidationReport r = ValidateProject(p);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.FullReport().find("error: the project has components but no power drive unit; add a component of type "
                                "\"pdu\" that drives the transmission\n"),
            std::string::npos)
      << r.FullReport();
}

TEST(Validate, ReferencesInScenariosAndLoadCases) {
  EXPECT_EQ(Issues(Edit("\"component\": \"gra\"", "\"component\": \"gar\"")),
            "E [gar.] scenario 'jam': jam of unknown component 'gar'; did you mean 'gra'?\n");
  EXPECT_EQ(Issues(Edit("\"component\": \"disc\"", "\"component\": \"wtb\"")),
            "E [wtb.] scenario 'rupture': rupture of component 'wtb' (wing_tip_brake); it must be one of: "
            "torque_shaft, disconnector\n");
  EXPECT_EQ(Issues(Edit("\"load_case\": \"lc\"", "\"load_case\": \"lcc\"")),
            "E [.] scenario 'jam': unknown load case 'lcc'; did you mean 'lc'? Load cases: lc\n");
  EXPECT_EQ(Issues(Edit("\"actuator_loads\": {\"gra\"", "\"actuator_loads\": {\"stl\"")),
            "E [stl.] load case 'lc': actuator load on component 'stl' (system_torque_limiter), which is not an "
            "actuator; give loads for geared_rotary_actuator or ballscrew_actuator components\n");
  EXPECT_EQ(Issues(Edit("\"actuator_loads\": {\"gra\"", "\"actuator_loads\": {\"gra_9\"")),
            "E [gra_9.] load case 'lc': actuator load for unknown component 'gra_9'; did you mean 'gra'?\n");
}

TEST(Validate, ProgrammaticProjectsAreCheckedToo) {
  Project p = ParseProject(kValid);
  p.components[5].parameters["eta_opposing"].nominal = 1.5;
  p.components[5].parameters["eta_opposing"].domain = Domain::Point(1.5);
  p.components[2].type = "torque_shaf";
  const ValidationReport r = ValidateProject(p);
  const std::string full = r.FullReport();
  EXPECT_NE(full.find(": component 'gra' (geared_rotary_actuator): parameter 'eta_opposing' = 1.5 is outside "
                      "its valid range [0.01, 1]\n"),
            std::string::npos)
      << full;
  EXPECT_NE(full.find(": component 'shaft_1': unknown component type 'torque_shaf'; did you mean "
                      "'torque_shaft'?"),
            std::string::npos)
      << full;
  EXPECT_EQ(r.BriefReport().substr(0, 8), "invalid:");
}

TEST(Validate, FloatingElementIslandIsAWarning) {
  Project p;
  p.name = "elements";
  Component inertia;
  inertia.id = "inertia1";
  inertia.type = "Inertia";
  Component spring;
  spring.id = "spring";
  spring.type = "Spring";
  p.elements = {inertia, spring};
  p.element_connections = {{{"inertia1", "flange_b"}, {"spring", "flange_a"}, {}}};
  const ValidationReport r = ValidateProject(p);
  EXPECT_NE(r.FullReport().find("warning: element network island 'inertia1', 'spring' has no Fixed element and no "
                                "source; it floats freely"),
            std::string::npos)
      << r.FullReport();
}

TEST(Validate, ElementFlangeMayTakeSeveralConnections) {
  // As in Modelica: fixed.flange grounds two elements (MSL Rotational.Examples.First does so).
  const std::string text = R"json({
    "format": "highlift-project/1", "name": "elements",
    "elements": [
      {"id": "fixed", "type": "Fixed"},
      {"id": "inertia1", "type": "Inertia", "parameters": {"J": 1}},
      {"id": "spring", "type": "Spring", "parameters": {"c": 100}},
      {"id": "damper", "type": "Damper", "parameters": {"d": 1}}
    ],
    "element_connections": [
      ["fixed.flange", "spring.flange_a"], ["fixed.flange", "damper.flange_a"],
      ["spring.flange_b", "inertia1.flange_a"], ["damper.flange_b", "inertia1.flange_a"]
    ]
  })json";
  const std::string issues = Issues(text);
  EXPECT_EQ(issues.find("connected 2 times"), std::string::npos) << issues;
  EXPECT_EQ(issues.find("E "), std::string::npos) << issues;
}

}  // namespace
}  // namespace highlift
