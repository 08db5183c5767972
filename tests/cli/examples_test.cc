// Every bundled example runs through `highlift validate` and `highlift info` (text and --json),
// states where its numbers come from, and gives the numbers of its domain.md section.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/run_cli.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/icsp/parser.h"
#include "highlift/model/describe.h"

namespace highlift {
namespace {

using testing::RunCli;
using model::DescribeProject;
using model::ProjectDescription;

struct ExampleExpectation {
  std::string file;       // relative to the source dir
  int stations;           // actuators, both wings
  double shaft_length;    // m, both wings
  double shaft_mass;      // kg, both wings (nominal tube geometry, rho = 4420 kg/m^3)
  double inertia;         // kg*m^2 reflected to the PDU output (hand estimate from domain.md)
  double inertia_tolerance;
};

// Shaft masses: tube area pi/4 (D^2 - d^2) x 4420 kg/m^3: 50 x 2.0 -> 1.333 kg/m,
// 45 x 1.8 -> 1.080 kg/m, 38 x 1.5 -> 0.7603 kg/m (domain.md s3/s4 quote 1.33, 1.08, 0.76).
// Inertias: domain.md s3 lumps 0.26 + 2 x (4.7e-3 + 6 x 1.25e-2 + 8.8e-4) = 0.42 kg*m^2;
// s4 lumps 0.087 + 2 x (1.4e-3 + 4 x 2.15e-3 + 4.3e-4) = 0.11 kg*m^2. The examples add
// limiters, joints and bearings, so the tolerance is a few per cent of the total.
const ExampleExpectation kExamples[] = {
    {"examples/a380_class_flaps.json", 12, 51.0, 2 * (14.0 * 1.3329 + 11.5 * 1.0797), 0.42, 0.03},
    {"examples/a320_class_flaps.json", 8, 28.0, 28.0 * 0.76025, 0.11, 0.01},
    {"examples/a320_class_slats.json", 20, 32.8, 32.8 * 0.76025, 0.0, 0.0},
};

std::string Source(const std::string& relative) {
  return (std::filesystem::path(HIGHLIFT_SOURCE_DIR) / relative).string();
}

TEST(Examples, ValidateExitsZeroAndCountsComponents) {
  for (const auto& e : kExamples) {
    SCOPED_TRACE(e.file);
    const auto r = RunCli({"validate", e.file});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("ok: ", 0), 0u) << r.out;
    const Project p = LoadProject(Source(e.file));
    EXPECT_NE(r.out.find(std::to_string(p.components.size()) + " components"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(std::to_string(p.connections.size()) + " connections"), std::string::npos) << r.out;
  }
}

TEST(Examples, ValidateJsonIsOneDocument) {
  for (const auto& e : kExamples) {
    SCOPED_TRACE(e.file);
    const auto r = RunCli({"validate", e.file, "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);  // throws if not exactly one document
    EXPECT_TRUE(doc.at("ok").get<bool>());
    EXPECT_EQ(doc.at("errors").get<int>(), 0);
    EXPECT_GT(doc.at("counts").at("components").get<int>(), 50);
  }
}

TEST(Examples, InfoReportsStationsShaftLengthAndInertia) {
  for (const auto& e : kExamples) {
    SCOPED_TRACE(e.file);
    const auto r = RunCli({"info", e.file, "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    EXPECT_EQ(doc.at("counts").at("stations").get<int>(), e.stations);
    EXPECT_EQ(doc.at("stations").size(), static_cast<std::size_t>(e.stations));
    EXPECT_NEAR(doc.at("shafts").at("length_m").get<double>(), e.shaft_length, 1e-9);
    EXPECT_NEAR(doc.at("shafts").at("mass_kg").get<double>(), e.shaft_mass, 0.002 * e.shaft_mass);
    const auto& by_side = doc.at("shafts").at("by_side");
    ASSERT_EQ(by_side.size(), 2u);  // left and right, mirrored
    EXPECT_EQ(by_side[0].at("side"), "left");
    EXPECT_EQ(by_side[1].at("side"), "right");
    EXPECT_NEAR(by_side[0].at("shaft_length_m").get<double>(), e.shaft_length / 2, 1e-9);
    EXPECT_EQ(by_side[0].at("stations").get<int>(), e.stations / 2);
    const double J = doc.at("reflected_inertia").at("nominal_kg_m2").get<double>();
    const auto range = doc.at("reflected_inertia").at("range_kg_m2");
    EXPECT_LE(range[0].get<double>(), J);
    EXPECT_GE(range[1].get<double>(), J);
    if (e.inertia > 0) {
      EXPECT_NEAR(J, e.inertia, e.inertia_tolerance);
    }
    EXPECT_TRUE(doc.at("reflected_inertia").at("unreachable").empty());
    // Every station is reached from the PDU.
    for (const auto& s : doc.at("stations")) EXPECT_GT(s.at("speed_ratio").get<double>(), 0) << s.dump();
  }
}

TEST(Examples, InfoTextShowsTheKeyNumbers) {
  const auto r = RunCli({"info", "examples/a380_class_flaps.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Stations (12)"), std::string::npos) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(\nall\s+26\s+51\s+62\.\d+\s+12\n)"))) << r.out;
  EXPECT_NE(r.out.find("geared_rotary_actuator"), std::string::npos);
  EXPECT_NE(r.out.find("Inertia reflected to the PDU output"), std::string::npos);
  EXPECT_NE(r.out.find("Unknown parameters"), std::string::npos);
  EXPECT_NE(r.out.find("Wide parameters"), std::string::npos);
  // The station ratio of domain.md s3: 2:1 station gearbox x 200:1 GRA.
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(gra_l1\s+left\s+1\s+2\s+400\n)"))) << r.out;

  const auto brief = RunCli({"info", "examples/a380_class_flaps.json", "--brief"});
  ASSERT_EQ(brief.exit_code, 0) << brief.err;
  EXPECT_NE(brief.out.find("12 stations, 51 m of shaft"), std::string::npos) << brief.out;
}

TEST(Examples, A380ClassHasTheArchitectureOfDomainSection3) {
  const Project p = LoadProject(Source("examples/a380_class_flaps.json"));
  ASSERT_TRUE(ValidateProject(p).ok()) << ValidateProject(p).FullReport();
  const ProjectDescription d = DescribeProject(p);
  auto count = [&](const std::string& type) {
    for (const auto& [t, n] : d.components_by_type)
      if (t == type) return n;
    return 0;
  };
  EXPECT_EQ(count("pdu"), 1);
  EXPECT_EQ(count("system_torque_limiter"), 2);
  EXPECT_EQ(count("angle_gearbox"), 2);
  EXPECT_EQ(count("branch_gearbox"), 12);
  EXPECT_EQ(count("station_torque_limiter"), 12);
  EXPECT_EQ(count("geared_rotary_actuator"), 12);
  EXPECT_EQ(count("wing_tip_brake"), 2);
  EXPECT_EQ(count("position_sensor"), 3);  // APPU at each shaft end, FPPU at the PDU
  for (const char* id : {"pdu", "stl_left", "stl_right", "rgb_left", "rgb_right", "wtb_left", "wtb_right",
                         "appu_left", "appu_right", "fppu", "tgb_l1", "stl_l1", "gra_l1", "gra_r6", "shaft_l1"})
    EXPECT_NE(p.FindComponent(id), nullptr) << id;
  // Scenarios: extension, a jam at each of the 12 stations, the rupture with WTB by the monitor.
  ASSERT_NE(p.FindScenario("extension"), nullptr);
  for (const char side : {'l', 'r'})
    for (int i = 1; i <= 6; ++i) {
      const std::string station = std::string(1, side) + std::to_string(i);
      const Scenario* s = p.FindScenario("jam_" + station);
      ASSERT_NE(s, nullptr) << station;
      EXPECT_EQ(s->kind, "jam");
      EXPECT_EQ(s->jam_component.value_or(""), "gra_" + station);
    }
  const Scenario* rupture = p.FindScenario("rupture_wtb");
  ASSERT_NE(rupture, nullptr);
  EXPECT_EQ(rupture->kind, "rupture");
  EXPECT_EQ(rupture->wtb_trigger, "monitor");
  // The ruptured shaft lies between the left root gearbox and the first left station.
  ASSERT_TRUE(rupture->rupture_component.has_value());
  const std::string broken = *rupture->rupture_component;
  bool from_rgb = false, to_station = false;
  for (const auto& c : p.connections) {
    for (const auto& [mine, other] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
      if (mine.component != broken) continue;
      from_rgb |= other.component == "rgb_left";
      to_station |= other.component == "tgb_l1";
    }
  }
  EXPECT_TRUE(from_rgb && to_station) << broken;
  const LoadCase* extend = p.FindLoadCase(rupture->load_case);
  ASSERT_NE(extend, nullptr);
  EXPECT_EQ(extend->direction, "extend");
  EXPECT_EQ(extend->actuator_loads.size(), 12u);
  // Speed profile: 0 -> w_max = 25.3 rad/s in 0.4 s, ends at rest, extension within 40 s.
  ASSERT_TRUE(extend->pdu_speed.has_value());
  const Table& w = *extend->pdu_speed;
  EXPECT_DOUBLE_EQ(w.y.front(), 0.0);
  EXPECT_DOUBLE_EQ(w.x[1], 0.4);
  EXPECT_NEAR(w.y[1], 25.3, 1e-9);
  EXPECT_DOUBLE_EQ(w.y.back(), 0.0);
  EXPECT_LE(w.x.back(), 40.0);
  // The profile covers the 140 shaft revolutions of full travel (trapezoidal integral).
  double angle = 0;
  for (std::size_t i = 1; i < w.x.size(); ++i) angle += 0.5 * (w.y[i] + w.y[i - 1]) * (w.x[i] - w.x[i - 1]);
  EXPECT_NEAR(angle, 140 * 2 * 3.141592653589793, 0.5);
  // Opposing airload rises with flap position.
  const Table& load = extend->actuator_loads.at("gra_l1");
  EXPECT_EQ(load.abscissa, "position");
  for (std::size_t i = 1; i < load.y.size(); ++i) EXPECT_GT(load.y[i], load.y[i - 1]);
  EXPECT_NEAR(load.y.back(), 20e3, 1e-6);
  const LoadCase* retract = p.FindLoadCase("retract_aiding");
  ASSERT_NE(retract, nullptr);
  EXPECT_EQ(retract->direction, "retract");
  EXPECT_LT(retract->actuator_loads.at("gra_r6").y.back(), 0.0);  // aiding
}

TEST(Examples, EveryGivenValueCarriesItsProvenanceTag) {
  const std::regex tag(R"(\((P|P-low|E|P/E)\))");
  for (const auto& e : kExamples) {
    SCOPED_TRACE(e.file);
    const Project p = LoadProject(Source(e.file));
    EXPECT_NE(p.description.find("domain.md"), std::string::npos);
    EXPECT_FALSE(p.sources.empty());
    int given = 0;
    for (const auto& c : p.components)
      for (const auto& [name, parameter] : c.parameters) {
        if (parameter.provenance != Provenance::kUser) continue;
        ++given;
        EXPECT_TRUE(std::regex_search(parameter.note, tag)) << c.id << "." << name << ": '" << parameter.note << "'";
      }
    EXPECT_GT(given, 200);
  }
}

TEST(Examples, RequirementsNameExistingComponentsAndParameters) {
  // `component.parameter` names in requirement expressions refer to real components and
  // parameters of their type, or to a quantity the network derives for the component (a tube's
  // torque_capacity); results such as peak.<scenario>.<component> name a scenario.
  const std::regex name(R"(\b([a-z_][a-z0-9_]*)\.([a-z_][a-z0-9_]*)(?:\.([a-z_][a-z0-9_]*))?)");
  for (const auto& e : kExamples) {
    SCOPED_TRACE(e.file);
    const Project p = LoadProject(Source(e.file));
    const icsp::DriveSystemNetwork network = icsp::BuildDriveSystemNetwork(p);
    ASSERT_FALSE(p.requirements.empty());
    for (const auto& r : p.requirements) {
      for (auto it = std::sregex_iterator(r.expression.begin(), r.expression.end(), name); it != std::sregex_iterator();
           ++it) {
        const std::string a = (*it)[1], b = (*it)[2], c = (*it)[3];
        if (a == "peak") {
          EXPECT_NE(p.FindScenario(b), nullptr) << r.id << ": " << r.expression;
          EXPECT_NE(p.FindComponent(c), nullptr) << r.id << ": " << r.expression;
        } else if (a == "travel_time") {
          EXPECT_NE(p.FindScenario(b), nullptr) << r.id << ": " << r.expression;
        } else {
          const Component* component = p.FindComponent(a);
          ASSERT_NE(component, nullptr) << r.id << ": " << r.expression;
          const ComponentTypeSpec* type = FindComponentType(component->type);
          ASSERT_NE(type, nullptr);
          EXPECT_TRUE(type->FindParameter(b) != nullptr || network.network.FindVariable(a + "." + b).value >= 0)
              << r.id << ": " << r.expression;
        }
      }
    }
  }
}

TEST(Examples, RequirementsParseInTheConstraintLanguage) {
  for (const auto& e : kExamples) {
    SCOPED_TRACE(e.file);
    const Project p = LoadProject(Source(e.file));
    icsp::Network network;
    const icsp::NameResolver resolve = [&](std::string_view name) {
      const icsp::VariableId v = network.FindVariable(name);
      return v.value >= 0 ? v : network.AddVariable(std::string(name), icsp::Interval::whole());
    };
    for (const auto& r : p.requirements) {
      EXPECT_NO_THROW(icsp::ParseConstraint(network, r.expression, "requirement '" + r.id + "'", r.where, resolve))
          << r.expression;
    }
  }
}

}  // namespace
}  // namespace highlift

namespace highlift {
namespace {

// Issue 20 and issue 26 item 3: `check` passes every example but the infeasible variant, which
// exists to show a conflict. Since the station torque limiter passes what its brake does not
// ground (docs/reduced_models.md, "The station torque limiter in a jam"), `size` and `peak` find
// that the examples' limiter brakes (2 x the lock-out torque) cannot ground what the drive puts
// into a jammed station: `size` flags max_brake_torque, `peak` the actuators' margins (the
// simulation agrees: 563-730 N*m at the A380-class actuator inputs against 278 N*m), and the flaps
// back-driven in a rupture load the actuators beyond any allowable in domain.md's ranges (README's
// table: a physical conflict of back-drivable actuators, not a setting). check states its scope.
TEST(Examples, CheckPassesButSizeAndPeakFlagTheStationLimitersThatCannotGroundAJam) {
  struct Expected {
    std::string file;
    int size, check, peak;
  };
  const Expected expected[] = {{"examples/a380_class_flaps.json", 1, 0, 1},
                               {"examples/hydraulic_pdu_flaps.json", 1, 0, 1},
                               {"examples/a320_class_flaps.json", 1, 0, 1},
                               {"examples/a320_class_slats.json", 1, 0, 1},
                               {"examples/a380_class_flaps_infeasible.json", 1, 1, 1}};
  for (const auto& e : expected) {
    SCOPED_TRACE(e.file);
    const auto size = RunCli({"size", e.file});
    EXPECT_EQ(size.exit_code, e.size) << size.out << size.err;
    // The only settings out of their rules are the limiter brakes.
    for (std::size_t at = size.out.find("OUT OF RANGE"); at != std::string::npos; at = size.out.find("OUT OF RANGE", at + 1)) {
      const std::size_t line = size.out.rfind('\n', at) + 1;
      EXPECT_NE(size.out.substr(line, at - line).find("max_brake_torque"), std::string::npos) << size.out;
    }
    EXPECT_NE(size.out.find("max_brake_torque"), std::string::npos) << size.out;
    const auto check = RunCli({"check", e.file});
    EXPECT_EQ(check.exit_code, e.check) << check.out << check.err;
    if (e.check == 0) {
      EXPECT_NE(check.out.find("the nominal design meets all"), std::string::npos) << check.out;
    }
    // Its verdict is on the project's requirements, and it says so: the margins are size's and peak's.
    EXPECT_NE(check.out.find("scope: the project's requirements over the parameter domains; component margins"),
              std::string::npos)
        << check.out;
    const auto peak = RunCli({"peak", e.file, "--json"});
    EXPECT_EQ(peak.exit_code, e.peak) << peak.err;
    const nlohmann::json j = nlohmann::json::parse(peak.out);
    EXPECT_FALSE(j.at("ok").get<bool>());
    // Only actuators behind a station limiter have negative margins.
    for (const auto& w : j.at("worst")) {
      if (w.at("margin").is_null() || w.at("margin").get<double>() >= 0) continue;
      EXPECT_EQ(w.at("component").get<std::string>().rfind("gra_", 0), 0u) << w.dump();
    }
    // Every rupture is capped where its wing-tip brake slips, and the cap is what it reports.
    for (const auto& c : j.at("cases")) {
      if (c.at("kind") != "rupture") continue;
      SCOPED_TRACE(c.at("name").get<std::string>());
      ASSERT_FALSE(c.at("stop_limit_N_m").is_null());
      EXPECT_LE(c.at("tau_max_N_m").at("nominal").get<double>(), c.at("stop_limit_N_m").at("nominal").get<double>());
      EXPECT_LE(c.at("tau_max_N_m").at("max").get<double>(), c.at("stop_limit_N_m").at("max").get<double>());
    }
  }
}

}  // namespace
}  // namespace highlift

namespace highlift {
namespace {

// Issue 26 item 3: on the bundled examples at the nominal point, `peak --transient` compares every
// component on a load path with the largest torque the simulations of every jam and rupture put
// into it. The single-DOF value bounds the actuators and station limiters (the limiter law is the
// simulated one); where it is not a bound (the rupture cap on the shafts next to the brake, the PDU,
// which carries both wings) the row says so and by how much; and `peak` gives the actuators the
// verdict the simulation gives them against the same allowable. (The hydraulic example shares the
// A380-class transmission; the 16 sampled points per example are not run here: see the report.)
// Each example's peak --transient: every actuator and station limiter row is a bound of the
// simulation (jams at the end-stop law of the limiter, ruptures at the flap stopped on the
// limiter's end stop: docs/reduced_models.md), every row's flag matches its numbers, and peak and
// the simulation give the same verdict on the actuators. The sampled points are
// campaign.single_dof_against_transient (tests/campaign/single_dof_bound_test.cc). Under
// AddressSanitizer the smallest example only (the 36 simulations of the A380-class example took
// 333 s there; the same code path).
TEST(Examples, PeakBoundsTheSimulatedActuatorAndLimiterLoadsAndSaysWhereItIsNoBound) {
#if defined(__SANITIZE_ADDRESS__)
  const std::vector<const char*> files = {"examples/a320_class_flaps.json"};
#else
  const std::vector<const char*> files = {"examples/a380_class_flaps.json", "examples/a320_class_flaps.json",
                                          "examples/a320_class_slats.json"};
#endif
  for (const char* file : files) {
    SCOPED_TRACE(file);
    const auto peak = RunCli({"peak", file, "--transient", "--json", "--tightness", "0"});
    ASSERT_EQ(peak.exit_code, 1) << peak.err;  // the actuators' margins (README)
    const nlohmann::json j = nlohmann::json::parse(peak.out);
    std::map<std::string, nlohmann::json> worst;
    for (const auto& w : j.at("worst")) worst[w.at("component").get<std::string>()] = w;
    int actuators = 0, limiters = 0, not_bound = 0;
    for (const auto& c : j.at("transient_components")) {
      const std::string id = c.at("component").get<std::string>();
      SCOPED_TRACE(id);
      const double single_dof = c.at("single_dof_N_m").get<double>(), transient = c.at("transient_N_m").get<double>();
      const bool bound = c.at("bound").get<bool>();
      EXPECT_EQ(bound, transient <= single_dof * (1 + 1e-6));
      if (!bound) {
        ++not_bound;
        EXPECT_NEAR(c.at("exceeded_by").get<double>(), transient / single_dof - 1.0, 1e-9);
      }
      if (id.rfind("gra_", 0) == 0) {
        ++actuators;
        // Before the slats' load inertia reached the simulation, 1017 N*m here against 290-442.
        EXPECT_TRUE(bound) << single_dof << " < " << transient;
        EXPECT_GT(transient, 0.0);
        // The same verdict: the simulated torque against the allowable the margin uses.
        const double allowable = worst.at(id).at("allowable_N_m").get<double>();
        const double margin = worst.at(id).at("margin").get<double>();
        EXPECT_EQ(margin < 0, transient > allowable) << "peak margin " << margin << ", simulated " << transient
                                                     << " against " << allowable;
      }
      if (id.rfind("stl_", 0) == 0 && id != "stl_left" && id != "stl_right") {
        ++limiters;
        EXPECT_TRUE(bound) << single_dof << " < " << transient;
      }
    }
    EXPECT_GT(actuators, 0);
    EXPECT_GT(limiters, 0);
    // Every rupture case loads the actuators beyond its break.
    for (const auto& c : j.at("cases"))
      if (c.at("kind") == "rupture") {
        EXPECT_FALSE(c.at("flap_loads").empty()) << c.at("name");
      }
    // Each case row says whether its single-DOF value bounds its simulation.
    int cases_not_bound = 0;
    for (const auto& t : j.at("transient")) {
      ASSERT_TRUE(t.at("ok").get<bool>()) << t.dump();
      EXPECT_EQ(t.at("bound").get<bool>(), t.at("transient").get<double>() <= t.at("single_dof").get<double>() * (1 + 1e-6));
      cases_not_bound += !t.at("bound").get<bool>();
    }
    if (std::string(file) == "examples/a380_class_flaps.json") continue;  // the text once more: the smaller examples
    const auto text = RunCli({"peak", file, "--transient", "--no-intervals"});
    if (not_bound > 0) {
      EXPECT_NE(text.out.find("NOT A BOUND: the simulation exceeds it by"), std::string::npos);
    }
    if (cases_not_bound > 0) {
      EXPECT_NE(text.out.find("NOT A BOUND: exceeded by"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace highlift
