// The report's Synthesis section (`highlift report --optimize RESULT.json`): its data is the
// result of a real optimize run on a small design problem (tests/report/data/one_station_design.json:
// a one-station rig whose two inboard shafts are the design) with a Pareto front; a result of another project, malformed JSON and a document
// that is not optimize's are refused with messages that name the file, the JSON path and the remedy.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "common/run_cli.h"
#include "highlift/campaign/campaign.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/optimize/optimize.h"
#include "highlift/report/report.h"

namespace highlift::report {
namespace {

const std::string kProjectFile = std::string(HIGHLIFT_SOURCE_DIR) + "/tests/report/data/one_station_design.json";

std::filesystem::path Dir() {
  const auto dir = std::filesystem::path(HIGHLIFT_BINARY_DIR) / "tests" / "report" / "synthesis";
  std::filesystem::create_directories(dir);
  return dir;
}

/// The document `highlift optimize --json` prints, from the API (the CLI adds the same keys).
nlohmann::json ResultDocument(const Project& project, const optimize::Report& r) {
  nlohmann::json j = r.ToJson();
  j["project"] = project.file;
  j["project_name"] = project.name;
  j["project_hash"] = campaign::ProjectHash(project);
  return j;
}

/// Without peak: the rig's actuator back-drives after the tip-brake rupture at every design.
optimize::Options Options() {
  optimize::Options o;
  o.verify_peak = false;
  return o;
}

optimize::Report ParetoRun(const Project& project) {
  optimize::Options o = Options();
  o.pareto = "shaft_1.outer_diameter";
  o.pareto_points = 4;
  return optimize::Optimize(project, o);
}

std::string MessageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(ReportSynthesis, SectionDataIsTheOptimizeResultWithItsParetoFront) {
  const Project project = LoadProject(kProjectFile);
  const optimize::Report r = ParetoRun(project);
  ASSERT_TRUE(r.found) << r.FullReport();
  ASSERT_GE(r.pareto.size(), 3u) << r.FullReport();
  const nlohmann::json s = SynthesisJson(project, ResultDocument(project, r), "result.json");

  EXPECT_EQ(s["relation"], "project");
  EXPECT_EQ(s["status"], optimize::ToString(r.status));
  EXPECT_EQ(s["found"], true);
  EXPECT_NE(s["status_words"].get<std::string>().find("certified"), std::string::npos) << s["status_words"];
  EXPECT_EQ(s["objective"], "mass");
  EXPECT_EQ(s["objective_unit"], "kg");
  EXPECT_DOUBLE_EQ(s["best"].get<double>(), r.best);
  EXPECT_DOUBLE_EQ(s["lower_bound"].get<double>(), r.lower_bound);
  EXPECT_LE(s["lower_bound"].get<double>(), s["best"].get<double>());
  EXPECT_DOUBLE_EQ(s["gap"].get<double>(), r.gap);
  // The design table: variable, component (for the link), optimised value, domain, at bound.
  ASSERT_EQ(s["design"].size(), r.design.size());
  for (std::size_t i = 0; i < r.design.size(); ++i) {
    EXPECT_EQ(s["design"][i]["name"], r.design[i].name);
    EXPECT_EQ(s["design"][i]["component"], r.design[i].name.substr(0, 7));  // shaft_1 or shaft_2
    EXPECT_DOUBLE_EQ(s["design"][i]["value"].get<double>(), r.design[i].value);
    EXPECT_DOUBLE_EQ(s["design"][i]["lower"].get<double>(), r.design[i].lower);
    EXPECT_DOUBLE_EQ(s["design"][i]["upper"].get<double>(), r.design[i].upper);
    EXPECT_EQ(s["design"][i]["at_bound"], r.design[i].at_bound);
  }
  ASSERT_EQ(s["active_constraints"].size(), r.active.size());
  for (std::size_t i = 0; i < r.active.size(); ++i) EXPECT_EQ(s["active_constraints"][i]["label"], r.active[i].label);
  ASSERT_EQ(s["mass_terms"].size(), r.mass_terms.size());
  ASSERT_FALSE(r.mass_terms.empty());
  EXPECT_EQ(s["mass_terms"][0]["component"], r.mass_terms[0].component);
  EXPECT_EQ(s["mass_terms"][0]["law"], r.mass_terms[0].law);
  // The front: every point with its design as rows carrying their units.
  ASSERT_TRUE(s["pareto"].is_object());
  EXPECT_EQ(s["pareto"]["objectives"], nlohmann::json({"mass", "shaft_1.outer_diameter"}));
  EXPECT_EQ(s["pareto"]["units"], nlohmann::json({"kg", "mm"}));
  ASSERT_EQ(s["pareto"]["front"].size(), r.pareto.size());
  for (std::size_t i = 0; i < r.pareto.size(); ++i) {
    const nlohmann::json& p = s["pareto"]["front"][i];
    EXPECT_DOUBLE_EQ(p["objective"].get<double>(), r.pareto[i].objective);
    EXPECT_DOUBLE_EQ(p["second"].get<double>(), r.pareto[i].second);
    EXPECT_DOUBLE_EQ(p["epsilon"].get<double>(), r.pareto[i].epsilon);
    ASSERT_EQ(p["design"].size(), r.design.size()) << p.dump();
    for (const auto& d : p["design"]) EXPECT_EQ(d["unit"], "mm") << d.dump();  // diameters and walls
  }
}

// --tube-sizes: the section names the table and each shaft's size, as optimize's report does.
TEST(ReportSynthesis, TubeSizesOfTheResultAreShown) {
  const Project project = LoadProject(kProjectFile);
  optimize::Options o = Options();
  o.tube_sizes = componentdb::StandardTubeSizes();
  const optimize::Report r = optimize::Optimize(project, o);
  ASSERT_TRUE(r.found) << r.FullReport();
  ASSERT_FALSE(r.tube_sizes.empty());
  const nlohmann::json s = SynthesisJson(project, ResultDocument(project, r), "result.json");
  EXPECT_EQ(s["tube_sizes"]["table"], "standard");
  for (const auto& [shaft, size] : r.tube_sizes) {
    EXPECT_FALSE(size.empty()) << shaft;
    EXPECT_EQ(s["tube_sizes"]["shafts"][shaft], size);
  }
  // Without --tube-sizes: an empty object.
  const nlohmann::json plain = SynthesisJson(project, ResultDocument(project, optimize::Optimize(project, Options())), "r.json");
  EXPECT_TRUE(plain["tube_sizes"].empty());
}

TEST(ReportSynthesis, ReportCarriesTheSectionAndThePageEscapesIt) {
  const Project project = LoadProject(kProjectFile);
  const optimize::Report r = ParetoRun(project);
  nlohmann::json doc = ResultDocument(project, r);
  doc["message"] = "</script><script>alert(1)</script>";  // text of the file never ends the data island
  const auto file = Dir() / "pareto.json";
  std::ofstream(file) << doc.dump(2);
  ReportOptions options;
  options.transient = false;
  options.scenarios = false;
  options.optimize = file;
  const DesignReport report = BuildDesignReport(project, project, "", options);
  ASSERT_TRUE(report.data["synthesis"].is_object());
  EXPECT_TRUE(report.synthesis_ok);
  EXPECT_EQ(report.data["synthesis"]["pareto"]["front"].size(), r.pareto.size());
  EXPECT_NE(report.BriefReport().find("synthesis: " + optimize::ToString(r.status)), std::string::npos);
  const std::string html = RenderHtml(report);
  EXPECT_NE(html.find("\"synthesis\":{"), std::string::npos);
  EXPECT_EQ(html.find("</script><script>alert"), std::string::npos);
  EXPECT_NE(html.find("id=\"synthesis\""), std::string::npos);

  // Without --optimize the section's data is null (the page says how to add it).
  options.optimize.clear();
  EXPECT_TRUE(BuildDesignReport(project, project, "", options).data["synthesis"].is_null());
}

// A proved-infeasible result is shown (status, explanation) and is not ok: `report` exits 1.
TEST(ReportSynthesis, ResultWithoutADesignIsShownAndNotOk) {
  Project project = LoadProject(kProjectFile);
  project.requirements[0].expression = "shaft_1.torque_capacity >= 1e9 N*m";
  const optimize::Report r = ParetoRun(project);
  ASSERT_EQ(r.status, optimize::Status::kInfeasible) << r.BriefReport();
  const auto file = Dir() / "infeasible.json";
  std::ofstream(file) << ResultDocument(project, r).dump(2);
  ReportOptions options;
  options.transient = false;
  options.scenarios = false;
  options.optimize = file;
  const DesignReport report = BuildDesignReport(project, project, "", options);
  EXPECT_FALSE(report.synthesis_ok);
  const nlohmann::json& s = report.data["synthesis"];
  EXPECT_EQ(s["status"], "infeasible");
  EXPECT_EQ(s["found"], false);
  EXPECT_TRUE(s["best"].is_null());
  EXPECT_NE(s["status_words"].get<std::string>().find("proved infeasible"), std::string::npos);
  EXPECT_NE(s["explanation"].get<std::string>().find("capacity_1"), std::string::npos) << s["explanation"];
  EXPECT_TRUE(s["design"].empty());
}

TEST(ReportSynthesis, ResultOfTheWrittenDesignIsAcceptedForIt) {
  const Project project = LoadProject(kProjectFile);
  const optimize::Report r = optimize::Optimize(project, Options());
  ASSERT_TRUE(r.found);
  nlohmann::json doc = ResultDocument(project, r);
  std::vector<std::pair<std::string, double>> values;
  for (const auto& d : r.design) values.push_back({d.name, d.value_si});
  const Project design = optimize::FixDesign(project, values);
  doc["design_hash"] = campaign::ProjectHash(design);
  EXPECT_EQ(SynthesisJson(design, doc, "result.json")["relation"], "design");
  EXPECT_EQ(SynthesisJson(project, doc, "result.json")["relation"], "project");
}

TEST(ReportSynthesis, ResultOfAnotherProjectIsRefusedNamingBoth) {
  const Project project = LoadProject(kProjectFile);
  const nlohmann::json doc = ResultDocument(project, optimize::Optimize(project, Options()));
  Project changed = project;
  changed.name = "one station, edited";
  changed.requirements[0].expression = "shaft_1.torque_capacity >= 2500 N*m";
  const std::string m = MessageOf([&] { SynthesisJson(changed, doc, "result.json"); });
  EXPECT_NE(m.find("--optimize result.json: /project_hash: the result is of project 'one-station design problem' (content hash " +
                   doc["project_hash"].get<std::string>() + ")"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("holds 'one station, edited'"), std::string::npos) << m;
  EXPECT_NE(m.find("valid are the project optimize read, unchanged, and the design its --write wrote"), std::string::npos) << m;
  EXPECT_NE(m.find("run `highlift optimize"), std::string::npos) << m;
}

TEST(ReportSynthesis, MalformedResultsAreRefusedWithTheJsonPath) {
  const Project project = LoadProject(kProjectFile);
  const nlohmann::json good = ResultDocument(project, optimize::Optimize(project, Options()));
  const std::string remedy = "give the document `highlift optimize PROJECT --json` prints, saved with `> FILE`";

  const auto broken = Dir() / "broken.json";
  std::ofstream(broken) << "{\"status\": \"optimal\", ";
  std::string m = MessageOf([&] { ReadSynthesis(project, broken); });
  EXPECT_NE(m.find("--optimize " + broken.string() + ": not JSON ("), std::string::npos) << m;
  EXPECT_NE(m.find(remedy), std::string::npos) << m;

  m = MessageOf([&] { ReadSynthesis(project, Dir() / "no-such-result.json"); });
  EXPECT_NE(m.find("no-such-result.json: cannot read the file (no such file)"), std::string::npos) << m;

  m = MessageOf([&] { SynthesisJson(project, nlohmann::json::array({1, 2}), "r.json"); });
  EXPECT_NE(m.find("--optimize r.json: the document: expected a JSON object, found array [1,2]"), std::string::npos) << m;

  nlohmann::json no_hash = good;
  no_hash.erase("project_hash");
  m = MessageOf([&] { SynthesisJson(project, no_hash, "r.json"); });
  EXPECT_NE(m.find("--optimize r.json: /project_hash: missing; " + remedy), std::string::npos) << m;

  nlohmann::json bad_value = good;
  bad_value["design"][1]["value"] = "thick";
  m = MessageOf([&] { SynthesisJson(project, bad_value, "r.json"); });
  EXPECT_NE(m.find("--optimize r.json: /design/1/value: expected a number, found string \"thick\"; " + remedy),
            std::string::npos)
      << m;

  nlohmann::json bad_status = good;
  bad_status["status"] = "great";
  m = MessageOf([&] { SynthesisJson(project, bad_status, "r.json"); });
  EXPECT_NE(m.find("/status: 'great' is no status of optimize (optimal, stopped_at_limit, infeasible, no_design_found)"),
            std::string::npos)
      << m;

  nlohmann::json bad_name = good;
  bad_name["design"][0]["name"] = "shaft_9.outer_diameter";
  m = MessageOf([&] { SynthesisJson(project, bad_name, "r.json"); });
  EXPECT_NE(m.find("/design/0/name: 'shaft_9.outer_diameter' is no parameter of"), std::string::npos) << m;

  nlohmann::json bad_front = ResultDocument(project, ParetoRun(project));
  bad_front["pareto"]["front"][0]["design"] = {{"nope.x", 1.0}};
  m = MessageOf([&] { SynthesisJson(project, bad_front, "r.json"); });
  EXPECT_NE(m.find("/pareto/front/0/design/nope.x: 'nope.x' is none of the result's design variables"), std::string::npos)
      << m;
}

// The command line: `optimize --json > FILE` then `report --optimize FILE`, on the project and on
// the design optimize wrote; another project's report refuses the file (exit 2, nothing written).
TEST(ReportCommand, OptimizeResultIsShownAndAnotherProjectsIsRefused) {
  const auto dir = Dir();
  const auto best = dir / "best.json", result = dir / "cli_result.json", out = dir / "cli_report.html";
  std::filesystem::remove(best);
  std::filesystem::remove(out);
  // --no-estimate: the estimator gives each shaft's stiffness a domain of its own (from the nominal
  // geometry), which no design variable reaches, so optimize would find no design. --gap 1e-3:
  // with the tubes' torsional buckling law the front's points stop at the box limit with gaps of
  // 0.02-0.08 % (above the default 1e-6), and the report shows a closed synthesis.
  const auto run = testing::RunCli({"optimize", kProjectFile, "--no-estimate", "--no-verify-peak", "--pareto", "mass,shaft_1.outer_diameter",
                                    "--pareto-points", "4", "--gap", "1e-3", "--write", best.string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::ofstream(result) << run.out;
  const nlohmann::json doc = nlohmann::json::parse(run.out);
  EXPECT_EQ(doc["project_name"], "one-station design problem");
  EXPECT_TRUE(doc["project_hash"].is_string());
  EXPECT_TRUE(doc["design_hash"].is_string());

  auto r = testing::RunCli({"report", kProjectFile, "--optimize", result.string(), "--no-transient", "--no-scenarios",
                            "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("synthesis: optimal"), std::string::npos) << r.out;
  std::ifstream in(out);
  std::stringstream html;
  html << in.rdbuf();
  EXPECT_NE(html.str().find("\"relation\":\"project\""), std::string::npos);
  EXPECT_NE(html.str().find("\"objectives\":[\"mass\",\"shaft_1.outer_diameter\"]"), std::string::npos);

  // The design optimize wrote (a project file read back) belongs to the same result.
  r = testing::RunCli({"report", best.string(), "--optimize", result.string(), "--no-transient", "--no-scenarios",
                       "--out", out.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["synthesis_ok"], true);
  std::ifstream again(out);
  std::stringstream html2;
  html2 << again.rdbuf();
  EXPECT_NE(html2.str().find("\"relation\":\"design\""), std::string::npos);

  const auto other = dir / "other.html";
  std::filesystem::remove(other);
  r = testing::RunCli({"report", "examples/a320_class_flaps.json", "--optimize", result.string(), "--no-transient",
                       "--no-scenarios", "--out", other.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--optimize " + result.string() + ": /project_hash: the result is of project 'one-station design problem'"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(other));

  // The result file is an input: the report is never written over it.
  r = testing::RunCli({"report", kProjectFile, "--optimize", result.string(), "--no-transient", "--no-scenarios",
                       "--out", result.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  std::ifstream kept(result);
  EXPECT_EQ(nlohmann::json::parse(kept)["project_name"], "one-station design problem");
}

}  // namespace
}  // namespace highlift::report
