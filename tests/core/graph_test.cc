#include "highlift/core/graph.h"

#include <gtest/gtest.h>

#include "highlift/core/project_io.h"

namespace highlift {
namespace {

// PDU - STL - shaft - root gearbox 1.5:1 - shaft - station gearbox 2:1 - (branch) GRA 200:1
//                                                             \- (through) WTB
const char* kTransmission = R"json({
  "format": "highlift-project/1", "name": "graph",
  "components": [
    {"id": "pdu", "type": "pdu"},
    {"id": "stl", "type": "system_torque_limiter"},
    {"id": "shaft_0", "type": "torque_shaft", "parameters": {"length": "4 m"}},
    {"id": "rgb", "type": "angle_gearbox", "parameters": {"ratio": 1.5}},
    {"id": "shaft_1", "type": "torque_shaft", "parameters": {"length": "3 m"}},
    {"id": "sgb", "type": "branch_gearbox", "parameters": {"ratio": 2}},
    {"id": "gra", "type": "geared_rotary_actuator", "parameters": {"ratio": 200}},
    {"id": "wtb", "type": "wing_tip_brake"},
    {"id": "loose", "type": "steady_bearing"}
  ],
  "connections": [
    ["pdu.left", "stl.input"], ["stl.output", "shaft_0.a"], ["shaft_0.b", "rgb.input"],
    ["rgb.output", "shaft_1.a"], ["shaft_1.b", "sgb.input"], ["sgb.branch", "gra.input"],
    ["sgb.through", "wtb.a"]
  ]
})json";

TEST(ComponentGraph, WalksFromThePduBreadthFirst) {
  const Project p = ParseProject(kTransmission);
  const ComponentGraph g(p);
  EXPECT_EQ(g.pdu(), "pdu");
  const std::vector<std::string> order = {"pdu", "stl", "shaft_0", "rgb", "shaft_1", "sgb", "gra", "wtb"};
  EXPECT_EQ(g.ReachOrder(), order);
  const PowerPath* path = g.PathTo("gra");
  ASSERT_NE(path, nullptr);
  EXPECT_EQ(g.Route("gra"), (std::vector<std::string>{"pdu", "stl", "shaft_0", "rgb", "shaft_1", "sgb", "gra"}));
  EXPECT_EQ(path->previous, "sgb");
  EXPECT_EQ(path->depth, 6u);
  EXPECT_EQ(path->entry_port, "input");
  EXPECT_EQ(path->pdu_port, "left");
  EXPECT_FALSE(path->reversed);
  EXPECT_EQ(g.PathTo("loose"), nullptr);
}

TEST(ComponentGraph, SpeedRatiosAreProductsOfInverseGearRatios) {
  const Project p = ParseProject(kTransmission);
  const ComponentGraph g(p);
  EXPECT_DOUBLE_EQ(*g.SpeedRatio("pdu"), 1.0);
  EXPECT_DOUBLE_EQ(*g.SpeedRatio("shaft_0"), 1.0);
  EXPECT_DOUBLE_EQ(*g.SpeedRatio("rgb"), 1.0);          // entered at its input
  EXPECT_DOUBLE_EQ(*g.SpeedRatio("shaft_1"), 1 / 1.5);
  EXPECT_DOUBLE_EQ(*g.SpeedRatio("gra"), 1 / 3.0);      // 1.5 x 2 before the GRA input
  EXPECT_DOUBLE_EQ(*g.SpeedRatio("wtb"), 1 / 1.5);      // through is 1:1
  EXPECT_DOUBLE_EQ(*g.SpeedRatioAtPort("sgb", "branch"), 1 / 3.0);
  EXPECT_DOUBLE_EQ(*g.SpeedRatioAtPort("rgb", "output"), 1 / 1.5);
  EXPECT_FALSE(g.SpeedRatio("loose").has_value());
}

TEST(ComponentGraph, NeighboursAndIslands) {
  const Project p = ParseProject(kTransmission);
  const ComponentGraph g(p);
  const auto& n = g.Neighbours("sgb");
  ASSERT_EQ(n.size(), 3u);
  EXPECT_EQ(n[0].port, "input");
  EXPECT_EQ(n[0].neighbour, (PortRef{"shaft_1", "b"}));
  EXPECT_EQ(*g.ConnectedTo({"gra", "input"}), (PortRef{"sgb", "branch"}));
  EXPECT_FALSE(g.ConnectedTo({"wtb", "b"}).has_value());
  EXPECT_TRUE(g.Neighbours("nobody").empty());
  const auto islands = g.Islands();
  ASSERT_EQ(islands.size(), 2u);
  EXPECT_EQ(islands[0].size(), 8u);
  EXPECT_EQ(islands[1], std::vector<std::string>{"loose"});
}

TEST(ComponentGraph, PortSpeedFactorBothWays) {
  Component gearbox;
  gearbox.type = "angle_gearbox";
  gearbox.parameters["ratio"].nominal = 4.0;
  bool known = false;
  EXPECT_DOUBLE_EQ(PortSpeedFactor(gearbox, "input", "output", &known), 0.25);
  EXPECT_TRUE(known);
  EXPECT_DOUBLE_EQ(PortSpeedFactor(gearbox, "output", "input"), 4.0);
  gearbox.parameters["ratio"].nominal.reset();
  EXPECT_DOUBLE_EQ(PortSpeedFactor(gearbox, "input", "output", &known), 1.0);
  EXPECT_FALSE(known);
}

}  // namespace
}  // namespace highlift
