#include "highlift/icsp/parser.h"

#include <gtest/gtest.h>

#include "highlift/icsp/propagator.h"

namespace highlift::icsp {
namespace {

std::string ErrorOf(Network& net, const std::string& text) {
  try {
    AddConstraintText(net, text, {"R1", "", ConstraintRole::kRequirement});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Network TwoParameters() {
  Network net;
  net.AddVariable("wtb_left.static_limit_torque", Interval(0, 1e4));
  net.AddVariable("shaft.stiffness", Interval(0, 1e6));
  return net;
}

TEST(Parser, PrecedenceAndAssociativity) {
  Network net;
  net.AddVariable("x", Interval(2, 2));
  const ExprId e = ParseExpression(net, "-x^2 + 2 * 3^2 / 6 - (1 - 4)", "test");
  EXPECT_EQ(net.ExprText(e), "-x^2 + 2 * 3^2 / 6 - (1 - 4)");
  Box box = net.InitialBox();
  const ConstraintId c = AddConstraintText(net, "y == -x^2 + 2 * 3^2 / 6 - (1 - 4)", {}, {},
                                           [&](std::string_view name) {
                                             VariableId v = net.FindVariable(name);
                                             return v.value >= 0 ? v : net.AddVariable(std::string(name), Whole());
                                           });
  (void)c;
  box = net.InitialBox();
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  const Interval y = box[net.FindVariable("y").value];
  EXPECT_NEAR(y.lower(), 2.0, 1e-12);  // -4 + 3 + 3
  EXPECT_NEAR(y.upper(), 2.0, 1e-12);
}

TEST(Parser, ConstantsWithUnitsAreSI) {
  Network net;
  net.AddVariable("d", Whole());
  net.AddVariable("tau", Whole());
  AddConstraintText(net, "d == 2 mm", {});
  AddConstraintText(net, "tau <= [500, 550] N*m", {});
  Box box = net.InitialBox();
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  EXPECT_NEAR(box[0].lower(), 0.002, 1e-15);
  EXPECT_NEAR(box[1].upper(), 550.0, 1e-12);
  const ExprId speed = ParseExpression(net, "242 rpm * 2", "speed");
  EXPECT_NEAR(net.node(ExprId{net.node(speed).a}).value.lower(), 242.0 * M_PI / 30.0, 1e-9);
}

TEST(Parser, DecimalConstantsAndUnitConversionsAreEnclosed) {
  // 0.1 is no double: the constant is the interval of the two doubles around it, so a point
  // that satisfies x == 0.1 exactly is never cut off. 0.5 is exact and stays a point.
  Network net;
  const VariableId x = net.AddVariable("x", Whole());
  const VariableId h = net.AddVariable("h", Whole());
  const VariableId d = net.AddVariable("d", Whole());
  const VariableId w = net.AddVariable("w", Whole());
  const VariableId g = net.AddVariable("g", Whole());
  const VariableId tau = net.AddVariable("tau", Whole());
  AddConstraintText(net, "x == 0.1", {});
  AddConstraintText(net, "h == 0.5", {});
  AddConstraintText(net, "d == 2 mm", {});
  AddConstraintText(net, "w == 242 rpm", {});
  AddConstraintText(net, "g == [43, 51] GPa", {});
  const ConstraintId c = AddConstraintText(net, "tau <= 1.5 kN*m", {"R", "", ConstraintRole::kRequirement});
  Box box = net.InitialBox();
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  auto encloses = [](const Interval& i, long double v) { return i.lower() <= v && v <= i.upper(); };
  EXPECT_EQ(box[x.value].lower(), 0x1.9999999999999p-4);
  EXPECT_EQ(box[x.value].upper(), 0x1.999999999999ap-4);
  EXPECT_EQ(box[h.value].lower(), 0.5);
  EXPECT_EQ(box[h.value].upper(), 0.5);
  EXPECT_TRUE(encloses(box[d.value], 0.002L)) << ToString(box[d.value]);
  EXPECT_LT(box[d.value].upper() - box[d.value].lower(), 1e-17);
  EXPECT_TRUE(encloses(box[w.value], 242.0L * 3.14159265358979323846264338327950288L / 30.0L)) << ToString(box[w.value]);
  EXPECT_EQ(box[g.value].lower(), 43e9);  // integer factors are exact
  EXPECT_EQ(box[g.value].upper(), 51e9);
  EXPECT_EQ(box[tau.value].upper(), 1500.0);
  // Printed as written (the enclosure is an implementation detail), and the requirement keeps its
  // source text with units for explanations.
  EXPECT_EQ(net.ConstraintText(ConstraintId{0}), "x == 0.1");
  EXPECT_EQ(net.constraint(c).info.source, "tau <= 1.5 kN*m");
  // A constant exponent is the double nearest the number written.
  EXPECT_EQ(net.node(ParseExpression(net, "x^0.3", "t")).p, 0.3);
}

TEST(Parser, NamesWithDotsAndFunctions) {
  Network net = TwoParameters();
  const ConstraintId c = AddConstraintText(
      net, "max(wtb_left.static_limit_torque, 1) >= sqrt(abs(shaft.stiffness)) + exp(log(2)) * min(1, 2, 3)", {});
  EXPECT_EQ(net.ConstraintText(c),
            "max(wtb_left.static_limit_torque, 1) >= sqrt(abs(shaft.stiffness)) + exp(log(2)) * min(min(1, 2), 3)");
}

TEST(Parser, UnknownParameterShowsColumnCaretAndSuggestion) {
  Network net = TwoParameters();
  const std::string msg = ErrorOf(net, "wtb_left.static_limit_torqe >= 1.5 * shaft.stiffness");
  EXPECT_NE(msg.find("requirement 'R1': unknown parameter 'wtb_left.static_limit_torqe' at column 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("\n  wtb_left.static_limit_torqe >= 1.5 * shaft.stiffness\n  ^~~~~~~~~~~~~~~~~~~~~~~~~~~\n"),
            std::string::npos) << msg;
  EXPECT_NE(msg.find("did you mean 'wtb_left.static_limit_torque'?"), std::string::npos) << msg;
}

TEST(Parser, SyntaxErrorsNameThePosition) {
  Network net = TwoParameters();
  std::string msg = ErrorOf(net, "shaft.stiffness >= 2 *");
  EXPECT_NE(msg.find("expression ends too early at column 23"), std::string::npos) << msg;
  msg = ErrorOf(net, "shaft.stiffness > 2");
  EXPECT_NE(msg.find("strict relation '>' is not supported at column 17"), std::string::npos) << msg;
  EXPECT_NE(msg.find("write '>='"), std::string::npos) << msg;
  msg = ErrorOf(net, "shaft.stiffness >= 2 blorps");
  EXPECT_NE(msg.find("unknown unit 'blorps' at column 22"), std::string::npos) << msg;
  msg = ErrorOf(net, "sqrtt(shaft.stiffness) >= 2");
  EXPECT_NE(msg.find("unknown function 'sqrtt' at column 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("did you mean 'sqrt'?"), std::string::npos) << msg;
  msg = ErrorOf(net, "shaft.stiffness + 1");
  EXPECT_NE(msg.find("expected '==', '<=' or '>=' here at column 20"), std::string::npos) << msg;
  msg = ErrorOf(net, "shaft.stiffness <= 1 <= 2");
  EXPECT_NE(msg.find("unexpected text after the end of the expression at column 22"), std::string::npos) << msg;
  msg = ErrorOf(net, "shaft.stiffness # 2");
  EXPECT_NE(msg.find("unexpected character '#' at column 17"), std::string::npos) << msg;
}

TEST(Parser, PowersWithIntegerRealAndVariableExponents) {
  Network net;
  net.AddVariable("x", Interval(2, 2));
  net.AddVariable("p", Interval(3, 3));
  EXPECT_EQ(net.node(ParseExpression(net, "x^3", "t")).op, Op::kPowInt);
  EXPECT_EQ(net.node(ParseExpression(net, "x^2", "t")).op, Op::kSqr);
  EXPECT_EQ(net.node(ParseExpression(net, "x^0.5", "t")).op, Op::kPowReal);
  EXPECT_EQ(net.node(ParseExpression(net, "x^-2", "t")).op, Op::kPowInt);
  EXPECT_EQ(net.node(ParseExpression(net, "x^p", "t")).op, Op::kExp);
}

}  // namespace
}  // namespace highlift::icsp
