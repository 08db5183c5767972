#include "highlift/core/project_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/scratch.h"

namespace highlift {
namespace {

// A small valid project: PDU, STL, shaft, branch gearbox, limiter, GRA, WTB.
const char* kRig = R"json({
  "format": "highlift-project/1",
  "name": "rig",
  "description": "one-station rig",
  "sources": ["domain.md s3 (E)"],
  "settings": {"shaft_elements": 2, "output_interval": "2 ms", "values": {"g": "9.81 m/s^2"}},
  "components": [
    {"id": "pdu", "type": "pdu", "parameters": {"max_output_speed": "242 rpm", "motor_count": 2}},
    {"id": "stl", "type": "system_torque_limiter", "parameters": {"lockout_torque_extend": "470 N*m"}},
    {"id": "shaft_1", "type": "torque_shaft", "labels": {"side": "left"},
     "parameters": {"length": "4 m", "outer_diameter": "50 mm", "wall_thickness": "2.0 mm",
                    "shear_modulus": "[43, 51] GPa",
                    "density": {"value": 4420, "unit": "kg/m^3", "note": "domain.md s1 (P)"},
                    "allowable_shear_stress": "550 [500, 600] MPa"}},
    {"id": "sgb_1", "type": "branch_gearbox", "parameters": {"ratio": 2}},
    {"id": "stlim_1", "type": "station_torque_limiter"},
    {"id": "gra_1", "type": "geared_rotary_actuator",
     "parameters": {"eta_opposing": {"value": 0.85, "min": 0.80, "max": 0.90, "provenance": "estimated"},
                    "output_torque_rating": {"part": "GRA-200-A380C"}}},
    {"id": "wtb", "type": "wing_tip_brake"},
    {"id": "appu", "type": "position_sensor", "parameters": {"role": "appu"}}
  ],
  "connections": [
    ["pdu.left", "stl.input"], ["stl.output", "shaft_1.a"], ["shaft_1.b", "sgb_1.input"],
    ["sgb_1.branch", "stlim_1.input"], ["stlim_1.output", "gra_1.input"], ["sgb_1.through", "wtb.a"],
    ["wtb.b", "appu.a"]
  ],
  "requirements": [{"id": "wtb_capacity", "expression": "wtb.static_capacity >= 550 N*m"}],
  "load_cases": [
    {"name": "extend_opposing", "direction": "extend",
     "pdu_speed": {"against": "time", "unit": ["s", "rpm"], "points": [[0, 0], [0.4, 242], [40, 242]]},
     "actuator_loads": {"gra_1": {"against": "position", "unit": ["1", "kN*m"], "points": [[0, 5], [1, 20]]}},
     "values": {"airload_factor": 1.0}}
  ],
  "scenarios": [
    {"name": "extension", "kind": "extension", "load_case": "extend_opposing", "stop_time": "41 s"},
    {"name": "jam_gra_1", "kind": "jam", "load_case": "extend_opposing", "stop_time": "3 s",
     "jam": {"component": "gra_1", "time": "1 s"}},
    {"name": "rupture_wtb", "kind": "rupture", "load_case": "extend_opposing", "stop_time": "4 s",
     "rupture": {"component": "shaft_1", "time": "1 s"}, "wtb": {"trigger": "time", "time": "1100 ms"}}
  ]
})json";

// The message of the InputError thrown by parsing `text`, with its location.
std::string ErrorOf(const std::string& text) {
  try {
    ParseProject(text, "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// kRig with `from` replaced by `to` (once; the test fails if `from` is missing).
std::string Rig(const std::string& from, const std::string& to) {
  std::string s = kRig;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

TEST(ProjectIo, ReadsAValidProject) {
  const Project p = ParseProject(kRig, "rig.json");
  EXPECT_EQ(p.name, "rig");
  EXPECT_EQ(p.file, "rig.json");
  ASSERT_EQ(p.components.size(), 8u);
  EXPECT_EQ(p.connections.size(), 7u);
  EXPECT_EQ(p.connections[0].a, (PortRef{"pdu", "left"}));
  EXPECT_EQ(p.connections[0].b, (PortRef{"stl", "input"}));
  EXPECT_EQ(p.settings.shaft_elements, 2);
  EXPECT_DOUBLE_EQ(p.settings.output_interval, 2e-3);
  EXPECT_DOUBLE_EQ(p.settings.relative_tolerance, 1e-6);
  EXPECT_DOUBLE_EQ(p.settings.structural_damping, 4e-4);  // the default
  EXPECT_DOUBLE_EQ(p.settings.values.at("g"), 9.81);

  const Component& shaft = *p.FindComponent("shaft_1");
  EXPECT_EQ(shaft.labels.at("side"), "left");
  EXPECT_DOUBLE_EQ(*shaft.parameters.at("length").nominal, 4.0);
  EXPECT_EQ(shaft.parameters.at("length").provenance, Provenance::kUser);
  EXPECT_EQ(shaft.parameters.at("length").where.line, 11);
  EXPECT_EQ(shaft.parameters.at("length").where.column, 31);
  const Parameter& g = shaft.parameters.at("shear_modulus");
  EXPECT_FALSE(g.nominal.has_value());
  EXPECT_EQ(g.domain, (Domain{43e9, 51e9}));
  const Parameter& rho = shaft.parameters.at("density");
  EXPECT_DOUBLE_EQ(*rho.nominal, 4420);
  EXPECT_EQ(rho.note, "domain.md s1 (P)");
  const Parameter& tau = shaft.parameters.at("allowable_shear_stress");
  EXPECT_DOUBLE_EQ(*tau.nominal, 550e6);
  EXPECT_EQ(tau.domain, (Domain{500e6, 600e6}));
  // not given: catalogue default with its source; optional without default: absent
  const Parameter& drag = shaft.parameters.at("drag_per_length");
  EXPECT_EQ(drag.provenance, Provenance::kDefault);
  EXPECT_DOUBLE_EQ(*drag.nominal, 0.25);
  EXPECT_EQ(drag.note, FindComponentType("torque_shaft")->FindParameter("drag_per_length")->source);
  EXPECT_EQ(shaft.parameters.count("stiffness"), 0u);

  const Component& gra = *p.FindComponent("gra_1");
  EXPECT_EQ(gra.parameters.at("eta_opposing").provenance, Provenance::kEstimated);
  EXPECT_EQ(gra.parameters.at("eta_opposing").domain, (Domain{0.80, 0.90}));
  const Parameter& rating = gra.parameters.at("output_torque_rating");
  EXPECT_EQ(rating.database_part, "GRA-200-A380C");
  EXPECT_EQ(rating.provenance, Provenance::kDatabase);
  EXPECT_FALSE(rating.nominal.has_value());
  EXPECT_EQ(p.FindComponent("appu")->texts.at("role"), "appu");
  EXPECT_DOUBLE_EQ(*p.FindComponent("pdu")->parameters.at("motor_count").nominal, 2);

  const LoadCase& lc = *p.FindLoadCase("extend_opposing");
  ASSERT_TRUE(lc.pdu_speed.has_value());
  EXPECT_NEAR(lc.pdu_speed->y[1], 242 * M_PI / 30, 1e-12);
  EXPECT_EQ(lc.actuator_loads.at("gra_1").abscissa, "position");
  EXPECT_DOUBLE_EQ(lc.actuator_loads.at("gra_1").y[1], 20e3);
  const Scenario& rupture = *p.FindScenario("rupture_wtb");
  EXPECT_EQ(*rupture.rupture_component, "shaft_1");
  EXPECT_DOUBLE_EQ(*rupture.wtb_time, 1.1);
  EXPECT_EQ(rupture.wtb_trigger, "time");
  EXPECT_DOUBLE_EQ(p.FindScenario("jam_gra_1")->stop_time, 3.0);
}

TEST(ProjectIo, RoundTripGivesAnEqualProject) {
  const Project first = ParseProject(kRig, "rig.json");
  const auto dir = std::filesystem::temp_directory_path() / ("highlift_core_roundtrip_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  testing::RemoveAfterTheTest(dir);
  const auto file = dir / "rig.json";
  SaveProject(first, file);
  const Project second = LoadProject(file);
  EXPECT_EQ(DescribeDifference(first, second), "");
  // and once more through text
  const Project third = ParseProject(ProjectToJson(second).dump(1));
  EXPECT_EQ(DescribeDifference(second, third), "");
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp." + std::to_string(::getpid())));
}

TEST(ProjectIo, DescribeDifferenceNamesTheParameter) {
  const Project a = ParseProject(kRig);
  Project b = a;
  b.FindComponent("shaft_1")->parameters.at("length").nominal = 3.5;
  EXPECT_EQ(DescribeDifference(a, b), "components[2]: 'shaft_1': parameter 'length': nominal 4 vs 3.5");
}

TEST(ProjectIo, SaveLeavesDefaultsOut) {
  const nlohmann::json j = ProjectToJson(ParseProject(kRig));
  const auto& shaft = j["components"][2];
  EXPECT_EQ(shaft["id"], "shaft_1");
  EXPECT_FALSE(shaft["parameters"].contains("drag_per_length"));
  EXPECT_EQ(shaft["parameters"]["length"], 4.0);
  EXPECT_EQ(shaft["parameters"]["shear_modulus"], (nlohmann::json{{"min", 43e9}, {"max", 51e9}}));
}

// An element network's run as a Modelica experiment annotation, and the absolute tolerance.
TEST(ProjectIo, ExperimentBlockAndAbsoluteToleranceRoundTrip) {
  const std::string text = R"({"format": "highlift-project/1", "name": "x",
    "settings": {"absolute_tolerance": 1e-10},
    "experiment": {"StopTime": "2 s", "Interval": "5 ms", "Tolerance": 1e-7}})";
  const Project p = ParseProject(text);
  ASSERT_TRUE(p.experiment.has_value());
  EXPECT_EQ(p.experiment->stop_time, 2.0);
  EXPECT_EQ(p.experiment->interval.value_or(0), 0.005);
  EXPECT_EQ(p.experiment->tolerance.value_or(0), 1e-7);
  EXPECT_EQ(p.settings.absolute_tolerance.value_or(0), 1e-10);
  const Project back = ParseProject(ProjectToJson(p).dump());
  EXPECT_EQ(back.experiment->stop_time, 2.0);
  EXPECT_EQ(back.settings.absolute_tolerance.value_or(0), 1e-10);
  EXPECT_NE(ErrorOf(R"({"format": "highlift-project/1", "name": "x", "experiment": {"StopTime": "1 s", "Tolerence": 1e-6}})")
                .find("unknown key 'Tolerence' in the experiment; did you mean 'Tolerance'?"),
            std::string::npos);
  EXPECT_NE(ErrorOf(R"({"format": "highlift-project/1", "name": "x", "experiment": {"Interval": "1 ms"}})")
                .find("the experiment needs 'StopTime'"),
            std::string::npos);
}

TEST(ProjectIo, UnknownKeySuggestsTheClosest) {
  EXPECT_EQ(ErrorOf(Rig("\"sources\"", "\"source\"")),
            "t.json:5:3 at /source: unknown key 'source' in the project; did you mean 'sources'? Allowed keys: format, "
            "name, description, sources, settings, components, connections, elements, element_connections, "
            "requirements, load_cases, scenarios, experiment");
  EXPECT_EQ(ErrorOf(Rig("\"labels\"", "\"lables\"")),
            "t.json:10:47 at /components/2/lables: unknown key 'lables' in component 'shaft_1'; did you mean "
            "'labels'? Allowed keys: id, type, description, labels, parameters");
}

TEST(ProjectIo, UnknownParameterSuggestsTheClosest) {
  const std::string e = ErrorOf(Rig("\"length\"", "\"lenght\""));
  EXPECT_EQ(e.substr(0, e.find(" Parameters of")),
            "t.json:11:21 at /components/2/parameters/lenght: component 'shaft_1' (torque_shaft): unknown parameter "
            "'lenght'; did you mean 'length'?");
  EXPECT_NE(e.find("Parameters of torque_shaft: length, outer_diameter, wall_thickness"), std::string::npos);
}

TEST(ProjectIo, UnknownTypeListsTheClosestTypes) {
  const std::string e = ErrorOf(Rig("\"geared_rotary_actuator\"", "\"geared_rotary_actuatr\""));
  EXPECT_EQ(e.substr(0, e.find(" Valid types")),
            "t.json:17:29 at /components/5/type: component 'gra_1': unknown component type 'geared_rotary_actuatr'; "
            "did you mean 'geared_rotary_actuator'?");
  EXPECT_NE(e.find("Valid types: pdu, system_torque_limiter, torque_shaft"), std::string::npos);
}

TEST(ProjectIo, WrongDimensionSaysWhichWasExpected) {
  EXPECT_EQ(ErrorOf(Rig("\"4 m\"", "\"5 N*m\"")),
            "t.json:11:31 at /components/2/parameters/length: component 'shaft_1' (torque_shaft): parameter 'length': "
            "expected a length (m), got a torque (N*m) in \"5 N*m\"");
}

TEST(ProjectIo, UnknownUnitIsNamed) {
  const std::string e = ErrorOf(Rig("\"4 m\"", "\"5 mmm\""));
  EXPECT_EQ(e.substr(0, e.find(" (units are")),
            "t.json:11:31 at /components/2/parameters/length: component 'shaft_1' (torque_shaft): parameter 'length': "
            "unknown unit 'mmm' in \"5 mmm\"");
}

TEST(ProjectIo, ValueOutsideTheValidRangeNamesTheRange) {
  EXPECT_EQ(ErrorOf(Rig("\"value\": 0.85, \"min\": 0.80", "\"value\": 1.2, \"min\": 0.80, \"unused\": 1")),
            "t.json:18:65 at /components/5/parameters/eta_opposing/unused: component 'gra_1' (geared_rotary_actuator): "
            "parameter 'eta_opposing': unknown key 'unused' in a quantity; allowed keys: value, min, max, unit, note, "
            "provenance, part, design");
  EXPECT_EQ(ErrorOf(Rig("\"eta_opposing\": {\"value\": 0.85, \"min\": 0.80, \"max\": 0.90, \"provenance\": \"estimated\"}",
                        "\"eta_opposing\": 1.2")),
            "t.json:18:37 at /components/5/parameters/eta_opposing: component 'gra_1' (geared_rotary_actuator): "
            "parameter 'eta_opposing' = 1.2 is outside its valid range [0.01, 1]; check the value and its unit");
  EXPECT_EQ(ErrorOf(Rig("\"4 m\"", "\"-4 m\"")),
            "t.json:11:31 at /components/2/parameters/length: component 'shaft_1' (torque_shaft): parameter 'length' "
            "= -4 m is outside its valid range [0.01, 100] m; check the value and its unit");
  EXPECT_EQ(ErrorOf(Rig("\"[43, 51] GPa\"", "\"[0.5, 51] GPa\"")),
            "t.json:12:38 at /components/2/parameters/shear_modulus: component 'shaft_1' (torque_shaft): parameter "
            "'shear_modulus': interval [0.5, 51] GPa is not inside its valid range [1, 300] GPa; check the bounds and "
            "their unit");
}

TEST(ProjectIo, StructuralDampingIsATimeInItsRange) {
  EXPECT_DOUBLE_EQ(ParseProject(Rig("\"output_interval\": \"2 ms\"", "\"structural_damping\": \"0.2 ms\""), "t.json")
                       .settings.structural_damping,
                   2e-4);
  EXPECT_EQ(ErrorOf(Rig("\"output_interval\": \"2 ms\"", "\"structural_damping\": \"-1 ms\"")),
            "t.json:6:59 at /settings/structural_damping: settings 'structural_damping' (d = beta*c) must lie in "
            "[0, 1) s (e.g. \"0.4 ms\"; 0: no damping beyond the components' own)");
  const std::string e = ErrorOf(Rig("\"output_interval\": \"2 ms\"", "\"structural_damping\": \"2 N*m\""));
  EXPECT_NE(e.find("settings 'structural_damping': expected a time (s), got a torque (N*m)"), std::string::npos) << e;
}

TEST(ProjectIo, DuplicateIdsAreRejected) {
  EXPECT_EQ(ErrorOf(Rig("{\"id\": \"wtb\"", "{\"id\": \"stl\"")),
            "t.json:20:12 at /components/6/id: duplicate id 'stl': already used by the component at line 9, column 12; "
            "give every component and element a unique id");
}

TEST(ProjectIo, SyntaxErrorsHaveLineAndColumn) {
  EXPECT_EQ(ErrorOf("{\n  \"format\": \"highlift-project/1\",\n  \"name\": \"x\",\n}"),
            "t.json:4:1: invalid JSON: trailing comma before '}' is not allowed in JSON");
  EXPECT_EQ(ErrorOf("{\"format\": \"highlift-project/1\", \"name\": \"x\" \"a\": 1}"),
            "t.json:1:46: invalid JSON: expected ',' or '}' after an object member, found '\"'");
  EXPECT_EQ(ErrorOf("{\"name\": 1, \"name\": 2}"),
            "t.json:1:13: invalid JSON: duplicate key 'name' in the same object; give each key once");
  EXPECT_EQ(ErrorOf(""), "t.json:1:1: invalid JSON: the file is empty; a project file is one JSON object");
}

TEST(ProjectIo, FormatAndNameAreRequired) {
  EXPECT_EQ(ErrorOf("{\"name\": \"x\"}"),
            "t.json:1:1: missing key 'format'; start the file with \"format\": \"highlift-project/1\"");
  EXPECT_EQ(ErrorOf("{\"format\": \"highlift-project/2\", \"name\": \"x\"}"),
            "t.json:1:12 at /format: unsupported format 'highlift-project/2'; this version of highlift reads "
            "\"highlift-project/1\"");
  EXPECT_EQ(ErrorOf("[1]"), "t.json:1:1: a project file must be a JSON object {...}, got an array");
}

TEST(ProjectIo, BadConnectionsAndScenarios) {
  EXPECT_EQ(ErrorOf(Rig("[\"pdu.left\", \"stl.input\"]", "[\"pdu_left\", \"stl.input\"]")),
            "t.json:24:6 at /connections/0/0: connection 0: 'pdu_left' is not a port reference; write "
            "\"component.port\", e.g. \"pdu.left\"");
  EXPECT_EQ(ErrorOf(Rig("\"kind\": \"jam\"", "\"kind\": \"jamm\"")),
            "t.json:37:35 at /scenarios/1/kind: scenario 'jam_gra_1': unknown kind 'jamm'; did you mean 'jam'? Valid "
            "kinds: extension, jam, rupture");
  EXPECT_EQ(ErrorOf(Rig("\"wtb\": {\"trigger\": \"time\", \"time\": \"1100 ms\"}", "\"wtb\": {\"trigger\": \"time\"}")),
            "t.json:40:65 at /scenarios/2/wtb: scenario 'rupture_wtb': 'wtb': trigger \"time\" needs \"time\": the "
            "moment the brakes are applied");
  EXPECT_EQ(ErrorOf(Rig("[0.4, 242], [40, 242]", "[0.4, 242], [0.4, 242]")),
            "t.json:31:92 at /load_cases/0/pdu_speed/points/2: load case 'extend_opposing': 'pdu_speed': point 2 does "
            "not increase the abscissa (0.4 after 0.4); sort the points by x");
  EXPECT_EQ(ErrorOf(Rig("\"unit\": [\"s\", \"rpm\"]", "\"unit\": [\"s\", \"N*m\"]")),
            "t.json:31:53 at /load_cases/0/pdu_speed/unit/1: load case 'extend_opposing': 'pdu_speed': value unit: "
            "expected an angular velocity (rad/s), got a torque (N*m) in \"N*m\"");
}

TEST(ProjectIo, ParseQuantityForms) {
  using namespace dimensions;
  const SourceLocation where{"f.json", "/x", 3, 4};
  EXPECT_DOUBLE_EQ(*ParseQuantity(12.5, Length(), where).nominal, 12.5);
  const Parameter q = ParseQuantity("44 [43, 51] GPa", Pressure(), where);
  EXPECT_DOUBLE_EQ(*q.nominal, 44e9);
  EXPECT_EQ(q.domain, (Domain{43e9, 51e9}));
  const Parameter half = ParseQuantity(nlohmann::json{{"min", "0 N*m"}}, Torque(), where);
  EXPECT_EQ(half.domain, (Domain{0, std::numeric_limits<double>::infinity()}));
  const Parameter inf = ParseQuantity("[-inf, 5] kN*m", Torque(), where);
  EXPECT_EQ(inf.domain, (Domain{-std::numeric_limits<double>::infinity(), 5e3}));
  EXPECT_NEAR(*ParseQuantity("1.2 kg/m", LinearDensity(), where).nominal, 1.2, 1e-15);
  EXPECT_NEAR(*ParseQuantity("5000 psi", Pressure(), where).nominal, 3.447378646584e7, 1e-3);
  try {
    ParseQuantity("5 mmm", Length(), where);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.what(), std::string("f.json:3:4 at /x: unknown unit 'mmm' in \"5 mmm\" (units are UDUNITS-2 "
                                    "expressions such as mm, N*m, rpm, kg*m^2, GPa)"));
  }
  try {
    ParseQuantity("60 [43, 51] GPa", Pressure(), where);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "the nominal value lies outside its interval");
  }
  try {
    ParseQuantity("[51, 43] GPa", Pressure(), where);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "the interval is empty (min > max); write [min, max]");
  }
  EXPECT_THROW(ParseQuantity("GPa", Pressure(), where), InputError);
  EXPECT_THROW(ParseQuantity(true, Pressure(), where), InputError);
}

TEST(ProjectIo, MissingFileIsAnInputError) {
  try {
    LoadProject("/nonexistent/highlift.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/highlift.json: cannot open the project file; check the path");
  }
}

}  // namespace
}  // namespace highlift

namespace highlift {
namespace {

// The complete example in docs/project-format.md must stay a valid project.
TEST(ProjectIo, DocumentedExampleIsValid) {
  std::ifstream in(std::string(HIGHLIFT_SOURCE_DIR) + "/docs/project-format.md");
  ASSERT_TRUE(in);
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const auto section = doc.find("## A complete small example");
  ASSERT_NE(section, std::string::npos);
  const auto begin = doc.find("```json\n", section);
  ASSERT_NE(begin, std::string::npos);
  const auto end = doc.find("```\n", begin + 8);
  const Project p = ParseProject(doc.substr(begin + 8, end - begin - 8), "project-format.md");
  EXPECT_EQ(p.components.size(), 4u);
  EXPECT_EQ(p.scenarios.size(), 2u);
}

}  // namespace
}  // namespace highlift

namespace highlift {
namespace {

// Every bundled example survives load -> save -> load unchanged.
TEST(ProjectIo, ExamplesRoundTrip) {
  const std::filesystem::path examples = std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples)) {
    if (entry.path().extension() != ".json") continue;
    const Project first = LoadProject(entry.path());
    const Project second = ParseProject(ProjectToJson(first).dump(2), "saved");
    EXPECT_EQ(DescribeDifference(first, second), "") << entry.path();
    ++count;
  }
  if (count == 0) GTEST_SKIP() << "no examples in " << examples;
}

}  // namespace
}  // namespace highlift
