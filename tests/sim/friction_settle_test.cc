// The settled stuck friction element (sim/src/msl_elements.h, Friction::Settle): when the event
// iteration alternates an element between stuck and sliding (its torque at the capacity within
// roundoff, each mode inconsistent by a rounding error), it settles stuck and its capacity root
// is re-armed kSettledAllowance above the capacity until its next event. Without that, a torque
// that keeps rising with the capacity crossed the 1e-10 margin again 1e-14 s later, event after
// event, and a run crawled into the step limit (one sampled rupture of the A380-class campaign,
// a torque limiter's brake whose normal force grows with the spring's twist).
#include <gtest/gtest.h>

#include "brake_elements.h"

namespace highlift::sim::detail {
namespace {

TEST(FrictionSettle, ASettledBrakesCapacityRootIsRearmedAboveTheCapacityUntilItsNextEvent) {
  ShaftBrake brake("stl.brake", "ShaftBrake", 100.0, 100.0);
  brake.u_signal = 0;
  brake.p = 0;
  brake.m = 1;
  Eval e;
  e.signal = {0.5};  // capacity u * tauB_lim = 50 N*m
  e.phi = {0.0, 0.0};
  e.w = {0.0, 0.0};
  e.acc = {0.0, 0.0};
  e.force = {0.0, 0.0};
  const double capacity = 50.0;
  brake.mode = msl::kStuck;
  brake.tau = capacity * (1 + 5e-10);  // beyond the root's margin of 1e-10
  double g[3] = {0.0, 0.0, 0.0};
  brake.Roots(e, g);
  EXPECT_LT(g[1], 0.0) << "the capacity root has crossed";

  brake.Settle(e);
  EXPECT_EQ(brake.mode, msl::kStuck);
  brake.Roots(e, g);
  EXPECT_NEAR(g[1], capacity * (msl::Friction::kSettledAllowance + 1e-10 - 5e-10), 1e-12);
  EXPECT_GT(g[1], 0.0) << "re-armed above the capacity";
  brake.tau = -capacity * (1 + 5e-10);  // either direction
  brake.Roots(e, g);
  EXPECT_GT(g[1], 0.0);
  brake.tau = capacity * (1 + 2 * msl::Friction::kSettledAllowance);
  brake.Roots(e, g);
  EXPECT_LT(g[1], 0.0) << "a torque rising on beyond the allowance is located";

  brake.PrepareEvent(e);  // the element's next event: the allowance ends
  brake.mode = msl::kStuck;
  brake.tau = capacity * (1 + 5e-10);
  brake.Roots(e, g);
  EXPECT_LT(g[1], 0.0);
}

}  // namespace
}  // namespace highlift::sim::detail
