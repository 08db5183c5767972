#include "highlift/core/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include "highlift/core/error.h"
#include "unit_table.h"  // core/src: the built-in unit table

namespace highlift {
namespace {

using namespace dimensions;
constexpr double kRel = 1e-12;

TEST(Units, ConvertsEngineeringUnitsToSI) {
  EXPECT_NEAR(ToSI(50, "mm", Length()), 0.05, 0.05 * kRel);
  EXPECT_NEAR(ToSI(242, "rpm", AngularVelocity()), 242 * 2 * std::numbers::pi / 60, 25 * kRel);
  EXPECT_NEAR(ToSI(5000, "psi", Pressure()), 5000 * 6894.757293168361, 3.5e7 * kRel);
  EXPECT_NEAR(ToSI(207, "bar", Pressure()), 207e5, 207e5 * kRel);
  EXPECT_NEAR(ToSI(90, "deg", Dimensionless()), std::numbers::pi / 2, kRel);
  EXPECT_NEAR(ToSI(1, "rev", Dimensionless()), 2 * std::numbers::pi, kRel);
  EXPECT_NEAR(ToSI(3e-4, "kg*m^2", Inertia()), 3e-4, 3e-4 * kRel);
  EXPECT_NEAR(ToSI(3e-4, "kg m2", Inertia()), 3e-4, 3e-4 * kRel);
  EXPECT_NEAR(ToSI(1.2, "kg/m", LinearDensity()), 1.2, kRel);
  EXPECT_NEAR(ToSI(44, "GPa", Pressure()), 44e9, 44e9 * kRel);
  EXPECT_NEAR(ToSI(20, "kN*m", Torque()), 2e4, 2e4 * kRel);
  EXPECT_NEAR(ToSI(18, "kW", Power()), 1.8e4, 1.8e4 * kRel);
  EXPECT_NEAR(ToSI(100, "ms", Time()), 0.1, kRel);
  EXPECT_NEAR(ToSI(4.4, "cm^3/rev", Volume()), 4.4e-6 / (2 * std::numbers::pi), 1e-18);
}

TEST(Units, AnglesAreDimensionless) {
  // rad is 1: a torsional stiffness is a torque, an angular velocity is 1/s.
  EXPECT_EQ(ParseUnit("N*m/rad").dimension, Torque());
  EXPECT_EQ(ParseUnit("rad/s").dimension, AngularVelocity());
  EXPECT_EQ(ParseUnit("rad").dimension, Dimensionless());
  EXPECT_EQ(ParseUnit("N*m*s/rad").dimension, RotationalDamping());
}

TEST(Units, AcceptsCommonSpellingsOfNewtonMetre) {
  for (const char* u : {"N*m", "N.m", "N m", "Nm", "N\u00b7m"}) {
    const UnitConversion c = ParseUnit(u);
    EXPECT_EQ(c.dimension, Torque()) << u;
    EXPECT_DOUBLE_EQ(c.scale, 1.0) << u;
  }
}

TEST(Units, TemperatureHasAnOffset) {
  EXPECT_NEAR(ParseUnit("degC").offset, 273.15, 1e-9);
}

TEST(Units, UnknownUnitNamesTheUnit) {
  try {
    ParseUnit("mmm");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "unknown unit 'mmm'");
  }
}

TEST(Units, WrongDimensionSaysWhatWasExpected) {
  try {
    ToSI(5, "mm", Torque());
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "expected a torque (N*m), got a length (mm)");
  }
  try {
    ToSI(5, "kg*m^3", Inertia());
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "expected an inertia (kg*m^2), got a quantity of dimension kg*m^3 (kg*m^3)");
  }
}

TEST(Units, ExponentOverflowIsAnError) {
  // Issue 27 item 9: UDUNITS-2 read the exponent into an int, so m^4294967297 was m^1 (4 m).
  for (const std::string unit : {"m^4294967297", "m4294967297", "m**4294967297", "s^-4294967297", "kg*m^0004294967298"}) {
    try {
      ParseUnit(unit);
      ADD_FAILURE() << unit << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(e.message().find("is beyond what highlift handles (-24 to 24)"), std::string::npos) << e.message();
      EXPECT_NE(e.message().find("the exponent " + std::string(unit[0] == 's' ? "-" : "") + "42949672"),
                std::string::npos) << e.message();
    }
  }
  EXPECT_THROW(ToSI(4, "m^4294967297", Length()), InputError);
  // Exponents in range, and digits of numbers, are as before.
  EXPECT_EQ(ParseUnit("m^2").dimension, Area());
  EXPECT_EQ(ParseUnit("kg m2").dimension, Inertia());
  EXPECT_EQ(ParseUnit("s-1").dimension, AngularVelocity());
  EXPECT_NEAR(ToSI(1, "1e3 m", Length()), 1e3, 1e-9);
}

TEST(Units, FromSIInvertsToSI) {
  EXPECT_NEAR(FromSI(ToSI(242, "rpm", AngularVelocity()), "rpm", AngularVelocity()), 242, 242 * kRel);
  EXPECT_NEAR(FromSI(300.15, "degC", ParseUnit("K").dimension), 27, 1e-9);
  EXPECT_THROW(FromSI(1, "mm", Time()), InputError);
}

TEST(Units, DimensionArithmeticAndText) {
  EXPECT_EQ(Torque() / Length(), Force());
  EXPECT_EQ(Length().pow(2) * Mass(), Inertia());
  EXPECT_EQ(Torque().ToString(), "kg*m^2*s^-2");
  EXPECT_EQ(Dimensionless().ToString(), "1");
  EXPECT_EQ(DescribeDimension(Pressure()), "pressure");
  EXPECT_EQ(DescribeDimension(Length().pow(5)), "m^5");
}

TEST(Units, ParsingIsThreadSafe) {
  std::vector<std::thread> threads;
  std::vector<double> results(8, 0.0);
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([t, &results] {
      double sum = 0;
      for (int i = 0; i < 50; ++i) sum += ToSI(1.0, i % 2 ? "kN*m" : "N*m", Torque());
      results[static_cast<std::size_t>(t)] = sum;
    });
  }
  for (auto& th : threads) th.join();
  for (double r : results) EXPECT_DOUBLE_EQ(r, 25 * 1000.0 + 25 * 1.0);
}

TEST(Units, BuiltInTableAgreesWithUdunitsBitForBit) {
  // Every entry of the built-in table is what UDUNITS-2's database gives for its text: the same
  // doubles (not merely close) and the same dimension, so a project converts as it did before.
  ASSERT_TRUE(detail::BuiltInUnitsApply()) << "this machine reads UDUNITS-2's default database";
  ASSERT_FALSE(detail::BuiltInUnits().empty());
  for (const auto& b : detail::BuiltInUnits()) {
    const UnitConversion db = detail::ParseUnitWithDatabase(b.text);
    EXPECT_EQ(b.conversion.scale, db.scale) << b.text;
    EXPECT_EQ(b.conversion.offset, db.offset) << b.text;
    EXPECT_EQ(b.conversion.dimension, db.dimension) << b.text;
    const UnitConversion parsed = ParseUnit(b.text);  // the table's answer
    EXPECT_EQ(parsed.scale, db.scale) << b.text;
    EXPECT_EQ(parsed.dimension, db.dimension) << b.text;
  }
  // Around the table, ParseUnit trims and falls back to the database as before.
  EXPECT_EQ(ParseUnit("  N*m/rad ").dimension, Torque());
  EXPECT_EQ(ParseUnit("mrad").scale, detail::ParseUnitWithDatabase("mrad").scale);
  EXPECT_EQ(ParseUnit("1").dimension, Dimensionless());
}

}  // namespace
}  // namespace highlift
