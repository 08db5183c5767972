// DescribeProject (the computation behind `highlift info`): reflected inertia, station ratios,
// shaft totals and the unknown/wide parameter lists, against hand calculations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "common/run_cli.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/model/describe.h"

namespace highlift::model {
namespace {

// PDU -> STL -> shaft (2 m, 50 x 2 mm Ti) -> station gearbox 2:1 -> limiter -> GRA 200:1,
// with every inertia given, and the through flange driving a second shaft to a WTB.
const char* const kRig = R"json({
  "format": "highlift-project/1",
  "name": "one-station rig",
  "components": [
    {"id": "pdu", "type": "pdu", "parameters": {"motor_count": 2, "motor_inertia": "3e-4 kg*m^2",
      "ratio": 20, "gear_inertia": "0.02 kg*m^2"}},
    {"id": "stl", "type": "system_torque_limiter", "labels": {"side": "left"},
     "parameters": {"inertia": "1e-3 kg*m^2"}},
    {"id": "shaft_1", "type": "torque_shaft", "labels": {"side": "left"},
     "parameters": {"length": "2 m", "outer_diameter": "50 mm", "wall_thickness": "2 mm",
                    "density": "4420 kg/m^3", "shear_modulus": "[43, 51] GPa"}},
    {"id": "tgb_1", "type": "branch_gearbox", "labels": {"side": "left", "station": "1"},
     "parameters": {"ratio": 2, "inertia": "1e-3 kg*m^2"}},
    {"id": "lim_1", "type": "station_torque_limiter", "labels": {"side": "left", "station": "1"},
     "parameters": {"inertia": "5e-4 kg*m^2"}},
    {"id": "gra_1", "type": "geared_rotary_actuator", "labels": {"side": "left", "station": "1"},
     "parameters": {"ratio": 200, "input_inertia": "1e-3 kg*m^2", "load_inertia": "0.04 kg*m^2",
                    "eta_opposing": {"value": 0.7, "min": 0.5, "max": 0.9, "note": "guess (E)"}}},
    {"id": "shaft_2", "type": "torque_shaft", "labels": {"side": "left"},
     "parameters": {"length": "1.5 m", "inertia": "2e-3 kg*m^2"}},
    {"id": "wtb", "type": "wing_tip_brake", "labels": {"side": "left"},
     "parameters": {"inertia": "5e-4 kg*m^2"}}
  ],
  "connections": [
    ["pdu.left", "stl.input"], ["stl.output", "shaft_1.a"], ["shaft_1.b", "tgb_1.input"],
    ["tgb_1.branch", "lim_1.input"], ["lim_1.output", "gra_1.input"],
    ["tgb_1.through", "shaft_2.a"], ["shaft_2.b", "wtb.a"]
  ]
})json";

/// J of the inertia-free-of-defaults parts that are at PDU speed or half of it.
double ExpectedReflectedInertia(const Project& p) {
  const double pdu = 2 * 3e-4 * 20 * 20 + 0.02;  // motors reflected through 20:1, plus gears
  const double D = 0.05, d = 0.046;
  const double shaft_1 = 4420 * std::numbers::pi / 32 * (std::pow(D, 4) - std::pow(d, 4)) * 2.0;
  const double at_pdu_speed = pdu + 1e-3 /*stl*/ + shaft_1 + 1e-3 /*tgb*/ + 2e-3 /*shaft_2*/ + 5e-4 /*wtb*/;
  const double at_half_speed = 5e-4 /*lim*/ + 1e-3 + 0.04 /*gra*/;
  (void)p;
  return at_pdu_speed + at_half_speed / 4;
}

TEST(DescribeProject, ReflectsInertiaThroughTheStationRatio) {
  const Project p = ParseProject(kRig, "rig.json");
  ASSERT_TRUE(ValidateProject(p).ok()) << ValidateProject(p).FullReport();
  const ProjectDescription d = DescribeProject(p);
  EXPECT_NEAR(d.reflected_inertia, ExpectedReflectedInertia(p), 1e-12);
  EXPECT_NEAR(d.reflected_inertia, 0.2764, 1e-4);  // 0.26 of the PDU dominates
  EXPECT_LE(d.reflected_inertia_domain.lo, d.reflected_inertia);
  EXPECT_GE(d.reflected_inertia_domain.hi, d.reflected_inertia);
  EXPECT_TRUE(d.unreachable.empty());
  for (const auto& c : d.inertias) {
    const double expected_ratio = (c.component == "lim_1" || c.component == "gra_1") ? 2.0 : 1.0;
    EXPECT_DOUBLE_EQ(c.speed_ratio, expected_ratio) << c.component;
    EXPECT_NEAR(c.reflected, c.inertia / (expected_ratio * expected_ratio), 1e-15) << c.component;
  }
}

TEST(DescribeProject, FindsStationsWithTheirRatiosAndPaths) {
  const ProjectDescription d = DescribeProject(ParseProject(kRig, "rig.json"));
  ASSERT_EQ(d.stations.size(), 1u);
  const StationSummary& s = d.stations[0];
  EXPECT_EQ(s.actuator, "gra_1");
  EXPECT_EQ(s.side, "left");
  EXPECT_EQ(s.station, "1");
  EXPECT_DOUBLE_EQ(s.speed_ratio, 2.0);
  EXPECT_DOUBLE_EQ(s.total_ratio, 400.0);
  const std::vector<std::string> path = {"pdu", "stl", "shaft_1", "tgb_1", "lim_1", "gra_1"};
  EXPECT_EQ(s.path, path);
}

TEST(DescribeProject, SumsShaftLengthAndMassPerSide) {
  const ProjectDescription d = DescribeProject(ParseProject(kRig, "rig.json"));
  EXPECT_EQ(d.shaft_count, 2);
  EXPECT_DOUBLE_EQ(d.shaft_length, 3.5);
  ASSERT_EQ(d.sides.size(), 1u);
  EXPECT_EQ(d.sides[0].side, "left");
  EXPECT_EQ(d.sides[0].stations, 1);
  // shaft_1: 2 m of 50 x 2 mm Ti = 1.333 kg/m; shaft_2 gives no geometry but the catalogue's
  // default tube (50 x 2 mm, 4420 kg/m^3): another 1.5 m at 1.333 kg/m.
  const double per_metre = 4420 * std::numbers::pi / 4 * (0.05 * 0.05 - 0.046 * 0.046);
  EXPECT_NEAR(d.shaft_mass, 3.5 * per_metre, 1e-9);
}

// The inertia and mass of a shaft given by its linear density (a composite tube) are the
// lumped models' (torque_shaft.cc): J = m_l L r^2 at the mean radius r = (D - t)/2, m = m_l L;
// the tube's density does not enter.
TEST(DescribeProject, ShaftOfGivenLinearDensityHasTheLumpedModelsInertiaAndMass) {
  nlohmann::json rig = nlohmann::json::parse(kRig);
  for (auto& c : rig["components"])
    if (c["id"] == "shaft_1") c["parameters"]["linear_density"] = "0.28 kg/m";
  const ProjectDescription d = DescribeProject(ParseProject(rig.dump(), "rig.json"));
  const double r = (0.05 - 0.002) / 2;
  const auto shaft = std::find_if(d.inertias.begin(), d.inertias.end(),
                                  [](const InertiaContribution& c) { return c.component == "shaft_1"; });
  ASSERT_NE(shaft, d.inertias.end());
  EXPECT_NEAR(shaft->inertia, 0.28 * 2.0 * r * r, 1e-15);
  const double per_metre = 4420 * std::numbers::pi / 4 * (0.05 * 0.05 - 0.046 * 0.046);  // shaft_2: the tube
  EXPECT_NEAR(d.shaft_mass, 0.28 * 2.0 + 1.5 * per_metre, 1e-9);
}

TEST(DescribeProject, ListsUnknownAndWideParametersWithProvenance) {
  const ProjectDescription d = DescribeProject(ParseProject(kRig, "rig.json"));
  const ParameterConcern* shear = nullptr;
  const ParameterConcern* eta = nullptr;
  for (const auto& c : d.concerns) {
    if (c.component == "shaft_1" && c.parameter == "shear_modulus") shear = &c;
    if (c.component == "gra_1" && c.parameter == "eta_opposing") eta = &c;
  }
  // "[43, 51] GPa" has no nominal value: unknown.
  ASSERT_NE(shear, nullptr);
  EXPECT_EQ(shear->kind, ParameterConcern::Kind::kUnknown);
  EXPECT_EQ(shear->provenance, Provenance::kUser);
  EXPECT_DOUBLE_EQ(shear->domain.lo, 43e9);
  // 0.7 in [0.5, 0.9]: width 0.4 / 0.7 = 57 % > 20 %: wide, with its note.
  ASSERT_NE(eta, nullptr);
  EXPECT_EQ(eta->kind, ParameterConcern::Kind::kWide);
  EXPECT_NEAR(eta->relative_width, 0.4 / 0.7, 1e-12);
  EXPECT_EQ(eta->note, "guess (E)");
  // Unknown ones come first.
  EXPECT_EQ(d.concerns.front().kind, ParameterConcern::Kind::kUnknown);
  // A point value given by the user is neither.
  for (const auto& c : d.concerns) EXPECT_FALSE(c.component == "gra_1" && c.parameter == "ratio");
  // A narrower threshold lists more.
  DescribeOptions strict;
  strict.wide_relative_width = 0.01;
  EXPECT_GT(DescribeProject(ParseProject(kRig, "rig.json"), strict).CountConcerns(ParameterConcern::Kind::kWide),
            d.CountConcerns(ParameterConcern::Kind::kWide));
}

TEST(DescribeProject, ReportsAndJsonAgree) {
  const ProjectDescription d = DescribeProject(ParseProject(kRig, "rig.json"));
  const std::string brief = d.BriefReport();
  EXPECT_NE(brief.find("one-station rig: 8 components, 1 stations, 3.5 m of shaft"), std::string::npos) << brief;
  const std::string full = d.FullReport();
  EXPECT_NE(full.find("Components by type"), std::string::npos);
  EXPECT_NE(full.find("shaft_1"), std::string::npos);  // in the unknown list (shear modulus)
  const nlohmann::json j = d.ToJson();
  EXPECT_EQ(j.at("counts").at("stations"), 1);
  EXPECT_DOUBLE_EQ(j.at("reflected_inertia").at("nominal_kg_m2").get<double>(), d.reflected_inertia);
  EXPECT_EQ(j.at("components_by_type").at("torque_shaft"), 2);
  EXPECT_EQ(j.at("unknown_parameters").size(),
            static_cast<std::size_t>(d.CountConcerns(ParameterConcern::Kind::kUnknown)));
}

TEST(InfoCommand, InvalidGraphExitsWithTwo) {
  std::string text = kRig;
  text.replace(text.find("[\"shaft_2.b\", \"wtb.a\"]"), 22, "[\"shaft_2.b\", \"wtb.b\"]");
  const auto path = testing::RemoveAfterTheTest(std::filesystem::temp_directory_path() /
                                                ("highlift_info_test_" + std::to_string(::getpid()) + ".json"));
  std::ofstream(path) << text;
  const auto r = testing::RunCli({"info", path.string(), "--json"});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_FALSE(nlohmann::json::parse(r.out).at("ok").get<bool>());
  EXPECT_NE(r.err.find("highlift validate"), std::string::npos) << r.err;
}

TEST(InfoCommand, ListsTheCatalogueTypes) {
  const auto types = testing::RunCli({"info", "--types", "--json"});
  ASSERT_EQ(types.exit_code, 0) << types.err;
  const auto doc = nlohmann::json::parse(types.out);
  ASSERT_EQ(doc.size(), ComponentTypes().size());
  for (std::size_t i = 0; i < doc.size(); ++i) EXPECT_EQ(doc[i].at("name"), ComponentTypes()[i].name);
  const auto& gra = *std::find_if(doc.begin(), doc.end(), [](const auto& t) { return t.at("name") == "geared_rotary_actuator"; });
  EXPECT_EQ(gra.at("ports")[0].at("name"), "input");
  EXPECT_EQ(gra.at("parameters")[0].at("name"), "ratio");

  const auto text = testing::RunCli({"info", "--types"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_TRUE(std::regex_search(text.out, std::regex(R"(\nbranch_gearbox\s+input through\* branch\s+ratio )")))
      << text.out;

  const auto elements = testing::RunCli({"info", "--elements"});
  ASSERT_EQ(elements.exit_code, 0) << elements.err;
  for (const auto& e : ElementTypes()) EXPECT_NE(elements.out.find("\n" + e.name + " "), std::string::npos) << e.name;
}

TEST(InfoCommand, WithoutProjectExitsWithTwo) {
  const auto r = testing::RunCli({"info"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no project file given"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace highlift::model
