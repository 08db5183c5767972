#include "highlift/core/catalogue.h"

#include <gtest/gtest.h>

#include "highlift/core/error.h"
#include "highlift/model/component_model.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace highlift {
namespace {

TEST(Catalogue, HasTheFifteenDriveSystemTypesInOrder) {
  const std::vector<std::string> expected = {
      "pdu", "system_torque_limiter", "torque_shaft", "steady_bearing", "universal_joint", "angle_gearbox",
      "branch_gearbox", "station_torque_limiter", "station_input_gearbox", "geared_rotary_actuator",
      "ballscrew_actuator", "wing_tip_brake", "position_sensor", "disconnector", "jam"};
  EXPECT_EQ(ComponentTypeNames(), expected);
  for (const auto& name : expected) EXPECT_NE(FindComponentType(name), nullptr) << name;
  EXPECT_EQ(FindComponentType("gra"), nullptr);
}

// The declarations live in the model layer, which installs them when the program starts; a
// program without it is told what to link.
TEST(Catalogue, IsInstalledByTheModelLayerAndSaysSoWhenItIsNot) {
  ASSERT_TRUE(ComponentCatalogueInstalled());
  EXPECT_EQ(&ComponentTypes(), &model::ComponentCatalogue());
  InstallComponentCatalogue(nullptr);
  EXPECT_FALSE(ComponentCatalogueInstalled());
  try {
    FindComponentType("pdu");
    ADD_FAILURE() << "expected an InternalError";
  } catch (const InternalError& e) {
    EXPECT_NE(std::string(e.what()).find("no component catalogue is installed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("link highlift::model"), std::string::npos) << e.what();
  }
  model::InstallComponentCatalogue();
  ASSERT_TRUE(ComponentCatalogueInstalled());
  EXPECT_NE(FindComponentType("pdu"), nullptr);
}

TEST(Catalogue, EveryTypeHasItsPorts) {
  const std::map<std::string, std::vector<std::pair<std::string, bool>>> ports = {
      {"pdu", {{"left", true}, {"right", false}}},
      {"system_torque_limiter", {{"input", true}, {"output", true}}},
      {"torque_shaft", {{"a", true}, {"b", true}}},
      {"steady_bearing", {{"a", true}, {"b", true}}},
      {"universal_joint", {{"a", true}, {"b", true}}},
      {"angle_gearbox", {{"input", true}, {"output", true}}},
      {"branch_gearbox", {{"input", true}, {"through", false}, {"branch", true}}},
      {"station_torque_limiter", {{"input", true}, {"output", true}}},
      {"station_input_gearbox", {{"input", true}, {"through", false}, {"branch", true}}},
      {"geared_rotary_actuator", {{"input", true}}},
      {"ballscrew_actuator", {{"input", true}}},
      {"wing_tip_brake", {{"a", true}, {"b", false}}},
      {"position_sensor", {{"a", true}, {"b", false}}},
      {"disconnector", {{"a", true}, {"b", true}}},
      {"jam", {{"a", true}}},
  };
  for (const auto& t : ComponentTypes()) {
    ASSERT_TRUE(ports.count(t.name)) << t.name;
    const auto& want = ports.at(t.name);
    ASSERT_EQ(t.ports.size(), want.size()) << t.name;
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(t.ports[i].name, want[i].first) << t.name;
      EXPECT_EQ(t.ports[i].required, want[i].second) << t.name << "." << want[i].first;
      EXPECT_EQ(t.FindPort(want[i].first), &t.ports[i]);
    }
    EXPECT_EQ(t.FindPort("nonexistent"), nullptr);
  }
}

TEST(Catalogue, EveryDefaultLiesInsideItsValidRange) {
  for (const auto& t : ComponentTypes()) {
    std::set<std::string> names;
    for (const auto& p : t.parameters) {
      const std::string what = t.name + "." + p.name;
      EXPECT_TRUE(names.insert(p.name).second) << "duplicate parameter " << what;
      EXPECT_FALSE(p.description.empty()) << what;
      EXPECT_FALSE(p.source.empty()) << what;
      if (p.kind == ParameterKind::kText || p.kind == ParameterKind::kTable) continue;
      EXPECT_FALSE(p.valid_range.empty()) << what;
      EXPECT_FALSE(p.default_domain.empty()) << what;
      EXPECT_LE(p.valid_range.lo, p.default_domain.lo) << what;
      EXPECT_GE(p.valid_range.hi, p.default_domain.hi) << what;
      if (p.nominal) {
        EXPECT_TRUE(p.default_domain.contains(*p.nominal)) << what;
        EXPECT_TRUE(std::isfinite(*p.nominal)) << what;
      } else {
        EXPECT_TRUE(p.optional || p.name == "length") << what << " has no nominal value but is not optional";
      }
      // the display unit belongs to the declared dimension
      EXPECT_EQ(ParseUnit(p.unit.empty() ? "1" : p.unit).dimension, p.dimension) << what << " unit " << p.unit;
    }
  }
}

TEST(Catalogue, ElementTypeDefaultsLieInsideTheirValidRanges) {
  for (const auto& t : ElementTypes()) {
    EXPECT_EQ(FindElementType(t.name), &t);
    for (const auto& p : t.parameters) {
      const std::string what = t.name + "." + p.name;
      if (p.kind == ParameterKind::kText || p.kind == ParameterKind::kTable) continue;
      EXPECT_LE(p.valid_range.lo, p.default_domain.lo) << what;
      EXPECT_GE(p.valid_range.hi, p.default_domain.hi) << what;
      if (p.nominal) {
        EXPECT_TRUE(p.default_domain.contains(*p.nominal)) << what;
      }
      EXPECT_EQ(ParseUnit(p.unit.empty() ? "1" : p.unit).dimension, p.dimension) << what << " unit " << p.unit;
    }
  }
}

TEST(Catalogue, ParametersTheOtherModulesReadExist) {
  const std::map<std::string, std::vector<std::string>> needed = {
      {"torque_shaft", {"length", "outer_diameter", "wall_thickness", "shear_modulus", "density",
                        "allowable_shear_stress", "stiffness", "inertia"}},
      {"pdu", {"motor_count", "motor_inertia", "ratio", "gear_inertia", "efficiency", "max_output_speed",
               "stall_torque", "power", "brake_torque", "speed_ramp_time"}},
      {"geared_rotary_actuator", {"ratio", "eta_opposing", "eta_aiding", "input_inertia", "output_torque_rating",
                                  "travel_angle", "eta_settle_angle"}},
      {"wing_tip_brake", {"max_dynamic_torque", "static_capacity", "time_to_max_torque", "engagement_latency"}},
      {"station_torque_limiter", {"lockout_torque_extend", "lockout_torque_retract", "end_stop_torque",
                                  "stiffness_normal", "stiffness_lockout", "stiffness_end_stop"}},
      {"steady_bearing", {"coulomb_torque", "viscous_coefficient", "stribeck_torque", "stribeck_decay"}},
      {"angle_gearbox", {"ratio", "eta_mesh", "meshes", "backlash"}},
      {"position_sensor", {"latency", "asymmetry_threshold"}},
  };
  for (const auto& [type, params] : needed)
    for (const auto& p : params) EXPECT_NE(FindComponentType(type)->FindParameter(p), nullptr) << type << "." << p;
}

TEST(Catalogue, DefaultsMatchTheReferenceData) {
  // domain.md s3: Ti-6Al-4V G 44 GPa, rho 4420 kg/m3; GRA 200:1, eta 0.85/0.70; 242 rpm.
  const auto* shaft = FindComponentType("torque_shaft");
  EXPECT_DOUBLE_EQ(*shaft->FindParameter("shear_modulus")->nominal, 44e9);
  EXPECT_EQ(shaft->FindParameter("shear_modulus")->default_domain, (Domain{43e9, 51e9}));
  EXPECT_DOUBLE_EQ(*shaft->FindParameter("density")->nominal, 4420);
  EXPECT_DOUBLE_EQ(*shaft->FindParameter("outer_diameter")->nominal, 0.05);
  const auto* gra = FindComponentType("geared_rotary_actuator");
  EXPECT_DOUBLE_EQ(*gra->FindParameter("ratio")->nominal, 200);
  EXPECT_DOUBLE_EQ(*gra->FindParameter("eta_opposing")->nominal, 0.85);
  EXPECT_DOUBLE_EQ(*gra->FindParameter("eta_aiding")->nominal, 0.70);
  EXPECT_NEAR(*FindComponentType("pdu")->FindParameter("max_output_speed")->nominal, 25.34, 0.01);
  EXPECT_NEAR(*FindComponentType("wing_tip_brake")->FindParameter("engagement_latency")->nominal, 0.1, 1e-12);
}

TEST(Catalogue, EveryInertiaStiffnessDampingAndTorqueStatesItsGearSide) {
  // A value on the wrong side of a gear is off by the ratio squared (issue 20): each declaration
  // says where it counts.
  const std::vector<Dimension> rotational = {dimensions::Inertia(), dimensions::Torque(),
                                             dimensions::RotationalDamping(), dimensions::TorquePerLength()};
  int stated = 0;
  for (const auto& t : ComponentTypes())
    for (const auto& p : t.parameters) {
      if (p.kind != ParameterKind::kScalar) continue;
      const bool needs_side = std::find(rotational.begin(), rotational.end(), p.dimension) != rotational.end();
      if (needs_side) {
        EXPECT_NE(p.referred_to, ReferenceSide::kNone) << t.name << "." << p.name;
        ++stated;
      }
    }
  EXPECT_GT(stated, 50);
}

TEST(Catalogue, GearSidesRoundTripAndReadInTheDocs) {
  for (const ReferenceSide side : {ReferenceSide::kNone, ReferenceSide::kMotor, ReferenceSide::kPduOutput,
                                   ReferenceSide::kShaft, ReferenceSide::kActuatorInput,
                                   ReferenceSide::kActuatorOutput})
    EXPECT_EQ(ParseReferenceSide(ToString(side)), side) << ToString(side);
  EXPECT_FALSE(ParseReferenceSide("shaft side").has_value());
  const auto* gra = FindComponentType("geared_rotary_actuator");
  EXPECT_EQ(gra->FindParameter("load_inertia")->referred_to, ReferenceSide::kActuatorInput);
  EXPECT_EQ(gra->FindParameter("output_torque_rating")->referred_to, ReferenceSide::kActuatorOutput);
  EXPECT_EQ(FindComponentType("pdu")->FindParameter("motor_inertia")->referred_to, ReferenceSide::kMotor);
  EXPECT_EQ(FindComponentType("pdu")->FindParameter("stall_torque")->referred_to, ReferenceSide::kPduOutput);
  EXPECT_EQ(FindComponentType("torque_shaft")->FindParameter("stiffness")->referred_to, ReferenceSide::kShaft);
  EXPECT_EQ(FindComponentType("station_torque_limiter")->FindParameter("lockout_torque_extend")->referred_to,
            ReferenceSide::kActuatorInput);
  const std::string md = CatalogueMarkdown();
  EXPECT_NE(md.find("| referred to |"), std::string::npos);
  EXPECT_NE(md.find("| `load_inertia` | `J_load` | `kg*m^2` | actuator input | 0.0388 |"), std::string::npos);
  EXPECT_NE(md.find("| `motor_inertia` | `J_m` | `kg*m^2` | motor side |"), std::string::npos);
}

TEST(Catalogue, DefaultFlapInertiaIsTheShaftSideValueReferredToTheActuatorInput) {
  // domain.md s3 (E): reflected flap 9.7e-3 kg*m^2 at the shaft; the GRA's load_inertia counts at
  // the actuator input, behind the default station gearbox (2:1): 9.7e-3 x 2^2.
  const double station_ratio = *FindComponentType("branch_gearbox")->FindParameter("ratio")->nominal;
  const double at_input = *FindComponentType("geared_rotary_actuator")->FindParameter("load_inertia")->nominal;
  EXPECT_DOUBLE_EQ(station_ratio, 2.0);
  EXPECT_NEAR(at_input / (station_ratio * station_ratio), 9.7e-3, 1e-12);
  // The station limiter sits behind the same gearbox: domain.md s3 "station limiter about 1.5 x
  // 58.8 = 90 N m" at the shaft.
  const double trip = *FindComponentType("station_torque_limiter")->FindParameter("lockout_torque_extend")->nominal;
  EXPECT_DOUBLE_EQ(trip / station_ratio, 90.0);
}

TEST(Suggest, FindsCloseNames) {
  const std::vector<std::string> names = ComponentTypeNames();
  EXPECT_EQ(Suggest("geared_rotary_actuatr", names), std::vector<std::string>{"geared_rotary_actuator"});
  EXPECT_EQ(Suggest("PDU", names), std::vector<std::string>{"pdu"});
  EXPECT_EQ(Suggest("wingtip_brake", names), std::vector<std::string>{"wing_tip_brake"});
  EXPECT_TRUE(Suggest("completely_different", names).empty());
  EXPECT_EQ(Suggest("lenght", {"length", "width", "height"}, 1), std::vector<std::string>{"length"});
}

}  // namespace
}  // namespace highlift
