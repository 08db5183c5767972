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
