// The component registry: every catalogue type has its model, in catalogue order; the roles,
// speed laws and lumped laws the analyses ask for; one law body serves double and intervals.
#include <gtest/gtest.h>

#include <string>
#include <type_traits>

#include "highlift/core/catalogue.h"
#include "highlift/model/component_model.h"

namespace highlift::model {
namespace {

Component Make(const std::string& id, const std::string& type, std::map<std::string, double> values) {
  Component c;
  c.id = id;
  c.type = type;
  for (const auto& [name, v] : values) {
    Parameter p;
    p.nominal = v;
    p.domain = Domain{v, v};
    p.provenance = Provenance::kUser;
    c.parameters[name] = p;
  }
  return c;
}

/// Reads the component's nominal values (double) or value +- 10 % (Interval).
template <class T>
class Reader final : public ParameterReader<T> {
 public:
  explicit Reader(const Component& c) : c_(c) {}
  T operator()(std::string_view name) const override {
    const double v = *c_.parameters.at(std::string(name)).nominal;
    if constexpr (std::is_same_v<T, double>) return v;
    else return T(0.9 * v, 1.1 * v);
  }
  bool Has(std::string_view name) const override { return c_.parameters.count(std::string(name)) > 0; }
  double Nominal(std::string_view name) const override { return *c_.parameters.at(std::string(name)).nominal; }

 private:
  const Component& c_;
};

TEST(ComponentRegistry, EveryCatalogueTypeHasItsModelInCatalogueOrder) {
  const auto& types = ComponentTypes();
  ASSERT_EQ(ComponentModels().size(), types.size());
  for (std::size_t i = 0; i < types.size(); ++i) {
    EXPECT_EQ(ComponentModels()[i]->type(), types[i].name);
    EXPECT_EQ(FindComponentModel(types[i].name), ComponentModels()[i]);
  }
  EXPECT_EQ(FindComponentModel("no_such_type"), nullptr);
}

TEST(ComponentRegistry, RolesNameTheActuatorsAndTheFailureSites) {
  EXPECT_EQ(TypesWithRole(&ComponentRoles::actuator),
            (std::vector<std::string>{"geared_rotary_actuator", "ballscrew_actuator"}));
  EXPECT_EQ(TypesWithRole(&ComponentRoles::rupturable), (std::vector<std::string>{"torque_shaft", "disconnector"}));
  EXPECT_EQ(TypesWithRole(&ComponentRoles::drive_unit), (std::vector<std::string>{"pdu"}));
  EXPECT_EQ(TypesWithRole(&ComponentRoles::chain_member),
            (std::vector<std::string>{"torque_shaft", "steady_bearing", "universal_joint"}));
}

TEST(ComponentRegistry, GearSpeedRatioFollowsThePowerPath) {
  const Component gearbox = Make("agb", "angle_gearbox", {{"ratio", 4.0}});
  const ComponentModel& m = *FindComponentModel("angle_gearbox");
  EXPECT_DOUBLE_EQ(m.SpeedRatio(gearbox, "input", "output"), 0.25);
  EXPECT_DOUBLE_EQ(m.SpeedRatio(gearbox, "output", "input"), 4.0);
  const Component branch = Make("tgb", "branch_gearbox", {{"ratio", 2.0}});
  const ComponentModel& b = *FindComponentModel("branch_gearbox");
  EXPECT_DOUBLE_EQ(b.SpeedRatio(branch, "input", "through"), 1.0);
  EXPECT_DOUBLE_EQ(b.SpeedRatio(branch, "input", "branch"), 0.5);
  EXPECT_EQ(b.PowerPorts(), (std::vector<std::string>{"branch", "through"}));
  const Component shaft = Make("s", "torque_shaft", {{"length", 1.0}});
  EXPECT_DOUBLE_EQ(FindComponentModel("torque_shaft")->SpeedRatio(shaft, "a", "b"), 1.0);
}

TEST(ComponentRegistry, MissingRatioNamesTheComponentAndParameter) {
  const Component gearbox = Make("agb_7", "angle_gearbox", {});
  try {
    FindComponentModel("angle_gearbox")->SpeedRatio(gearbox, "input", "output");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("component 'agb_7' (angle_gearbox): parameter 'ratio'"), std::string::npos)
        << e.what();
  }
}

// The lumped law is written once; its interval instance encloses its double instance.
TEST(ComponentRegistry, LumpedLawOfThePduServesDoubleAndIntervals) {
  const Component pdu = Make("pdu", "pdu", {{"motor_inertia", 3e-4}, {"motor_count", 2}, {"ratio", 20}, {"gear_inertia", 0.02}});
  const ComponentModel& m = *FindComponentModel("pdu");
  const Lumped<double> point = m.LumpedAtInput(Reader<double>(pdu));
  EXPECT_NEAR(point.J, 3e-4 * 2 * 20 * 20 + 0.02, 1e-15);
  EXPECT_FALSE(point.c);
  const Lumped<Interval> box = m.LumpedAtInput(Reader<Interval>(pdu));
  EXPECT_TRUE(box.J.contains(point.J));
  EXPECT_GT(box.J.width(), 0.0);
}

TEST(ComponentRegistry, ShaftLumpedLawIsTheTubeLaw) {
  const double G = 44e9, D = 0.05, t = 0.002, L = 2.0, rho = 4420;
  const Component shaft = Make("s", "torque_shaft", {{"shear_modulus", G}, {"outer_diameter", D},
                                                     {"wall_thickness", t}, {"length", L}, {"density", rho}});
  const Lumped<double> law = FindComponentModel("torque_shaft")->LumpedAtInput(Reader<double>(shaft));
  const double d = D - 2 * t, polar = 3.14159265358979323846 / 32 * (D * D * D * D - d * d * d * d);
  ASSERT_TRUE(law.c);
  EXPECT_NEAR(*law.c, G * polar / L, 1e-9 * *law.c);
  EXPECT_NEAR(law.J, rho * polar * L, 1e-9 * law.J);
  const Lumped<Interval> box = FindComponentModel("torque_shaft")->LumpedAtInput(Reader<Interval>(shaft));
  EXPECT_TRUE(box.c->contains(*law.c));
  EXPECT_TRUE(box.J.contains(law.J));
}

TEST(ComponentRegistry, LimiterIsElasticWithItsNormalStiffness) {
  const Component stl = Make("stl", "station_torque_limiter", {{"stiffness_normal", 2e4}, {"inertia", 1e-3}});
  const Lumped<double> law = FindComponentModel("station_torque_limiter")->LumpedAtInput(Reader<double>(stl));
  ASSERT_TRUE(law.c);
  EXPECT_EQ(*law.c, 2e4);
  EXPECT_EQ(law.J, 1e-3);
}

}  // namespace
}  // namespace highlift::model
