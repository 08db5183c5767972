#include <gtest/gtest.h>

#include "highlift/icsp/parser.h"
#include "highlift/icsp/propagator.h"

namespace highlift::icsp {
namespace {

/// A small drive: shaft stiffness from diameter, speed from ratio; three requirements of which
/// two conflict through the physics.
Network SmallDrive() {
  Network net;
  net.AddVariable("shaft.diameter", Interval(0.02, 0.08), "m", "default");
  net.AddVariable("shaft.stiffness", Interval(0, 1e9), "N*m/rad", "default");
  net.AddVariable("shaft.mass", Interval(0, 1e3), "kg", "default");
  net.AddVariable("pdu.speed", Interval(50, 150), "rad/s", "user");
  net.AddVariable("gear.ratio", Interval(50, 200), "", "default");
  net.AddVariable("flap.time", Interval(0, 1e3), "s", "default");
  AddConstraintText(net, "shaft.stiffness == 1e8 * shaft.diameter^4", {"shaft.c", "tube stiffness", ConstraintRole::kPhysics});
  AddConstraintText(net, "shaft.mass == 2e4 * shaft.diameter^2", {"shaft.m", "tube mass", ConstraintRole::kPhysics});
  AddConstraintText(net, "flap.time == 300 * gear.ratio / pdu.speed", {"flap.t", "extension time", ConstraintRole::kPhysics});
  AddConstraintText(net, "shaft.stiffness >= 900", {"R1", "stiff enough", ConstraintRole::kRequirement});
  AddConstraintText(net, "shaft.mass <= 80", {"R2", "light enough", ConstraintRole::kRequirement});
  AddConstraintText(net, "flap.time <= 400 s", {"R3", "fast enough", ConstraintRole::kRequirement});
  return net;
}

TEST(Explain, FeasibleNetworkHasNoExplanation) {
  const Network net = SmallDrive();
  const Explanation ex = Explain(net, net.InitialBox());
  EXPECT_FALSE(ex.infeasible);
}

TEST(Explain, NamesTheMinimalConflictAndTheChain) {
  Network net = SmallDrive();
  // stiffness >= 900 needs d >= 0.0548; mass <= 12 needs d <= 0.0245: R1 and R4 conflict.
  AddConstraintText(net, "shaft.mass <= 12", {"R4", "lighter still", ConstraintRole::kRequirement});
  const Explanation ex = Explain(net, net.InitialBox());
  ASSERT_TRUE(ex.infeasible);
  EXPECT_FALSE(ex.physics_alone);
  ASSERT_EQ(ex.conflict.size(), 2u);
  EXPECT_EQ(net.constraint(ConstraintId{ex.conflict[0]}).info.label, "R1");
  EXPECT_EQ(net.constraint(ConstraintId{ex.conflict[1]}).info.label, "R4");
  EXPECT_NE(ex.text.find("These requirements cannot be met together"), std::string::npos) << ex.text;
  EXPECT_NE(ex.text.find("requirement 'R1' (stiff enough): shaft.stiffness >= 900"), std::string::npos) << ex.text;
  EXPECT_NE(ex.text.find("requirement 'R4' (lighter still): shaft.mass <= 12"), std::string::npos) << ex.text;
  EXPECT_EQ(ex.text.find("'R3'"), std::string::npos) << ex.text;  // irrelevant requirement left out
  EXPECT_NE(ex.text.find("shaft.diameter"), std::string::npos) << ex.text;  // the chain passes the diameter
  EXPECT_FALSE(ex.chain.empty());
}

/// The conflict is minimal: it is infeasible with only the physics and those requirements, and
/// dropping any one of them leaves a network propagation no longer proves infeasible.
void ExpectMinimal(const Network& net, const Explanation& ex) {
  const int nc = net.num_constraints();
  std::vector<char> only(nc, 0);
  for (int c = 0; c < nc; ++c) only[c] = net.constraint(ConstraintId{c}).info.role == ConstraintRole::kPhysics;
  for (int c : ex.conflict) only[c] = 1;
  Propagator prop(net);
  Box box = net.InitialBox();
  EXPECT_EQ(prop.Propagate(box, only).status, Status::kInfeasible);
  for (int c : ex.conflict) {
    std::vector<char> without = only;
    without[c] = 0;
    box = net.InitialBox();
    EXPECT_NE(prop.Propagate(box, without).status, Status::kInfeasible)
        << net.constraint(ConstraintId{c}).info.label << " is not needed for the conflict";
  }
}

TEST(Explain, ConflictIsMinimalAndTheChainStartsAtEachRequirement) {
  Network net = SmallDrive();
  AddConstraintText(net, "shaft.mass <= 12", {"R4", "lighter still", ConstraintRole::kRequirement});
  AddConstraintText(net, "shaft.stiffness >= 800", {"R5", "weaker stiffness wish", ConstraintRole::kRequirement});
  const Explanation ex = Explain(net, net.InitialBox());
  ASSERT_TRUE(ex.infeasible);
  ExpectMinimal(net, ex);
  // Every requirement of the conflict starts a way through the network in the chain.
  for (int r : ex.conflict) {
    bool found = false;
    for (const ChainStep& s : ex.chain) found = found || s.constraint == r;
    EXPECT_TRUE(found) << net.constraint(ConstraintId{r}).info.label;
    EXPECT_NE(ex.text.find("from requirement '" + net.constraint(ConstraintId{r}).info.label + "':"), std::string::npos)
        << ex.text;
  }
}

TEST(Explain, PhysicsAloneIsSaidSo) {
  Network net;
  net.AddVariable("a", Interval(0, 1));
  net.AddVariable("b", Interval(5, 6));
  AddConstraintText(net, "a == b", {"link", "a equals b", ConstraintRole::kPhysics});
  const Explanation ex = Explain(net, net.InitialBox());
  ASSERT_TRUE(ex.infeasible);
  EXPECT_TRUE(ex.physics_alone);
  EXPECT_TRUE(ex.conflict.empty());
  EXPECT_NE(ex.text.find("infeasible even without requirements"), std::string::npos) << ex.text;
}

}  // namespace
}  // namespace highlift::icsp
