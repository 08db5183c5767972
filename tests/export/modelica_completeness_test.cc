// The completeness checker (CheckModelicaCompleteness) on small models, on the HighLift library,
// and on every export of the bundled examples and test projects: every scenario, both
// resolutions, with the simulator's start (as `highlift export` writes it) and without.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "export_test_util.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/project_io.h"
#include "highlift/export/modelica.h"
#include "highlift/export/modelica_check.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"

namespace highlift {
namespace {

using testing::ExportTestDir;
using testing::FileOf;
using testing::Flatten;

std::string Issues(const std::vector<ModelicaIssue>& issues) {
  std::string text;
  for (const auto& issue : issues) text += issue.ToString() + "\n";
  return text;
}

std::string CompletenessOf(const std::string& model) {
  return Issues(CheckModelicaCompleteness({{"M.mo", model}}, HighLiftLibraryFiles()));
}

TEST(ModelicaCompleteness, ParameterWithoutDefaultNeedsAModifier) {
  const std::string issues = CompletenessOf(
      "model M\n"
      "  Modelica.Mechanics.Rotational.Components.Inertia inertia;\n"
      "  Modelica.Mechanics.Rotational.Components.Inertia given(J=2);\n"
      "end M;\n");
  EXPECT_NE(issues.find("M.mo:2: instance 'inertia' (Modelica.Mechanics.Rotational.Components.Inertia) in 'M': "
                        "parameter 'J' has no value (no default in Modelica.Mechanics.Rotational.Components.Inertia "
                        "and no modifier): give it, e.g. inertia(J=...)"),
            std::string::npos)
      << issues;
  EXPECT_EQ(issues.find("'given'"), std::string::npos) << issues;
}

TEST(ModelicaCompleteness, ReadsTheRequiredParametersOfHighLiftClasses) {
  // TorqueLimiter declares tau1_ext, c1, ... with a start value only; J has a default.
  const std::string issues = CompletenessOf(
      "model M\n"
      "  HighLift.Mechanical.TorqueLimiter stl(tau1_ext=1, tau1_ret=1, tau2_ext=2, tau2_ret=2, c1=1, c2=1, c3=1);\n"
      "  Modelica.Mechanics.Rotational.Components.Fixed fixed;\n"
      "equation\n"
      "  connect(stl.flange_a, fixed.flange);\n"
      "end M;\n");
  EXPECT_NE(issues.find("parameter 'tauB_max' has no value"), std::string::npos) << issues;
  EXPECT_EQ(issues.find("'J'"), std::string::npos) << issues;
  EXPECT_EQ(issues.find("'tauB_lim'"), std::string::npos) << issues;  // = tauB_max
}

TEST(ModelicaCompleteness, GearWithElasticFalseNeedsNoStiffness) {
  // The regression of issue 18: c had only a start value and the export wrote none.
  const std::string issues = CompletenessOf(
      "model M\n"
      "  HighLift.Mechanical.BranchGearbox gearbox(ratio=2, J=0.1);\n"
      "  HighLift.Mechanical.GearedRotaryActuator gra(ratio=200, J_in=0.01);\n"
      "  HighLift.Mechanical.GeneralRotationalElement element(ratio=1, J=0.1, elastic=false);\n"
      "end M;\n");
  EXPECT_EQ(issues.find("parameter 'c'"), std::string::npos) << issues;
}

TEST(ModelicaCompleteness, ConditionalConnectorsFollowTheirSwitch) {
  const std::string issues = CompletenessOf(
      "model M\n"
      "  Modelica.Mechanics.Rotational.Components.IdealGear open(ratio=2, useSupport=true);\n"
      "  Modelica.Mechanics.Rotational.Components.IdealGear off(ratio=2);\n"
      "  Modelica.Mechanics.Rotational.Components.Fixed fixed;\n"
      "equation\n"
      "  connect(off.support, fixed.flange);\n"
      "end M;\n");
  EXPECT_NE(issues.find("M.mo:2: instance 'open' (Modelica.Mechanics.Rotational.Components.IdealGear) in 'M': "
                        "connector 'support' is enabled (useSupport) but not connected"),
            std::string::npos)
      << issues;
  EXPECT_NE(issues.find("M.mo:3: instance 'off' (Modelica.Mechanics.Rotational.Components.IdealGear) in 'M': "
                        "connector 'support' is connected but disabled (useSupport is false)"),
            std::string::npos)
      << issues;
}

TEST(ModelicaCompleteness, InputsMustBeConnected) {
  const std::string issues = CompletenessOf(
      "model M\n"
      "  Modelica.Mechanics.Rotational.Components.Brake brake(fn_max=10);\n"
      "  HighLift.Drives.PDU pdu(useStopInput=true);\n"
      "end M;\n");
  EXPECT_NE(issues.find("instance 'brake' (Modelica.Mechanics.Rotational.Components.Brake) in 'M': input "
                        "'f_normalized' is not connected: connect it to a signal source"),
            std::string::npos)
      << issues;
  EXPECT_NE(issues.find("instance 'pdu' (HighLift.Drives.PDU) in 'M': connector 'stop' is enabled (useStopInput) "
                        "but not connected"),
            std::string::npos)
      << issues;
}

TEST(ModelicaCompleteness, ASimulatedModelBindsItsOwnParameters) {
  const std::string issues = CompletenessOf(
      "model M\n"
      "  parameter Real k \"no value\";\n"
      "  parameter Real given = 1;\n"
      "end M;\n");
  EXPECT_NE(issues.find("M.mo:2: parameter 'k' of model 'M' has no value: give it a binding (= value)"),
            std::string::npos)
      << issues;
  EXPECT_EQ(issues.find("'given'"), std::string::npos) << issues;
}

TEST(ModelicaCompleteness, TheHighLiftLibraryIsComplete) {
  const auto library = HighLiftLibraryFiles();
  EXPECT_EQ(Issues(CheckModelicaCompleteness(library)), "");
}

// ---- Every export -------------------------------------------------------------------------------

std::vector<std::filesystem::path> ExportedProjects() {
  std::vector<std::filesystem::path> files;
  for (const auto& dir : {std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples", ExportTestDir()})
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// The simulator's start, as `highlift export` passes it.
ModelicaExportOptions WithSimulatorStart(const Project& project) {
  ModelicaExportOptions options;
  options.start = [&project](const model::DriveModel& model) {
    return sim::ComputeStartValues(model.network, sim::DriveModel{model}.Options(project));
  };
  return options;
}

void ExpectComplete(const ModelicaExportReport& report, const std::string& what) {
  EXPECT_EQ(Issues(CheckModelica(report.files)), "") << what;
  EXPECT_EQ(Issues(CheckModelicaCompleteness(report.files)), "") << what;
}

/// Calls `check(project, options, what)` for every example and test project, every scenario
/// (none for a project without), both resolutions of a drive system; `options` has scenario
/// and resolution set. Returns the number of exports.
int ForEveryExport(const std::function<void(const Project&, ModelicaExportOptions, const std::string&)>& check) {
  int exports = 0;
  for (const auto& file : ExportedProjects()) {
    const Project project = LoadProject(file);
    std::vector<std::string> scenarios;
    for (const auto& s : project.scenarios) scenarios.push_back(s.name);
    if (scenarios.empty()) scenarios.push_back("");
    const bool drive = !project.components.empty();
    for (const auto& scenario : scenarios) {
      for (auto resolution : {ModelResolution::kFull, ModelResolution::kReduced}) {
        if (!drive && resolution == ModelResolution::kReduced) continue;
        ModelicaExportOptions options;
        options.scenario = scenario;
        options.resolution = resolution;
        check(project, options, file.filename().string() + " '" + scenario + "' " + ToString(resolution));
        ++exports;
      }
    }
  }
  return exports;
}

TEST(ModelicaCompleteness, EveryExportOfEveryExampleAndScenarioIsComplete) {
  const int exports = ForEveryExport([](const Project& project, ModelicaExportOptions options, const std::string& what) {
    options.start = WithSimulatorStart(project).start;
    const ModelicaExportReport report = GenerateModelica(project, options);
    ExpectComplete(report, what);
    if (!project.components.empty()) {
      const std::string model = FileOf(report, report.model_file).content;
      EXPECT_NE(model.find("fixed=true"), std::string::npos) << what;
      EXPECT_NE(report.start, "rest") << what;
    }
  });
  EXPECT_GT(exports, 50);
}

// Issue 28, item 1 and "Done when": the other options on every export. --tables-in-file (the
// MSL tables read from HighLift/Models/<Model>.txt; a table parameter of any other class, such
// as the hydraulic PDU's Brake mu_pos, stays a modifier), with --start rest and a model name of
// our own, every example and scenario at both resolutions.
TEST(ModelicaCompleteness, EveryExportWithTablesInFileAndStartRestIsComplete) {
  int tables = 0;
  const int exports = ForEveryExport([&](const Project& project, ModelicaExportOptions options, const std::string& what) {
    const bool drive = !project.components.empty();
    options.tables_in_file = true;  // and no start: --start rest
    options.model_name = "Exported";
    const ModelicaExportReport report = GenerateModelica(project, options);
    ExpectComplete(report, what);
    const std::string model = Flatten(FileOf(report, report.model_file).content);
    if (drive) {  // element networks carry their own starts
      EXPECT_EQ(model.find("fixed=true"), std::string::npos) << what;
    }
    // Every table is read from the file, by the MSL table blocks only.
    for (std::size_t at = model.find("tableOnFile=true"); at != std::string::npos;
         at = model.find("tableOnFile=true", at + 1)) {
      const std::size_t line = model.rfind('\n', at) + 1;
      const std::string declaration = model.substr(line, at - line);
      EXPECT_TRUE(declaration.find("Modelica.Blocks.Sources.CombiTimeTable ") != std::string::npos ||
                  declaration.find("Modelica.Blocks.Tables.CombiTable1Ds ") != std::string::npos)
          << what << ": " << declaration;
      ++tables;
    }
    if (model.find("tableOnFile=true") != std::string::npos) {
      EXPECT_NE(FileOf(report, "HighLift/Models/Exported.txt").content.find("double "), std::string::npos) << what;
    }
    EXPECT_EQ(model.find("table=["), std::string::npos) << what;
  });
  EXPECT_GT(exports, 50);
  EXPECT_GT(tables, 100);
}

// Issue 28, item 1: the hydraulic PDU's pressure-off brakes keep their friction table.
TEST(ModelicaCompleteness, TablesInFileKeepTheBrakeFrictionTable) {
  const Project project = LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "hydraulic_pdu_flaps.json");
  ModelicaExportOptions options;
  options.tables_in_file = true;
  const ModelicaExportReport report = GenerateModelica(project, options);
  const std::string model = Flatten(FileOf(report, report.model_file).content);
  const std::regex brake(R"(Modelica\.Mechanics\.Rotational\.Components\.Brake (\w+)\(([^\n]*)\))");
  int brakes = 0;
  for (std::sregex_iterator it(model.begin(), model.end(), brake), end; it != end; ++it) {
    const std::string modifiers = (*it)[2];
    EXPECT_NE(modifiers.find("mu_pos=["), std::string::npos) << (*it)[1];
    EXPECT_EQ(modifiers.find("tableOnFile"), std::string::npos) << (*it)[1];
    ++brakes;
  }
  EXPECT_GT(brakes, 0);
  ExpectComplete(report, "hydraulic_pdu_flaps.json --tables-in-file");
}

// Issue 28, item 7: the library's examples give every mechanical degree of freedom a start, as
// the exported models do: an Inertia instance its phi and w start values with fixed=true,
// every other instance with an inertia inside (torque limiter, actuator, wing-tip brake) an
// initial equation on the angle and on the speed of its flange_a.
TEST(ModelicaLibraryExamples, EveryInertiaHasAStart) {
  std::map<std::string, std::string> text_of;
  for (const auto& f : HighLiftLibraryFiles()) text_of[f.path] = f.content;
  auto has_inertia = [&](std::string cls) {
    if (cls.rfind("HighLift.", 0) != 0) return false;
    std::replace(cls.begin(), cls.end(), '.', '/');
    const std::string& text = text_of[cls + ".mo"];
    return text.find("Modelica.Mechanics.Rotational.Components.Inertia ") != std::string::npos ||
           text.find("LossyInertia ") != std::string::npos;
  };
  int examples = 0, starts = 0;
  const std::regex declaration(R"(\n  ((?:Modelica|HighLift)\.[\w.]+) (\w+)(\(([^;]*?)\))?\s*(\n\s*"[^"]*")?\s*annotation)");
  for (const auto& [path, text] : text_of) {
    if (path.rfind("HighLift/Examples/", 0) != 0 || path.find("package.") != std::string::npos) continue;
    const std::string flat = Flatten(text);
    ++examples;
    for (std::sregex_iterator it(flat.begin(), flat.end(), declaration), end; it != end; ++it) {
      const std::string cls = (*it)[1], name = (*it)[2], modifiers = (*it)[4];
      if (cls == "Modelica.Mechanics.Rotational.Components.Inertia") {
        EXPECT_TRUE(std::regex_search(modifiers, std::regex(R"((^|[ ,])phi\(start=[^)]*fixed=true\))")))
            << path << ": " << name << "(" << modifiers << ")";
        EXPECT_TRUE(std::regex_search(modifiers, std::regex(R"((^|[ ,])w\(start=[^)]*fixed=true\))")))
            << path << ": " << name << "(" << modifiers << ")";
        ++starts;
      } else if (has_inertia(cls)) {
        EXPECT_NE(flat.find("\n  " + name + ".flange_a.phi = "), std::string::npos) << path << ": " << name;
        EXPECT_NE(flat.find("\n  der(" + name + ".flange_a.phi) = "), std::string::npos) << path << ": " << name;
        ++starts;
      }
    }
  }
  EXPECT_EQ(examples, 3);
  EXPECT_GE(starts, 5);
}

TEST(ModelicaCompleteness, StartRestWritesNoStartValues) {
  const Project project = LoadProject(ExportTestDir() / "small_drive.json");
  ModelicaExportOptions options;  // no start: --start rest
  const ModelicaExportReport report = GenerateModelica(project, options);
  ExpectComplete(report, "rest");
  const std::string model = FileOf(report, report.model_file).content;
  EXPECT_EQ(model.find("fixed=true"), std::string::npos);
  EXPECT_EQ(model.find("initial equation"), std::string::npos);
  EXPECT_EQ(report.start, "rest");
  EXPECT_NE(model.find("The model starts at rest with untwisted springs"), std::string::npos);
}

// ---- The start: where the simulator starts --------------------------------------------------------

// "name(phi(start=v, fixed=true), w(start=u, fixed=true))" -> name -> {v, u}.
std::map<std::string, std::pair<double, double>> FixedInertiaStarts(const std::string& model) {
  std::map<std::string, std::pair<double, double>> out;
  const std::regex pattern(
      R"(Inertia (\w+)\([^\n]*phi\(start=([-+0-9.e]+), fixed=true\), w\(start=([-+0-9.e]+), fixed=true\))");
  for (std::sregex_iterator it(model.begin(), model.end(), pattern), end; it != end; ++it)
    out[(*it)[1]] = {std::stod((*it)[2]), std::stod((*it)[3])};
  return out;
}

TEST(ModelicaStart, TwistsBetweenFixedInertiasAreTheSimulatorsStartTwists) {
  const auto file = std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a320_class_flaps.json";
  const Project project = LoadProject(file);
  ModelicaExportOptions options = WithSimulatorStart(project);
  options.scenario = "rupture_wtb";
  const ModelicaExportReport report = GenerateModelica(project, options);
  const std::string model = Flatten(FileOf(report, report.model_file).content);
  EXPECT_NE(report.start.find("static equilibrium"), std::string::npos) << report.start;
  const auto starts = FixedInertiaStarts(model);
  ASSERT_GT(starts.size(), 10u);

  // The simulator's first row: the twist of every shaft spring-damper.
  sim::DriveNetworkOptions drive;
  drive.scenario = "rupture_wtb";
  const sim::DriveModel dm = sim::BuildDriveNetwork(project, drive);
  sim::Simulator simulator(dm.network);
  sim::MemorySink sink;
  sim::SimulationOptions run = dm.Options(project);
  run.stop_time = run.output_interval;
  ASSERT_TRUE(simulator.Run(run, sink).ok());
  int compared = 0;
  double largest = 0.0;
  for (const auto& e : dm.network.elements()) {
    if (e.type != "SpringDamper") continue;
    // Its flanges: the inertias it connects, when both are fixed in the export.
    std::string a, b;
    for (const auto& c : dm.network.connections())
      for (const auto& [mine, other] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
        if (mine.component != e.id) continue;
        const auto* o = dm.network.Find(other.component);
        if (o == nullptr || o->type != "Inertia") continue;
        (mine.port == "flange_a" ? a : b) = other.component;
      }
    auto name = [](std::string id) {
      std::replace(id.begin(), id.end(), '.', '_');
      return id;
    };
    if (a.empty() || b.empty() || !starts.count(name(a)) || !starts.count(name(b))) continue;
    const double twist = starts.at(name(b)).first - starts.at(name(a)).first;
    const double simulated = sink.rows().front()[sink.Column(e.id + ".phi_rel")];
    largest = std::max(largest, std::abs(simulated));
    EXPECT_NEAR(twist, simulated, 1e-12 + 1e-9 * std::abs(simulated)) << e.id;
    EXPECT_EQ(starts.at(name(a)).second, 0.0) << a;  // parked
    ++compared;
  }
  EXPECT_GT(compared, 10);
  EXPECT_GT(largest, 1e-6);  // the airloads twist the shafts: the start is not the untwisted rest
}

TEST(ModelicaStart, OneStartPerDegreeOfFreedomAndNoneUnreached) {
  const Project project = LoadProject(ExportTestDir() / "small_drive.json");
  for (const auto& scenario : {"rupture_wtb", "jam_gra_1"}) {
    sim::DriveNetworkOptions drive;
    drive.scenario = scenario;
    const sim::DriveModel dm = sim::BuildDriveNetwork(project, drive);
    const model::StartValues start = sim::ComputeStartValues(dm.network, dm.Options(project));
    EXPECT_TRUE(start.unreached.empty()) << scenario;
    EXPECT_LT(start.inconsistency, 1e-9) << scenario;
    // Every inertia of the drive is a body of its own (spring-dampers between them), except
    // the ones a gear ties to another: at most one start per inertia, at least one.
    int inertias = 0;
    for (const auto& e : dm.network.elements()) inertias += e.type == "Inertia";
    EXPECT_GT(static_cast<int>(start.flanges.size()), 0) << scenario;
    EXPECT_LE(static_cast<int>(start.flanges.size()), inertias + 40) << scenario;
    for (const auto& f : start.flanges) {
      ASSERT_TRUE(f.phi.has_value() && f.w.has_value()) << f.flange.ToString();
      EXPECT_EQ(*f.w, 0.0) << f.flange.ToString();
    }
  }
}

// ---- Packaging and numbers ------------------------------------------------------------------------

TEST(ModelicaPackaging, TheModelIsAClassOfHighLiftModels) {
  const Project project = LoadProject(ExportTestDir() / "small_drive.json");
  ModelicaExportOptions options;
  options.model_name = "Rig";
  const ModelicaExportReport report = GenerateModelica(project, options);
  EXPECT_EQ(report.model_path, "HighLift.Models.Rig");
  EXPECT_EQ(report.model_file, "HighLift/Models/Rig.mo");
  EXPECT_EQ(FileOf(report, report.model_file).content.rfind("within HighLift.Models;\nmodel Rig", 0), 0u);
  EXPECT_NE(FileOf(report, "HighLift/package.order").content.find("\nModels\n"), std::string::npos);
  EXPECT_EQ(FileOf(report, "HighLift/Models/package.order").content, "Rig\n");
  // One top-level class: every file is below HighLift/.
  for (const auto& f : report.files) EXPECT_EQ(f.path.rfind("HighLift/", 0), 0u) << f.path;
  EXPECT_EQ(Issues(CheckModelica(report.files)), "");
}

TEST(ModelicaNumbers, DecimalDataPrintsAsItsDecimal) {
  EXPECT_EQ(FormatModelicaReal(0.034999999999999996), "0.035");
  EXPECT_EQ(FormatModelicaReal(0.15000000000000002), "0.15");
  EXPECT_EQ(FormatModelicaReal(1.6500000000000001), "1.65");
  EXPECT_EQ(FormatModelicaReal(0.07 * 0.5), "0.035");
  // Values whose 15-digit text is further than 2 ulp away keep their round-trip digits.
  EXPECT_EQ(std::stod(FormatModelicaReal(1.0 / 3.0)), 1.0 / 3.0);
  EXPECT_EQ(std::stod(FormatModelicaReal(15.915494309189533)), 15.915494309189533);
  for (double v : {0.035, 1e-7 * 3, 123456.789, 2.2250738585072014e-308}) {
    const double back = std::stod(FormatModelicaReal(v));
    EXPECT_LE(std::abs(back - v), 2 * (std::nextafter(std::abs(v), HUGE_VAL) - std::abs(v))) << v;
  }
}

// ---- The hydraulic PDU's brakes hold brake_torque at the output -------------------------------------

TEST(HydraulicPduBrakes, TogetherTheyHoldBrakeTorqueAtTheOutput) {
  const auto file = std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "hydraulic_pdu_flaps.json";
  const Project project = LoadProject(file);
  const Component* pdu = nullptr;
  for (const auto& c : project.components)
    if (c.type == "pdu") pdu = &c;
  ASSERT_NE(pdu, nullptr);
  sim::DriveNetworkOptions drive;
  drive.scenario = "rupture_wtb";
  const sim::DriveModel dm = sim::BuildDriveNetwork(project, drive);
  const auto* gear = dm.network.Find(pdu->id + ".gear");
  ASSERT_NE(gear, nullptr);
  const double ratio = gear->parameters.scalars.at("ratio");
  double holding = 0.0;  // at the output: each motor carries 1/n of the gear input torque
  int brakes = 0;
  for (const auto& e : dm.network.elements())
    if (e.type == "Brake" && e.id.rfind(pdu->id + ".pob", 0) == 0) {
      const double at_motor = e.parameters.scalars.at("cgeo") * 0.5 * e.parameters.scalars.at("fn_max");
      holding = at_motor;
      ++brakes;
    }
  ASSERT_GT(brakes, 0);
  double brake_torque = 0.0;
  if (auto it = pdu->parameters.find("brake_torque"); it != pdu->parameters.end() && it->second.nominal)
    brake_torque = *it->second.nominal;
  else
    brake_torque = *FindComponentType("pdu")->FindParameter("brake_torque")->nominal;
  const int motors = dm.network.Find(pdu->id + ".differential") != nullptr ? 2 : 1;
  EXPECT_NEAR(holding * motors * ratio, brake_torque, 1e-9 * brake_torque);
}

}  // namespace
}  // namespace highlift
