// The drive-system network of the example projects, through the library and through the CLI.
#include "highlift/icsp/drive_system.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/run_cli.h"
#include "highlift/core/project_io.h"

namespace highlift::icsp {
namespace {

const std::string kFlaps = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json";
const std::string kInfeasible = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps_infeasible.json";

Interval Final(const CheckResult& r, const std::string& name) {
  for (const auto& p : r.parameters) {
    if (p.name == name) return p.final;
  }
  ADD_FAILURE() << "no quantity " << name;
  return Empty();
}

TEST(DriveSystem, FlapProjectMeetsItsRequirementsAndDerivesThePhysics) {
  const Project project = LoadProject(kFlaps);
  const DriveSystemNetwork net = BuildDriveSystemNetwork(project);
  EXPECT_GT(net.physics_constraints, 100);
  EXPECT_EQ(net.requirement_constraints, static_cast<int>(project.requirements.size()));
  const CheckResult r = CheckDriveSystem(net);
  ASSERT_TRUE(r.feasible) << r.report.BriefReport();
  EXPECT_EQ(r.report.status, Status::kFixedPoint);
  // Extension time: 2.2 rad * 200 * 2 / 25.3 rad/s = 34.78 s.
  const Interval t = Final(r, "travel_time.extension");
  EXPECT_NEAR(t.lower(), 2.2 * 200 * 2 / 25.3, 1e-6);
  // Station input torque: 20 kN*m / (i_act eta_opp) / (i_branch eta_mesh), 60.64 N*m at the
  // nominal efficiencies 0.85 and 0.97; the bounds come from the efficiency domains.
  const Interval station = Final(r, "tgb_l1.station_torque");
  EXPECT_LE(station.lower(), 20000.0 / (200 * 0.85) / (2 * 0.97));
  EXPECT_GE(station.upper(), 20000.0 / (200 * 0.85) / (2 * 0.97));
  const Interval eta_opp = Final(r, "gra_l1.eta_opposing"), eta_mesh = Final(r, "tgb_l1.eta_mesh");
  EXPECT_NEAR(station.lower(), 20000.0 / (200 * eta_opp.upper()) / (2 * eta_mesh.upper()), 1e-9);
  EXPECT_NEAR(station.upper(), 20000.0 / (200 * eta_opp.lower()) / (2 * eta_mesh.lower()), 1e-9);
  // Tube stiffness c = G Ip / L of a 50 x 2 mm tube, 2 m long, G = 44 GPa (domain of G may be wider).
  const Interval c = Final(r, "shaft_l0a.c");
  const double ip = M_PI / 32 * (std::pow(0.05, 4) - std::pow(0.046, 4));
  EXPECT_LE(c.lower(), 44e9 * ip / 2.0 * 1.0000001);
  EXPECT_GE(c.upper(), 44e9 * ip / 2.0 * 0.9999999);
  // Equation (1) at the jam of station 1 is positive and finite.
  const Interval peak = Final(r, "peak.jam_l1.torque");
  EXPECT_GT(peak.lower(), 0.0);
  EXPECT_TRUE(std::isfinite(peak.upper()));
}

TEST(DriveSystem, InfeasibleVariantNamesTheConflictingRequirements) {
  const DriveSystemNetwork net = BuildDriveSystemNetwork(LoadProject(kInfeasible));
  const CheckResult r = CheckDriveSystem(net);
  ASSERT_FALSE(r.feasible);
  std::vector<std::string> names;
  for (int c : r.explanation.conflict) names.push_back(net.network.constraint(ConstraintId{c}).info.label);
  EXPECT_EQ(names, (std::vector<std::string>{"extension_time", "jam_l1_fitting"}));
  EXPECT_NE(r.explanation.text.find("pdu.max_output_speed"), std::string::npos) << r.explanation.text;
}

TEST(CheckCommand, FeasibleProjectExitsZero) {
  const auto r = testing::RunCli({"check", "examples/a380_class_flaps.json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("all requirements can be met"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("shaft_l0a.c"), std::string::npos);
  EXPECT_NE(r.out.find("narrowed %"), std::string::npos);
}

TEST(CheckCommand, InfeasibleProjectExitsOneWithExplanation) {
  const auto r = testing::RunCli({"check", "examples/a380_class_flaps_infeasible.json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("requirements violated: extension_time, jam_l1_fitting"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("These requirements cannot be met together"), std::string::npos) << r.out;
}

TEST(CheckCommand, JsonHasTheSameContent) {
  const auto r = testing::RunCli({"check", "examples/a380_class_flaps_infeasible.json", "--json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["status"], "infeasible");
  EXPECT_EQ(doc["all_requirements_met"], false);
  EXPECT_EQ(doc["violated_requirements"], nlohmann::json({"extension_time", "jam_l1_fitting"}));
  EXPECT_GT(doc["parameters"].size(), 100u);
  EXPECT_TRUE(doc["parameters"][0].contains("provenance"));
}

TEST(CheckCommand, UsesEstimatedDomainsWhereTheProjectGivesNone) {
  // Shaft stiffness is not given in the example: the estimator derives it from the tube
  // geometry and material (provenance "estimated"); --no-estimate leaves the catalogue default.
  const auto r = testing::RunCli({"check", "examples/a380_class_flaps.json", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_NE(doc["estimation"].get<std::string>().find("0 conflicts"), std::string::npos) << doc["estimation"];
  std::string provenance;
  for (const auto& p : doc["parameters"])
    if (p["name"] == "shaft_l1.stiffness") provenance = p["provenance"];
  EXPECT_EQ(provenance, "estimated");

  const auto raw = testing::RunCli({"check", "examples/a380_class_flaps.json", "--json", "--no-estimate"});
  ASSERT_EQ(raw.exit_code, 0) << raw.err;
  const auto raw_doc = nlohmann::json::parse(raw.out);
  EXPECT_EQ(raw_doc["estimation"], "");
  for (const auto& p : raw_doc["parameters"]) {
    if (p["name"] == "shaft_l1.stiffness") {
      EXPECT_NE(p["provenance"], "estimated");
    }
  }
}

TEST(TradeoffCommand, SlicesTheSpeedDomain) {
  const auto r = testing::RunCli({"tradeoff", "examples/a380_class_flaps_infeasible.json", "--vary",
                                  "pdu.max_output_speed=20:32:4", "--show", "travel_time.extension,peak.jam_l1.torque",
                                  "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["rows"].size(), 4u);
  // Every slice conflicts (too slow or too hard a jam); the project itself says so.
  for (const auto& row : doc["rows"]) EXPECT_FALSE(row["feasible"].get<bool>()) << row.dump();
  const auto ok = testing::RunCli({"tradeoff", "examples/a380_class_flaps.json", "--vary",
                                   "gra_l1.ratio=150:250:2", "--show", "travel_time.extension"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("travel_time.extension [s]"), std::string::npos) << ok.out;
}

TEST(TradeoffCommand, UnknownNameIsInvalidInputWithSuggestion) {
  const auto r = testing::RunCli({"tradeoff", "examples/a380_class_flaps.json", "--vary", "pdu.max_output_sped=1:2:2",
                                  "--show", "travel_time.extension"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown quantity 'pdu.max_output_sped'; did you mean 'pdu.max_output_speed'?"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace highlift::icsp
