#include "highlift/reduced_models/analyses.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "test_project.h"

namespace highlift::reduced_models {
namespace {

TEST(Modes, ReducedModelsStayCloseToFullResolution) {
  const ModesReport r = AnalyseModes(test_projects::OneWingProject(), {8, 4});
  ASSERT_EQ(r.models.size(), 3u);
  EXPECT_GT(r.models[0].degrees_of_freedom, r.models[1].degrees_of_freedom);
  for (const auto& m : r.models) {
    ASSERT_FALSE(m.clamped_hz.empty());
    EXPECT_LT(std::abs(m.first_clamped_error), 0.05) << ToString(m.reduction);
    EXPECT_LT(std::abs(m.first_free_error), 0.05) << ToString(m.reduction);
  }
  EXPECT_NEAR(FirstEigenfrequency(test_projects::OneWingProject()) / (2 * 3.141592653589793),
              AnalyseModes(test_projects::OneWingProject()).models[0].clamped_hz[0], 1e-9);
}

TEST(Peak, JamAndRuptureCasesWithEnclosuresAndRanking) {
  const PeakReport r = AnalysePeaks(test_projects::OneWingProject());
  int jams = 0, ruptures = 0;
  for (const auto& c : r.cases) {
    (c.kind == "jam" ? jams : ruptures)++;
    EXPECT_NEAR(c.tau_dynamic.nominal, c.w_max * std::sqrt(c.c_star * c.J_star), 1e-9 * c.tau_dynamic.nominal);
    EXPECT_TRUE(c.tau_dynamic.bounds.contains(c.tau_dynamic.nominal)) << c.name;
    EXPECT_GT(c.tau_dynamic.bounds.width(), 0.0) << c.name;
    ASSERT_FALSE(c.ranking.empty()) << c.name;
    double sum = 0.0;
    for (const auto& p : c.ranking) sum += p.share;
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
  EXPECT_EQ(jams, 3);
  EXPECT_EQ(ruptures, 3);  // shaft_1..3; the tip shaft has the brake itself beyond it
  const PeakCase& rupture = r.cases.back();
  EXPECT_EQ(rupture.acts_at, "wtb");
  EXPECT_GT(rupture.w_max, 25.3);
  EXPECT_FALSE(r.worst.empty());
}

// Each parameter's share is taken with only that parameter over its domain, every other at its
// nominal value: the single-parameter modes share the nominal mode's values where their
// parameter changes nothing (the peak memory of issue 30), and must share none that it changes.
// So every kind of parameter keeps a width of its own, a parameter that changes nothing of a case
// has none there, and taking the uncertainty off one parameter leaves every other parameter's
// width as it was, bit for bit.
TEST(Peak, EachParametersShareIsItsOwnWhateverElseIsUncertain) {
  const Project project = test_projects::OneWingProject();
  const PeakReport all = AnalysePeaks(project);
  auto width = [](const PeakCase& c, const std::string& parameter) {
    for (const auto& p : c.ranking)
      if (p.parameter == parameter) return p.width;
    return 0.0;
  };
  const PeakCase* rupture = nullptr;
  for (const auto& c : all.cases)
    if (c.name == "rupture_shaft_1") rupture = &c;
  ASSERT_NE(rupture, nullptr);
  const double widest = rupture->ranking.at(0).width;
  // An inertia, stiffnesses, a shaft's wall (stiffness, inertia and drag), an efficiency (the
  // back-drive flow), a drag (the friction flow only) and a latency (the timing only).
  for (const char* parameter : {"gra_1.load_inertia", "tgb_1.inertia", "slim_1.stiffness_normal", "shaft_3.shear_modulus",
                                "shaft_3.wall_thickness", "gra_1.eta_aiding", "shaft_3.drag_per_length",
                                "wtb.engagement_latency"})
    EXPECT_GT(width(*rupture, parameter), 1e-3 * widest) << parameter;

  // A parameter that changes nothing of a case is not ranked there (its mode's values are the
  // nominal mode's, whose widths are outward rounding of a point, not uncertainty).
  for (const auto& c : all.cases) {
    if (c.name == "jam_gra_1") {
      EXPECT_EQ(width(c, "wtb.engagement_latency"), 0.0);  // a timing: nothing of a jam
      EXPECT_EQ(width(c, "gra_3.stribeck_decay"), 0.0);     // friction: not the jam's dynamics
      EXPECT_GT(width(c, "shaft_1.shear_modulus"), 0.0);
    }
    if (c.name == "rupture_shaft_3") {
      EXPECT_EQ(width(c, "shaft_1.shear_modulus"), 0.0);  // inboard of the rupture
    }
    for (const auto& p : c.ranking) EXPECT_GT(p.width, 1e-9 * c.ranking.at(0).width) << c.name << ": " << p.parameter;
  }

  Project fewer = project;
  for (Component& c : fewer.components)
    if (c.id == "shaft_2") {
      Parameter& g = c.parameters.at("shear_modulus");
      g.domain = Domain::Point(*g.nominal);
    }
  const PeakReport without = AnalysePeaks(fewer);
  ASSERT_EQ(without.cases.size(), all.cases.size());
  for (std::size_t k = 0; k < all.cases.size(); ++k) {
    const PeakCase& before = all.cases[k];
    const PeakCase& after = without.cases[k];
    EXPECT_EQ(width(after, "shaft_2.shear_modulus"), 0.0) << after.name;
    for (const auto& p : before.ranking) {
      if (p.parameter == "shaft_2.shear_modulus") continue;
      EXPECT_EQ(width(after, p.parameter), p.width) << before.name << ": " << p.parameter;
    }
  }
}

// The wing-tip brake is a friction brake: after a rupture the shaft at it carries no more than it
// passes before it slips, the larger of its dynamic and static torques (domain-wide too). A brake
// stronger than the rigid-stop estimate leaves the estimate as it is.
TEST(Peak, RuptureIsCappedWhereTheBrakeSlips) {
  auto with_brake = [](double dynamic, double holding) {
    Project p = test_projects::OneWingProject();
    for (Component& c : p.components) {
      if (c.id != "wtb") continue;
      Parameter& d = c.parameters["max_dynamic_torque"];
      d.nominal = dynamic;
      d.domain = Domain{0.9 * dynamic, 1.1 * dynamic};
      Parameter& h = c.parameters["static_capacity"];
      h.nominal = holding;
      h.domain = Domain::Point(holding);
    }
    PeakOptions options;
    options.only_case = "rupture_shaft_1";
    options.rank = false;
    return AnalysePeaks(p, options).cases.at(0);
  };
  const PeakCase strong = with_brake(1e6, 1.2e6);
  ASSERT_TRUE(strong.stop_limit.has_value());
  EXPECT_DOUBLE_EQ(strong.stop_limit->nominal, 1.2e6);
  EXPECT_DOUBLE_EQ(strong.tau_total.nominal, strong.tau_dynamic.nominal + strong.tau_static);
  ASSERT_LT(strong.tau_total.nominal, 1e6);

  // Slips at its dynamic torque while it turns; holds more once halted: the larger counts.
  const double rigid = strong.tau_total.nominal;
  const PeakCase weak = with_brake(0.2 * rigid, 0.3 * rigid);
  EXPECT_DOUBLE_EQ(weak.tau_total.nominal, 0.3 * rigid);
  EXPECT_DOUBLE_EQ(weak.tau_total.bounds.hi, 0.3 * rigid);  // the static capacity is a point
  const PeakCase sliding = with_brake(0.3 * rigid, 0.2 * rigid);
  EXPECT_DOUBLE_EQ(sliding.tau_total.nominal, 0.3 * rigid);
  EXPECT_NEAR(sliding.tau_total.bounds.hi, 1.1 * 0.3 * rigid, 1e-9 * rigid);  // its domain's upper bound
  // The dynamic part itself, equation (1), is what it was: only the total is capped.
  EXPECT_DOUBLE_EQ(weak.tau_dynamic.nominal, strong.tau_dynamic.nominal);
}

// Issue 26 item 4: the cap is no bound (the shaft next to the brake also decelerates the rotor
// and shaft between it and the friction face, and the transient exceeds the cap), so a capped
// rupture says it is an estimate in the table and the JSON; an uncapped one does not.
TEST(Peak, ACappedRuptureIsLabelledAnEstimateInTheTableAndTheJson) {
  auto report = [](double dynamic, double holding) {
    Project p = test_projects::OneWingProject();
    for (Component& c : p.components) {
      if (c.id != "wtb") continue;
      c.parameters["max_dynamic_torque"].nominal = dynamic;
      c.parameters["max_dynamic_torque"].domain = Domain::Point(dynamic);
      c.parameters["static_capacity"].nominal = holding;
      c.parameters["static_capacity"].domain = Domain::Point(holding);
    }
    PeakOptions options;
    options.only_case = "rupture_shaft_1";
    options.rank = false;
    return AnalysePeaks(p, options);
  };
  const PeakReport strong = report(1e6, 1.2e6);
  const double rigid = strong.cases.at(0).tau_total.nominal;
  const PeakReport weak = report(0.2 * rigid, 0.3 * rigid);
  ASSERT_DOUBLE_EQ(weak.cases.at(0).tau_total.nominal, 0.3 * rigid);
  EXPECT_EQ(strong.FullReport().find("ESTIMATE, not a bound"), std::string::npos);
  EXPECT_NE(weak.FullReport().find("ESTIMATE, not a bound: tau_max of 1 rupture case(s) is capped"), std::string::npos);
  EXPECT_EQ(strong.ToJson()["cases"][0]["tau_max_is_estimate"], false);
  EXPECT_EQ(weak.ToJson()["cases"][0]["tau_max_is_estimate"], true);
  EXPECT_NE(weak.cases.at(0).note.find("an estimate, not a bound"), std::string::npos);
}

TEST(Peak, EnclosureContainsSampledPointResults) {
  const Project base = test_projects::OneWingProject();
  PeakOptions options;
  options.only_case = "jam_gra_2";
  options.rank = false;
  const PeakReport wide = AnalysePeaks(base, options);
  ASSERT_EQ(wide.cases.size(), 1u);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  options.intervals = false;
  for (int sample = 0; sample < 10; ++sample) {
    Project p = base;
    for (Component& c : p.components)
      for (const ParameterSpec& spec : FindComponentType(c.type)->parameters) {
        if (spec.kind != ParameterKind::kScalar || !spec.nominal) continue;
        Parameter q;
        if (c.parameters.count(spec.name)) {
          q = c.parameters[spec.name];
        } else {
          q.nominal = spec.nominal;
          q.domain = spec.default_domain;
        }
        if (!q.domain.bounded() || q.domain.is_point()) continue;
        q.nominal = q.domain.lo + unit(random) * q.domain.width();
        c.parameters[spec.name] = q;
      }
    const double tau = AnalysePeaks(p, options).cases[0].tau_dynamic.nominal;
    EXPECT_TRUE(wide.cases[0].tau_dynamic.bounds.contains(tau))
        << tau << " not in [" << wide.cases[0].tau_dynamic.bounds.lo << ", " << wide.cases[0].tau_dynamic.bounds.hi << "]";
  }
}

TEST(Peak, UnknownCaseListsTheCases) {
  PeakOptions options;
  options.only_case = "jam_gra_9";
  try {
    AnalysePeaks(test_projects::OneWingProject(), options);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("peak case 'jam_gra_9' does not exist; the cases are: jam_gra_1"),
              std::string::npos)
        << e.what();
  }
}

// Issue 27 item 19 ("J = -nan" naming the wrong node): a derived value that is not finite names
// the component and the parameters it came from, not the lumped node it reaches. Project files
// cannot carry such values (their valid ranges stop them); a project built in code, a sampled
// domain or a library user can: the values here are set past validation.
std::string ModesError(const Project& project) {
  try {
    AnalyseModes(project);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("(not an InputError) ") + e.what();
  }
  return "(no error)";
}

Project SmallDrive() { return LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/tests/export/small_drive.json"); }

void Set(Project& project, const std::string& id, const std::string& name, double value) {
  for (auto& c : project.components)
    if (c.id == id) c.parameters[name].nominal = value;
}

TEST(NonFiniteDerivedValues, AnInertiaThatOverflowsWhenReflectedNamesItsComponentAndParameter) {
  // stl_1 sits behind the branch gearbox (w_branch = w_in / ratio): with ratio 1e-3 its
  // 1e303 kg*m^2 reflect as 1e303 x 1e6 -> inf; before, the lumped node got J = inf and the
  // modes a non-finite matrix.
  Project p = SmallDrive();
  Set(p, "gbx_1", "ratio", 1e-3);
  Set(p, "stl_1", "inertia", 1e303);
  const std::string m = ModesError(p);
  EXPECT_NE(m.find("component 'stl_1': its inertia reflected to the PDU output speed [kg*m^2] is not finite (inf), "
                   "computed from its lumped inertia 1e"),
            std::string::npos)
      << m;
}

TEST(NonFiniteDerivedValues, ASpeedRatioThatOverflowsNamesTheGearboxAndItsRatio) {
  Project p = SmallDrive();
  Set(p, "gbx_1", "ratio", 1e-320);  // w_branch = w_in * ratio or / ratio: 0 or inf either way
  const std::string m = ModesError(p);
  EXPECT_NE(m.find("component 'gbx_1': its speed ratio towards '"), std::string::npos) << m;
  EXPECT_NE(m.find("computed from its parameter ratio = "), std::string::npos) << m;
}

TEST(NonFiniteDerivedValues, ALumpedLawThatOverflowsNamesTheParametersItRead) {
  // The shaft's lumped stiffness G Ip / L with G = 1e308 Pa overflows.
  Project p = SmallDrive();
  Set(p, "shaft_3", "shear_modulus", 1e308);
  Set(p, "shaft_3", "length", 1e-300);
  const std::string m = ModesError(p);
  EXPECT_NE(m.find("component 'shaft_3': its lumped stiffness c [N*m/rad] is not finite (inf), computed from its "
                   "parameters "),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("shear_modulus = 1e"), std::string::npos) << m;
}

}  // namespace
}  // namespace highlift::reduced_models
