#include "highlift/icsp/network.h"

#include <gtest/gtest.h>

#include "highlift/icsp/parser.h"

namespace highlift::icsp {
namespace {

TEST(Network, SharedSubexpressionIsOneNode) {
  Network net;
  const VariableId c = net.AddVariable("c", Interval(1, 10));
  const VariableId J = net.AddVariable("J", Interval(1, 10));
  const ExprId a = net.Sqrt(net.Mul(net.Var(c), net.Var(J)));
  const ExprId b = net.Sqrt(net.Mul(net.Var(c), net.Var(J)));
  EXPECT_EQ(a, b);
  const int before = net.num_nodes();
  AddConstraintText(net, "sqrt(c * J) <= 5", {"r1", "", ConstraintRole::kRequirement});
  AddConstraintText(net, "2 * sqrt(c * J) >= 3", {"r2", "", ConstraintRole::kRequirement});
  // New nodes: consts 5, 2, 3, the two Subs and 2*sqrt(..): sqrt(c*J) itself is reused.
  EXPECT_EQ(net.num_nodes(), before + 6);
  // Within one constraint, a repeated subexpression appears once in the evaluation order.
  const ConstraintId k = AddConstraintText(net, "c * J + sqrt(c * J) == 7", {});
  int mul_nodes = 0;
  for (int id : net.TopoOf(k)) mul_nodes += net.node(ExprId{id}).op == Op::kMul;
  EXPECT_EQ(mul_nodes, 1);
}

TEST(Network, ReplaceRebuildsOnlyWhatContainsAReplacedNode) {
  Network net;
  net.AddVariable("x", Interval(0, 1));
  net.AddVariable("y", Interval(0, 1));
  net.AddVariable("s", Interval(0, 2));
  const ExprId sum = ParseExpression(net, "x + y", "");
  const ExprId e = ParseExpression(net, "(x + y) * sqrt(x) + (x + y)", "");
  const ExprId replaced = net.Replace(e, {{sum.value, ParseExpression(net, "s", "")}});
  EXPECT_EQ(net.ExprText(replaced), net.ExprText(ParseExpression(net, "s * sqrt(x) + s", "")));
  EXPECT_EQ(replaced, ParseExpression(net, "s * sqrt(x) + s", ""));  // hash-consed: the same node
  const ExprId untouched = ParseExpression(net, "sqrt(x) * y", "");
  const int before = net.num_nodes();
  EXPECT_EQ(net.Replace(untouched, {{sum.value, ParseExpression(net, "s", "")}}), untouched);
  EXPECT_EQ(net.num_nodes(), before);
  EXPECT_EQ(net.Replace(e, {}), e);
}

TEST(Network, ScopesAndAdjacency) {
  Network net;
  const VariableId x = net.AddVariable("x", Interval(0, 1));
  const VariableId y = net.AddVariable("y", Interval(0, 1));
  const VariableId z = net.AddVariable("z", Interval(0, 1));
  const ConstraintId c0 = AddConstraintText(net, "x + y == 1", {});
  const ConstraintId c1 = AddConstraintText(net, "y^2 <= z", {});
  EXPECT_EQ(net.ScopeOf(c0).size(), 2u);
  EXPECT_EQ(net.ScopeOf(c1).size(), 2u);
  EXPECT_EQ(net.ConstraintsOf(y).size(), 2u);
  EXPECT_EQ(net.ConstraintsOf(x).size(), 1u);
  EXPECT_EQ(net.ConstraintsOf(z).size(), 1u);
  EXPECT_EQ(net.ConstraintText(c0), "x + y == 1");
  EXPECT_EQ(net.ConstraintText(c1), "y^2 <= z");
}

TEST(Network, DuplicateVariableNameIsAnInputError) {
  Network net;
  net.AddVariable("pdu.speed", Interval(0, 1));
  try {
    net.AddVariable("pdu.speed", Interval(0, 2));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'pdu.speed' is declared twice"), std::string::npos) << e.what();
  }
}

TEST(Network, MonotoneConstraintRejectsMismatchedDeclarations) {
  Network net;
  const VariableId y = net.AddVariable("y", Interval(0, 1));
  const VariableId x = net.AddVariable("x", Interval(0, 1));
  MonotoneFunction f;
  f.f = [](std::span<const double> v) { return v[0]; };
  try {
    net.AddMonotone(y, {x}, f, {"w", "", ConstraintRole::kPhysics});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1 arguments but 0 monotonicity declarations"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace highlift::icsp
