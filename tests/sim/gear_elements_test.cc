// HighLift gears and failure elements (sim/src/gear_elements.cc): analytic cases for every
// type, mode sequences, the efficiency law of figure 7, bad parameters, and the energy balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

using Scalars = std::map<std::string, double>;
using Rows = std::vector<std::vector<double>>;

ElementParameters P(Scalars s, std::map<std::string, Rows> t = {}) {
  return {std::move(s), std::move(t)};
}

struct RunResult {
  MemorySink sink;
  SimulationReport report;
  std::vector<double> Col(const std::string& name) const { return sink.Series(name); }
  const std::vector<double>& t() const { return sink.times(); }
  /// The value of column `name` at the last output row with time <= t.
  double At(const std::string& name, double time) const {
    const auto column = Col(name);
    std::size_t k = 0;
    while (k + 1 < t().size() && t()[k + 1] <= time + 1e-12) ++k;
    return column[k];
  }
};

RunResult Simulate(const Network& net, double stop, double dt, bool energy = false,
                   double rtol = 1e-8) {
  RunResult r;
  Simulator sim(net);
  SimulationOptions o;
  o.energy = energy;
  o.stop_time = stop;
  o.output_interval = dt;
  o.relative_tolerance = rtol;
  o.absolute_tolerance = 1e-10;
  r.report = sim.Run(o, r.sink);
  return r;
}

std::string ErrorOf(const Network& net) {
  try {
    Simulator sim(net);
    MemorySink sink;
    SimulationOptions o;
    o.stop_time = 0.01;
    const SimulationReport report = sim.Run(o, sink);
    return report.ok() ? "" : report.message;
  } catch (const InputError& e) {
    return e.message();
  }
}

// ------------------------------------------------------------------------------------------
// GearedRotaryActuator

constexpr double kRatio = 100.0, kEtaOp = 0.85, kEtaAi = 0.70, kTauC = 0.5;

/// A speed source turns the actuator input at w_in through a stiff drive shaft (a speed
/// source rigidly on a stuck gear would over-determine the input); a constant torque `load`
/// acts on the output (negative: opposing the forward motion).
Network ActuatorOnSpeedSource(double w_in, double load, Scalars extra = {},
                              bool drive_shaft = true) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Ramp", "w_ref", P({{"height", w_in}, {"duration", 0.05}}));
  net.AddElement("Speed", "pdu", P({{"f_crit", 50}}));
  Scalars gra{{"ratio", kRatio}, {"eta_op", kEtaOp}, {"eta_ai", kEtaAi}, {"J_in", 1e-3},
              {"J_load", 2e-4}, {"tau_C", kTauC}, {"phi_eta", 1.0}, {"w_eta", 0.5}};
  for (const auto& [k, v] : extra) gra[k] = v;
  net.AddElement("GearedRotaryActuator", "gra", P(gra));
  net.AddElement("ConstantTorque", "airload", P({{"tau_constant", load}}));
  net.Connect("w_ref.y", "pdu.w_ref");
  net.Connect("pdu.support", "fixed.flange");
  if (drive_shaft) {
    net.AddElement("SpringDamper", "drive_shaft", P({{"c", 1e4}, {"d", 20}}));
    net.Connect("pdu.flange", "drive_shaft.flange_a");
    net.Connect("drive_shaft.flange_b", "gra.flange_a");
  } else {
    net.Connect("pdu.flange", "gra.flange_a");
  }
  net.Connect("gra.flange_b", "airload.flange");
  return net;
}

// Opposing load T: the input torque is (T/ratio + tau_C)/eta_op once the mesh is engaged
// (MSL LossyGear quadrant 1: tau_out = ratio*(eta*tau_in - tau_bf)).
TEST(GearedRotaryActuator, OpposingLoadReflectsThroughEtaOp) {
  const double T = 500.0;
  const RunResult r = Simulate(ActuatorOnSpeedSource(5.0, -T), 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double expected = (T / kRatio + kTauC) / kEtaOp;  // 6.47 N*m
  EXPECT_NEAR(r.At("gra.tau", 1.0), expected, 1e-4 * expected);
  EXPECT_NEAR(r.At("gra.tau_out", 1.0), T, 1e-4 * T);
  EXPECT_NEAR(r.At("gra.eta_GE", 1.0), kEtaOp, 1e-9);
  EXPECT_EQ(r.At("gra.mode", 1.0), 1.0);
  EXPECT_GT(r.At("gra.lossPower", 1.0), 0.0);
}

// Aiding load T: the load back-drives the actuator and the input holds it with
// eta_ai*(T/ratio - tau_C) (quadrant 2: power flows from the output to the input).
TEST(GearedRotaryActuator, AidingLoadReflectsThroughEtaAi) {
  const double T = 500.0;
  const RunResult r = Simulate(ActuatorOnSpeedSource(5.0, +T), 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double expected = -kEtaAi * (T / kRatio - kTauC);  // -3.15 N*m
  EXPECT_NEAR(r.At("gra.tau", 1.0), expected, 1e-4 * std::abs(expected));
  EXPECT_NEAR(r.At("gra.tau_out", 1.0), -T, 1e-4 * T);
  EXPECT_NEAR(r.At("gra.eta_GE", 1.0), kEtaAi, 1e-9);
  // The loss opposes the motion in both quadrants: it is never a source of power.
  for (double p : r.Col("gra.lossPower")) EXPECT_GE(p, -1e-9);
}

// Figure 7: after the start eta_GE falls from 1 to its final value linearly in the input angle
// over phi_eta; when the unit slows down below w_eta it rises linearly in the speed back to 1;
// after the reversal it settles again over phi_eta, measured from the reversal.
TEST(GearedRotaryActuator, EfficiencyFollowsFigure7) {
  const double phi_eta = 2.0, w_eta = 0.5;
  Network net;
  net.AddElement("Fixed", "fixed");
  // Input speed: up to 2 rad/s, down to -2 rad/s through zero at t = 3 s.
  net.AddElement("TimeTable", "w_ref",
                 P({}, {{"table", {{0, 0}, {0.1, 2}, {2.0, 2}, {4.0, -2}, {6.0, -2}}}}));
  net.AddElement("Speed", "pdu", P({{"f_crit", 100}}));
  net.AddElement("GearedRotaryActuator", "gra",
                 P({{"ratio", 50}, {"eta_op", 0.8}, {"J_in", 1e-3}, {"phi_eta", phi_eta},
                    {"w_eta", w_eta}, {"tau_C", 0.2}}));
  net.AddElement("Damper", "flap", P({{"d", 2e4}}));  // opposes the motion both ways
  net.Connect("w_ref.y", "pdu.w_ref");
  net.Connect("pdu.support", "fixed.flange");
  net.AddElement("SpringDamper", "drive_shaft", P({{"c", 1e4}, {"d", 20}}));
  net.Connect("pdu.flange", "drive_shaft.flange_a");
  net.Connect("drive_shaft.flange_b", "gra.flange_a");
  net.Connect("gra.flange_b", "flap.flange_a");
  net.Connect("flap.flange_b", "fixed.flange");
  const RunResult r = Simulate(net, 6.0, 2e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto t = r.t();
  const auto phi = r.Col("gra.phi"), w = r.Col("gra.w"), eta = r.Col("gra.eta_GE");
  const auto mode = r.Col("gra.mode");
  // The reversal: Forward, then (stuck at zero speed) Backward. Its angle is that of the row
  // before the first Backward row (the stuck angle, or the left limit at the event).
  std::vector<double> sequence;
  for (double m : mode)
    if (sequence.empty() || sequence.back() != m) sequence.push_back(m);
  EXPECT_EQ(sequence, (std::vector<double>{0, 1, 0, -1})) << r.report.FullReport();
  const std::size_t reversal = std::find(mode.begin(), mode.end(), -1.0) - mode.begin();
  ASSERT_LT(reversal, mode.size());
  const double phi_reversal = phi[reversal - 1];
  int checked_angle = 0, checked_speed = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (std::abs(w[k]) < 1e-6) continue;
    const double from_start = k < reversal ? std::abs(phi[k] - phi[0]) : std::abs(phi[k] - phi_reversal);
    const double e_angle = std::min(1.0, from_start / phi_eta);
    const double e_speed = std::min(1.0, std::abs(w[k]) / w_eta);
    EXPECT_NEAR(eta[k], 1 - std::min(e_angle, e_speed) * (1 - 0.8), 1e-6) << "t = " << t[k];
    if (e_angle > 0.2 && e_angle < 0.8 && e_speed == 1.0) ++checked_angle;
    if (e_speed > 0.2 && e_speed < 0.8 && e_angle == 1.0) ++checked_speed;
  }
  EXPECT_GT(checked_angle, 20) << "rows on the angle ramp (figure 7b)";
  EXPECT_GT(checked_speed, 20) << "rows on the speed ramp (figure 7a)";
  EXPECT_NEAR(r.At("gra.eta_GE", 2.0), 0.8, 1e-9);
  EXPECT_NEAR(r.At("gra.eta_GE", 6.0), 0.8, 1e-9);
}

// The regularised actuator (w_small > 0) reverses under a sinusoidal speed command. Its one root,
// the input speed crossing zero, is kinematic: the simulator locates it on the interpolant from
// the states alone, so CVODE evaluates no root function at all here. Each reversal is found
// once, at w = 0, and restarts the angle of figure 7 there.
TEST(GearedRotaryActuator, RegularisedReversalsAreLocatedFromTheStatesAlone) {
  const double phi_eta = 0.3, w_eta = 0.5, eta_op = 0.8;
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Sine", "w_ref", P({{"amplitude", 2.0}, {"f", 2.0}}));
  net.AddElement("Speed", "pdu", P({{"f_crit", 100}}));
  net.AddElement("GearedRotaryActuator", "gra",
                 P({{"ratio", 50}, {"eta_op", eta_op}, {"J_in", 1e-3}, {"J_load", 1e-4}, {"phi_eta", phi_eta},
                    {"w_eta", w_eta}, {"tau_C", 0.2}, {"w_small", 0.05}}));
  net.AddElement("Damper", "flap", P({{"d", 2e4}}));
  net.AddElement("SpringDamper", "drive_shaft", P({{"c", 1e4}, {"d", 20}}));
  net.Connect("w_ref.y", "pdu.w_ref");
  net.Connect("pdu.support", "fixed.flange");
  net.Connect("pdu.flange", "drive_shaft.flange_a");
  net.Connect("drive_shaft.flange_b", "gra.flange_a");
  net.Connect("gra.flange_b", "flap.flange_a");
  net.Connect("flap.flange_b", "fixed.flange");
  const RunResult r = Simulate(net, 2.0, 1e-3, false, 1e-7);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_EQ(r.report.statistics.root_evaluations, 0) << r.report.FullReport();
  const auto t = r.t();
  const auto phi = r.Col("gra.phi"), w = r.Col("gra.w"), eta = r.Col("gra.eta_GE");
  std::vector<double> reversals;
  for (const SimulationEvent& e : r.report.events)
    if (e.kind == "state" && e.what == "gra contact") reversals.push_back(e.time);
  // The command reverses every 0.25 s (7 times after the start in 2 s), the actuator a little
  // later.
  ASSERT_EQ(reversals.size(), 7u) << r.report.FullReport();
  for (std::size_t k = 0; k < reversals.size(); ++k)
    EXPECT_NEAR(reversals[k], 0.25 * static_cast<double>(k + 1), 0.02) << "reversal " << k;
  // At each reversal the speed is zero to the root tolerance (w changes by about 25 rad/s^2),
  // and the efficiency law restarts its angle there.
  double phi_start = phi[0];
  std::size_t next = 0;
  int checked_angle = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (next < reversals.size() && t[i] == reversals[next]) {
      EXPECT_NEAR(w[i], 0.0, 1e-9) << "t = " << t[i];
      phi_start = phi[i];
      ++next;
      continue;
    }
    const double e_angle = std::min(1.0, std::abs(phi[i] - phi_start) / phi_eta);
    const double e_speed = std::min(1.0, std::abs(w[i]) / w_eta);
    EXPECT_NEAR(eta[i], 1 - std::min(e_angle, e_speed) * (1 - eta_op), 1e-6) << "t = " << t[i];
    if (e_angle > 0.2 && e_angle < 0.8 && e_speed == 1.0) ++checked_angle;
  }
  EXPECT_EQ(next, reversals.size()) << "a row at every reversal";
  EXPECT_GT(checked_angle, 20) << "rows on the angle ramp after the reversals (figure 7b)";

  // After a reversal the elements are evaluated with the restarted angle only for a row that
  // reads them; a sink that reads no values gets the same steps, events and peaks.
  struct NoValues : OutputSink {
    void Begin(const std::vector<std::string>&) override {}
    void Row(double, const std::vector<double>&) override { ++rows; }
    bool ReadsValues() const override { return false; }
    std::size_t rows = 0;
  } no_values;
  SimulationOptions o;
  o.stop_time = 2.0;
  o.output_interval = 1e-3;
  o.relative_tolerance = 1e-7;
  o.absolute_tolerance = 1e-10;
  const SimulationReport lean = Simulator(net).Run(o, no_values);
  ASSERT_TRUE(lean.ok()) << lean.FullReport();
  EXPECT_EQ(no_values.rows, t.size());
  EXPECT_EQ(lean.statistics.steps, r.report.statistics.steps);
  EXPECT_EQ(lean.statistics.continuous_roots, 7);
  ASSERT_EQ(lean.events.size(), r.report.events.size());
  for (std::size_t i = 0; i < lean.events.size(); ++i) EXPECT_EQ(lean.events[i].time, r.report.events[i].time) << i;
  ASSERT_EQ(lean.peak_torques.size(), r.report.peak_torques.size());
  for (std::size_t i = 0; i < lean.peak_torques.size(); ++i) {
    EXPECT_EQ(lean.peak_torques[i].tau, r.report.peak_torques[i].tau) << lean.peak_torques[i].element;
    EXPECT_EQ(lean.peak_torques[i].time, r.report.peak_torques[i].time) << lean.peak_torques[i].element;
  }
}

// A torque-driven actuator: it runs out against an opposing load, stops and sticks (held by
// the breakaway friction peak*(tau_C + tau_S)), then the load back-drives it (aiding). The
// mode sequence is Stuck, Forward, Stuck, Backward; eta_GE is 1 while stuck and eta_ai at the
// end; the energy balance closes over the stick-slip run.
TEST(GearedRotaryActuator, StickSlipModeSequenceAndEnergyBalance) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("TimeTable", "command",
                 P({}, {{"table", {{0, 1.5}, {0.05, 10}, {1.0, 10}, {1.0, 1.5}, {2.0, 1.5},
                                   {2.0, 0.5}, {4.0, 0.5}}}}));
  net.AddElement("Torque", "motor");
  net.AddElement("GearedRotaryActuator", "gra",
                 P({{"ratio", 50}, {"eta_op", 0.85}, {"eta_ai", 0.7}, {"J_in", 0.01},
                    {"J_load", 0.02}, {"tau_C", 0.5}, {"tau_S", 0.25}, {"peak", 1.2},
                    {"phi_eta", 1.0}, {"w_eta", 0.5}}));
  net.AddElement("ConstantTorque", "airload", P({{"tau_constant", -100}}));
  net.AddElement("Damper", "flap", P({{"d", 1000}}));
  net.Connect("command.y", "motor.tau");
  net.Connect("motor.support", "fixed.flange");
  net.Connect("motor.flange", "gra.flange_a");
  net.Connect("gra.flange_b", "airload.flange");
  net.Connect("gra.flange_b", "flap.flange_a");
  net.Connect("flap.flange_b", "fixed.flange");
  const RunResult r = Simulate(net, 4.0, 1e-3, true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  std::vector<double> sequence;
  for (double m : r.Col("gra.mode"))
    if (sequence.empty() || sequence.back() != m) sequence.push_back(m);
  EXPECT_EQ(sequence, (std::vector<double>{0, 1, 0, -1})) << r.report.FullReport();
  // Held between t = 1 and 2: the load (2 N*m at the input) less the motor (1.5 N*m) is below
  // the breakaway torque 1.2*(0.5 + 0.25) = 0.9 N*m.
  EXPECT_EQ(r.At("gra.mode", 1.9), 0.0);
  EXPECT_EQ(r.At("gra.eta_GE", 1.9), 1.0);
  // The holding friction acts forward (tauLoss > 0 would oppose a forward motion).
  EXPECT_NEAR(r.At("gra.tauLoss", 1.9), -(100.0 / 50 - 1.5), 1e-6);
  // Back-driven at the end: aiding, the motor holds back, the mesh loses 1 - eta_ai.
  EXPECT_EQ(r.At("gra.mode", 4.0), -1.0);
  EXPECT_GT(r.At("gra.tau", 4.0), 0.0);
  EXPECT_NEAR(r.At("gra.eta_GE", 4.0), 0.7, 1e-9);
  const EnergyBalance& b = r.report.energy;
  ASSERT_TRUE(b.computed);
  EXPECT_GT(b.dissipated, 10.0);
  EXPECT_NEAR(b.Residual(), 0.0, 1e-4 * b.Scale()) << r.report.FullReport();
}

// elastic = true: an ElastoBacklash in front of the actuator (a composite). The steady twist
// of the spring carries the input torque; eta_GE is available as a signal output.
TEST(GearedRotaryActuator, ElasticActuatorIsBacklashInFrontAndExportsEtaGE) {
  Network net = ActuatorOnSpeedSource(
      5.0, -500.0, {{"elastic", 1}, {"c", 2e3}, {"d", 5}, {"b", 0.01}}, /*drive_shaft=*/false);
  net.AddElement("Constant", "two", P({{"k", 2}}));
  net.AddElement("Product", "eta_twice");
  net.Connect("gra.eta_GE", "eta_twice.u1");
  net.Connect("two.y", "eta_twice.u2");
  const RunResult r = Simulate(net, 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double tau_in = (500.0 / kRatio + kTauC) / kEtaOp;
  // MSL sign convention: tau = flange_b.tau of the spring, -tau_in when it drives.
  EXPECT_NEAR(r.At("gra.elastoBacklash.tau", 1.0), -tau_in, 1e-3 * tau_in);
  EXPECT_NEAR(r.At("gra.elastoBacklash.phi_rel", 1.0), -(tau_in / 2e3 + 0.005), 1e-6);
  EXPECT_NEAR(r.At("gra.tau", 1.0), tau_in, 1e-3 * tau_in);
  EXPECT_NEAR(r.At("eta_twice.y", 1.0), 2 * kEtaOp, 1e-9);
}

TEST(GearedRotaryActuator, RejectsBadParametersNamingElementAndParameter) {
  EXPECT_EQ(ErrorOf(ActuatorOnSpeedSource(1.0, 0.0, {{"ratio", 0}})),
            "element 'gra' (GearedRotaryActuator): parameter 'ratio' = 0 is not a gear; give the "
            "speed ratio input / output (non-zero, e.g. 200 for an actuator)");
  EXPECT_EQ(ErrorOf(ActuatorOnSpeedSource(1.0, 0.0, {{"elastic", 1}})),
            "element 'gra' (GearedRotaryActuator): parameter 'c' (torsional stiffness, N*m/rad) "
            "is required when elastic = true; give c or set elastic = false");
  try {
    ActuatorOnSpeedSource(1.0, 0.0, {{"eta_ai", 0}});
    ADD_FAILURE() << "eta_ai = 0 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("element 'gra' (GearedRotaryActuator): parameter 'eta_ai'"),
              std::string::npos)
        << e.message();
    EXPECT_NE(e.message().find("outside its valid range"), std::string::npos) << e.message();
  }
}

// ------------------------------------------------------------------------------------------
// GeneralRotationalElement and BranchGearbox

// Without inertia and friction the element is ElastoBacklash + IdealGear: a torque T on the
// input with the output fixed twists the spring by T/c + b/2 and the housing reacts
// ratio*T at the output.
TEST(GeneralRotationalElement, MasslessLosslessElementIsBacklashAndIdealGear) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "motor", P({{"tau_constant", 30}}));
  net.AddElement("Inertia", "rotor", P({{"J", 0.01}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("GeneralRotationalElement", "gearbox",
                 P({{"ratio", 3}, {"c", 1e4}, {"d", 20}, {"b", 0.02}, {"J", 0}}));
  net.Connect("motor.flange", "rotor.flange_a");
  net.Connect("motor.support", "fixed.flange");
  net.Connect("rotor.flange_b", "gearbox.flange_a");
  net.Connect("gearbox.flange_b", "fixed.flange");
  const RunResult r = Simulate(net, 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.At("rotor.phi", 1.0), 30 / 1e4 + 0.01, 1e-7);
  EXPECT_NEAR(r.At("gearbox.elastoBacklash.tau", 1.0), -30.0, 1e-5);
  EXPECT_NEAR(r.At("gearbox.flange_b.tau", 1.0), -3 * 30.0, 1e-4);
}

// The full element with its LossyInertia (brake family): bearing friction tau_C on the input
// side of the gear and the inertia J. Run only once the LossyInertia type is in the build.
TEST(GeneralRotationalElement, LossyInertiaPartCarriesInertiaAndFriction) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "motor", P({{"tau_constant", 10}}));
  net.AddElement("GeneralRotationalElement", "gearbox",
                 P({{"ratio", 2}, {"elastic", 0}, {"J", 0.5}, {"tau_C", 4}}));
  net.AddElement("Inertia", "load", P({{"J", 2}, {"phi_start", 0}, {"w_start", 0}}));
  net.Connect("motor.flange", "gearbox.flange_a");
  net.Connect("motor.support", "fixed.flange");
  net.Connect("gearbox.flange_b", "load.flange_a");
  if (FindElementType("LossyInertia") == nullptr) {
    EXPECT_NE(ErrorOf(net).find("element 'gearbox' (GeneralRotationalElement): J > 0, friction "
                                "or eta_GE < 1 need the element type 'LossyInertia'"),
              std::string::npos)
        << ErrorOf(net);
    GTEST_SKIP() << "LossyInertia (brake family) is not in this build yet";
  }
  const RunResult r = Simulate(net, 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  // Input-referred: (J + J_load/ratio^2) * a_in = T - tau_C  =>  a_in = 6 / 1.0.
  const double a_in = (10.0 - 4.0) / (0.5 + 2.0 / 4.0);
  EXPECT_NEAR(r.At("load.w", 1.0), a_in / 2 * 1.0, 1e-4 * a_in);
}

// The full element under an alternating drive: the backlash opens and closes, the bearing
// friction sticks and slips, the mesh loses 1 - eta_GE; the energy balance closes.
TEST(GeneralRotationalElement, EnergyBalanceClosesOverStickSlipAndBacklash) {
  if (FindElementType("LossyInertia") == nullptr)
    GTEST_SKIP() << "LossyInertia (brake family) is not in this build yet";
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Sine", "command", P({{"amplitude", 6}, {"f", 1.5}}));
  net.AddElement("Torque", "motor");
  net.AddElement("Inertia", "rotor", P({{"J", 0.02}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("GeneralRotationalElement", "gearbox",
                 P({{"ratio", 2}, {"c", 2e3}, {"d", 2}, {"b", 0.01}, {"J", 0.05}, {"tau_C", 1},
                    {"tau_S", 0.5}, {"peak", 1.2}, {"eta_GE", 0.9}}));
  net.AddElement("Inertia", "load", P({{"J", 0.4}}));
  net.AddElement("SpringDamper", "tether", P({{"c", 40}, {"d", 1}}));
  net.Connect("command.y", "motor.tau");
  net.Connect("motor.support", "fixed.flange");
  net.Connect("motor.flange", "rotor.flange_a");
  net.Connect("rotor.flange_b", "gearbox.flange_a");
  net.Connect("gearbox.flange_b", "load.flange_a");
  net.Connect("load.flange_b", "tether.flange_a");
  net.Connect("tether.flange_b", "fixed.flange");
  const RunResult r = Simulate(net, 2.0, 1e-3, true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  bool stuck = false, sliding = false;
  for (double m : r.Col("gearbox.lossyInertia.mode")) stuck |= m == 0, sliding |= std::abs(m) == 1;
  EXPECT_TRUE(stuck && sliding) << "the run should exercise stick and slip";
  const EnergyBalance& b = r.report.energy;
  EXPECT_GT(b.dissipated, 0.5);
  EXPECT_NEAR(b.Residual(), 0.0, 1e-3 * b.Scale()) << r.report.FullReport();
}

// The through-drive is rigid and the branch turns at 1/ratio: w_branch = w_b/ratio at every
// instant; the branch torque reflects through the ratio. (A stiff drive shaft joins the speed
// source: a speed source rigidly on a stuck friction would over-determine the input.)
Network BranchGearboxOnSpeedSource(Scalars gearbox) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Ramp", "w_ref", P({{"height", 4}, {"duration", 0.1}}));
  net.AddElement("Speed", "pdu", P({{"f_crit", 50}}));
  net.AddElement("BranchGearbox", "tgb", P(gearbox));
  net.AddElement("Inertia", "outboard", P({{"J", 0.1}}));
  net.AddElement("Inertia", "station", P({{"J", 1.0}}));
  net.AddElement("Damper", "station_load", P({{"d", 8}}));
  net.Connect("w_ref.y", "pdu.w_ref");
  net.Connect("pdu.support", "fixed.flange");
  net.AddElement("SpringDamper", "drive_shaft", P({{"c", 1e4}, {"d", 20}}));
  net.Connect("pdu.flange", "drive_shaft.flange_a");
  net.Connect("drive_shaft.flange_b", "tgb.flange_a");
  net.Connect("tgb.flange_b", "outboard.flange_a");
  net.Connect("tgb.flange_branch", "station.flange_a");
  net.Connect("station.flange_b", "station_load.flange_a");
  net.Connect("station_load.flange_b", "fixed.flange");
  return net;
}

TEST(BranchGearbox, ThroughDriveIsRigidAndBranchTurnsAtOneOverRatio) {
  const RunResult r = Simulate(BranchGearboxOnSpeedSource({{"ratio", 4}, {"J", 0}}), 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto w_out = r.Col("outboard.w"), w_branch = r.Col("station.w");
  for (std::size_t k = 0; k < w_out.size(); ++k) EXPECT_NEAR(w_branch[k], w_out[k] / 4, 1e-9);
  EXPECT_NEAR(r.At("outboard.w", 1.0), 4.0, 1e-4);
  // Steady: the station damper takes 8 * 1 rad/s = 8 N*m at the branch, 2 N*m at the input.
  EXPECT_NEAR(r.At("tgb.flange_a.tau", 1.0), 2.0, 1e-3);
  EXPECT_NEAR(r.At("pdu.tau", 1.0), 2.0, 1e-3);
}

// The branch friction (equation 3, at the input speed) adds to the input torque: steady
// 2 N*m for the station plus tau_C + d_vis*w_in = 0.5 + 0.1*4.
TEST(BranchGearbox, BranchFrictionIsReferredToTheInput) {
  if (FindElementType("LossyInertia") == nullptr)
    GTEST_SKIP() << "LossyInertia (brake family) is not in this build yet";
  const RunResult r = Simulate(
      BranchGearboxOnSpeedSource({{"ratio", 4}, {"J", 0.01}, {"tau_C", 0.5}, {"d_vis", 0.1}}),
      1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.At("outboard.w", 1.0), 4.0, 1e-4);
  EXPECT_NEAR(r.At("station.w", 1.0), 1.0, 1e-4);
  EXPECT_NEAR(r.At("pdu.tau", 1.0), 2.0 + 0.5 + 0.1 * 4, 1e-3);
}

// ------------------------------------------------------------------------------------------
// Disconnector

Network TwoInertiasThroughDisconnector(Scalars disconnector) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "motor", P({{"tau_constant", 12}}));
  net.AddElement("Inertia", "inboard", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("Disconnector", "shaft", P(disconnector));
  net.AddElement("Inertia", "outboard", P({{"J", 2}}));
  net.Connect("motor.flange", "inboard.flange_a");
  net.Connect("motor.support", "fixed.flange");
  net.Connect("inboard.flange_b", "shaft.flange_a");
  net.Connect("shaft.flange_b", "outboard.flange_a");
  return net;
}

// Intact: both inertias accelerate together at T/(J1 + J2) = 4 rad/s^2 and the coupling
// carries J2*a = 8 N*m (tau = flange_b.tau = -8 N*m in the MSL sign convention). From t_disconnect the coupling carries nothing: the inboard side
// accelerates at T/J1 = 12 rad/s^2 and the outboard side keeps its speed.
TEST(Disconnector, BreaksAtTDisconnectAndTransmitsNothingAfter) {
  const RunResult r = Simulate(TwoInertiasThroughDisconnector({{"t_disconnect", 0.5}, {"c", 2e3}}), 1.0, 1e-3, true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.At("shaft.tau", 0.4), -8.0, 1e-3);
  EXPECT_EQ(r.At("shaft.broken", 0.4), 0.0);
  EXPECT_EQ(r.At("shaft.broken", 0.6), 1.0);
  const double w_break = r.At("outboard.w", 0.5);
  EXPECT_NEAR(w_break, 2.0, 1e-3);
  for (std::size_t k = 0; k < r.t().size(); ++k) {
    if (r.t()[k] > 0.5) {
      EXPECT_EQ(r.Col("shaft.tau")[k], 0.0);
    }
  }
  EXPECT_NEAR(r.At("outboard.w", 1.0), w_break, 1e-6);
  EXPECT_NEAR(r.At("inboard.w", 1.0) - r.At("inboard.w", 0.6), 12.0 * 0.4, 1e-6);
  bool logged = false;
  for (const auto& ev : r.report.events)
    logged |= ev.element == "shaft" && ev.what == "intact -> broken" &&
              std::abs(ev.time - 0.5) < 1e-9;
  EXPECT_TRUE(logged) << r.report.FullReport();
  EXPECT_NEAR(r.report.energy.Residual(), 0.0, 1e-4 * r.report.energy.Scale())
      << r.report.FullReport();
}

// On the input: the rupture happens when disconnect rises above 0.5 and is latched when the
// command falls back.
TEST(Disconnector, BreaksOnTheInputAndStaysBroken) {
  Network net = TwoInertiasThroughDisconnector({{"useDisconnectInput", 1}});
  net.AddElement("Pulse", "command", P({{"period", 0.4}, {"width", 25}, {"startTime", 0.3}}));
  net.Connect("command.y", "shaft.disconnect");
  const RunResult r = Simulate(net, 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_EQ(r.At("shaft.broken", 0.29), 0.0);
  EXPECT_EQ(r.At("shaft.broken", 0.31), 1.0);
  EXPECT_EQ(r.At("shaft.broken", 0.5), 1.0);  // command back at 0, still broken
  EXPECT_NEAR(r.At("outboard.w", 1.0), r.At("outboard.w", 0.31), 1e-6);
}

TEST(Disconnector, RejectsAConnectedInputWithoutUseDisconnectInput) {
  Network net = TwoInertiasThroughDisconnector({});
  net.AddElement("Constant", "command", P({{"k", 1}}));
  net.Connect("command.y", "shaft.disconnect");
  EXPECT_EQ(ErrorOf(net),
            "element 'shaft' (Disconnector): input 'disconnect' is connected but "
            "useDisconnectInput = false; set useDisconnectInput = true or remove the connection");
}

// ------------------------------------------------------------------------------------------
// Jam

Network SpinningInertiaWithJam(Scalars jam) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Inertia", "flap", P({{"J", 0.5}, {"phi_start", 0}, {"w_start", 3}}));
  net.AddElement("Jam", "jam", P(jam));
  net.Connect("flap.flange_a", "jam.flange");
  net.Connect("jam.support", "fixed.flange");
  return net;
}

// Equation (1) of the paper: an inertia J at speed w0 stopped by a stiffness c reaches
// tau_max = w0*sqrt(c*J), and oscillates about the angle at which it jammed.
TEST(Jam, LocksAtTJamAndPeakTorqueIsW0SqrtCJ) {
  const double c = 2e4, J = 0.5, w0 = 3.0, t_jam = 0.2;
  const RunResult r = Simulate(SpinningInertiaWithJam({{"c", c}, {"t_jam", t_jam}}), 0.4, 1e-4, true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.At("flap.w", 0.19), w0, 1e-9);
  EXPECT_EQ(r.At("jam.tau", 0.19), 0.0);
  EXPECT_EQ(r.At("jam.jammed", 0.21), 1.0);
  EXPECT_NEAR(r.At("jam.phi_jam", 0.3), w0 * t_jam, 1e-8);
  double peak = 0.0, phi_max = 0.0;
  const auto tau = r.Col("jam.tau"), phi = r.Col("flap.phi");
  for (std::size_t k = 0; k < tau.size(); ++k) {
    peak = std::max(peak, std::abs(tau[k]));
    phi_max = std::max(phi_max, phi[k]);
  }
  EXPECT_NEAR(peak, w0 * std::sqrt(c * J), 1e-3 * w0 * std::sqrt(c * J));
  EXPECT_NEAR(phi_max, w0 * t_jam + w0 / std::sqrt(c / J), 1e-5);
  for (const auto& p : r.report.peak_torques) {
    if (p.element == "jam") {
      EXPECT_NEAR(std::abs(p.tau), w0 * std::sqrt(c * J), 2e-3 * peak);
    }
  }
  EXPECT_NEAR(r.report.energy.Residual(), 0.0, 1e-5 * r.report.energy.Scale())
      << r.report.FullReport();
}

// A run's peak torques are located between its step ends (the vertex of the parabola through
// the three samples around a sampled maximum), so they do not depend on the output grid, and
// at rtol 1e-6, where the steps are long, the located jam load is within 2e-6 of the analytic
// w0 sqrt(c J) of equation (1) (4.8e-7 measured; the largest step-end sample is 4.3e-5 low).
TEST(Jam, PeakIsLocatedBetweenStepEndsForAnyOutputGrid) {
  const double c = 2e4, J = 0.5, w0 = 3.0, t_jam = 0.2, exact = w0 * std::sqrt(c * J);
  std::vector<SimulationReport> reports;
  for (const double dt : {1e-4, 0.4}) {  // a row every 0.1 ms, or only at the start and the end
    const RunResult r = Simulate(SpinningInertiaWithJam({{"c", c}, {"t_jam", t_jam}}), 0.4, dt, false, 1e-6);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    reports.push_back(r.report);
  }
  ASSERT_EQ(reports[0].peak_torques.size(), reports[1].peak_torques.size());
  for (std::size_t i = 0; i < reports[0].peak_torques.size(); ++i) {
    EXPECT_EQ(reports[0].peak_torques[i].tau, reports[1].peak_torques[i].tau) << reports[0].peak_torques[i].element;
    EXPECT_EQ(reports[0].peak_torques[i].time, reports[1].peak_torques[i].time) << reports[0].peak_torques[i].element;
  }
  for (const auto& p : reports[1].peak_torques) {
    if (p.element != "jam") continue;
    EXPECT_NEAR(std::abs(p.tau), exact, 2e-6 * exact) << "steps " << reports[1].statistics.steps;
    // The maxima of |tau| are a quarter period after the jam and every half period after that.
    EXPECT_NEAR(std::fmod(p.time - t_jam, M_PI / std::sqrt(c / J)), 0.5 * M_PI / std::sqrt(c / J), 1e-6);
  }
}

// On the input, with damping: latched, and the damped oscillation comes to rest at phi_jam.
TEST(Jam, JamsOnTheInputAndStaysJammed) {
  Network net = SpinningInertiaWithJam({{"c", 2e4}, {"d", 50}, {"useJamInput", 1}});
  net.AddElement("Pulse", "command", P({{"period", 1.0}, {"width", 5}, {"startTime", 0.1}}));
  net.Connect("command.y", "jam.jam");
  const RunResult r = Simulate(net, 1.0, 1e-4, true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_EQ(r.At("jam.jammed", 0.09), 0.0);
  EXPECT_EQ(r.At("jam.jammed", 0.5), 1.0);
  EXPECT_NEAR(r.At("jam.phi_jam", 1.0), 0.3, 1e-6);
  EXPECT_NEAR(r.At("flap.phi", 1.0), 0.3, 1e-6);
  EXPECT_NEAR(r.At("flap.w", 1.0), 0.0, 1e-6);
  const EnergyBalance& b = r.report.energy;
  EXPECT_NEAR(b.dissipated, 0.5 * 0.5 * 9.0, 1e-3);  // all kinetic energy into the damper
  EXPECT_NEAR(b.Residual(), 0.0, 1e-4 * b.Scale()) << r.report.FullReport();
}

TEST(Jam, RejectsAConnectedInputWithoutUseJamInput) {
  Network net = SpinningInertiaWithJam({});
  net.AddElement("Constant", "command", P({{"k", 1}}));
  net.Connect("command.y", "jam.jam");
  EXPECT_EQ(ErrorOf(net),
            "element 'jam' (Jam): input 'jam' is connected but useJamInput = false; set "
            "useJamInput = true or remove the connection");
}

}  // namespace
}  // namespace highlift::sim
