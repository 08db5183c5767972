// A thin torque tube (80 x 1 mm, D/t 80) in the one-wing project: `highlift peak` and
// `highlift size` set its loads against min(tau_allow, tau_cr) 2 Ip / D (laws.h), and its jam
// peak fails by torsional buckling while it stays far below the tube's capacity in shear.
#include <gtest/gtest.h>

#include <string>

#include "highlift/model/laws.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sizing.h"
#include "test_project.h"

namespace highlift::reduced_models {
namespace {

Project ThinTubeProject() {
  Project p = test_projects::OneWingProject();
  for (Component& c : p.components)
    if (c.id == "shaft_1") {
      c.parameters["outer_diameter"] = test_projects::Value(0.080);
      c.parameters["wall_thickness"] = test_projects::Value(0.001);
    }
  return p;
}

// Over the domains: G [43, 51] GPa (the project), nu [0.31, 0.34] and tau_allow [500, 600] MPa
// (the catalogue defaults), knock-down 0.67: the least buckling torque at G 43 GPa, nu 0.31.
constexpr double kD = 0.080, kT = 0.001, kL = 3.5;
double ShearCapacity() { return model::TubeTorqueCapacity(500e6, kD, model::TubePolarMoment(kD, kT)); }
double BucklingCapacity() {
  return model::TubeTorqueCapacity(model::TubeBucklingStress(43e9, 0.31, 0.67, kD, kT, kL), kD, model::TubePolarMoment(kD, kT));
}

TEST(ShaftBuckling, AThinTubesPeakFailsByBucklingNotByShear) {
  const PeakReport r = AnalysePeaks(ThinTubeProject());
  const ComponentPeak* w = nullptr;
  for (const ComponentPeak& c : r.worst)
    if (c.component == "shaft_1") w = &c;
  ASSERT_TRUE(w);
  EXPECT_EQ(w->allowable_name, "torque capacity (torsional buckling)");
  EXPECT_NEAR(w->allowable_min, BucklingCapacity(), 1e-6 * BucklingCapacity());
  EXPECT_LE(w->allowable_min, BucklingCapacity());
  EXPECT_LT(BucklingCapacity(), 0.2 * ShearCapacity());
  EXPECT_LT(w->margin, 0.0) << "peak " << w->local_torque << " N*m against " << w->allowable_min;
  EXPECT_LT(w->local_torque, ShearCapacity()) << "it would carry the peak in shear";
  EXPECT_FALSE(r.ok());
}

TEST(ShaftBuckling, SizingSetsTheOperatingTorqueAgainstTheBucklingTorque) {
  const SizingReport r = Size(ThinTubeProject());
  const AllowableMargin* m = nullptr;
  for (const AllowableMargin& a : r.margins)
    if (a.component == "shaft_1") m = &a;
  ASSERT_TRUE(m);
  EXPECT_NEAR(m->allowable, BucklingCapacity(), 1e-6 * BucklingCapacity());
  EXPECT_LE(m->allowable, BucklingCapacity());
  EXPECT_NEAR(m->margin, m->allowable / m->load - 1.0, 1e-9);
}

}  // namespace
}  // namespace highlift::reduced_models
