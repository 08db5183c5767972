// Empirical fits over database parts.
#include <gtest/gtest.h>

#include <cmath>

#include "highlift/componentdb/database.h"
#include "highlift/estimation/fit.h"

namespace highlift::estimation {
namespace {

componentdb::Quantity Point(const std::string& name, double si) {
  componentdb::Quantity q;
  q.name = name;
  q.value = si;
  q.value_si = si;
  q.domain_si = Domain::Point(si);
  q.unit = "SI";
  q.source = "synthetic";
  return q;
}

std::vector<componentdb::Part> SyntheticGras(int n, double exponent) {
  std::vector<componentdb::Part> parts;
  for (int i = 0; i < n; ++i) {
    componentdb::Part p;
    p.type = "geared_rotary_actuator";
    p.designation = "SYN-" + std::to_string(i);
    const double torque = 2e3 * std::pow(1.4, i);
    // A deterministic +-10 % scatter around 4e-8 T^exponent.
    const double scatter = 1.0 + 0.1 * std::sin(1.3 * i + 0.4);
    p.parameters = {Point("output_torque_rating", torque), Point("input_inertia", 4e-8 * std::pow(torque, exponent) * scatter)};
    parts.push_back(p);
  }
  // A part of another type and a part without the fitted parameter are ignored.
  componentdb::Part other;
  other.type = "wing_tip_brake";
  other.designation = "OTHER";
  other.parameters = {Point("output_torque_rating", 5e3), Point("input_inertia", 1.0)};
  parts.push_back(other);
  componentdb::Part partial;
  partial.type = "geared_rotary_actuator";
  partial.designation = "NO-INERTIA";
  partial.parameters = {Point("output_torque_rating", 5e3)};
  parts.push_back(partial);
  return parts;
}

TEST(FitParameter, RecoversTheExponentAndRecordsThePartsUsed) {
  const auto fit = FitParameter(SyntheticGras(10, 1.6), "geared_rotary_actuator", "input_inertia", "output_torque_rating");
  ASSERT_TRUE(fit.ok()) << fit.message;
  EXPECT_NEAR(fit.law.exponent, 1.6, 0.05);
  EXPECT_EQ(fit.parts_used.size(), 10u);
  EXPECT_EQ(fit.parts_used.front(), "SYN-0");
  for (const auto& d : fit.parts_used) EXPECT_NE(d, "OTHER");
  // The prediction interval holds the nominal prediction and widens away from the data.
  const Domain at_middle = fit.PredictionInterval(Domain::Point(10e3));
  EXPECT_TRUE(at_middle.contains(fit.Predict(10e3)));
  const Domain far = fit.PredictionInterval(Domain::Point(1e6));
  EXPECT_GT(far.hi / far.lo, at_middle.hi / at_middle.lo);
  EXPECT_TRUE(fit.Extrapolates(Domain::Point(1e6)));
  EXPECT_FALSE(fit.Extrapolates(Domain::Point(10e3)));
  // A rating interval gives the hull of the intervals at its ends.
  const Domain hull = fit.PredictionInterval({8e3, 12e3});
  EXPECT_LE(hull.lo, fit.PredictionInterval(Domain::Point(8e3)).lo);
  EXPECT_GE(hull.hi, fit.PredictionInterval(Domain::Point(12e3)).hi);
}

TEST(FitParameter, TooFewPartsSaysSoWithTheCount) {
  const auto fit = FitParameter(SyntheticGras(2, 1.6), "geared_rotary_actuator", "input_inertia", "output_torque_rating");
  EXPECT_FALSE(fit.ok());
  EXPECT_EQ(fit.message,
            "no fit of geared_rotary_actuator.input_inertia against output_torque_rating: only 2 database parts of "
            "type geared_rotary_actuator have both values, at least 4 are needed; import more parts (highlift db "
            "import) or give the value");
}

TEST(FitParameter, SeedDatabaseGivesGraInertiaAroundTheSectionSixValue) {
  const auto seed = componentdb::SeedRecords();
  const auto fit = FitParameter(seed.parts, "geared_rotary_actuator", "input_inertia", "output_torque_rating");
  ASSERT_TRUE(fit.ok()) << fit.message;
  EXPECT_GE(fit.parts_used.size(), 20u);
  // domain.md s6: GRA input J about 1e-3 kg m^2 at 20 kN m.
  const Domain at20 = fit.PredictionInterval(Domain::Point(20e3));
  EXPECT_TRUE(at20.contains(1e-3)) << at20.lo << " " << at20.hi;
  EXPECT_GT(fit.law.exponent, 0.2);  // rises with torque, slower than 5/3 above the floor
}

}  // namespace
}  // namespace highlift::estimation
