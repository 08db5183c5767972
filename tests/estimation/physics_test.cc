// The physics laws against hand-computed values (domain.md s3/s4) and on intervals.
#include <gtest/gtest.h>

#include <boost/numeric/interval.hpp>

#include "highlift/estimation/physics.h"

namespace highlift::estimation {
namespace {

constexpr double kG = 44e9;     // Pa, Ti-6Al-4V (domain.md s3)
constexpr double kRho = 4420;   // kg/m^3

TEST(ShaftStiffness, TitaniumTube50x2Over4MetresIs1914) {
  // GJ = 44e9 * pi/32 * (0.05^4 - 0.046^4) = 7657 N m^2; c = GJ / 4 m = 1914 N m/rad.
  EXPECT_NEAR(kG * TubePolarMoment(0.05, 0.046), 7657.0, 1.0);
  EXPECT_NEAR(ShaftStiffness(kG, 0.05, 0.046, 4.0), 1914.0, 0.5);
  // The other segments of the A380-class table.
  EXPECT_NEAR(ShaftStiffness(kG, 0.05, 0.046, 3.0), 2552.0, 0.5);
  EXPECT_NEAR(ShaftStiffness(kG, 0.045, 0.0414, 3.5), 1435.0, 0.5);
  EXPECT_NEAR(ShaftStiffness(kG, 0.045, 0.0414, 1.5), 3349.0, 0.5);
  // A320-class 38 x 1.5 mm: GJ = 2525 N m^2.
  EXPECT_NEAR(ShaftStiffness(kG, 0.038, 0.035, 1.0), 2525.0, 1.0);
}

TEST(ShaftMassPerLength, TitaniumTube50x2Is1Point33KgPerMetre) {
  EXPECT_NEAR(ShaftMassPerLength(kRho, 0.05, 0.046), 1.333, 0.001);
  EXPECT_NEAR(ShaftMassPerLength(kRho, 0.045, 0.0414), 1.08, 0.005);
  EXPECT_NEAR(ShaftMassPerLength(kRho, 0.038, 0.035), 0.76, 0.005);
  EXPECT_NEAR(ShaftMass(kRho, 0.05, 0.046, 4.0), 4 * 1.333, 0.005);
}

TEST(ShaftInertia, EqualsDensityTimesPolarMomentTimesLength) {
  // J = rho Ip L = 4420 * 1.7403e-7 * 4 = 3.077e-3 kg m^2 for the 4 m PCU-RGB segment.
  EXPECT_NEAR(ShaftInertia(kRho, 0.05, 0.046, 4.0), 3.077e-3, 2e-6);
}

TEST(ShaftTorqueCapacity, TitaniumTubesMatchDomainUltimates) {
  EXPECT_NEAR(ShaftTorqueCapacity(550e6, 0.05, 0.046), 3828.0, 5.0);     // about 3.8 kN m
  EXPECT_NEAR(ShaftTorqueCapacity(550e6, 0.045, 0.0414), 2791.0, 1.0);   // about 2.8 kN m
  EXPECT_NEAR(ShaftTorqueCapacity(550e6, 0.038, 0.035), 1661.0, 5.0);    // about 1.66 kN m
}

TEST(ReflectedInertia, ThroughAGearScalesWithTheRatioSquared) {
  EXPECT_DOUBLE_EQ(InertiaAtInput(4.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(InertiaAtOutput(1.0, 2.0), 4.0);
  EXPECT_DOUBLE_EQ(InertiaAtInput(InertiaAtOutput(3e-4, 20.0), 20.0), 3e-4);
}

TEST(FlapInertiaAtInput, A380ClassPanelGivesTheStationValue) {
  // 1200 kg over 2.5 m stroke and 2.2 rad GRA travel, station ratio 400: 9.7e-3 kg m^2 (s3).
  EXPECT_NEAR(FlapInertiaAtInput(1200.0, 2.5, 2.2, 400.0), 9.7e-3, 0.05e-3);
}

TEST(PduOutputInertia, MatchesTheA380AndA320ClassLumps) {
  EXPECT_NEAR(PduOutputInertia(3e-4, 2.0, 20.0, 0.02), 0.26, 1e-12);
  EXPECT_NEAR(PduOutputInertia(1.5e-4, 2.0, 16.0, 0.01), 0.0868, 1e-12);
}

TEST(GearScaling, InertiaAboveTheFloorGrowsWithFiveThirdsPowerOfTorque) {
  const GearScaling k;
  EXPECT_NEAR(ActuatorInputInertia(20e3, 200.0, 0.85), 1e-3, 1e-12);  // the reference GRA
  // 8^(5/3) = 32 on the part above the floor.
  EXPECT_NEAR(GearboxInertiaFromTorque(8.0 * k.input_torque_reference), 3e-4 + 7e-4 * 32.0, 1e-9);
  // A320-class flap GRA, 6 kN m at 300:1 (domain.md s4): 3.5e-4 kg m^2.
  EXPECT_NEAR(ActuatorInputInertia(6e3, 300.0, 0.85), 3.48e-4, 0.01e-4);
  EXPECT_NEAR(GearboxMassFromTorque(20e3), 20.0, 1e-12);
  EXPECT_NEAR(GearboxMassFromTorque(40e3), 20.0 * std::pow(2.0, 0.8), 1e-9);
}

TEST(BearingDragPerLength, DividesTheDragOfOneBearingByTheSpacing) {
  EXPECT_DOUBLE_EQ(BearingDragPerLength(0.1, 0.5), 0.2);
}

TEST(ShaftStiffness, OnIntervalsEnclosesEveryPointResult) {
  using I = boost::numeric::interval<double>;
  const I G(43e9, 51e9), D(0.0499, 0.0501), t(0.0019, 0.0021), L(4.0, 4.0);
  const I c = ShaftStiffness(G, D, D - t - t, L);
  for (double g : {43e9, 47e9, 51e9})
    for (double dd : {0.0499, 0.05, 0.0501})
      for (double tt : {0.0019, 0.002, 0.0021}) {
        const double v = ShaftStiffness(g, dd, dd - 2 * tt, 4.0);
        EXPECT_LE(c.lower(), v);
        EXPECT_GE(c.upper(), v);
      }
  EXPECT_GT(c.lower(), 1650.0);  // d = D - 2t evaluated naively: a little wider
  EXPECT_LT(c.upper(), 2500.0);
}

}  // namespace
}  // namespace highlift::estimation
