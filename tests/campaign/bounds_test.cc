// campaign::CompareWithTransient, the one comparison behind the bound / NOT A BOUND flags of
// `peak --transient` and of the design report (campaign/include/highlift/campaign/bounds.h).
#include "highlift/campaign/bounds.h"

#include <gtest/gtest.h>

#include <cmath>

#include "highlift/reduced_models/analyses.h"

namespace highlift::campaign {
namespace {

reduced_models::ComponentPeak Worst(const std::string& id, double local_nominal, const std::string& worst_case) {
  reduced_models::ComponentPeak w;
  w.component = id;
  w.local_nominal = local_nominal;
  w.worst_case = worst_case;
  return w;
}

TEST(ComponentBounds, TheLargestSimulatedTorqueOfAnySuccessfulCaseAgainstTheSingleDofValue) {
  reduced_models::PeakReport report;
  report.worst = {Worst("gra_l1", 400.0, "jam_l1"), Worst("stl_l1", 500.0, "rupture_wtb"), Worst("fppu", 0.0, "jam_l1"),
                  Worst("shaft_l7", 600.0, "rupture_wtb")};
  const std::vector<SimulatedCase> simulated = {
      {"jam_l1", true, {{"gra_l1", 380.0}, {"stl_l1", 300.0}, {"shaft_l7", 100.0}}},
      {"rupture_wtb", true, {{"gra_l1", 390.0}, {"stl_l1", 500.0 * (1 + 0.5 * kBoundTolerance)}, {"shaft_l7", 606.0}}},
      // A failed simulation is no result: its torques count nowhere.
      {"jam_l2", false, {{"gra_l1", 9000.0}, {"fppu", 1.0}}},
  };
  const std::vector<ComponentBound> out = CompareWithTransient(report, simulated);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].component, "gra_l1");
  EXPECT_DOUBLE_EQ(out[0].transient, 390.0);
  EXPECT_EQ(out[0].transient_case, "rupture_wtb");
  EXPECT_TRUE(out[0].bound());
  EXPECT_EQ(out[0].Flag(), "bound");
  EXPECT_TRUE(out[1].bound()) << "within the tolerance counts as at the bound";
  EXPECT_TRUE(out[2].bound()) << "no simulated torque, no single-DOF load";
  EXPECT_EQ(out[2].transient_case, "");
  EXPECT_FALSE(out[3].bound());
  EXPECT_NEAR(out[3].exceeded_by, 0.01, 1e-12);
  EXPECT_EQ(out[3].Flag(), "NOT A BOUND: the simulation exceeds it by 1 %");
  // A simulated torque where the single-DOF analysis gives none is no bound either.
  const auto none = CompareWithTransient(report, {{"jam_l1", true, {{"fppu", 2.0}}}});
  EXPECT_FALSE(none[2].bound());
  EXPECT_TRUE(std::isinf(none[2].exceeded_by));
  EXPECT_EQ(none[2].Flag(), "NOT A BOUND: the simulation exceeds it by (no single-DOF load)");
}

TEST(ComponentBounds, TorquesAtTheInputFlangeOfABranchGearboxAndAsReportedElsewhere) {
  Project p;
  Component tgb;
  tgb.id = "tgb";
  tgb.type = "branch_gearbox";
  Parameter ratio;
  ratio.nominal = 2.0;
  tgb.parameters["ratio"] = ratio;
  p.components.push_back(tgb);
  Component shaft;
  shaft.id = "shaft";
  shaft.type = "torque_shaft";
  p.components.push_back(shaft);
  const auto at_input = ComponentTorquesAtInput(p, {{"tgb", -100.0, 1.0}, {"shaft", -50.0, 1.0}});
  // The gearbox's element torque is at its branch, which turns 1/2 as fast as its input.
  EXPECT_NEAR(at_input.at("tgb"), 50.0, 1e-9);
  EXPECT_DOUBLE_EQ(at_input.at("shaft"), 50.0);
}

}  // namespace
}  // namespace highlift::campaign
