// The exported mechanical drive model against the simulator's model of the same project
// (sim::BuildDriveNetwork, the model layer's network that both read), element by element: the A380-class example
// at both resolutions in the scenarios that exercise every part of the translation (extension,
// jam of an actuator, shaft rupture with the monitor, WTBs applied at a time, a retraction with
// position-dependent airloads). Every simulator element has its instance (same class, every
// parameter value written or equal to the class default, tables equal), every exported instance
// is a simulator element, and two ports share a node in the export iff they do in the simulator.
// A second test changes a value, drops a connection or an instance and checks that the comparison
// reports it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "exported_model.h"
#include "highlift/core/catalogue.h"
#include "highlift/sim/drive_network.h"

namespace highlift {
namespace {

using testing::ExportedModel;
using testing::ModifierMatrix;
using testing::ModifierNumber;
using testing::ParseExportedModel;

/// The example with two scenarios it lacks: WTBs applied at a time, and a retraction (the
/// airload tables against position with keys from -travel to 0).
Project Example() {
  Project project =
      LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a380_class_flaps.json");
  Scenario timed = *project.FindScenario("rupture_wtb");
  timed.name = "rupture_wtb_timed";
  timed.wtb_trigger = "time";
  timed.wtb_time = 1.2;
  project.scenarios.push_back(timed);
  Scenario retraction = *project.FindScenario("extension");
  retraction.name = "retraction";
  retraction.load_case = "retract_aiding";
  retraction.output_interval = 0.02;
  project.scenarios.push_back(retraction);
  return project;
}

const Project& ExampleProject() {
  static const Project project = Example();
  return project;
}

const std::vector<std::string>& Scenarios() {
  static const std::vector<std::string> names = {"extension", "jam_l1", "rupture_wtb", "rupture_wtb_timed",
                                                 "retraction"};
  return names;
}


/// The simulator's side of the comparison: the elements and connections of a drive network.
struct SimSide {
  std::vector<sim::NetworkElement> elements;
  std::vector<sim::NetworkConnection> connections;
};

SimSide Simulated(const Project& project, ModelResolution resolution, const std::string& scenario) {
  sim::DriveNetworkOptions options;
  options.resolution =
      resolution == ModelResolution::kFull ? sim::DriveResolution::kFull : sim::DriveResolution::kReduced;
  options.scenario = scenario;
  const sim::DriveModel model = sim::BuildDriveNetwork(project, options);
  return {model.network.elements(), model.network.connections()};
}

/// The exported instance of a simulator element: the element id as a Modelica identifier
/// (the export writes the model layer's network, the one the simulator integrates).
std::string InstanceOf(const std::string& id) { return SanitizeModelicaIdentifier(id); }

std::string ClassOf(const sim::NetworkElement& e) {
  static const std::map<std::string, std::string> classes = {
      {"PDU", "HighLift.Drives.PDU"},
      {"Monitoring", "HighLift.Control.Monitoring"},
      {"TorqueLimiter", "HighLift.Mechanical.TorqueLimiter"},
      {"LossyInertia", "HighLift.Mechanical.LossyInertia"},
      {"GeneralRotationalElement", "HighLift.Mechanical.GeneralRotationalElement"},
      {"BranchGearbox", "HighLift.Mechanical.BranchGearbox"},
      {"GearedRotaryActuator", "HighLift.Mechanical.GearedRotaryActuator"},
      {"WingTipBrake", "HighLift.Mechanical.WingTipBrake"},
      {"Disconnector", "HighLift.Mechanical.Disconnector"},
      {"Jam", "HighLift.Mechanical.Jam"},
      {"Inertia", "Modelica.Mechanics.Rotational.Components.Inertia"},
      {"SpringDamper", "Modelica.Mechanics.Rotational.Components.SpringDamper"},
      {"Torque", "Modelica.Mechanics.Rotational.Sources.Torque"},
      {"AngleSensor", "Modelica.Mechanics.Rotational.Sensors.AngleSensor"},
      {"SpeedSensor", "Modelica.Mechanics.Rotational.Sensors.SpeedSensor"},
      {"CombiTimeTable", "Modelica.Blocks.Sources.CombiTimeTable"},
      {"CombiTable1Ds", "Modelica.Blocks.Tables.CombiTable1Ds"},
      {"Gain", "Modelica.Blocks.Math.Gain"},
      {"Integrator", "Modelica.Blocks.Continuous.Integrator"},
      // The WTB command at a time: a 0/1 Step in the simulator, the Boolean step in Modelica.
      {"Step", "Modelica.Blocks.Sources.BooleanStep"}};
  auto it = classes.find(e.type);
  return it == classes.end() ? "(no class for element type " + e.type + ")" : it->second;
}

/// Parameters the Modelica counterpart has not, or derives: (element type, parameter).
bool NotAModifier(const sim::NetworkElement& e, const std::string& name) {
  // BooleanStep has no height: its output is true from startTime on (the Step's 0 -> 1).
  if (e.type == "Step") return name == "height" || name == "offset";
  return false;
}

/// The differences between the simulator's network and the exported model, one line each.
std::vector<std::string> Differences(const SimSide& simulated, const ExportedModel& exported) {
  std::vector<std::string> out;
  auto differ = [&](std::string what) { out.push_back(std::move(what)); };
  std::set<std::string> matched;
  std::map<std::string, std::string> instance_of;  // simulator id -> exported instance
  for (const sim::NetworkElement& e : simulated.elements) {
    const std::string instance = InstanceOf(e.id);
    instance_of[e.id] = instance;
    auto it = exported.instances.find(instance);
    if (it == exported.instances.end()) {
      differ("simulator element " + e.id + " (" + e.type + ") has no exported instance " + instance);
      continue;
    }
    if (!matched.insert(instance).second) differ("two simulator elements map to instance " + instance);
    const testing::ExportedInstance& x = it->second;
    if (x.class_path != ClassOf(e)) {
      differ(instance + ": class " + x.class_path + ", simulator " + e.type + " (" + ClassOf(e) + ")");
      continue;
    }
    const ComponentTypeSpec* spec = FindElementType(e.type);
    if (!spec) {
      differ(e.id + ": unknown element type " + e.type);
      continue;
    }
    std::set<std::string> compared;
    for (const auto& [name, value] : e.parameters.scalars) {
      if (NotAModifier(e, name)) continue;
      compared.insert(name);
      auto m = x.modifiers.find(name);
      if (m == x.modifiers.end()) {
        // Not written: the class default applies, which is the element type's default.
        const ParameterSpec* p = spec->FindParameter(name);
        if (!p || !p->nominal || *p->nominal != value)
          differ(instance + "." + name + " is not exported; the simulator has " + FormatModelicaReal(value) +
                 (p && p->nominal ? ", the default is " + FormatModelicaReal(*p->nominal) : ", no default"));
        continue;
      }
      double v = 0;
      if (!ModifierNumber(m->second, v)) {
        differ(instance + "." + name + " = " + m->second + " is no number");
      } else if (!(std::abs(v - value) <= 1e-12 * std::abs(value))) {
        differ(instance + "." + name + " = " + m->second + ", the simulator has " + FormatModelicaReal(value));
      }
    }
    for (const auto& [name, rows] : e.parameters.tables) {
      compared.insert(name);
      auto m = x.modifiers.find(name);
      if (m == x.modifiers.end()) {
        differ(instance + "." + name + ": the simulator's table is not exported");
        continue;
      }
      const auto table = ModifierMatrix(m->second);
      bool same = table.size() == rows.size();
      for (std::size_t i = 0; same && i < rows.size(); ++i) {
        same = table[i].size() == rows[i].size();
        for (std::size_t j = 0; same && j < rows[i].size(); ++j)
          same = std::abs(table[i][j] - rows[i][j]) <= 1e-12 * std::abs(rows[i][j]);
      }
      if (!same) differ(instance + "." + name + " = " + m->second + " differs from the simulator's table");
    }
    // Every written modifier is a parameter of the simulator's element, or the switch of an
    // input the simulator enables by connecting it.
    for (const auto& [name, value] : x.modifiers) {
      if (compared.count(name)) continue;
      if (e.type == "PDU" && name == "useStopInput") continue;  // checked with the connections
      differ(instance + "." + name + " = " + value + " is exported but not a parameter of the simulator's " + e.type);
    }
  }
  for (const auto& [instance, x] : exported.instances)
    if (!matched.count(instance)) differ("exported " + x.class_path + " " + instance + " has no simulator element");

  // Connections: the same ports share a node in both.
  testing::PortGroups sim_groups, export_groups;
  std::set<std::string> ports;
  std::set<std::string> stops;  // PDU instances whose input stop the simulator connects
  for (const sim::NetworkConnection& c : simulated.connections) {
    auto ref = [&](const PortRef& p) {
      auto it = instance_of.find(p.component);
      return (it == instance_of.end() ? "(unknown " + p.component + ")" : it->second) + "." + p.port;
    };
    const std::string a = ref(c.a), b = ref(c.b);
    sim_groups.Join(a, b);
    ports.insert(a);
    ports.insert(b);
    for (const PortRef& p : {c.a, c.b})
      if (p.port == "stop") stops.insert(instance_of[p.component]);
  }
  for (const auto& [a, b] : exported.connects) {
    export_groups.Join(a, b);
    ports.insert(a);
    ports.insert(b);
  }
  // Compare the partition: each port with the representative of its simulator group and of
  // its export group (quadratic in the ports otherwise).
  std::map<std::string, std::string> sim_first, export_first;  // root -> first port seen
  std::map<std::string, std::string> sim_partner, export_partner;
  for (const std::string& p : ports) {
    sim_partner[p] = sim_first.emplace(sim_groups.Root(p), p).first->second;
    export_partner[p] = export_first.emplace(export_groups.Root(p), p).first->second;
  }
  for (const std::string& p : ports) {
    if (sim_partner[p] == export_partner[p]) continue;
    // Different representatives: some port is joined to p on one side only.
    if (sim_groups.Root(p) != sim_groups.Root(export_partner[p]))
      differ(p + " and " + export_partner[p] + " are connected in the export, not in the simulator");
    else
      differ(p + " and " + sim_partner[p] + " are connected in the simulator, not in the export");
  }
  for (const auto& [instance, x] : exported.instances) {
    if (x.class_path != "HighLift.Drives.PDU") continue;
    auto it = x.modifiers.find("useStopInput");
    const bool enabled = it != x.modifiers.end() && it->second == "true";
    if (enabled != (stops.count(instance) > 0))
      differ(instance + ": useStopInput " + (enabled ? "true" : "false") + " but the simulator " +
             (stops.count(instance) ? "connects" : "does not connect") + " its input stop");
  }
  return out;
}

std::string Join(const std::vector<std::string>& lines) {
  std::string text;
  for (std::size_t i = 0; i < lines.size() && i < 40; ++i) text += lines[i] + "\n";
  if (lines.size() > 40) text += "... (" + std::to_string(lines.size()) + " differences)\n";
  return text;
}

TEST(DriveSystemAgreement, A380ClassExampleAgreesWithTheSimulatorElementByElement) {
  const Project& project = ExampleProject();
  for (auto resolution : {ModelResolution::kFull, ModelResolution::kReduced}) {
    for (const std::string& scenario : Scenarios()) {
      SCOPED_TRACE(scenario + " " + ToString(resolution));
      const SimSide simulated = Simulated(project, resolution, scenario);
      const ExportedModel exported = ParseExportedModel(testing::ExportedModelText(project, resolution, scenario));
      const auto differences = Differences(simulated, exported);
      EXPECT_TRUE(differences.empty()) << Join(differences);
      EXPECT_EQ(exported.instances.size(), simulated.elements.size());
      EXPECT_GT(simulated.elements.size(), resolution == ModelResolution::kFull ? 250u : 100u);
    }
  }
}

// The rig of the golden files (tests/export/small_drive.json: shaft drag, WTB applied by the
// monitor or at a time, a jam and a rupture) agrees as well.
TEST(DriveSystemAgreement, OneStationRigAgreesWithTheSimulatorElementByElement) {
  const Project project = LoadProject(testing::ExportTestDir() / "small_drive.json");
  for (auto resolution : {ModelResolution::kFull, ModelResolution::kReduced}) {
    for (const Scenario& scenario : project.scenarios) {
      SCOPED_TRACE(scenario.name + " " + ToString(resolution));
      const auto differences = Differences(Simulated(project, resolution, scenario.name),
                                           ParseExportedModel(testing::ExportedModelText(project, resolution, scenario.name)));
      EXPECT_TRUE(differences.empty()) << Join(differences);
    }
  }
}

// The features the simulator's translation gained are in the comparison (not only equal by
// being absent on both sides): regularised friction, structural damping, the shutdown command.
TEST(DriveSystemAgreement, ComparisonCoversFrictionRegularisationDampingAndShutdown) {
  const Project& project = ExampleProject();
  const ExportedModel exported =
      ParseExportedModel(testing::ExportedModelText(project, ModelResolution::kFull, "jam_l1"));
  int regularised = 0, damped = 0;
  for (const auto& [name, x] : exported.instances) {
    if (x.modifiers.count("w_small") && x.modifiers.at("w_small") == "0.1") ++regularised;
    if (x.modifiers.count("d") && x.modifiers.at("d") != "0") ++damped;
  }
  EXPECT_GT(regularised, 60);  // bearings, gearboxes, actuators, shaft end masses
  EXPECT_GT(damped, 100);      // shaft elements, torque limiters, the jam
  EXPECT_EQ(exported.instances.at("gra_l1_jam").modifiers.count("d"), 1u);
  EXPECT_EQ(exported.instances.at("pdu").modifiers.at("useStopInput"), "true");
  const std::string timed = testing::Flatten(testing::ExportedModelText(project, ModelResolution::kReduced, "rupture_wtb_timed"));
  EXPECT_NE(timed.find("connect(wtb_command.y, pdu.stop)"), std::string::npos);
  EXPECT_NE(testing::ExportedModelText(project, ModelResolution::kReduced, "retraction").find("Interval=0.02"), std::string::npos);
}

// The comparison is not vacuous: a changed value, a dropped connection, a lost instance and a
// changed simulator element are each reported, naming what differs.
TEST(DriveSystemAgreement, ComparisonReportsAChangedValueConnectionOrInstance) {
  const Project& project = ExampleProject();
  const SimSide simulated = Simulated(project, ModelResolution::kReduced, "rupture_wtb");
  const ExportedModel exported = ParseExportedModel(testing::ExportedModelText(project, ModelResolution::kReduced, "rupture_wtb"));
  ASSERT_TRUE(Differences(simulated, exported).empty());
  auto reported = [](const std::vector<std::string>& differences, const std::string& piece) {
    return std::any_of(differences.begin(), differences.end(),
                       [&](const std::string& d) { return d.find(piece) != std::string::npos; });
  };
  {
    ExportedModel changed = exported;
    changed.instances.at("gra_l2").modifiers.at("w_small") = "0.2";
    changed.instances.at("stl_l3").modifiers.at("d") = "0";
    const auto d = Differences(simulated, changed);
    EXPECT_EQ(d.size(), 2u) << Join(d);
    EXPECT_TRUE(reported(d, "gra_l2.w_small = 0.2, the simulator has 0.1")) << Join(d);
    EXPECT_TRUE(reported(d, "stl_l3.d = 0, the simulator has")) << Join(d);
  }
  {
    ExportedModel changed = exported;
    changed.instances.at("gra_r4").modifiers.erase("w_small");  // the class default 0 would apply
    EXPECT_TRUE(reported(Differences(simulated, changed), "gra_r4.w_small is not exported"));
  }
  {
    ExportedModel changed = exported;
    auto it = std::find_if(changed.connects.begin(), changed.connects.end(), [](const auto& c) {
      return c.first == "monitor.wtb" && c.second == "pdu.stop";
    });
    ASSERT_NE(it, changed.connects.end());
    changed.connects.erase(it);
    const auto d = Differences(simulated, changed);
    EXPECT_TRUE(reported(d, "pdu.stop")) << Join(d);
  }
  {
    ExportedModel changed = exported;
    changed.instances.erase("tgb_l4");
    EXPECT_TRUE(reported(Differences(simulated, changed),
                         "simulator element tgb_l4 (BranchGearbox) has no exported instance"));
  }
  {
    SimSide changed = simulated;
    for (auto& e : changed.elements)
      if (e.id == "pdu") e.parameters.scalars["T_i"] = 0.1;
    EXPECT_TRUE(reported(Differences(changed, exported), "pdu.T_i is not exported; the simulator has 0.1"));
  }
}

}  // namespace
}  // namespace highlift
