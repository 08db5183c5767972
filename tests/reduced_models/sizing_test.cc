#include "highlift/reduced_models/sizing.h"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "highlift/core/error.h"
#include "test_project.h"

namespace highlift::reduced_models {
namespace {

const ComponentTorque& Find(const LoadCaseSizing& s, const std::string& id) {
  for (const auto& c : s.components)
    if (c.component == id) return c;
  throw std::runtime_error("no component " + id);
}

TEST(Sizing, StationTorqueFollowsRatioEfficiencyAndDrag) {
  const SizingReport r = Size(test_projects::OneWingProject());
  ASSERT_EQ(r.cases.size(), 2u);
  const LoadCaseSizing& extend = r.cases[0];
  // GRA input: 20 kN*m / (200 * 0.85) + Stribeck drag (0.2 N*m Coulomb + small terms at 12.65 rad/s).
  const double gra = Find(extend, "gra_1").torque.nominal;
  EXPECT_NEAR(gra, 20e3 / (200 * 0.85) + 0.2, 0.1);
  EXPECT_NEAR(Find(extend, "gra_1").speed, 25.3 / 2.0, 1e-12);
  // Through the 2:1 branch gearbox (eta 0.97) plus its drag.
  const double station = Find(extend, "tgb_3").torque.nominal - Find(extend, "shaft_tip").torque.nominal;
  EXPECT_NEAR(station, gra / (2.0 * 0.97) + 0.1, 0.05);
  // Retraction with aiding loads: the drive holds back, torques negative at the root.
  const LoadCaseSizing& retract = r.cases[1];
  EXPECT_NEAR(Find(retract, "gra_1").torque.nominal, -20e3 * 0.70 / 200 + 0.2, 0.1);
  EXPECT_LT(retract.pdu_torque.nominal, 0.0);
  EXPECT_GT(extend.pdu_power.nominal, 0.0);
  EXPECT_NEAR(extend.pdu_power.nominal, extend.pdu_torque.nominal * 25.3, 1e-9);
}

TEST(Sizing, EnclosureContainsSampledPointResults) {
  const Project base = test_projects::OneWingProject();
  const SizingReport wide = Size(base);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int sample = 0; sample < 20; ++sample) {
    Project p = base;
    // Draw every uncertain parameter (given or catalogue default) inside its domain.
    for (Component& c : p.components) {
      const ComponentTypeSpec* type = FindComponentType(c.type);
      for (const ParameterSpec& spec : type->parameters) {
        if (spec.kind != ParameterKind::kScalar) continue;
        Parameter q;
        if (c.parameters.count(spec.name)) {
          q = c.parameters[spec.name];
        } else if (spec.nominal) {
          q.nominal = spec.nominal;
          q.domain = spec.default_domain;
        } else {
          continue;
        }
        if (!q.domain.bounded() || q.domain.is_point()) continue;
        q.nominal = q.domain.lo + unit(random) * q.domain.width();
        c.parameters[spec.name] = q;
      }
    }
    const SizingReport point = Size(p, {false});
    for (std::size_t k = 0; k < point.cases.size(); ++k)
      for (std::size_t i = 0; i < point.cases[k].components.size(); ++i) {
        const double value = point.cases[k].components[i].torque.nominal;
        const Domain& box = wide.cases[k].components[i].torque.bounds;
        EXPECT_TRUE(box.contains(value)) << point.cases[k].components[i].component << ": " << value << " not in ["
                                         << box.lo << ", " << box.hi << "]";
      }
  }
}

TEST(Sizing, RecommendsLimiterSettingsFromTheOperatingTorque) {
  const SizingReport r = Size(test_projects::OneWingProject());
  bool stl_seen = false, station_seen = false, wtb_seen = false;
  double stl_operating = 0.0, wtb_holding = -1.0;
  for (const auto& s : r.settings) {
    EXPECT_NEAR(s.recommended, s.factor * s.operating.nominal, 1e-9);
    EXPECT_NEAR(s.recommended_robust.lo, s.factor_min * s.operating.bounds.hi, 1e-9);
    if (s.current) {
      EXPECT_EQ(s.robust, s.recommended_robust.contains(*s.current));
    }
    if (s.component == "stl" && s.parameter == "lockout_torque_extend") {
      stl_seen = true;
      EXPECT_DOUBLE_EQ(s.factor, 1.3);
      ASSERT_TRUE(s.current.has_value());
      EXPECT_DOUBLE_EQ(*s.current, 200.0);
      EXPECT_EQ(s.ok, s.current_factor >= 1.2 && s.current_factor <= 1.4);
    }
    if (s.component == "slim_2" && s.parameter == "lockout_torque_extend") {
      station_seen = true;
      EXPECT_NEAR(s.operating.nominal, 20e3 / (200 * 0.85) + 0.2, 0.1);
    }
    if (s.component == "stl" && s.parameter == "lockout_torque_extend") stl_operating = s.operating.nominal;
    if (s.component == "wtb") {
      wtb_seen = true;
      wtb_holding = s.operating.nominal;
    }
  }
  EXPECT_TRUE(stl_seen && station_seen && wtb_seen);
  // The brake holds the larger of the wing's operating torque at its root (the STL's, driving
  // three stations against 20 kN*m) and its back-drive torque (no friction): here the former.
  const double backdrive = 3 * 20e3 * 0.70 / 200 / 2.0 * 0.97;
  EXPECT_GT(stl_operating, backdrive);
  EXPECT_DOUBLE_EQ(wtb_holding, std::max(stl_operating, backdrive));
  EXPECT_GT(r.shaft_mass, 10.0 * 1.2);
  EXPECT_FALSE(r.FullReport().empty());
  EXPECT_EQ(r.ToJson()["load_cases"].size(), 2u);
}

TEST(Sizing, ProjectWithoutLoadCasesIsAnInputErrorWithARemedy) {
  Project p = test_projects::OneWingProject();
  p.load_cases.clear();
  try {
    Size(p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has no load cases"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("add one under \"load_cases\""), std::string::npos) << e.what();
  }
}

TEST(Sizing, ProjectWithoutPduIsAnInputError) {
  Project p = test_projects::OneWingProject();
  p.components.erase(p.components.begin());
  try {
    Size(p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has no component of type 'pdu'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace highlift::reduced_models
