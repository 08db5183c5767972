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


// --- hostile input (issue 19) ------------------------------------------------------------------

Network WithUnits() {
  Network net;
  net.AddVariable("pdu.max_output_torque", Interval(100, 900), "N*m");
  net.AddVariable("gra.ratio", Interval(100, 250), "");
  return net;
}

TEST(ParserLimits, DeepNestingIsAnInputErrorNotACrash) {
  // Was: SIGSEGV at 10^5 levels.
  const std::size_t n = 100000;
  for (const std::string& text : {std::string(n, '(') + "gra.ratio" + std::string(n, ')') + " >= 1",
                                  [&] {
                                    std::string t;
                                    for (std::size_t i = 0; i < n; ++i) t += "- ";
                                    return t + "gra.ratio >= 1";
                                  }(),
                                  [&] {
                                    std::string t;
                                    for (std::size_t i = 0; i < n; ++i) t += "abs(";
                                    return t + "gra.ratio" + std::string(n, ')') + " >= 1";
                                  }(),
                                  [&] {
                                    std::string t = "gra.ratio";
                                    for (std::size_t i = 0; i < n; ++i) t += "^1";
                                    return t + " >= 1";
                                  }()}) {
    Network net = WithUnits();
    const std::string message = ErrorOf(net, text);
    EXPECT_NE(message.find("nested more than 200 levels deep"), std::string::npos) << message.substr(0, 200);
    EXPECT_LT(message.size(), 10000u);  // the 100 kB text is cut in the message
  }
  Network net = WithUnits();
  EXPECT_EQ(ErrorOf(net, std::string(150, '(') + "gra.ratio" + std::string(150, ')') + " >= 1"), "");
}

TEST(ParserLimits, LongChainsAreCutBeforeLaterWalksRecurseTooDeep) {
  std::string chain = "gra.ratio";
  for (int i = 0; i < 100000; ++i) chain += " + gra.ratio";
  Network net = WithUnits();
  const std::string message = ErrorOf(net, chain + " >= 1");
  EXPECT_NE(message.find("a chain of more than 5000 operations"), std::string::npos) << message.substr(0, 300);
  std::string ok = "gra.ratio";
  for (int i = 0; i < 3000; ++i) ok += " + " + std::to_string(i);
  Network net2 = WithUnits();
  ASSERT_EQ(ErrorOf(net2, ok + " >= 1"), "");
  EXPECT_FALSE(net2.ExprText(ExprId{net2.constraint(ConstraintId{0}).root}).empty());
}

TEST(ParserInputErrors, DivisionByTheConstantZero) {
  Network net = WithUnits();
  const std::string message = ErrorOf(net, "pdu.max_output_torque >= 1 N*m / 0");
  EXPECT_NE(message.find("division by zero at column 34"), std::string::npos) << message;
  EXPECT_NE(ErrorOf(net, "gra.ratio / (2 - 2) >= 1").find("division by zero"), std::string::npos);
  EXPECT_EQ(ErrorOf(net, "gra.ratio / 2 >= 1"), "");
}

TEST(ParserInputErrors, LogAndSqrtOfConstantsOutsideTheirDomain) {
  Network net = WithUnits();
  EXPECT_NE(ErrorOf(net, "log(-1) <= gra.ratio").find("log() of the constant -1, which is not positive"),
            std::string::npos);
  EXPECT_NE(ErrorOf(net, "log(0) <= gra.ratio").find("not positive"), std::string::npos);
  EXPECT_NE(ErrorOf(net, "sqrt(-4) <= gra.ratio").find("sqrt() of the negative constant -4"), std::string::npos);
  EXPECT_EQ(ErrorOf(net, "log(2) <= gra.ratio"), "");
}

TEST(ParserInputErrors, RequirementSidesMustHaveTheSameDimension) {
  Network net = WithUnits();
  const std::string message = ErrorOf(net, "pdu.max_output_torque >= 145 kg");
  EXPECT_NE(message.find("'>=' compares a torque (kg*m^2*s^-2) with a mass (kg)"), std::string::npos) << message;
  EXPECT_NE(ErrorOf(net, "pdu.max_output_torque + 1 m <= 5 N*m").find("'+' adds a torque"), std::string::npos);
  EXPECT_NE(ErrorOf(net, "max(pdu.max_output_torque, 2 s) <= 5 N*m").find("mixes"), std::string::npos);
  EXPECT_NE(ErrorOf(net, "exp(pdu.max_output_torque) <= 5").find("exp() of a torque"), std::string::npos);
  // Consistent units, products and bare numbers are fine.
  EXPECT_EQ(ErrorOf(net, "pdu.max_output_torque >= 0.5 kN*m"), "");
  EXPECT_EQ(ErrorOf(net, "pdu.max_output_torque / gra.ratio >= 1 N*m"), "");
  EXPECT_EQ(ErrorOf(net, "pdu.max_output_torque * 2 m >= 1 N*m*m"), "");
  EXPECT_EQ(ErrorOf(net, "pdu.max_output_torque >= 145"), "");
}

TEST(ParserInputErrors, UnitPowerOverflowNamesTheUnit) {
  Network net = WithUnits();
  const std::string message = ErrorOf(net, "pdu.max_output_torque >= 4 m^200");
  EXPECT_NE(message.find("unit 'm^200'"), std::string::npos) << message;
  EXPECT_NE(message.find("the power of m is 200"), std::string::npos) << message;
  EXPECT_EQ(message.find("internal error"), std::string::npos) << message;
}
}  // namespace
}  // namespace highlift::icsp
