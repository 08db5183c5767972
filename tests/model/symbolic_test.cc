// The symbolic scalar (model/symbolic.h): what the component laws render to for the propagator,
// the signs it derives, BySign's branches, missing values and the named subexpressions.
#include "highlift/model/symbolic.h"

#include <gtest/gtest.h>

#include "highlift/core/error.h"
#include "highlift/model/laws.h"

namespace highlift::model {
namespace {

Sym Positive(const char* name) { return Sym::Variable(name, Sign::Positive()); }

TEST(Symbolic, RendersTheGearLawOfAnOpposingTorqueWithoutTheSplit) {
  const Sym tau = Sym::Variable("tau", Sign::NonNegative());
  EXPECT_EQ(GearInputTorque(tau, Positive("i"), Positive("eta_op"), Positive("eta_ai")).Text(), "tau / (i * eta_op)");
}

TEST(Symbolic, RendersTheGearLawOfAnAidingConstantWithItsAidingEfficiency) {
  const Sym out = GearInputTorque(Sym(-20000.0), Positive("i"), Positive("eta_op"), Positive("eta_ai"));
  EXPECT_EQ(out.Text(), "(-20000) * eta_ai / i");
  EXPECT_EQ(out.sign(), Sign::Negative());
  // Its magnitude: the minus goes into the constant.
  EXPECT_EQ((-out).Text(), "20000 * eta_ai / i");
}

TEST(Symbolic, SplitsATorqueOfEitherSignExactlyAtZero) {
  const Sym tau = Sym::Variable("tau", Sign::Either());
  EXPECT_EQ(GearInputTorque(tau, Positive("i"), Positive("eta"), Positive("eta")).Text(),
            "max(tau, 0) / (i * eta) + min(tau, 0) * eta / i");
}

TEST(Symbolic, BySignOnAnUndeclaredSignIsAnInternalErrorNamingTheLaw) {
  const Sym tau = Sym::Variable("tau", Sign::Unknown());
  try {
    GearInputTorque(tau, Positive("i"), Positive("eta"), Positive("eta"));
    FAIL() << "no error";
  } catch (const InternalError& e) {
    EXPECT_NE(std::string(e.what()).find("the law 'GearInputTorque' changes at zero"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(tau)"), std::string::npos) << e.what();
  }
}

TEST(Symbolic, SimplifiesOnlyByExactIdentities) {
  const Sym x = Positive("x"), y = Positive("y");
  EXPECT_EQ((Sym(1.0) * x).Text(), "x");
  EXPECT_EQ((x / Sym(1.0)).Text(), "x");
  EXPECT_EQ((x + Sym(0.0)).Text(), "x");
  EXPECT_EQ((Sym(0.0) - x).Text(), "-x");
  EXPECT_EQ((-(-x)).Text(), "x");
  EXPECT_EQ((x * x * x).Text(), "x^3");             // a gear train's eta_mesh^meshes
  EXPECT_EQ((y * Sym(2.0) * x * x).Text(), "y * 2 * x^2");  // the motors' n J_m i^2
  EXPECT_EQ((Sym(0.1) * Sym(3.0)).Text(), "0.10000000000000001 * 3");  // constants are not folded
  EXPECT_EQ((x - (y - x)).Text(), "x - (y - x)");   // the tree's shape is kept
  EXPECT_EQ((x / (y * x)).Text(), "x / (y * x)");
  EXPECT_EQ((-(x * y)).Text(), "-(x * y)");
  EXPECT_EQ(exp(-(x * y)).Text(), "exp(-(x * y))");
}

TEST(Symbolic, DerivesSignsFromItsOperands) {
  const Sym x = Positive("x"), either = Sym::Variable("e", Sign::Either());
  EXPECT_EQ((x * x + Sym(1.0)).sign(), Sign::Positive());
  EXPECT_EQ((x - x).sign(), Sign::Either());
  EXPECT_EQ((Sym(-2.0) * x).sign(), Sign::Negative());
  EXPECT_EQ(exp(either).sign(), Sign::Positive());
  EXPECT_EQ(pow(either, 2).sign(), Sign::NonNegative());
  EXPECT_EQ(max(either, Sym(0.0)).sign(), Sign::NonNegative());
  EXPECT_EQ(min(either, Sym(0.0)).sign(), Sign::NonPositive());
  EXPECT_EQ((x * Sym::Variable("u", Sign::Unknown())).sign(), Sign::Unknown());
  EXPECT_EQ(abs(x).Text(), "x");  // abs of a non-negative value is the value
  EXPECT_EQ(abs(either).Text(), "abs(e)");
}

TEST(Symbolic, AMissingValueSpreadsExceptTimesZero) {
  const Sym m = Sym::Missing("gb.eta_mesh");
  EXPECT_TRUE((m * Positive("x") + Sym(1.0)).missing());
  EXPECT_EQ((m * Positive("x")).missing_what(), "gb.eta_mesh");
  EXPECT_FALSE((Sym(0.0) * m).missing());  // a law without friction does not need the friction's values
  EXPECT_THROW(m.Text(), InternalError);
}

TEST(Symbolic, WritesANamedSubexpressionAsItsVariable) {
  const Sym D = Positive("s.D"), t = Positive("s.t"), G = Positive("s.G"), L = Positive("s.L");
  const Sym Ip = TubePolarMoment(D, t);
  EXPECT_EQ(Ip.Text(), "0.39269908169872414 * (s.D^2 + (s.D - 2 * s.t)^2) * (s.D - s.t) * s.t");
  EXPECT_EQ(ShaftStiffness(G, D, t, L).Text({{Ip, "s.polar_moment"}}), "s.G * s.polar_moment / s.L");
}

}  // namespace
}  // namespace highlift::model
