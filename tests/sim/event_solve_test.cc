// The solve around events (System). At an event the speeds are projected onto the velocity-level
// constraints (ProjectSpeeds): the speeds that meet them with the least change of kinetic
// energy, solved group by group (the nodes that the constraints couple). Checked against the
// closed forms of a gear pair, of a chain of two gears (two rows in one group) and of a rotor
// pair coupled twice (redundant rows), all in one network, and against the kinetic energy the
// projection reports as lost. Between events the groups of the acceleration solve are not
// compared with the active constraints again (their pattern changes only with the modes); an
// event that changes a mode makes the next solve build them anew: a brake that holds a geared
// pair of rotors (two rows in one group) releases at an event, and the solve after it has one
// row left. The commonest group of the acceleration solve, two rotors and one gear, is solved
// from a flat array of its own (System::PairGroup): checked against the closed form, beside
// other pairs and a group of two rows.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "system.h"

namespace highlift::sim::detail {
namespace {

ElementParameters P(std::map<std::string, double> s) { return {std::move(s), {}}; }

// The speed state of the node of rotor `id`.
int SpeedState(const System& sys, const std::string& id) {
  for (const auto& el : sys.elements())
    if (el->id == id) return sys.nodes()[static_cast<std::size_t>(el->Nodes().front())].s_w;
  ADD_FAILURE() << "no rotor " << id;
  return 0;
}

constexpr double kJa = 0.5, kJb = 0.2, kRatio = 4.0;                // pair: w_a = 4 w_b
constexpr double kJc = 0.3, kJd = 0.7, kJe = 1.1;                   // chain: w_c = 2 w_d, w_d = 3 w_e
constexpr double kJf = 0.4, kJg = 0.9;                              // twice coupled: w_f = w_g
constexpr double kWa = 10.0, kWb = -1.0, kWc = 3.0, kWd = 5.0, kWe = -2.0, kWf = 8.0, kWg = 1.0;

Network ThreeGroups() {
  Network net;
  auto rotor = [&](const std::string& id, double J) { net.AddElement("Inertia", id, P({{"J", J}, {"phi_start", 0}})); };
  auto gear = [&](const std::string& id, double ratio, const std::string& from, const std::string& to) {
    net.AddElement("IdealGear", id, P({{"ratio", ratio}}));
    net.Connect(from + ".flange_b", id + ".flange_a");
    net.Connect(id + ".flange_b", to + ".flange_a");
  };
  rotor("a", kJa);
  rotor("b", kJb);
  gear("pair", kRatio, "a", "b");
  rotor("c", kJc);
  rotor("d", kJd);
  rotor("e", kJe);
  gear("chain1", 2.0, "c", "d");
  gear("chain2", 3.0, "d", "e");
  rotor("f", kJf);
  rotor("g", kJg);
  gear("twice1", 1.0, "f", "g");
  gear("twice2", 1.0, "f", "g");
  return net;
}

// Three gear pairs and a chain of two gears, each rotor driven by a torque of its own: a pair
// (w_a = ratio w_b) is one degree of freedom with the inertia ratio^2 J_a + J_b at b and the
// torque ratio tau_a + tau_b, so acc_b = (ratio tau_a + tau_b) / (ratio^2 J_a + J_b) and
// acc_a = ratio acc_b. A pair solved with another pair's nodes, inertias or gear would give that
// pair's numbers; the chain (two rows: not a pair) must still satisfy its two gears.
TEST(AccelerationSolve, GearPairsFromTheFlatArrayAreTheirClosedForm) {
  struct Pair {
    std::string a, b;
    double J_a, J_b, ratio, tau_a, tau_b;
  };
  const std::vector<Pair> pairs = {{"a", "b", 0.5, 0.2, 4.0, 3.0, -1.0},
                                   {"p", "q", 0.3, 0.8, -2.5, 2.0, 0.5},
                                   {"u", "v", 1.7, 0.05, 0.1, -0.4, 0.9}};
  Network net;
  auto rotor = [&](const std::string& id, double J, double tau) {
    net.AddElement("Inertia", id, P({{"J", J}, {"phi_start", 0}}));
    net.AddElement("ConstantTorque", "tau_" + id, P({{"tau_constant", tau}}));
    net.Connect("tau_" + id + ".flange", id + ".flange_a");
  };
  auto gear = [&](const std::string& id, double ratio, const std::string& from, const std::string& to) {
    net.AddElement("IdealGear", id, P({{"ratio", ratio}}));
    net.Connect(from + ".flange_b", id + ".flange_a");
    net.Connect(id + ".flange_b", to + ".flange_a");
  };
  for (const Pair& p : pairs) {
    rotor(p.a, p.J_a, p.tau_a);
    rotor(p.b, p.J_b, p.tau_b);
    gear("gear_" + p.a, p.ratio, p.a, p.b);
  }
  rotor("c", 0.3, 1.0);
  rotor("d", 0.7, -0.5);
  rotor("e", 1.1, 0.25);
  gear("chain1", 2.0, "c", "d");
  gear("chain2", 3.0, "d", "e");
  System sys(net);
  std::vector<double> y = sys.InitialState(0.0);
  std::vector<std::string> changes, who;
  ASSERT_TRUE(sys.HandleEvent(0.0, y.data(), true, &changes, &who)) << sys.error();
  std::vector<double> ydot(y.size(), NAN);
  ASSERT_TRUE(sys.Evaluate(0.0, y.data(), ydot.data())) << sys.error();
  auto acc = [&](const std::string& id) { return ydot[static_cast<std::size_t>(SpeedState(sys, id))]; };
  for (const Pair& p : pairs) {
    const double acc_b = (p.ratio * p.tau_a + p.tau_b) / (p.ratio * p.ratio * p.J_a + p.J_b);
    EXPECT_NEAR(acc(p.b), acc_b, 1e-12 * std::abs(acc_b)) << p.a << p.b;
    EXPECT_NEAR(acc(p.a), p.ratio * acc_b, 1e-12 * std::abs(p.ratio * acc_b)) << p.a << p.b;
  }
  // The chain: w_c = 2 w_d and w_d = 3 w_e, one degree of freedom at e.
  const double acc_e = (6.0 * 1.0 + 3.0 * -0.5 + 0.25) / (36.0 * 0.3 + 9.0 * 0.7 + 1.1);
  EXPECT_NEAR(acc("e"), acc_e, 1e-12 * std::abs(acc_e));
  EXPECT_NEAR(acc("d"), 3.0 * acc_e, 1e-12 * std::abs(acc_e));
  EXPECT_NEAR(acc("c"), 6.0 * acc_e, 1e-12 * std::abs(acc_e));
}

TEST(SpeedProjection, IsTheLeastKineticEnergyChangeThatMeetsTheConstraintsGroupByGroup) {
  System sys(ThreeGroups());
  std::vector<double> y = sys.InitialState(0.0);
  std::vector<std::string> changes, who;
  ASSERT_TRUE(sys.HandleEvent(0.0, y.data(), true, &changes, &who)) << sys.error();
  const double loss_before = sys.impulsive_loss();
  // Speeds that no constraint allows, as a restart after a jam or a brake engagement leaves them.
  const std::map<std::string, double> given = {{"a", kWa}, {"b", kWb}, {"c", kWc}, {"d", kWd},
                                               {"e", kWe}, {"f", kWf}, {"g", kWg}};
  const std::map<std::string, double> inertia = {{"a", kJa}, {"b", kJb}, {"c", kJc}, {"d", kJd},
                                                 {"e", kJe}, {"f", kJf}, {"g", kJg}};
  double kinetic_before = 0.0;
  for (const auto& [id, w] : given) {
    y[static_cast<std::size_t>(SpeedState(sys, id))] = w;
    kinetic_before += 0.5 * inertia.at(id) * w * w;
  }
  ASSERT_TRUE(sys.HandleEvent(0.5, y.data(), false, &changes, &who)) << sys.error();
  auto w = [&](const std::string& id) { return y[static_cast<std::size_t>(SpeedState(sys, id))]; };

  // min sum J/2 (w' - w)^2 subject to the rows: each group's momentum seen from its last rotor.
  const double wb = (kJa * kRatio * kWa + kJb * kWb) / (kJa * kRatio * kRatio + kJb);
  const double we = (kJc * 6.0 * kWc + kJd * 3.0 * kWd + kJe * kWe) / (kJc * 36.0 + kJd * 9.0 + kJe);
  const double wg = (kJf * kWf + kJg * kWg) / (kJf + kJg);
  const std::map<std::string, double> expected = {{"a", kRatio * wb}, {"b", wb}, {"c", 6.0 * we}, {"d", 3.0 * we},
                                                  {"e", we}, {"f", wg}, {"g", wg}};
  // (The projection weighs each inertia with 1e-9 of the largest added, which keeps a rotor
  // without inertia determined: a relative change of about 1e-9 here.)
  double kinetic_after = 0.0;
  for (const auto& [id, value] : expected) {
    EXPECT_NEAR(w(id), value, 1e-8 * std::abs(value)) << "rotor " << id;
    kinetic_after += 0.5 * inertia.at(id) * w(id) * w(id);
  }
  // The constraints hold to roundoff.
  EXPECT_NEAR(w("a"), kRatio * w("b"), 1e-14 * std::abs(w("a")));
  EXPECT_NEAR(w("c"), 2.0 * w("d"), 1e-14 * std::abs(w("c")));
  EXPECT_NEAR(w("d"), 3.0 * w("e"), 1e-14 * std::abs(w("d")));
  EXPECT_NEAR(w("f"), w("g"), 1e-14 * std::abs(w("f")));
  // The energy the projection takes out is the kinetic energy lost.
  EXPECT_NEAR(sys.impulsive_loss() - loss_before, kinetic_before - kinetic_after, 1e-9 * kinetic_before);
  EXPECT_GT(kinetic_before - kinetic_after, 0.0);
}

constexpr double kJ1 = 1.0, kJ2 = 0.25, kGearRatio = 2.0, kTorque = 50.0;

// Motor torque 50 N*m on rotor r1, geared (ratio 2) to r2; a shaft brake on r1 commanded by a
// ramp from 1 at t = 0 down to -1 at t = 1 s (released from t = 0.5 s on).
Network GearedPairOnABrake() {
  Network net;
  net.AddElement("Inertia", "r1", P({{"J", kJ1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("IdealGear", "gear", P({{"ratio", kGearRatio}}));
  net.AddElement("Inertia", "r2", P({{"J", kJ2}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("ShaftBrake", "brake", P({{"tauB_max", 100}, {"tauB_lim", 150}}));
  net.AddElement("Ramp", "command", P({{"height", -2}, {"duration", 1}, {"offset", 1}, {"startTime", 0}}));
  net.AddElement("Constant", "torque", P({{"k", kTorque}}));
  net.AddElement("Torque", "motor");
  net.Connect("r1.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "r2.flange_a");
  net.Connect("r1.flange_a", "brake.flange_a");
  net.Connect("command.y", "brake.u");
  net.Connect("torque.y", "motor.tau");
  net.Connect("motor.flange", "r1.flange_a");
  return net;
}

TEST(ConstraintPattern, TheSolveAfterAnEventFollowsTheNewModes) {
  System sys(GearedPairOnABrake());
  std::vector<double> y = sys.InitialState(0.0);
  std::vector<std::string> changes, who;
  ASSERT_TRUE(sys.HandleEvent(0.0, y.data(), true, &changes, &who)) << sys.error();
  const auto w1 = static_cast<std::size_t>(SpeedState(sys, "r1")), w2 = static_cast<std::size_t>(SpeedState(sys, "r2"));
  std::vector<double> ydot(y.size());
  // Held (50 N*m against up to 150 N*m): the rotors stand still, at every evaluation between events.
  for (const double t : {0.1, 0.2, 0.3}) {
    ASSERT_TRUE(sys.Evaluate(t, y.data(), ydot.data())) << sys.error();
    EXPECT_NEAR(ydot[w1], 0.0, 1e-12) << "t = " << t;
    EXPECT_NEAR(ydot[w2], 0.0, 1e-12) << "t = " << t;
  }
  // Released at the event at 0.7 s (command -0.4): the motor accelerates both rotors through the
  // gear, J1 a1 + J2 a2 / ratio = tau with a1 = ratio a2.
  ASSERT_TRUE(sys.HandleEvent(0.7, y.data(), false, &changes, &who)) << sys.error();
  const double a1 = kTorque / (kJ1 + kJ2 / (kGearRatio * kGearRatio));
  for (const double t : {0.7, 0.8, 0.9}) {
    ASSERT_TRUE(sys.Evaluate(t, y.data(), ydot.data())) << sys.error();
    EXPECT_NEAR(ydot[w1], a1, 1e-12 * a1) << "t = " << t;
    EXPECT_NEAR(ydot[w2], a1 / kGearRatio, 1e-12 * a1) << "t = " << t;
  }
}

}  // namespace
}  // namespace highlift::sim::detail
