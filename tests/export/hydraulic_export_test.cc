// The hydraulic components in the export (issue 8): the servo valve's spool models as modifiers
// of HighLift.Hydraulics.ServoValve, the hydraulic PDU of examples/hydraulic_pdu_flaps.json in
// every scenario and resolution (structural check), one motor lost at the scenario's
// `motor_lost_time`, and the exported PDU against the simulator's (sim/src/hydraulic_pdu.cc
// through sim/src/drive_network.cc): the same parts, classes, parameter values and connections.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "exported_model.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/sim/drive_network.h"

namespace highlift {
namespace {

using testing::CheckIssues;
using testing::FileOf;
using testing::Flatten;

const Project& HydraulicExample() {
  static const Project project =
      LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "hydraulic_pdu_flaps.json");
  return project;
}

/// The example with a third scenario: `extension` with one motor lost at 2.5 s.
Project WithMotorLost() {
  Project project = HydraulicExample();
  Scenario lost = *project.FindScenario("extension");
  lost.name = "one_motor_lost";
  lost.values["motor_lost_time"] = 2.5;
  project.scenarios.push_back(lost);
  return project;
}

std::string ModelText(const Project& project, ModelResolution resolution, const std::string& scenario) {
  return Flatten(testing::ExportedModelText(project, resolution, scenario));
}

/// Declarations of the model text: instance -> (class, modifiers).
std::map<std::string, std::pair<std::string, std::map<std::string, std::string>>> Declarations(
    const std::string& text) {
  std::map<std::string, std::pair<std::string, std::map<std::string, std::string>>> out;
  for (const auto& [name, instance] : testing::ParseExportedModel(text).instances)
    out[name] = {instance.class_path, instance.modifiers};
  return out;
}

/// The numeric value of modifier `name`, or nan.
double Modifier(const std::map<std::string, std::string>& modifiers, const std::string& name) {
  double v = 0;
  auto it = modifiers.find(name);
  if (it == modifiers.end() || !testing::ModifierNumber(it->second, v)) return std::nan("");
  return v;
}

TEST(HydraulicExport, ServoValveSpoolModelsExportWithTheirParameters) {
  const Project project = ParseProject(R"({
    "format": "highlift-project/1",
    "name": "valves",
    "elements": [
      {"id": "supply", "type": "PressureSource"},
      {"id": "tank", "type": "Tank"},
      {"id": "command", "type": "Constant", "parameters": {"k": 0.5}},
      {"id": "direct", "type": "ServoValve", "parameters": {"order": 0}},
      {"id": "lagged", "type": "ServoValve", "parameters": {"order": 1, "T_v": "4 ms"}},
      {"id": "second", "type": "ServoValve", "parameters": {"order": 2, "w_v": "300 rad/s", "D_v": 0.5}}
    ],
    "element_connections": [
      ["command.y", "direct.u"], ["command.y", "lagged.u"], ["command.y", "second.u"],
      ["supply.port", "direct.port_P"], ["supply.port", "lagged.port_P"], ["supply.port", "second.port_P"],
      ["tank.port", "direct.port_T"], ["tank.port", "lagged.port_T"], ["tank.port", "second.port_T"],
      ["direct.port_A", "lagged.port_A"], ["direct.port_B", "lagged.port_B"],
      ["second.port_A", "lagged.port_A"], ["second.port_B", "lagged.port_B"]
    ]
  })");
  const ModelicaExportReport report = GenerateModelica(project, ModelicaExportOptions{});
  EXPECT_EQ(CheckIssues(report), "");
  const std::string text = Flatten(FileOf(report, "HighLift/Models/Valves.mo").content);
  EXPECT_NE(text.find("HighLift.Hydraulics.ServoValve direct(order=0)"), std::string::npos) << text;
  EXPECT_NE(text.find("HighLift.Hydraulics.ServoValve lagged(order=1, T_v=0.004)"), std::string::npos) << text;
  EXPECT_NE(text.find("HighLift.Hydraulics.ServoValve second(order=2, w_v=300, D_v=0.5)"), std::string::npos)
      << text;
  // The library class has the three spool models.
  bool found = false;
  for (const auto& f : report.files) {
    if (f.path != "HighLift/Hydraulics/ServoValve.mo") continue;
    found = true;
    for (const char* piece : {"parameter Integer order(min=0, max=2) = 1", "parameter SI.AngularFrequency w_v",
                              "parameter Real D_v(min=0) = 0.7", "x = max(-1, min(1, u));",
                              "der(x) = (max(-1, min(1, u)) - x)/T_v;",
                              "der(v_x) = w_v^2*(max(-1, min(1, u)) - x) - 2*D_v*w_v*v_x;",
                              "x_open = max(-1, min(1, x));"})
      EXPECT_NE(f.content.find(piece), std::string::npos) << piece;
  }
  EXPECT_TRUE(found);
}

// The example in both scenarios at both resolutions, and with one motor lost.
TEST(HydraulicExport, ExamplePassesTheStructuralCheckInEveryScenario) {
  const Project project = WithMotorLost();
  for (const std::string scenario : {"extension", "rupture_wtb", "one_motor_lost"}) {
    for (auto resolution : {ModelResolution::kFull, ModelResolution::kReduced}) {
      const std::string text = ModelText(project, resolution, scenario);
      for (const char* instance : {"HighLift.Hydraulics.PressureSource pdu_supply", "HighLift.Hydraulics.ServoValve pdu_valve2",
                                   "HighLift.Hydraulics.DifferentialCylinder pdu_cylinder1",
                                   "HighLift.Hydraulics.VariableDisplacementMotor pdu_motor2",
                                   "HighLift.Hydraulics.MotorSpeedControl pdu_control1",
                                   "Modelica.Mechanics.Rotational.Components.IdealPlanetary pdu_differential"})
        EXPECT_NE(text.find(instance), std::string::npos) << scenario << ": " << instance;
    }
  }
}

// One motor lost: the last motor's `active` input steps from 1 to 0 and its pressure-off brake
// is applied at the scenario's motor_lost_time; the other motor stays active.
TEST(HydraulicExport, MotorLostAtTheScenarioTime) {
  const auto lost = Declarations(ModelText(WithMotorLost(), ModelResolution::kReduced, "one_motor_lost"));
  ASSERT_TRUE(lost.count("pdu_motor_lost"));
  EXPECT_EQ(lost.at("pdu_motor_lost").first, "Modelica.Blocks.Sources.Step");
  EXPECT_EQ(Modifier(lost.at("pdu_motor_lost").second, "startTime"), 2.5);
  EXPECT_EQ(Modifier(lost.at("pdu_motor_lost").second, "height"), -1.0);
  // The example has wing-tip brakes, so both motors also stop on the shutdown command.
  EXPECT_EQ(lost.at("pdu_active2").first, "Modelica.Blocks.Math.Product");
  ASSERT_TRUE(lost.count("pdu_pob2"));
  EXPECT_EQ(lost.at("pdu_pob2").first, "Modelica.Mechanics.Rotational.Components.Brake");
  EXPECT_EQ(lost.at("pdu_pob_command2").first, "Modelica.Blocks.Math.Add");

  const auto running = Declarations(ModelText(HydraulicExample(), ModelResolution::kReduced, "extension"));
  EXPECT_FALSE(running.count("pdu_motor_lost"));
  EXPECT_FALSE(running.count("pdu_active2"));
}

// The wing-tip brake command shuts the hydraulic PDU down, as the simulator's (AddHydraulicPdu
// with_stop): every motor out of operation (active = 1 - stop), its pressure-off brake applied
// (1 - active). The Boolean command becomes the 0/1 signal by a BooleanToReal.
TEST(HydraulicExport, WingTipBrakeCommandShutsThePduDown) {
  for (const std::string scenario : {"extension", "rupture_wtb"}) {
    const std::string text = ModelText(HydraulicExample(), ModelResolution::kFull, scenario);
    const auto declarations = Declarations(text);
    ASSERT_TRUE(declarations.count("pdu_stop")) << scenario;
    EXPECT_EQ(declarations.at("pdu_stop").first, "Modelica.Blocks.Math.BooleanToReal");
    EXPECT_NE(text.find("connect(monitor.wtb, pdu_stop.u)"), std::string::npos) << scenario;
    EXPECT_NE(text.find("connect(pdu_running.y, pdu_control1.active)"), std::string::npos) << scenario;
    EXPECT_NE(text.find("connect(pdu_pob_command2.y, pdu_pob2.f_normalized)"), std::string::npos) << scenario;
  }
}

// --- The exported hydraulic PDU against the simulator's, element by element ------------------

/// Export instance of a simulator element of the PDU: its id as a Modelica identifier (the
/// export writes the model layer's network, the one the simulator integrates).
std::string InstanceOf(const std::string& id) { return SanitizeModelicaIdentifier(id); }

std::string ClassOf(const std::string& id, const std::string& type) {
  // The shutdown input: an identity Gain on the 0/1 signal in the simulator, the conversion of
  // the Boolean wing-tip brake command in Modelica.
  if (id == "pdu.stop") return "Modelica.Blocks.Math.BooleanToReal";
  static const std::set<std::string> hydraulic = {"PressureSource", "Tank", "TurbulentResistance", "Volume",
                                                  "ServoValve", "DifferentialCylinder",
                                                  "VariableDisplacementMotor", "MotorSpeedControl"};
  if (hydraulic.count(type)) return "HighLift.Hydraulics." + type;
  if (type == "SpeedSensor") return "Modelica.Mechanics.Rotational.Sensors.SpeedSensor";
  if (type == "Mass") return "Modelica.Mechanics.Translational.Components.Mass";
  if (type == "AngleSensor") return "Modelica.Mechanics.Rotational.Sensors.AngleSensor";
  if (type == "Gain" || type == "Add" || type == "Product") return "Modelica.Blocks.Math." + type;
  if (type == "Step" || type == "Constant" || type == "CombiTimeTable") return "Modelica.Blocks.Sources." + type;
  return "Modelica.Mechanics.Rotational.Components." + type;  // Inertia, IdealGear, IdealPlanetary, Brake
}

using Groups = testing::PortGroups;

TEST(HydraulicExport, PduAgreesWithTheSimulatorElementByElement) {
  const Project project = WithMotorLost();
  sim::DriveNetworkOptions sim_options;
  sim_options.resolution = sim::DriveResolution::kReduced;
  sim_options.scenario = "one_motor_lost";
  const sim::DriveModel model = sim::BuildDriveNetwork(project, sim_options);
  const std::string text = ModelText(project, ModelResolution::kReduced, "one_motor_lost");
  const auto exported = Declarations(text);

  std::set<std::string> matched;
  int compared = 0;
  for (const sim::NetworkElement& e : model.network.elements()) {
    if (e.id != "pdu" && e.id.rfind("pdu.", 0) != 0) continue;
    const std::string instance = InstanceOf(e.id);
    if (instance.empty()) continue;
    ASSERT_TRUE(exported.count(instance)) << "simulator element " << e.id << " (" << e.type
                                          << ") has no exported instance " << instance;
    matched.insert(instance);
    const auto& [cls, modifiers] = exported.at(instance);
    EXPECT_EQ(cls, ClassOf(e.id, e.type)) << e.id;
    if (e.type == "CombiTimeTable") continue;  // the table and its Modelica enumeration
    if (e.id == "pdu.stop") continue;          // k = 1 of the identity Gain
    const ComponentTypeSpec* spec = FindElementType(e.type);
    ASSERT_NE(spec, nullptr) << e.type;
    for (const auto& [name, value] : e.parameters.scalars) {
      const double v = Modifier(modifiers, name);
      if (std::isnan(v)) {
        // Not written: the Modelica default applies, which is the element type's default.
        const ParameterSpec* p = spec->FindParameter(name);
        ASSERT_NE(p, nullptr) << e.id << "." << name;
        EXPECT_TRUE(p->nominal && *p->nominal == value)
            << e.id << "." << name << " = " << value << " in the simulator is not exported and not the default";
      } else {
        EXPECT_NEAR(v, value, 1e-12 * std::abs(value)) << e.id << "." << name;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 40);
  // Every exported part of the PDU is one of the simulator's (with wing-tip brakes every motor
  // has its `active` signal; without, the export feeds an unconnected one a constant 1).
  for (const auto& [instance, declaration] : exported)
    if (instance.rfind("pdu_", 0) == 0 && !matched.count(instance))
      ADD_FAILURE() << "exported " << declaration.first << " " << instance << " has no simulator element";

  // Connections: two ports of matched parts share a node in the simulator iff they do in the
  // export.
  Groups sim_groups, export_groups;
  std::set<std::string> ports;
  auto sim_port = [&](const PortRef& p) -> std::string {
    if (p.component != "pdu" && p.component.rfind("pdu.", 0) != 0) return "";
    const std::string instance = InstanceOf(p.component);
    return instance.empty() ? "" : instance + "." + p.port;
  };
  for (const sim::NetworkConnection& c : model.network.connections()) {
    const std::string a = sim_port(c.a), b = sim_port(c.b);
    if (a.empty() || b.empty()) continue;
    sim_groups.Join(a, b);
    ports.insert(a);
    ports.insert(b);
  }
  const std::regex connect(R"(connect\(([A-Za-z0-9_]+)\.([A-Za-z0-9_]+)(\[1\])?, ([A-Za-z0-9_]+)\.([A-Za-z0-9_]+)(\[1\])?\))");
  for (std::sregex_iterator it(text.begin(), text.end(), connect), end; it != end; ++it) {
    if (!matched.count((*it)[1]) || !matched.count((*it)[4])) continue;
    const std::string a = std::string((*it)[1]) + "." + std::string((*it)[2]);
    const std::string b = std::string((*it)[4]) + "." + std::string((*it)[5]);
    export_groups.Join(a, b);
    ports.insert(a);
    ports.insert(b);
  }
  ASSERT_GT(ports.size(), 40u);
  for (const std::string& a : ports) {
    for (const std::string& b : ports) {
      if (a < b) {
        EXPECT_EQ(sim_groups.Root(a) == sim_groups.Root(b), export_groups.Root(a) == export_groups.Root(b))
            << a << " and " << b;
      }
    }
  }
}

}  // namespace
}  // namespace highlift
