// The design report's data and page (report/include/highlift/report/report.h).
#include "highlift/report/report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"
#include "../../report/src/span_layout.h"

namespace highlift::report {
namespace {

const std::string kExample = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json";
const std::string kInfeasible = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps_infeasible.json";

/// The A380-class example with only the rupture scenario (and without the requirements that
/// name the other scenarios' peaks): with transient = false, one simulation.
Project RuptureOnly() {
  Project p = LoadProject(kExample);
  std::erase_if(p.scenarios, [](const Scenario& s) { return s.name != "rupture_wtb"; });
  p.requirements.clear();
  return p;
}

ReportOptions Quick() {
  ReportOptions o;
  o.transient = false;
  o.scenarios = false;
  return o;
}

TEST(DesignReport, SummaryIsTheCheckDocumentWithTheVerdictFirst) {
  const Project p = LoadProject(kExample);
  const DesignReport r = BuildDesignReport(p, p, "", Quick());
  const icsp::DriveSystemNetwork net = icsp::BuildDriveSystemNetwork(p);
  const nlohmann::json expected = CheckDocument(p, net, icsp::CheckDriveSystem(net), "");
  nlohmann::json got = r.data["check"], want = expected;
  got.erase("seconds");
  want.erase("seconds");
  EXPECT_EQ(got, want);
  // The example meets every requirement, over the domains and at the nominal design.
  EXPECT_TRUE(r.feasible);
  EXPECT_TRUE(r.nominal_feasible);
  EXPECT_EQ(r.data["verdict"]["headline"], "feasible: the nominal design meets all 32 requirements of the project");
}

/// The example with a wing-tip brake that does not slip below 5 kN*m: the rigid-stop peak after
/// the rupture of shaft_l1 then violates rupture_wtb_shaft at the nominal values, while values
/// within the domains (shorter latencies) meet it.
Project WithStrongBrake() {
  Project p = LoadProject(kExample);
  for (Component& c : p.components)
    if (c.id == "wtb_left")
      for (const char* name : {"max_dynamic_torque", "static_capacity"}) {
        c.parameters[name].nominal = 5000.0;
        c.parameters[name].domain = Domain::Point(5000.0);
      }
  return p;
}

TEST(Verdict, SaysWhichStatementConcernsTheDomainsAndWhichTheNominalDesign) {
  const Project p = WithStrongBrake();
  {
    const DesignReport r = BuildDesignReport(p, p, "", Quick());
    EXPECT_TRUE(r.feasible);
    EXPECT_FALSE(r.nominal_feasible);
    EXPECT_EQ(r.data["verdict"]["status"], "feasible_domains_nominal_violates");
    EXPECT_EQ(r.data["verdict"]["headline"], "feasible domains, but the nominal design violates rupture_wtb_shaft");
  }
  const icsp::DriveSystemNetwork net = icsp::BuildDriveSystemNetwork(p);
  const Verdict v = DescribeVerdict(CheckDocument(p, net, icsp::CheckDriveSystem(net), ""));
  EXPECT_EQ(v.domains.rfind("Parameter domains: all ", 0), 0u) << v.domains;
  EXPECT_NE(v.domains.find("can be met by values within the domains"), std::string::npos) << v.domains;
  EXPECT_EQ(v.nominal.rfind("Nominal design (every parameter at its nominal value): violates rupture_wtb_shaft", 0), 0u)
      << v.nominal;
  // The old contradiction: "all requirements can be met" beside "cannot be met" without saying of what.
  EXPECT_EQ(v.headline.find("all requirements can be met"), std::string::npos);
}

TEST(Verdict, InfeasibleNamesTheConflictingRequirements) {
  const Project p = LoadProject(kInfeasible);
  const icsp::DriveSystemNetwork net = icsp::BuildDriveSystemNetwork(p);
  const Verdict v = DescribeVerdict(CheckDocument(p, net, icsp::CheckDriveSystem(net), ""));
  EXPECT_EQ(v.status, "infeasible");
  EXPECT_EQ(v.headline,
            "infeasible: no values within the parameter domains meet extension_time and jam_l1_fitting together");
  EXPECT_NE(v.domains.find("the requirements extension_time, jam_l1_fitting cannot be met together"), std::string::npos)
      << v.domains;
  EXPECT_EQ(v.nominal, "");
}

TEST(Verdict, StoppedAtALimitClaimsNeither) {
  const nlohmann::json doc = {{"all_requirements_met", nullptr}, {"requirements", 3}};
  const Verdict v = DescribeVerdict(doc);
  EXPECT_EQ(v.status, "undecided");
  EXPECT_EQ(v.headline.find("feasible"), std::string::npos);
  EXPECT_NE(v.domains.find("no requirement was proved violated"), std::string::npos);
}

TEST(SpanLayout, TakesTheSpanPositionsOfTheProject) {
  const Project p = LoadProject(kExample);
  const SpanLayout layout = LayOutAlongSpan(p);
  auto index = [&](const std::string& id) {
    for (std::size_t i = 0; i < p.components.size(); ++i)
      if (p.components[i].id == id) return i;
    ADD_FAILURE() << id;
    return std::size_t{0};
  };
  EXPECT_DOUBLE_EQ(layout.x[index("tgb_l3")], -14.0);
  EXPECT_DOUBLE_EQ(layout.x[index("wtb_right")], 25.5);
  EXPECT_FALSE(layout.from_lengths);
  // Lanes: the drive line, the station's limiter and actuator below it, sensors above.
  EXPECT_EQ(layout.lane[index("tgb_l3")], 0);
  EXPECT_EQ(layout.lane[index("stl_l3")], 1);
  EXPECT_EQ(layout.lane[index("gra_l3")], 2);
  EXPECT_EQ(layout.lane[index("appu_left")], -1);
  EXPECT_EQ(layout.edges.size(), p.connections.size());
  // Model nodes: a shaft's sub-element node lies between its ends, outboard on the left wing.
  const double a = *layout.NodePosition(p, "shaft_l1/a", 4), b = *layout.NodePosition(p, "shaft_l1/b", 4);
  EXPECT_NEAR(a, -4.0, 1e-9);  // midpoint -5.5, length 3 m
  EXPECT_NEAR(b, -7.0, 1e-9);
  EXPECT_NEAR(*layout.NodePosition(p, "shaft_l1#1", 4), -4.75, 1e-9);
  EXPECT_FALSE(layout.NodePosition(p, "gra_l1", 4));  // off the drive line
  EXPECT_FALSE(layout.NodePosition(p, "no_such_node", 4));
  EXPECT_FALSE(layout.NodePosition(p, "shaft_l1#x", 4));
}

TEST(SpanLayout, ComputesPositionsFromShaftLengthsWhereNoneAreGiven) {
  Project p = LoadProject(kExample);
  for (Component& c : p.components) c.parameters.erase("span_position");
  const SpanLayout layout = LayOutAlongSpan(p);
  EXPECT_TRUE(layout.from_lengths);
  double wtb_left = NAN, wtb_right = NAN, tgb_l1 = NAN, tgb_l2 = NAN;
  for (std::size_t i = 0; i < p.components.size(); ++i) {
    const std::string& id = p.components[i].id;
    if (id == "wtb_left") wtb_left = layout.x[i];
    if (id == "wtb_right") wtb_right = layout.x[i];
    if (id == "tgb_l1") tgb_l1 = layout.x[i];
    if (id == "tgb_l2") tgb_l2 = layout.x[i];
  }
  // Shaft lengths of the left wing: 2 + 2 + 3 to station 1, 3.5 more to station 2.
  EXPECT_NEAR(tgb_l1, -7.0, 1e-9);
  EXPECT_NEAR(tgb_l2, -10.5, 1e-9);
  EXPECT_LT(wtb_left, -20.0);
  EXPECT_NEAR(wtb_right, -wtb_left, 1e-9);
}

TEST(DesignReport, PeakCasesStandBesideTheirCapacity) {
  const Project p = LoadProject(kExample);
  const DesignReport r = BuildDesignReport(p, p, "", Quick());
  const nlohmann::json& cases = r.data["peak_cases"];
  ASSERT_EQ(cases.size(), reduced_models::AnalysePeaks(p).cases.size());
  for (const auto& c : cases) {
    EXPECT_TRUE(c["transient"].is_null()) << c["name"];  // not simulated
    ASSERT_TRUE(c.contains("capacity")) << c["name"];
    EXPECT_GT(c["capacity"]["value"].get<double>(), 0.0);
  }
  // The rupture at the tip: the brake holds the wing, the capacity is the weakest on its path.
  // Margins come sorted, smallest first.
  const nlohmann::json& margins = r.data["margins"];
  ASSERT_FALSE(margins.empty());
  for (std::size_t i = 1; i < margins.size(); ++i) {
    if (!margins[i]["margin"].is_null()) {
      EXPECT_LE(margins[i - 1]["margin"].get<double>(), margins[i]["margin"].get<double>());
    }
  }
  // Every component with its parameters and their provenance.
  ASSERT_EQ(r.data["components"].size(), p.components.size());
  bool found = false;
  for (const auto& c : r.data["components"])
    if (c["id"] == "shaft_l1")
      for (const auto& q : c["parameters"])
        if (q["name"] == "length") {
          EXPECT_EQ(q["value"], 3.0);
          EXPECT_EQ(q["unit"], "m");
          EXPECT_EQ(q["provenance"], "user");
          found = true;
        }
  EXPECT_TRUE(found);
}

TEST(DesignReport, TimeHistoriesKeepThePeaksOfTheThinnedRows) {
  const Project p = RuptureOnly();
  ReportOptions o;
  o.transient = false;
  o.max_points = 300;
  const DesignReport r = BuildDesignReport(p, p, "", o);
  ASSERT_EQ(r.data["scenarios"].size(), 1u);
  const nlohmann::json& s = r.data["scenarios"][0];
  EXPECT_EQ(s["name"], "rupture_wtb");
  EXPECT_TRUE(s["ok"].get<bool>()) << s["message"];
  EXPECT_GT(s["rows_simulated"].get<std::size_t>(), s["time"].size());
  EXPECT_LE(s["time"].size(), 2u * 300u);
  std::set<std::string> names;
  for (const auto& g : s["signals"]) {
    names.insert(g["name"].get<std::string>());
    EXPECT_EQ(g["values"].size(), s["time"].size());
  }
  for (const char* expected : {"pdu.w", "appu_left.w", "wtb_left.tau", "wtb_right.tau", "monitor.wtb"})
    EXPECT_TRUE(names.count(expected)) << expected;
  // One shaft: the one with the largest peak.
  int shafts = 0;
  for (const auto& n : names) shafts += n.rfind("shaft_", 0) == 0;
  EXPECT_EQ(shafts, 1);
  // The brake command switches on (the monitor trips after the rupture).
  double command = 0;
  for (const auto& g : s["signals"])
    if (g["name"] == "monitor.wtb")
      for (const auto& v : g["values"]) command = std::max(command, v.get<double>());
  EXPECT_GT(command, 0.5);
  // Time ascending (an event gives two rows at one time: before and after).
  for (std::size_t i = 1; i < s["time"].size(); ++i) EXPECT_LE(s["time"][i - 1].get<double>(), s["time"][i].get<double>());
}

TEST(DesignReport, SimulationsSideBySideGiveTheSameHistoriesAsOneAfterAnother) {
  Project p = LoadProject(kExample);
  std::erase_if(p.scenarios, [](const Scenario& s) { return s.name != "rupture_wtb" && s.name != "jam_l6"; });
  p.requirements.clear();
  ReportOptions o;
  o.transient = false;
  o.max_points = 200;
  o.threads = 1;
  const DesignReport one = BuildDesignReport(p, p, "", o);
  o.threads = 2;
  const DesignReport two = BuildDesignReport(p, p, "", o);
  ASSERT_EQ(one.data["scenarios"].size(), 2u);
  EXPECT_EQ(two.timings.simulation_count, 2);
  for (std::size_t k = 0; k < 2; ++k) {
    nlohmann::json a = one.data["scenarios"][k], b = two.data["scenarios"][k];
    a.erase("wall_seconds");
    b.erase("wall_seconds");
    EXPECT_EQ(a, b) << k;
  }
}

TEST(RenderHtml, IsSelfContainedAndEscapesTheData) {
  Project p = LoadProject(kExample);
  p.description = "</script><script>alert(1)</script><!-- & \"quoted\"";
  p.name = "A<B> & C";
  const DesignReport r = BuildDesignReport(p, p, "", Quick());
  const std::string html = RenderHtml(r);
  EXPECT_EQ(html.find("<script>alert(1)"), std::string::npos);
  EXPECT_NE(html.find("\\u003c/script>\\u003cscript>alert(1)"), std::string::npos);
  EXPECT_NE(html.find("<title>Design report: A&lt;B&gt; &amp; C</title>"), std::string::npos);
  EXPECT_FALSE(std::regex_search(html, std::regex(R"((https?|ftp)://)")));
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_NE(html.find("var uPlot="), std::string::npos);  // the library, inlined
  EXPECT_NE(html.find("Permission is hereby granted"), std::string::npos);  // with its licence
  // The data island parses back to the report's data.
  const std::string open = "<script type=\"application/json\" id=\"report-data\">";
  const std::size_t from = html.find(open) + open.size();
  const nlohmann::json data = nlohmann::json::parse(html.substr(from, html.find("</script>", from) - from));
  EXPECT_EQ(data["project"]["description"], p.description);
  EXPECT_EQ(data["verdict"], r.data["verdict"]);
}

TEST(ReportOptions, DefaultsAreValidAndBadValuesNamed) {
  EXPECT_NO_THROW(ReportOptions{}.Validate());
  ReportOptions o;
  o.max_points = 10;
  try {
    o.Validate();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("max_points = 10: give at least 100"), std::string::npos) << e.what();
  }
}

TEST(DesignReport, RejectsAnElementNetwork) {
  const Project p = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/tests/sim/msl/Friction.json");
  try {
    BuildDesignReport(p, p, "", Quick());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has no components (an element network): use `highlift simulate`"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace highlift::report
