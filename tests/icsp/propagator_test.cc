#include "highlift/icsp/propagator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "highlift/icsp/parser.h"
#include "highlift/icsp/reference_networks.h"

namespace highlift::icsp {
namespace {

/// tau == w * sqrt(c * J) narrows every one of tau, w, c, J from the others.
TEST(Propagator, ConstraintsAreNondirectional) {
  Network net;
  const VariableId tau = net.AddVariable("tau", Interval(0, 100));
  const VariableId w = net.AddVariable("w", Interval(2, 2));
  const VariableId c = net.AddVariable("c", Interval(1, 100));
  const VariableId J = net.AddVariable("J", Interval(1, 4));
  AddConstraintText(net, "tau == w * sqrt(c * J)", {});
  Box box = net.InitialBox();
  box[tau.value] = Interval(0, 8);  // forces c * J <= 16
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  EXPECT_LE(box[c.value].upper(), 16.0 + 1e-12);
  EXPECT_GE(box[tau.value].lower(), 2.0 - 1e-12);  // c*J >= 1
  box = net.InitialBox();
  box[tau.value] = Interval(40, 40);  // c * J = 400: c >= 100 with J <= 4, J = 4
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  EXPECT_NEAR(box[c.value].lower(), 100.0, 1e-9);
  EXPECT_NEAR(box[J.value].lower(), 4.0, 1e-9);
  box = net.InitialBox();
  box[tau.value] = Interval(40, 40);
  box[c.value] = Interval(100, 100);
  box[J.value] = Interval(4, 4);
  box[w.value] = Interval(0, 10);
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  EXPECT_NEAR(box[w.value].lower(), 2.0, 1e-12);
  EXPECT_NEAR(box[w.value].upper(), 2.0, 1e-12);
}

/// sqrt(c * J) in three constraints is one DAG node; its forward value is computed once and
/// reused by every later revision while c and J keep their domains.
TEST(Propagator, SharedSubexpressionIsEvaluatedOncePerChangeOfItsVariables) {
  Network net;
  net.AddVariable("c", Interval(1, 4));
  net.AddVariable("J", Interval(1, 4));
  for (const char* name : {"tau1", "tau2", "tau3"}) net.AddVariable(name, Whole());
  AddConstraintText(net, "tau1 == sqrt(c * J)", {});
  AddConstraintText(net, "tau2 == 2 * sqrt(c * J)", {});
  AddConstraintText(net, "tau3 == sqrt(c * J) + 1", {});
  Propagator shared(net);
  EXPECT_EQ(shared.num_shared_subexpressions(), 2);  // c * J and sqrt(c * J)
  Box box = net.InitialBox();
  const PropagationReport r = shared.Propagate(box);
  ASSERT_EQ(r.status, Status::kFixedPoint);
  // c and J never narrow: only the first revision evaluates sqrt(c * J).
  EXPECT_EQ(r.reused_subexpressions, r.revisions - 1) << r.FullReport();
  EXPECT_NEAR(box[3].upper(), 8.0, 1e-12);
  // Off: the same fixed point, every revision evaluates it.
  PropagationOptions off;
  off.reuse_shared_subexpressions = false;
  Box plain = net.InitialBox();
  const PropagationReport p = Propagate(net, plain, off);
  EXPECT_EQ(p.reused_subexpressions, 0);
  EXPECT_EQ(p.revisions, r.revisions);
  for (std::size_t i = 0; i < box.size(); ++i) {
    EXPECT_EQ(box[i].lower(), plain[i].lower());
    EXPECT_EQ(box[i].upper(), plain[i].upper());
  }
  // When a variable below it narrows, the kept value is stale and is evaluated again.
  AddConstraintText(net, "c <= 2", {});
  Propagator narrowed(net);
  box = net.InitialBox();
  const PropagationReport n = narrowed.Propagate(box);
  ASSERT_EQ(n.status, Status::kFixedPoint);
  EXPECT_NEAR(box[2].upper(), std::sqrt(8.0), 1e-12);
  EXPECT_NEAR(box[3].upper(), 2 * std::sqrt(8.0), 1e-12);
  EXPECT_NEAR(box[4].upper(), std::sqrt(8.0) + 1, 1e-12);
}

/// Reusing shared values changes nothing but the work: on the random reference networks (whose
/// constraints share sqrt(x_a) and x_a * x_b), the same revisions and the same fixed point.
TEST(Propagator, ReusingSharedSubexpressionsKeepsTheFixedPoint) {
  const Network net = BuildNetwork(MakeRandomNetwork(1000));
  Propagator with(net);
  EXPECT_GT(with.num_shared_subexpressions(), 50);
  PropagationOptions off;
  off.reuse_shared_subexpressions = false;
  Propagator without(net, off);
  Box a = net.InitialBox(), b = net.InitialBox();
  const PropagationReport ra = with.Propagate(a), rb = without.Propagate(b);
  ASSERT_EQ(ra.status, Status::kFixedPoint);
  EXPECT_EQ(ra.revisions, rb.revisions);
  EXPECT_GT(ra.reused_subexpressions, 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].lower(), b[i].lower()) << i;
    EXPECT_EQ(a[i].upper(), b[i].upper()) << i;
  }
}

/// The periodic functions project back too: sin(phi) >= 0.5 with phi in [0, 3] rad narrows phi
/// to [pi/6, 5 pi/6]; cos(phi) == 1 with phi in [0.5, 6] rad is proved impossible.
TEST(Propagator, PeriodicFunctionsAreNondirectional) {
  Network net;
  const VariableId phi = net.AddVariable("phi", Interval(0, 3));
  AddConstraintText(net, "sin(phi) >= 0.5", {});
  Box box = net.InitialBox();
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  EXPECT_NEAR(box[phi.value].lower(), M_PI / 6, 1e-12);
  EXPECT_NEAR(box[phi.value].upper(), 5 * M_PI / 6, 1e-12);
  Network none;
  none.AddVariable("phi", Interval(0.5, 6));
  AddConstraintText(none, "cos(phi) == 1", {});
  box = none.InitialBox();
  EXPECT_EQ(Propagate(none, box).status, Status::kInfeasible);
}

TEST(Propagator, ProvedInfeasibleIsNotStoppedAtLimit) {
  Network net;
  net.AddVariable("x", Interval(0, 10));
  net.AddVariable("y", Interval(0, 10));
  AddConstraintText(net, "x + y >= 15", {});
  AddConstraintText(net, "x <= 4", {});
  AddConstraintText(net, "y <= 4", {});
  Box box = net.InitialBox();
  const PropagationReport r = Propagate(net, box);
  EXPECT_EQ(r.status, Status::kInfeasible);
  EXPECT_GE(r.empty_constraint, 0);
  EXPECT_NE(r.BriefReport().find("proved infeasible"), std::string::npos) << r.BriefReport();
  EXPECT_NE(r.FullReport().find("infeasible"), std::string::npos);
}

TEST(Propagator, RevisionLimitGivesStoppedAtLimitWithASoundBox) {
  // x == y / 2 + 1, y == x: converges to x = y = 2 only in the limit, by ever smaller steps.
  Network net;
  net.AddVariable("x", Interval(0, 100));
  net.AddVariable("y", Interval(0, 100));
  AddConstraintText(net, "x == y / 2 + 1", {});
  AddConstraintText(net, "y == x", {});
  Box box = net.InitialBox();
  PropagationOptions o;
  o.max_revisions = 10;
  const PropagationReport r = Propagate(net, box, o);
  EXPECT_EQ(r.status, Status::kStoppedAtLimit);
  EXPECT_EQ(r.revisions, 10);
  EXPECT_NE(r.message.find("max_revisions"), std::string::npos);
  EXPECT_TRUE(box[0].lower() <= 2.0 && 2.0 <= box[0].upper());
  // With a ratio, it stops early at a fixed point of that ratio.
  box = net.InitialBox();
  o.max_revisions = 1000000;
  o.ratio = 0.01;
  const PropagationReport r2 = Propagate(net, box, o);
  EXPECT_EQ(r2.status, Status::kFixedPoint);
  EXPECT_TRUE(box[0].lower() <= 2.0 && 2.0 <= box[0].upper());
  EXPECT_LT(box[0].upper() - box[0].lower(), 1.0);
}

TEST(PropagationOptions, DefaultsAreValidAndBadValuesAreNamed) {
  EXPECT_NO_THROW(PropagationOptions{}.Validate());
  EXPECT_NO_THROW(ShavingOptions{}.Validate());
  PropagationOptions o;
  o.ratio = 1.5;
  try {
    o.Validate();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("propagation ratio 1.5"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ScheduleFromString(ToString(Schedule::kSweep)), Schedule::kSweep);
  EXPECT_EQ(StatusFromString(ToString(Status::kInfeasible)), Status::kInfeasible);
  EXPECT_EQ(StatusFromString("nonsense"), std::nullopt);
}

TEST(Propagator, AllSchedulesReachTheSameFixedPoint) {
  const Network net = BuildNetwork(MakeDriveTrainNetwork(102, false));
  Box reference;
  for (Schedule s : {Schedule::kSweep, Schedule::kFifo, Schedule::kLifo}) {
    Box box = net.InitialBox();
    PropagationOptions o;
    o.schedule = s;
    ASSERT_EQ(Propagate(net, box, o).status, Status::kFixedPoint) << ToString(s);
    if (reference.empty()) {
      reference = box;
      continue;
    }
    for (std::size_t i = 0; i < box.size(); ++i) {
      EXPECT_EQ(box[i].lower(), reference[i].lower()) << ToString(s) << " variable " << i;
      EXPECT_EQ(box[i].upper(), reference[i].upper()) << ToString(s) << " variable " << i;
    }
  }
}

/// Whole networks: random constraints built around a random point (fixed seed); the point
/// satisfies them all, so it must stay inside the contracted box.
TEST(PropagatorSoundness, SatisfyingPointsAreNeverExcluded) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  const char* shapes[] = {"%a * %b + %c", "sqrt(abs(%a)) - %b", "exp(%a / 10) * %b", "%a^3 - %b^2",
                          "min(%a, %b) + max(%b, %c)", "log(1 + %a^2) + %c", "%a / (1 + %b^2)",
                          "abs(%a - %b) * %c", "sin(%a) + cos(%b)", "(%a + %b)^0.5"};
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Network net;
    std::vector<double> point;
    for (int i = 0; i < 8; ++i) {
      point.push_back(u(rng));
      net.AddVariable("v" + std::to_string(i), Interval(-5, 5));
    }
    auto fill = [&](std::string s) {
      std::vector<int> chosen;
      for (const char* key : {"%a", "%b", "%c"}) {
        const int v = static_cast<int>(rng() % 8);
        chosen.push_back(v);
        for (std::size_t p; (p = s.find(key)) != std::string::npos;) s.replace(p, 2, "v" + std::to_string(v));
      }
      return s;
    };
    for (int k = 0; k < 12; ++k) {
      const std::string shape = fill(shapes[rng() % 10]);
      // Value at the point, through the same parser: propagate the point box forward.
      Network probe;
      for (int i = 0; i < 8; ++i) probe.AddVariable("v" + std::to_string(i), Interval(point[i], point[i]));
      probe.AddVariable("g", Whole());
      AddConstraintText(probe, "g == " + shape, {});
      Box pb = probe.InitialBox();
      if (Propagate(probe, pb).status != Status::kFixedPoint) continue;  // outside the domain
      const Interval g = pb[8];
      if (!std::isfinite(g.lower()) || !std::isfinite(g.upper())) continue;
      char rhs[128];
      std::snprintf(rhs, sizeof rhs, " [%.17g, %.17g]", g.lower() - 1e-9, g.upper() + 1e-9);
      const int rel = static_cast<int>(rng() % 3);
      const std::string text = shape + (rel == 0 ? " == " : rel == 1 ? " <= " : " >= ") + rhs;
      AddConstraintText(net, text, {});
    }
    Box box = net.InitialBox();
    const PropagationReport r = Propagate(net, box);
    ASSERT_NE(r.status, Status::kInfeasible) << "trial " << trial;
    for (int i = 0; i < 8; ++i) {
      EXPECT_TRUE(box[i].lower() <= point[i] && point[i] <= box[i].upper())
          << "trial " << trial << " v" << i << " = " << point[i] << " excluded by " << ToString(box[i]);
    }
    ++checked;
  }
  EXPECT_GE(checked, 30);
}

TEST(Shaving, CutsBoundsThatHC4CannotTighten) {
  Network net;
  const VariableId x = net.AddVariable("x", Interval(-1, 1));
  const VariableId y = net.AddVariable("y", Interval(-1, 1));
  AddConstraintText(net, "x + y == 0", {});
  AddConstraintText(net, "x - y == 0", {});
  Box box = net.InitialBox();
  ASSERT_EQ(Propagate(net, box).status, Status::kFixedPoint);
  EXPECT_EQ(box[x.value].lower(), -1.0);  // HC4 alone leaves [-1, 1]
  ShavingOptions s;
  s.variables = {x};
  s.max_propagations = 60;
  const PropagationReport r = Shave(net, box, PropagationOptions{}, s);
  EXPECT_EQ(r.status, Status::kFixedPoint);
  EXPECT_GT(box[x.value].lower(), -0.1);
  EXPECT_LT(box[x.value].upper(), 0.1);
  EXPECT_TRUE(box[x.value].lower() <= 0.0 && 0.0 <= box[x.value].upper());
  EXPECT_LT(box[y.value].upper(), 0.1);
}

}  // namespace
}  // namespace highlift::icsp
