// Drive-system projects export to HighLift/MSL models: golden files for a small rig at full and
// reduced resolution, the scenario wiring (rupture, jam, WTB trigger), the lumping of the
// reduced model, tables in a file, and a structural check of the A380-class example.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "export_test_util.h"
#include "highlift/core/error.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"

namespace highlift {
namespace {

using testing::CheckIssues;
using testing::ExpectGolden;
using testing::ExportTestDir;
using testing::FileOf;

const Project& SmallDrive() {
  static const Project project = LoadProject(ExportTestDir() / "small_drive.json");
  return project;
}

ModelicaExportReport Export(ModelResolution resolution, const std::string& scenario = "") {
  ModelicaExportOptions options;
  options.resolution = resolution;
  options.scenario = scenario;
  return GenerateModelica(SmallDrive(), options);
}

// The value of modifier `name` of instance `instance` in `text` (first match), or nan.
double ModifierValue(const std::string& text, const std::string& instance, const std::string& name) {
  const auto start = text.find(" " + instance + "(");
  if (start == std::string::npos) return std::nan("");
  const auto end = text.find(";", start);
  const std::string decl = text.substr(start, end - start);
  std::smatch m;
  if (!std::regex_search(decl, m, std::regex("[(, \n]" + name + "=([-+0-9.e]+)"))) return std::nan("");
  return std::stod(m[1]);
}

TEST(DriveSystemExport, FullModelMatchesGolden) {
  const auto report = Export(ModelResolution::kFull);
  EXPECT_EQ(report.model_name, "OneStationRig");
  EXPECT_EQ(report.scenario, "rupture_wtb");
  ExpectGolden("OneStationRig_full.mo", FileOf(report, "HighLift/Models/OneStationRig.mo").content);
  EXPECT_EQ(CheckIssues(report), "");
}

// The export as `highlift export` writes it by default: the simulator's start (static
// equilibrium, PDU parked), one fixed angle and one fixed speed per start flange: start values
// of an Inertia, else initial equations on the flange. (No golden file: the start values are
// the last digits of an iterative solve.)
TEST(DriveSystemExport, FullModelWritesEveryStartOfTheSimulatorOnce) {
  const Project& project = SmallDrive();
  model::StartValues start;
  ModelicaExportOptions options;
  options.start = [&](const model::DriveModel& model) {
    start = sim::ComputeStartValues(model.network, sim::DriveModel{model}.Options(project));
    return start;
  };
  const auto report = GenerateModelica(project, options);
  EXPECT_NE(report.start.find("static equilibrium"), std::string::npos) << report.start;
  EXPECT_EQ(CheckIssues(report), "");
  const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/OneStationRig.mo").content);
  auto count = [&](const std::string& what) {
    int n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  ASSERT_GT(start.flanges.size(), 5u);
  const int angles = count("phi(start=") + count(".phi = ");
  const int speeds = count("w(start=") + count("der(");
  EXPECT_EQ(angles, static_cast<int>(start.flanges.size()));
  EXPECT_EQ(speeds, static_cast<int>(start.flanges.size()));
  for (const auto& f : start.flanges) {
    std::string name = f.flange.component;
    std::replace(name.begin(), name.end(), '.', '_');
    const bool written = text.find(" " + name + "(") != std::string::npos || text.find(name + ".") != std::string::npos;
    EXPECT_TRUE(written) << name;
  }
}

TEST(DriveSystemExport, ReducedModelMatchesGolden) {
  const auto report = Export(ModelResolution::kReduced);
  ExpectGolden("OneStationRig_reduced.mo", FileOf(report, "HighLift/Models/OneStationRig.mo").content);
  EXPECT_EQ(CheckIssues(report), "");
  EXPECT_LT(report.component_count, Export(ModelResolution::kFull).component_count);
}

TEST(DriveSystemExport, FullModelSplitsShaftsIntoSettingsElementsAtLeastFour) {
  const double G = 44e9, D = 0.05, d = 0.046, L = 3.0, rho = 4420;
  const double polar = M_PI / 32 * (std::pow(D, 4) - std::pow(d, 4));
  const double c = G * polar / L, J = rho * polar * L;
  // The rig asks for shaft_elements = 2; the simulator's lower bound of 4 applies (as in
  // sim::BuildDriveNetwork): springs with 4 c, end masses with J/8, inner masses J/4.
  {
    const auto report = Export(ModelResolution::kFull, "jam_gra_1");
    const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/OneStationRig.mo").content);
    EXPECT_NEAR(ModifierValue(text, "shaft_1_e1", "c"), 4 * c, 1e-9 * c);
    EXPECT_NEAR(ModifierValue(text, "shaft_1_e4", "c"), 4 * c, 1e-9 * c);
    EXPECT_NEAR(ModifierValue(text, "shaft_1_m0", "J"), J / 8, 1e-12);
    EXPECT_NEAR(ModifierValue(text, "shaft_1_m1", "J"), J / 4, 1e-12);
    EXPECT_EQ(text.find("shaft_1_e5"), std::string::npos);
    // No damping given: the structural damping d = beta*c per element (4 d for 4 c).
    EXPECT_NEAR(ModifierValue(text, "shaft_1_e2", "d"), 4 * 4e-4 * c, 1e-9 * c);
  }
  Project project = SmallDrive();
  project.settings.shaft_elements = 6;
  ModelicaExportOptions options;
  options.scenario = "jam_gra_1";
  const std::string text = testing::Flatten(FileOf(GenerateModelica(project, options), "HighLift/Models/OneStationRig.mo").content);
  EXPECT_NEAR(ModifierValue(text, "shaft_1_e6", "c"), 6 * c, 1e-9 * c);
  EXPECT_NEAR(ModifierValue(text, "shaft_1_m6", "J"), J / 12, 1e-12);
  EXPECT_EQ(text.find("shaft_1_e7"), std::string::npos);
}

// The drag of a shaft acts at its two end masses (half each, regularised friction), its
// interior masses are plain inertias, as in the simulator. (The inertias are the shared tube law
// of model/laws.h, pi/8 (D^2 + d^2)(D - t) t: the last digits differ from pi/32 (D^4 - d^4).)
TEST(DriveSystemExport, ShaftDragActsAtTheEndMassesWithRegularisedFriction) {
  const std::string text = testing::Flatten(FileOf(Export(ModelResolution::kFull), "HighLift/Models/OneStationRig.mo").content);
  EXPECT_NE(text.find("HighLift.Mechanical.LossyInertia shaft_1_m0(J=0.000288436658693623, tau_C=0.375, w_small=0.1)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Modelica.Mechanics.Rotational.Components.Inertia shaft_1_m1(J=0.000576873317387246)"),
            std::string::npos);
  EXPECT_NE(text.find("HighLift.Mechanical.LossyInertia shaft_1_m4(J=0.000288436658693623, tau_C=0.375, w_small=0.1)"),
            std::string::npos);
}

TEST(DriveSystemExport, ReducedModelLumpsChainsWithSeriesStiffness) {
  const auto report = Export(ModelResolution::kReduced, "jam_gra_1");
  const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/OneStationRig.mo").content);
  const double G = 44e9, D = 0.05, d = 0.046;
  const double polar = M_PI / 32 * (std::pow(D, 4) - std::pow(d, 4));
  const double c1 = G * polar / 3.0, c2 = G * polar / 2.0;
  // shaft_1 - brg_1 - shaft_2 is one chain: 1/c = 1/c1 + 1/c2 (the bearing is rigid).
  EXPECT_NEAR(ModifierValue(text, "shaft_1_shaft_2_spring", "c"), 1 / (1 / c1 + 1 / c2), 1e-9 * c1);
  // Its inertia (two shafts and the bearing) is split between the two ends.
  const double rho = 4420, J_bearing = 5e-5;
  const double J = rho * polar * 5.0 + J_bearing;
  EXPECT_NEAR(ModifierValue(text, "shaft_1_shaft_2_mass_a", "J"), J / 2, 1e-12);
  EXPECT_NEAR(ModifierValue(text, "shaft_1_shaft_2_mass_b", "J"), J / 2, 1e-12);
  EXPECT_NE(text.find("<li>shaft_1-shaft_2: shaft_1, brg_1, shaft_2</li>"), std::string::npos);
}

TEST(DriveSystemExport, RuptureScenarioInsertsADisconnectorAndTheMonitor) {
  for (auto resolution : {ModelResolution::kFull, ModelResolution::kReduced}) {
    const auto report = Export(resolution, "rupture_wtb");
    const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/OneStationRig.mo").content);
    EXPECT_NE(text.find("HighLift.Mechanical.Disconnector"), std::string::npos) << ToString(resolution);
    EXPECT_NE(text.find("t_disconnect=1"), std::string::npos);
    EXPECT_NE(text.find("HighLift.Control.Monitoring monitor("), std::string::npos);
    EXPECT_NE(text.find("connect(monitor.wtb, wtb.apply)"), std::string::npos);
    EXPECT_NE(text.find("connect(monitor.wtb, pdu.stop)"), std::string::npos);
    // The APPU sits behind the 1:1 through-drive: no gain between the tip and the PDU angle.
    EXPECT_NE(text.find("connect(appu_angle_sensor.phi, monitor.phi_left)"), std::string::npos);
    EXPECT_NE(text.find("experiment(StopTime=3, Tolerance=1e-06, Interval=0.001)"), std::string::npos);
  }
}

TEST(DriveSystemExport, JamScenarioJamsTheActuatorOutputAndTimesTheWtb) {
  const auto report = Export(ModelResolution::kFull, "jam_gra_1");
  const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/OneStationRig.mo").content);
  // Stiffness 1e5 N*m/rad at the input (x 200^2 at the output), structural damping beta*c.
  EXPECT_NE(text.find("HighLift.Mechanical.Jam gra_1_jam(c=4e+09, d=1600000, t_jam=1)"), std::string::npos) << text;
  EXPECT_NE(text.find("connect(gra_1.flange_b, gra_1_jam.flange)"), std::string::npos);
  EXPECT_NE(text.find("Modelica.Blocks.Sources.BooleanStep wtb_command(startTime=1.5)"), std::string::npos);
  // The WTB command also shuts the PDU down.
  EXPECT_NE(text.find("connect(wtb_command.y, pdu.stop)"), std::string::npos);
  EXPECT_NE(text.find("tauPOB=1100, useStopInput=true)"), std::string::npos);
  EXPECT_EQ(text.find("HighLift.Mechanical.Disconnector"), std::string::npos);
  EXPECT_EQ(CheckIssues(report), "");
}

TEST(DriveSystemExport, LoadsAgainstPositionUseTheOutputAngle) {
  const auto report = Export(ModelResolution::kFull);
  const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/OneStationRig.mo").content);
  // 5 -> 20 kN*m over the travel angle 2.2 rad, opposing the extension (negative).
  EXPECT_NE(text.find("gra_1_airload_table(table=[0, -5000; 2.2, -20000]"), std::string::npos) << text;
  EXPECT_NE(text.find("connect(gra_1_output_angle.phi, gra_1_airload_table.u)"), std::string::npos);
  EXPECT_NE(text.find("pdu_speed_command(table=[0, 0; 0.4, 25.3; 3, 25.3]"), std::string::npos);
}

TEST(DriveSystemExport, TablesInFileAreReadByCombiTimeTable) {
  ModelicaExportOptions options;
  options.tables_in_file = true;
  const auto report = GenerateModelica(SmallDrive(), options);
  const std::string& table = FileOf(report, "HighLift/Models/OneStationRig.txt").content;
  EXPECT_EQ(table.rfind("#1\ndouble pdu_speed_command(3,2)\n0 0\n0.4 25.3\n3 25.3\n", 0), 0u) << table;
  EXPECT_NE(table.find("double gra_1_airload_table(2,2)\n0 -5000\n2.2 -20000\n"), std::string::npos) << table;
  const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/OneStationRig.mo").content);
  EXPECT_NE(text.find("tableOnFile=true"), std::string::npos);
  EXPECT_NE(text.find("Modelica.Utilities.Files.loadResource(\"modelica://HighLift/Models/OneStationRig.txt\")"),
            std::string::npos);
  EXPECT_EQ(CheckIssues(report), "");
}

TEST(DriveSystemExport, OutputIsDeterministic) {
  for (auto resolution : {ModelResolution::kFull, ModelResolution::kReduced}) {
    const auto a = Export(resolution), b = Export(resolution);
    ASSERT_EQ(a.files.size(), b.files.size());
    for (std::size_t i = 0; i < a.files.size(); ++i) EXPECT_EQ(a.files[i].content, b.files[i].content);
  }
}

TEST(DriveSystemExport, UnknownScenarioListsTheScenarios) {
  try {
    Export(ModelResolution::kFull, "rupture_wtx");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown scenario 'rupture_wtx': use one of rupture_wtb, jam_gra_1"),
              std::string::npos)
        << e.what();
  }
}

TEST(DriveSystemExport, ParameterWithoutValueNamesComponentAndRemedy) {
  Project project = SmallDrive();
  Parameter& length = project.FindComponent("shaft_1")->parameters["length"];
  length.nominal.reset();
  length.domain = {2.5, 3.5};
  try {
    GenerateModelica(project, ModelicaExportOptions{});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("component 'shaft_1' (torque_shaft): parameter 'length' has no value for the drive model (simulate, export)"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("give a value"), std::string::npos) << e.what();
  }
}

TEST(DriveSystemExport, A380ClassExampleIsStructurallyValid) {
  const auto file = std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a380_class_flaps.json";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "examples/a380_class_flaps.json not present";
  const Project project = LoadProject(file);
  for (auto resolution : {ModelResolution::kFull, ModelResolution::kReduced}) {
    ModelicaExportOptions options;
    options.resolution = resolution;
    const auto report = GenerateModelica(project, options);
    EXPECT_EQ(CheckIssues(report), "") << ToString(resolution);
    EXPECT_GT(report.component_count, 50) << ToString(resolution);
  }
}

// ---- Names (issue 27, item 20; issue 28, items 4 and 6) ---------------------------------------------

std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  for (auto pos = text.find(from); pos != std::string::npos; pos = text.find(from, pos + to.size()))
    text.replace(pos, from.size(), to);
  return text;
}

// A component named like a predefined type is no instance of that name; a component whose id
// is a generated element's name keeps it, and the generated element's new name is reported.
TEST(DriveSystemNames, ReservedIdsAndClashesWithGeneratedNamesAreRenamedAndReported) {
  std::string text = testing::ReadText(ExportTestDir() / "small_drive.json");
  text = Replaced(text, "brg_1", "shaft_1_m1");  // the name of shaft_1's mass shaft_1.m1
  text = Replaced(text, "{\"id\": \"appu\"", "{\"id\": \"StateSelect\"");
  text = Replaced(text, "\"appu.", "\"StateSelect.");
  text = Replaced(text, "{\"id\": \"wtb\"", "{\"id\": \"Real\"");
  text = Replaced(text, "\"wtb.", "\"Real.");
  const Project project = ParseProject(text, "renamed_rig.json");
  const ModelicaExportReport report = GenerateModelica(project, ModelicaExportOptions{});
  const std::string model = testing::Flatten(FileOf(report, report.model_file).content);
  EXPECT_EQ(report.renamed.at("Real"), "Real_");
  EXPECT_EQ(report.renamed.at("StateSelect"), "StateSelect_");
  EXPECT_EQ(report.renamed.at("shaft_1.m1"), "shaft_1_m1_2");
  EXPECT_EQ(report.renamed.count("shaft_1_m1"), 0u);   // the project's id keeps its name
  EXPECT_EQ(report.renamed.count("shaft_1.m0"), 0u);   // renamed by the documented rule only
  EXPECT_EQ(model.find(" Real("), std::string::npos);
  EXPECT_EQ(model.find(" StateSelect("), std::string::npos);
  EXPECT_NE(model.find("HighLift.Mechanical.WingTipBrake Real_("), std::string::npos);
  EXPECT_NE(model.find("HighLift.Mechanical.LossyInertia shaft_1_m1("), std::string::npos);
  EXPECT_NE(model.find(" shaft_1_m1_2("), std::string::npos);
  EXPECT_NE(model.find("<li>shaft_1.m1 &rarr; shaft_1_m1_2</li>"), std::string::npos);
  EXPECT_EQ(CheckIssues(report), "");
}

// Item 6: a project name with accented letters keeps them as their base letters.
TEST(DriveSystemNames, ModelNameKeepsTheLettersOfTheProjectName) {
  Project project = SmallDrive();
  project.name = "Ünïcödé Rig";
  EXPECT_EQ(GenerateModelica(project, ModelicaExportOptions{}).model_name, "UnicodeRig");
  project.name = "Real";
  EXPECT_EQ(GenerateModelica(project, ModelicaExportOptions{}).model_name, "Real_");
}

// Item 4: the model documentation states the simulator's start in a sentence of its own, for
// every kind of start (the hydraulic example has no static equilibrium).
TEST(DriveSystemNames, DocumentationStatesTheStartInASentence) {
  for (const char* example : {"hydraulic_pdu_flaps.json", "a320_class_flaps.json"}) {
    const Project project = LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / example);
    ModelicaExportOptions options;
    options.start = [&project](const model::DriveModel& model) {
      return sim::ComputeStartValues(model.network, sim::DriveModel{model}.Options(project));
    };
    const ModelicaExportReport report = GenerateModelica(project, options);
    const std::string model = FileOf(report, report.model_file).content;
    EXPECT_EQ(model.find("in the no "), std::string::npos) << example;
    EXPECT_EQ(model.find("in the static"), std::string::npos) << example;
    EXPECT_NE(model.find("The model starts where <code>highlift simulate</code> starts, at rest (fixed start "
                         "values of one inertia per degree of freedom, initial equations on other flanges); the "
                         "simulator's start: " + report.start + "."),
              std::string::npos)
        << example << ": " << report.start;
  }
}

}  // namespace
}  // namespace highlift
