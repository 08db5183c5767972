// Element networks export to models that use the MSL classes directly, with the MSL example's
// instance names and parameters (golden files), deterministically.
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "common/shared_reference.h"
#include "export_test_util.h"
#include "highlift/core/error.h"

namespace highlift {
namespace {

using testing::CheckIssues;
using testing::ExpectGolden;
using testing::ExportTestDir;
using testing::FileOf;

ModelicaExportReport ExportFile(const std::string& name) {
  return GenerateModelica(LoadProject(ExportTestDir() / name), ModelicaExportOptions{});
}

TEST(ElementNetworkExport, FirstMatchesGolden) {
  const auto report = ExportFile("first.json");
  EXPECT_EQ(report.model_name, "First");
  EXPECT_EQ(report.kind, "element network");
  EXPECT_EQ(report.component_count, 9);
  EXPECT_EQ(report.connection_count, 10);
  ExpectGolden("First.mo", FileOf(report, "HighLift/Models/First.mo").content);
  EXPECT_EQ(CheckIssues(report), "");
}

TEST(ElementNetworkExport, FrictionMatchesGolden) {
  const auto report = ExportFile("friction.json");
  ExpectGolden("Friction.mo", FileOf(report, "HighLift/Models/Friction.mo").content);
  EXPECT_EQ(CheckIssues(report), "");
  const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/Friction.mo").content);
  // Supports connected to the ground switch useSupport on; start values are fixed.
  EXPECT_NE(text.find("Modelica.Mechanics.Rotational.Components.Brake brake(fn_max=1600, useSupport=true)"),
            std::string::npos);
  EXPECT_NE(text.find("inertia3(J=1, phi(start=0, fixed=true), w(start=100, fixed=true))"), std::string::npos);
  EXPECT_NE(text.find("experiment(StopTime=3, Tolerance=1e-06, Interval=0.001)"), std::string::npos);
}

// The model declares every instance the MSL reference results name, so a Modelica tool's
// output columns match the reference CSV headers.
TEST(ElementNetworkExport, InstanceNamesCoverTheReferenceColumns) {
  HIGHLIFT_REQUIRE_SHARED(msl, "msl");
  for (const std::string example : {"First", "Friction"}) {
    std::ifstream csv(msl / (example + ".csv"));
    std::string header;
    std::getline(csv, header);
    ASSERT_FALSE(header.empty()) << example;
    const auto report = ExportFile(example == "First" ? "first.json" : "friction.json");
    const std::string& text = FileOf(report, "HighLift/Models/" + example + ".mo").content;
    std::size_t pos = 0;
    int columns = 0;
    while ((pos = header.find('"', pos)) != std::string::npos) {
      const auto end = header.find('"', pos + 1);
      const std::string column = header.substr(pos + 1, end - pos - 1);
      pos = end + 1;
      if (column == "time") continue;
      const std::string instance = column.substr(0, column.find('.'));
      EXPECT_NE(text.find(" " + instance + "("), std::string::npos)
          << example << ": column " << column << " names no instance of the model";
      ++columns;
    }
    EXPECT_GT(columns, 3) << example;
  }
}

TEST(ElementNetworkExport, OutputIsDeterministic) {
  const auto a = ExportFile("friction.json");
  const auto b = ExportFile("friction.json");
  ASSERT_EQ(a.files.size(), b.files.size());
  for (std::size_t i = 0; i < a.files.size(); ++i) {
    EXPECT_EQ(a.files[i].path, b.files[i].path);
    EXPECT_EQ(a.files[i].content, b.files[i].content) << a.files[i].path;
  }
}

Component Element(std::string id, std::string type) {
  Component c;
  c.id = std::move(id);
  c.type = std::move(type);
  return c;
}

Parameter Given(double v) {
  Parameter p;
  p.nominal = v;
  p.domain = Domain::Point(v);
  p.provenance = Provenance::kUser;
  return p;
}

TEST(ElementNetworkExport, KeywordNamesAreRenamedAndDocumented) {
  Project project;
  project.name = "keyword \"test\" <net>";
  project.elements.push_back(Element("fixed", "Fixed"));
  Component end = Element("end", "Inertia");
  end.parameters["J"] = Given(1);
  project.elements.push_back(end);
  Component time = Element("time", "Spring");
  time.parameters["c"] = Given(100);
  project.elements.push_back(time);
  project.element_connections.push_back({{"fixed", "flange"}, {"time", "flange_a"}, {}});
  project.element_connections.push_back({{"time", "flange_b"}, {"end", "flange_a"}, {}});
  const auto report = GenerateModelica(project, ModelicaExportOptions{});
  EXPECT_EQ(report.model_name, "KeywordTestNet");
  EXPECT_EQ(report.renamed.at("end"), "end_");
  EXPECT_EQ(report.renamed.at("time"), "time_2");
  const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/KeywordTestNet.mo").content);
  EXPECT_NE(text.find("model KeywordTestNet \"keyword \\\"test\\\" <net>\""), std::string::npos) << text;
  EXPECT_NE(text.find("connect(time_2.flange_b, end_.flange_a)"), std::string::npos) << text;
  EXPECT_NE(text.find("keyword \\\"test\\\" &lt;net&gt;"), std::string::npos) << text;
  EXPECT_EQ(CheckIssues(report), "");
}

// Issue 27, item 20: an element id that is a predefined type name is renamed; an id that is
// an identifier keeps it, whatever the order, and the other takes the next name, reported.
TEST(ElementNetworkExport, ReservedNamesAndClashesAreRenamedAndReported) {
  Project project;
  project.name = "names";
  project.elements.push_back(Element("fixed", "Fixed"));
  Component inertia = Element("inertia-1", "Inertia");
  inertia.parameters["J"] = Given(1);
  project.elements.push_back(inertia);
  Component spring = Element("inertia_1", "Spring");  // the sanitised name of the one before
  spring.parameters["c"] = Given(100);
  project.elements.push_back(spring);
  Component real = Element("Real", "Inertia");
  real.parameters["J"] = Given(2);
  project.elements.push_back(real);
  project.element_connections.push_back({{"fixed", "flange"}, {"inertia_1", "flange_a"}, {}});
  project.element_connections.push_back({{"inertia_1", "flange_b"}, {"inertia-1", "flange_a"}, {}});
  project.element_connections.push_back({{"inertia-1", "flange_b"}, {"Real", "flange_a"}, {}});
  const auto report = GenerateModelica(project, ModelicaExportOptions{});
  EXPECT_EQ(report.renamed.at("Real"), "Real_");
  EXPECT_EQ(report.renamed.at("inertia-1"), "inertia_1_2");
  EXPECT_EQ(report.renamed.count("inertia_1"), 0u);
  const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/Names.mo").content);
  EXPECT_NE(text.find("Modelica.Mechanics.Rotational.Components.Spring inertia_1(c=100)"), std::string::npos) << text;
  EXPECT_NE(text.find("Modelica.Mechanics.Rotational.Components.Inertia Real_(J=2)"), std::string::npos) << text;
  EXPECT_NE(text.find("connect(inertia_1_2.flange_b, Real_.flange_a)"), std::string::npos) << text;
  EXPECT_EQ(CheckIssues(report), "");
}

// Issue 28, item 2: MSL 4.0.0 has no Sources.InverseSpeedDependentTorque (4.1.0 has): the
// element type exports as the HighLift class of that name, and the checker knows the MSL
// class is not in 4.0.0.
TEST(ElementNetworkExport, InverseSpeedDependentTorqueIsTheHighLiftClass) {
  const Project project =
      LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "tests" / "sim" / "msl" / "InverseSpeedDependentTorque.json");
  const auto report = GenerateModelica(project, ModelicaExportOptions{});
  const std::string text = FileOf(report, report.model_file).content;
  EXPECT_NE(text.find("HighLift.Sources.InverseSpeedDependentTorque "), std::string::npos) << text;
  EXPECT_EQ(text.find("Modelica.Mechanics.Rotational.Sources.InverseSpeedDependentTorque"), std::string::npos);
  EXPECT_EQ(CheckIssues(report), "");
  std::string completeness;
  for (const auto& issue : CheckModelicaCompleteness(report.files)) completeness += issue.ToString() + "\n";
  EXPECT_EQ(completeness, "");
  std::string issues;
  for (const auto& issue : CheckModelica({{"M.mo",
                                           "model M\n"
                                           "  Modelica.Mechanics.Rotational.Sources.InverseSpeedDependentTorque t(\n"
                                           "    tau_nominal=1, w_nominal=1);\n"
                                           "end M;\n"}}))
    issues += issue.ToString() + "\n";
  EXPECT_NE(issues.find("Modelica.Mechanics.Rotational.Sources.InverseSpeedDependentTorque"), std::string::npos)
      << issues;
}

TEST(ElementNetworkExport, UnknownElementTypeIsAnInputError) {
  Project project;
  project.name = "bad";
  project.elements.push_back(Element("w", "Flywheel"));
  try {
    GenerateModelica(project, ModelicaExportOptions{});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element 'w': element type 'Flywheel' has no Modelica class"),
              std::string::npos)
        << e.what();
  }
}

TEST(ElementNetworkExport, EmptyProjectIsAnInputError) {
  Project project;
  project.name = "empty";
  try {
    GenerateModelica(project, ModelicaExportOptions{});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has neither components nor elements"), std::string::npos);
  }
}

}  // namespace
}  // namespace highlift

namespace highlift {
namespace {

// Every element type of the catalogue (core/src/element_types.cc) maps to a class of the MSL
// list, and every parameter it declares becomes a modifier (or an initial equation) that the
// MSL 4.0.0 class accepts: the element catalogue and the exporter's list stay in step.
TEST(ElementNetworkExport, EveryElementTypeExportsToKnownClassesAndModifiers) {
  Project project;
  project.name = "all element types";
  int n = 0;
  for (const ComponentTypeSpec& type : ElementTypes()) {
    Component c;
    c.id = "e" + std::to_string(n++);
    c.type = type.name;
    for (const ParameterSpec& p : type.parameters) {
      if (p.kind == ParameterKind::kTable) {
        c.tables[p.name] = {{0, 1}};
      } else if (p.kind != ParameterKind::kText) {
        c.parameters[p.name] = Given(p.name == "useHeatPort" ? 1.0 : p.nominal.value_or(1.0));
      }
    }
    project.elements.push_back(c);
  }
  ASSERT_GT(n, 20);
  const auto report = GenerateModelica(project, ModelicaExportOptions{});
  EXPECT_EQ(CheckIssues(report), "");
  EXPECT_EQ(report.component_count, n + 1);  // plus the heat capacitor of the eddy current brake
  const std::string text = FileOf(report, "HighLift/Models/AllElementTypes.mo").content;
  EXPECT_NE(text.find("initial equation"), std::string::npos);  // Spring's w_rel_start
  EXPECT_NE(text.find("Modelica.Thermal.HeatTransfer.Components.HeatCapacitor"), std::string::npos);
}

}  // namespace
}  // namespace highlift

namespace highlift {
namespace {

// The PDU's shutdown input is enabled by its connection (the simulator has no switch for it):
// the export writes useStopInput = true when `stop` is connected, and the monitor's Boolean
// brake command connects to the Boolean input.
TEST(ElementNetworkExport, ConnectedPduStopInputIsSwitchedOn) {
  const Project project = ParseProject(R"({
    "format": "highlift-project/1",
    "name": "shutdown",
    "elements": [
      {"id": "command", "type": "Constant", "parameters": {"k": 10}},
      {"id": "pdu", "type": "PDU"},
      {"id": "spare", "type": "PDU"},
      {"id": "load", "type": "Inertia", "parameters": {"J": 1}},
      {"id": "spare_load", "type": "Inertia", "parameters": {"J": 1}},
      {"id": "monitor", "type": "Monitoring"}
    ],
    "element_connections": [
      ["command.y", "pdu.w_ref"], ["command.y", "spare.w_ref"],
      ["pdu.flange_left", "load.flange_a"], ["spare.flange_left", "spare_load.flange_a"],
      ["pdu.phi", "monitor.phi_left"], ["pdu.phi", "monitor.phi_right"], ["pdu.phi", "monitor.phi_pdu"],
      ["pdu.phi", "monitor.phi_cmd"], ["pdu.w", "monitor.w_left"], ["pdu.w", "monitor.w_right"],
      ["monitor.wtb", "pdu.stop"]
    ]
  })");
  const auto report = GenerateModelica(project, ModelicaExportOptions{});
  EXPECT_EQ(CheckIssues(report), "");
  const std::string text = testing::Flatten(FileOf(report, "HighLift/Models/Shutdown.mo").content);
  EXPECT_NE(text.find("HighLift.Drives.PDU pdu(useStopInput=true)"), std::string::npos) << text;
  EXPECT_NE(text.find("HighLift.Drives.PDU spare\n"), std::string::npos) << text;
  EXPECT_NE(text.find("connect(monitor.wtb, pdu.stop)"), std::string::npos);
}

}  // namespace
}  // namespace highlift
