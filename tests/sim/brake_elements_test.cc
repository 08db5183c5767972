// HighLift brakes, torque limiters and friction laws (sim/src/brake_elements.cc): analytic
// cases for ShaftBrake, BrakeActuation, WingTipBrake, NonlinearSpring, TorqueLimiter,
// StribeckFriction and LossyInertia, mode sequences, rejected parameters, and the energy
// balance over a run with stick and slip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "highlift/core/error.h"
#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

using Scalars = std::map<std::string, double>;

ElementParameters P(Scalars s) { return {std::move(s), {}}; }

struct RunResult {
  MemorySink sink;
  SimulationReport report;
  std::vector<double> Col(const std::string& name) const { return sink.Series(name); }
  const std::vector<double>& t() const { return sink.times(); }
  /// Value of a column at the last output row with time <= t.
  double At(const std::string& name, double time) const {
    const auto c = Col(name);
    std::size_t k = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (sink.times()[i] <= time + 1e-12) k = i;
    return c[k];
  }
};

RunResult Simulate(const Network& net, double stop, double dt, double rtol = 1e-8,
                   bool energy = false) {
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

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// ------------------------------------------------------------------------------------------
// ShaftBrake

// A fully applied brake stops an inertia spinning at w0 in t_s = J*w0/tauB_max, decelerating
// at tauB_max/J, and then holds it with zero torque: modes Forward -> Stuck.
TEST(ShaftBrake, StopsAnInertiaInJw0OverTauBmax) {
  const double J = 0.5, w0 = 20, tauB_max = 100;
  Network net;
  net.AddElement("Inertia", "rotor", P({{"J", J}, {"phi_start", 0}, {"w_start", w0}}));
  net.AddElement("ShaftBrake", "brake", P({{"tauB_max", tauB_max}, {"tauB_lim", 150}}));
  net.AddElement("Constant", "command", P({{"k", 1}}));
  net.Connect("rotor.flange_b", "brake.flange_a");
  net.Connect("command.y", "brake.u");
  const RunResult r = Simulate(net, 0.2, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double t_stop = J * w0 / tauB_max;  // 0.1 s
  const auto w = r.Col("rotor.w"), tau = r.Col("brake.tau"), mode = r.Col("brake.mode");
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double t = r.t()[i];
    if (t < t_stop - 1e-6) {
      EXPECT_NEAR(w[i], w0 - tauB_max / J * t, 1e-6) << "t = " << t;
      EXPECT_NEAR(tau[i], tauB_max, 1e-9) << "t = " << t;
      EXPECT_EQ(mode[i], 1) << "t = " << t;
    } else if (t > t_stop + 1e-6) {
      EXPECT_NEAR(w[i], 0.0, 1e-9) << "t = " << t;
      EXPECT_NEAR(tau[i], 0.0, 1e-9) << "held without load";
      EXPECT_EQ(mode[i], 0) << "t = " << t;
    }
  }
  bool stop_event = false;
  for (const auto& e : r.report.events)
    if (e.element == "brake" && std::abs(e.time - t_stop) < 1e-6) stop_event = true;
  EXPECT_TRUE(stop_event) << r.report.FullReport();
}

// Once stopped, the brake holds up to u*tauB_lim; above it the shaft slips against the lower
// dynamic torque u*tauB_max. A torque ramp T = 100 t (N*m) on J = 1 with u = 1, tauB_max =
// 100, tauB_lim = 150: held until t = 1.5 s, then J dw/dt = 100 t - 100.
TEST(ShaftBrake, HoldsUpToTauBlimThenSlipsAtTauBmax) {
  Network net;
  net.AddElement("Inertia", "rotor", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("ShaftBrake", "brake", P({{"tauB_max", 100}, {"tauB_lim", 150}}));
  net.AddElement("Constant", "command", P({{"k", 1}}));
  net.AddElement("Ramp", "ramp", P({{"height", 300}, {"duration", 3}}));
  net.AddElement("Torque", "motor");
  net.Connect("rotor.flange_b", "brake.flange_a");
  net.Connect("command.y", "brake.u");
  net.Connect("ramp.y", "motor.tau");
  net.Connect("motor.flange", "rotor.flange_a");
  const RunResult r = Simulate(net, 2.5, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.At("rotor.w", 1.4), 0.0, 1e-12);
  EXPECT_NEAR(r.At("brake.tau", 1.4), 140.0, 1e-6) << "holding torque = applied torque";
  EXPECT_EQ(r.At("brake.mode", 1.4), 0);
  const double t = 2.5;
  EXPECT_NEAR(r.At("rotor.w", t), 50 * (t * t - 2.25) - 100 * (t - 1.5), 1e-5);
  EXPECT_NEAR(r.At("brake.tau", t), 100.0, 1e-9);
  EXPECT_EQ(r.At("brake.mode", t), 1);
}

// u <= 0 releases the brake completely: the shaft coasts and the brake reports mode Free (2).
TEST(ShaftBrake, ReleasedBrakeTransmitsNothing) {
  Network net;
  net.AddElement("Inertia", "rotor", P({{"J", 1}, {"phi_start", 0}, {"w_start", 3}}));
  net.AddElement("ShaftBrake", "brake", P({{"tauB_max", 100}, {"tauB_lim", 100}}));
  net.AddElement("Constant", "command", P({{"k", -0.5}}));
  net.Connect("rotor.flange_b", "brake.flange_a");
  net.Connect("command.y", "brake.u");
  const RunResult r = Simulate(net, 0.5, 1e-2);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  for (double w : r.Col("rotor.w")) EXPECT_NEAR(w, 3.0, 1e-9);
  for (double m : r.Col("brake.mode")) EXPECT_EQ(m, 2);
  for (double x : r.Col("brake.tau")) EXPECT_EQ(x, 0.0);
}

TEST(ShaftBrake, RejectsAHoldingCapacityBelowTheDynamicTorque) {
  Network net;
  net.AddElement("Inertia", "rotor", P({{"J", 1}}));
  net.AddElement("ShaftBrake", "wtb_left", P({{"tauB_max", 700}, {"tauB_lim", 500}}));
  net.AddElement("Constant", "command", P({{"k", 1}}));
  net.Connect("rotor.flange_b", "wtb_left.flange_a");
  net.Connect("command.y", "wtb_left.u");
  const std::string message = ErrorOf([&] { Simulator sim(net); });
  EXPECT_TRUE(Contains(message, "element 'wtb_left' (ShaftBrake): parameter 'tauB_lim' = 500 N*m"))
      << message;
  EXPECT_TRUE(Contains(message, "raise tauB_lim or lower tauB_max")) << message;
  // Negative torques are outside the catalogue's valid range.
  const std::string negative = ErrorOf([&] {
    Network n;
    n.AddElement("ShaftBrake", "b", P({{"tauB_max", -1}, {"tauB_lim", 1}}));
  });
  EXPECT_TRUE(Contains(negative, "element 'b' (ShaftBrake): parameter 'tauB_max'")) << negative;
  EXPECT_TRUE(Contains(negative, "outside its valid range")) << negative;
  const std::string missing = ErrorOf([&] {
    Network n;
    n.AddElement("ShaftBrake", "b", P({{"tauB_max", 1}}));
  });
  EXPECT_TRUE(Contains(missing, "parameter 'tauB_lim'")) << missing;
  EXPECT_TRUE(Contains(missing, "is required")) << missing;
}

// ------------------------------------------------------------------------------------------
// BrakeActuation

RunResult RunActuation(bool latch) {
  Network net;
  net.AddElement("Inertia", "dummy", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
  // Command true from 0.2 s to 0.3 s.
  net.AddElement("Pulse", "trigger",
                 P({{"amplitude", 1}, {"width", 10}, {"period", 1}, {"nperiod", 1}, {"startTime", 0.2}}));
  net.AddElement("BrakeActuation", "actuation",
                 P({{"t_lat", 0.05}, {"t_rise", 0.1}, {"latch", latch ? 1.0 : 0.0}}));
  net.Connect("trigger.y", "actuation.trigger");
  return Simulate(net, 0.6, 1e-3);
}

// y = 0 until t_on + t_lat, then (t - t_on - t_lat)/t_rise up to 1; without the latch the
// brake releases when the command falls.
TEST(BrakeActuation, LatencyThenLinearRiseReleasedWithTheCommand) {
  const RunResult r = RunActuation(false);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto y = r.Col("actuation.y");
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double t = r.t()[i];
    double expected = 0.0;
    if (t > 0.25 + 1e-9 && t < 0.3 - 1e-9) expected = (t - 0.25) / 0.1;
    if (std::abs(t - 0.3) < 1e-9 || std::abs(t - 0.25) < 1e-9 || std::abs(t - 0.2) < 1e-9) continue;
    EXPECT_NEAR(y[i], expected, 1e-9) << "t = " << t;
  }
  EXPECT_NEAR(r.At("actuation.y", 0.299), 0.49, 1e-9);
  EXPECT_EQ(r.At("actuation.applied", 0.25), 1.0);
  EXPECT_EQ(r.At("actuation.applied", 0.5), 0.0);
}

// With the latch (wing-tip brakes are reset on ground only) the brake stays applied and y
// completes its rise after the command fell.
TEST(BrakeActuation, LatchKeepsTheBrakeApplied) {
  const RunResult r = RunActuation(true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.At("actuation.y", 0.2), 0.0, 1e-12);
  EXPECT_NEAR(r.At("actuation.y", 0.3), 0.5, 1e-9);
  EXPECT_NEAR(r.At("actuation.y", 0.33), 0.8, 1e-9);
  EXPECT_NEAR(r.At("actuation.y", 0.36), 1.0, 1e-12);
  EXPECT_NEAR(r.At("actuation.y", 0.6), 1.0, 1e-12);
  EXPECT_EQ(r.At("actuation.applied", 0.6), 1.0);
}

// ------------------------------------------------------------------------------------------
// WingTipBrake

// The monitor's command at t_a applies the brake after t_lat; the dynamic torque rises over
// t_B to tauB_max: the shaft (J_total = J_load + J_rotor) stops at
// t_s = t_a + t_lat + t_B/2 + J_total*w0/tauB_max and is then held.
TEST(WingTipBrake, StopsTheShaftAfterLatencyAndRise) {
  const double J_load = 0.1, J_rotor = 5e-4, w0 = 20, tauB_max = 50, t_lat = 0.1, t_B = 0.03;
  const double t_a = 0.2;
  Network net;
  net.AddElement("Inertia", "shaft", P({{"J", J_load}, {"phi_start", 0}, {"w_start", w0}}));
  net.AddElement("WingTipBrake", "wtb",
                 P({{"tauB_max", tauB_max}, {"tauB_lim", 70}, {"t_lat", t_lat}, {"t_B", t_B},
                    {"J", J_rotor}}));
  net.AddElement("Step", "monitor", P({{"startTime", t_a}}));
  net.Connect("shaft.flange_b", "wtb.flange_a");
  net.Connect("monitor.y", "wtb.apply");
  const RunResult r = Simulate(net, 0.5, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double J = J_load + J_rotor, t0 = t_a + t_lat;
  const double t_stop = t0 + t_B / 2 + J * w0 / tauB_max;
  EXPECT_NEAR(r.At("shaft.w", t0), w0, 1e-9) << "no torque before engagement";
  // During the rise: w = w0 - tauB_max (t - t0)^2 / (2 t_B J).
  const double t_mid = t0 + 0.02;
  EXPECT_NEAR(r.At("shaft.w", t_mid), w0 - tauB_max * 0.02 * 0.02 / (2 * t_B * J), 1e-6);
  EXPECT_NEAR(r.At("wtb.tau", t_mid), tauB_max * 0.02 / t_B, 1e-6);
  const double t_late = 0.35;  // on the output grid, 5.2 ms before the halt
  EXPECT_NEAR(r.At("shaft.w", t_late), tauB_max / J * (t_stop - t_late), 1e-5);
  EXPECT_NEAR(r.At("shaft.w", 0.45), 0.0, 1e-9);
  EXPECT_EQ(r.At("wtb.mode", 0.25), 2) << "free before engagement";
  EXPECT_EQ(r.At("wtb.mode", t_mid), 1) << "sliding";
  EXPECT_EQ(r.At("wtb.mode", 0.45), 0) << "stuck after the halt";
  EXPECT_EQ(r.At("wtb.actuation.applied", 0.45), 1.0);
  EXPECT_NEAR(r.At("wtb.u", 0.45), 1.0, 1e-12);
  bool stop_event = false;
  for (const auto& e : r.report.events)
    if (e.element == "wtb" && std::abs(e.time - t_stop) < 1e-6) stop_event = true;
  EXPECT_TRUE(stop_event) << "halt at t_s = " << t_stop << "\n" << r.report.FullReport();
}

TEST(WingTipBrake, RejectsAHoldingCapacityBelowTheDynamicTorque) {
  Network net;
  net.AddElement("Inertia", "shaft", P({{"J", 1}}));
  net.AddElement("WingTipBrake", "wtb_right", P({{"tauB_max", 550}, {"tauB_lim", 400}}));
  net.AddElement("Step", "monitor");
  net.Connect("shaft.flange_b", "wtb_right.flange_a");
  net.Connect("monitor.y", "wtb_right.apply");
  const std::string message = ErrorOf([&] { Simulator sim(net); });
  EXPECT_TRUE(Contains(message, "element 'wtb_right' (WingTipBrake): parameter 'tauB_lim' = 400"))
      << message;
}

// ------------------------------------------------------------------------------------------
// NonlinearSpring

struct SpringSettings {
  double tau1_ext = 100, tau1_ret = 70, tau2_ext = 150, tau2_ret = 100;
  double c1 = 2000, c2 = 200, c3 = 10000;
  double Phi1(bool ext) const { return (ext ? tau1_ext : tau1_ret) / c1; }
  double Phi2(bool ext) const {
    return Phi1(ext) + ((ext ? tau2_ext : tau2_ret) - (ext ? tau1_ext : tau1_ret)) / c2;
  }
  // Figure 4, written out per direction (x = |phi_rel|).
  double Tau(double phi) const {
    const bool ext = phi >= 0;
    const double x = std::abs(phi), s = ext ? 1.0 : -1.0;
    const double t1 = ext ? tau1_ext : tau1_ret, t2 = ext ? tau2_ext : tau2_ret;
    if (x <= Phi1(ext)) return s * c1 * x;
    if (x <= Phi2(ext)) return s * (t1 + c2 * (x - Phi1(ext)));
    return s * (t2 + c3 * (x - Phi2(ext)));
  }
  double Y(double phi) const {  // equation (2) with |phi_rel|
    const bool ext = phi >= 0;
    const double x = std::abs(phi);
    if (x < Phi1(ext)) return 0.0;
    if (x >= Phi2(ext)) return 1.0;
    return (x - Phi1(ext)) / (Phi2(ext) - Phi1(ext));
  }
  Scalars Parameters() const {
    return {{"tau1_ext", tau1_ext}, {"tau1_ret", tau1_ret}, {"tau2_ext", tau2_ext},
            {"tau2_ret", tau2_ret}, {"c1", c1},             {"c2", c2},
            {"c3", c3}};
  }
};

// The spring is twisted back and forth through all five regions (end stop retract, lock-out
// retract, normal, lock-out extend, end stop extend) by a speed source: torque and y follow
// figure 4 and equation (2) with the asymmetric settings.
TEST(NonlinearSpring, FollowsFigure4AndEquation2InBothDirections) {
  const SpringSettings s;
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("NonlinearSpring", "spring", P(s.Parameters()));
  net.AddElement("Inertia", "input", P({{"J", 1e-3}}));
  net.AddElement("Speed", "drive", P({{"f_crit", 200}, {"phi_start", 0}}));
  // w = A cos(2 pi f t): phi ~ A/(2 pi f) sin(2 pi f t), amplitude 0.4 rad > phi2 (0.3, 0.185).
  net.AddElement("Sine", "profile", P({{"amplitude", 0.4 * 2 * std::numbers::pi}, {"f", 1},
                                       {"phase", std::numbers::pi / 2}}));
  net.Connect("fixed.flange", "spring.flange_a");
  net.Connect("spring.flange_b", "input.flange_a");
  net.Connect("input.flange_b", "drive.flange");
  net.Connect("profile.y", "drive.w_ref");
  const RunResult r = Simulate(net, 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto phi = r.Col("spring.phi_rel"), tau = r.Col("spring.tau"), y = r.Col("spring.y");
  int regions[5] = {0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < phi.size(); ++i) {
    EXPECT_NEAR(tau[i], s.Tau(phi[i]), 1e-9 * (1 + std::abs(tau[i]))) << "phi_rel " << phi[i];
    EXPECT_NEAR(y[i], s.Y(phi[i]), 1e-12) << "phi_rel " << phi[i];
    const double p = phi[i];
    if (p <= -s.Phi2(false)) ++regions[0];
    else if (p <= -s.Phi1(false)) ++regions[1];
    else if (p < s.Phi1(true)) ++regions[2];
    else if (p < s.Phi2(true)) ++regions[3];
    else ++regions[4];
  }
  for (int k = 0; k < 5; ++k) EXPECT_GT(regions[k], 5) << "region " << k << " not visited";
  EXPECT_NEAR(s.Tau(s.Phi2(true)), 150, 1e-9);  // the test's own curve is continuous
}

TEST(NonlinearSpring, RejectsAnEndStopBelowTheLockout) {
  SpringSettings s;
  s.tau2_ret = 60;  // below tau1_ret = 70
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("NonlinearSpring", "stl_left", P(s.Parameters()));
  net.AddElement("Inertia", "input", P({{"J", 1}}));
  net.Connect("fixed.flange", "stl_left.flange_a");
  net.Connect("stl_left.flange_b", "input.flange_a");
  const std::string message = ErrorOf([&] { Simulator sim(net); });
  EXPECT_TRUE(Contains(message, "element 'stl_left' (NonlinearSpring): parameter 'tau2_ret' = 60 N*m "
                                "must exceed 'tau1_ret' = 70 N*m"))
      << message;
  const std::string zero = ErrorOf([&] {
    Network n;
    Scalars p = s.Parameters();
    p["c2"] = 0;
    n.AddElement("NonlinearSpring", "x", P(p));
  });
  EXPECT_TRUE(Contains(zero, "parameter 'c2'")) << zero;
}

// ------------------------------------------------------------------------------------------
// TorqueLimiter

// A jammed output (flange_b fixed) and a slowly rising input torque T: below tau1 the spring
// passes T; above it the balls ride up (c2), y > 0 presses the brake, and the input creeps with
// the brake sliding at y*tauB_max, so T = tau + y*tauB_max with y = (tau - tau1)/(tau2 - tau1):
// tau = tau1 + (T - tau1)/(1 + tauB_max/(tau2 - tau1)). The housing takes the rest.
// Extend settings act for phi_rel = phi_b - phi_a > 0, i.e. with the output jammed, for a drive
// torque that turns flange_a negative; a positive drive torque at flange_a locks out in retract.
void CheckLockout(bool extend) {
  const SpringSettings s;
  const double tauB_max = 300, sign = extend ? 1.0 : -1.0;  // sign of phi_rel and of tau
  const double tau1 = extend ? s.tau1_ext : s.tau1_ret, tau2 = extend ? s.tau2_ext : s.tau2_ret;
  Scalars p = s.Parameters();
  p["tauB_max"] = tauB_max;
  p["J"] = 0.01;
  p["d"] = 5;
  Network net;
  net.AddElement("Fixed", "jam");
  net.AddElement("TorqueLimiter", "stl", P(p));
  net.AddElement("Ramp", "ramp", P({{"height", -sign * 400}, {"duration", 4}}));
  net.AddElement("Torque", "pdu");
  net.Connect("pdu.flange", "stl.flange_a");
  net.Connect("stl.flange_b", "jam.flange");
  net.Connect("ramp.y", "pdu.tau");
  const RunResult r = Simulate(net, 4.0, 1e-2, 1e-7);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto tau = r.Col("stl.tau"), y = r.Col("stl.y"), brake = r.Col("stl.brake.tau");
  const auto mode = r.Col("stl.brake.mode"), phi_rel = r.Col("stl.phi_rel");
  bool locked = false;
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const double T = 100 * r.t()[i];  // |applied torque|
    const double transmitted = sign * tau[i], housing = -sign * brake[i];
    if (r.t()[i] > 0.05) {
      EXPECT_GT(sign * phi_rel[i], 0.0);
    }
    if (T < tau1 - 2) {
      EXPECT_NEAR(transmitted, T, 0.5) << "t = " << r.t()[i];
      EXPECT_EQ(y[i], 0.0) << "t = " << r.t()[i];
      EXPECT_EQ(mode[i], 2) << "brake free before lock-out";
    } else if (T > tau1 + 20) {
      locked = true;
      const double expected = tau1 + (T - tau1) / (1 + tauB_max / (tau2 - tau1));
      EXPECT_NEAR(transmitted, expected, 1.0) << "t = " << r.t()[i];
      EXPECT_NEAR(y[i], (transmitted - tau1) / (tau2 - tau1), 0.02);
      EXPECT_NEAR(housing, T - transmitted, 1.0) << "the housing takes the excess";
    }
  }
  EXPECT_TRUE(locked);
}

TEST(TorqueLimiter, LocksOutAboveTau1InExtend) { CheckLockout(true); }
TEST(TorqueLimiter, LocksOutAboveTheLowerTau1InRetract) { CheckLockout(false); }

// ------------------------------------------------------------------------------------------
// StribeckFriction and LossyInertia

// Coast-down of a LossyInertia with the Stribeck law (3): J dw/dt = -(tau_C + d_vis w +
// tau_S exp(-f_exp w)); the halt comes at t_s = integral_0^w0 J dw / tau_fric(w) (Simpson),
// after which the part sticks.
TEST(StribeckFriction, CoastDownStopsAtTheQuadratureTime) {
  const double J = 0.2, w0 = 10, tau_C = 1, d_vis = 0.05, tau_S = 0.5, f_exp = 2;
  Network net;
  net.AddElement("Inertia", "start", P({{"J", 0}, {"phi_start", 0}, {"w_start", w0}}));
  net.AddElement("LossyInertia", "bearing",
                 P({{"J", J}, {"tau_C", tau_C}, {"d_vis", d_vis}, {"tau_S", tau_S}, {"f_exp", f_exp}}));
  net.Connect("start.flange_b", "bearing.flange_a");
  const RunResult r = Simulate(net, 2.5, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  auto friction = [&](double w) { return tau_C + d_vis * w + tau_S * std::exp(-f_exp * w); };
  const int n = 2000;
  double t_stop = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double w = w0 * k / n, weight = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    t_stop += weight * J / friction(w);
  }
  t_stop *= w0 / n / 3;
  double t_halt = -1;
  for (const auto& e : r.report.events)
    if (e.element == "bearing" && e.kind == "state") t_halt = e.time;
  EXPECT_NEAR(t_halt, t_stop, 1e-6) << r.report.FullReport();
  EXPECT_NEAR(r.At("bearing.w", 2.4), 0.0, 1e-12);
  EXPECT_EQ(r.At("bearing.mode", 2.4), 0);
  EXPECT_NEAR(r.At("bearing.tau", 0.0), friction(w0), 1e-9);
}

// With eta_GE = 1 and no Stribeck or viscous part, StribeckFriction is MSL BearingFriction
// with a constant tau_pos: the same network with either gives the same motion.
TEST(StribeckFriction, MatchesMslBearingFrictionForCoulombFriction) {
  auto run = [](bool stribeck) {
    Network net;
    net.AddElement("Inertia", "rotor", P({{"J", 0.3}, {"phi_start", 0}, {"w_start", 0}}));
    net.AddElement("Sine", "command", P({{"amplitude", 5}, {"f", 2}}));
    net.AddElement("Torque", "motor");
    if (stribeck)
      net.AddElement("StribeckFriction", "f", P({{"tau_C", 2}, {"peak", 1.4}}));
    else
      net.AddElement("BearingFriction", "f", ElementParameters{{{"peak", 1.4}}, {{"tau_pos", {{0, 2}}}}});
    net.Connect("command.y", "motor.tau");
    net.Connect("motor.flange", "rotor.flange_a");
    net.Connect("rotor.flange_b", "f.flange_a");
    return Simulate(net, 1.0, 1e-3);
  };
  const RunResult a = run(true), b = run(false);
  ASSERT_TRUE(a.report.ok() && b.report.ok()) << a.report.FullReport() << b.report.FullReport();
  const auto wa = a.Col("rotor.w"), wb = b.Col("rotor.w");
  ASSERT_EQ(wa.size(), wb.size());
  double worst = 0, largest = 0;
  for (std::size_t i = 0; i < wa.size(); ++i) {
    worst = std::max(worst, std::abs(wa[i] - wb[i]));
    largest = std::max(largest, std::abs(wb[i]));
  }
  EXPECT_GT(largest, 0.5);
  EXPECT_LT(worst, 1e-6 * largest);
}

// Equation (4) in motion: a LossyInertia (J) between a drive torque T_in and a load inertia J
// with the external torque T_b slides with tau = tau_C + (1 - eta)*|tau_load|, where
// tau_load = (T_in - T_b)/2 for equal inertias, so J_total*a = T_in + T_b - tau.
TEST(LossyInertia, LoadDependentLossInMotion) {
  const double J = 0.5, T_in = 20, T_b = -5, tau_C = 1, eta = 0.8;
  Network net;
  net.AddElement("ConstantTorque", "drive", P({{"tau_constant", T_in}}));
  net.AddElement("LossyInertia", "gear", P({{"J", J}, {"tau_C", tau_C}, {"eta_GE", eta}}));
  net.AddElement("Inertia", "load", P({{"J", J}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("ConstantTorque", "airload", P({{"tau_constant", T_b}}));
  net.Connect("drive.flange", "gear.flange_a");
  net.Connect("gear.flange_b", "load.flange_a");
  net.Connect("airload.flange", "load.flange_b");
  const RunResult r = Simulate(net, 0.5, 1e-2);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double tau_load = (T_in - T_b) / 2, tau = tau_C + (1 - eta) * tau_load;
  const double acc = (T_in + T_b - tau) / (2 * J);
  EXPECT_NEAR(r.At("gear.tau_load", 0.3), tau_load, 1e-8);
  EXPECT_NEAR(r.At("gear.tau", 0.3), tau, 1e-8);
  EXPECT_NEAR(r.At("load.w", 0.5), acc * 0.5, 1e-7);
  EXPECT_NEAR(r.At("gear.w", 0.5), acc * 0.5, 1e-7);
  EXPECT_EQ(r.At("gear.mode", 0.3), 1);
}

// The same law through StribeckFriction with the efficiency from its input eta (as the geared
// rotary actuator feeds its eta_GE): inertia and friction as separate elements.
TEST(StribeckFriction, EfficiencyInputGivesTheLoadLoss) {
  const double J = 0.5, T_in = 20, T_b = -5, tau_C = 1, eta = 0.8;
  Network net;
  net.AddElement("ConstantTorque", "drive", P({{"tau_constant", T_in}}));
  net.AddElement("Inertia", "input", P({{"J", J}}));
  net.AddElement("StribeckFriction", "gear", P({{"tau_C", tau_C}, {"useEfficiencyInput", 1}}));
  net.AddElement("Constant", "efficiency", P({{"k", eta}}));
  net.AddElement("Inertia", "load", P({{"J", J}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("ConstantTorque", "airload", P({{"tau_constant", T_b}}));
  net.Connect("drive.flange", "input.flange_a");
  net.Connect("input.flange_b", "gear.flange_a");
  net.Connect("efficiency.y", "gear.eta");
  net.Connect("gear.flange_b", "load.flange_a");
  net.Connect("airload.flange", "load.flange_b");
  const RunResult r = Simulate(net, 0.5, 1e-2);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double tau_load = (T_in - T_b) / 2, tau = tau_C + (1 - eta) * tau_load;
  EXPECT_NEAR(r.At("gear.tau", 0.3), tau, 1e-8);
  EXPECT_NEAR(r.At("load.w", 0.5), (T_in + T_b - tau) / (2 * J) * 0.5, 1e-7);
  // Without the input connected the element names the missing signal.
  Network open;
  open.AddElement("Inertia", "input", P({{"J", J}}));
  open.AddElement("StribeckFriction", "gear", P({{"tau_C", tau_C}, {"useEfficiencyInput", 1}}));
  open.Connect("input.flange_b", "gear.flange_a");
  const std::string message = ErrorOf([&] { Simulator sim(open); });
  EXPECT_TRUE(Contains(message, "element 'gear' (StribeckFriction): signal input 'eta' is not connected"))
      << message;
}

// At standstill the load-dependent loss is absent: the part breaks away at peak*(tau_C +
// tau_S) of the net torque, however large the transmitted load, unless the sliding friction
// (which includes the load loss) would exceed the net torque: then it stays held.
TEST(LossyInertia, LoadLossActsOnlyInMotion) {
  auto run = [](double T_in, double T_b) {
    Network net;
    net.AddElement("ConstantTorque", "drive", P({{"tau_constant", T_in}}));
    net.AddElement("LossyInertia", "gear",
                   P({{"J", 0.5}, {"tau_C", 1}, {"peak", 2}, {"eta_GE", 0.8}}));
    net.AddElement("Inertia", "load", P({{"J", 0.5}, {"phi_start", 0}, {"w_start", 0}}));
    net.AddElement("ConstantTorque", "airload", P({{"tau_constant", T_b}}));
    net.Connect("drive.flange", "gear.flange_a");
    net.Connect("gear.flange_b", "load.flange_a");
    net.Connect("airload.flange", "load.flange_b");
    return Simulate(net, 0.2, 1e-2);
  };
  {  // net 1.5 < peak*tau_C = 2: held; the holding torque is the net torque
    const RunResult r = run(3, -1.5);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    EXPECT_EQ(r.At("gear.mode", 0.2), 0);
    EXPECT_NEAR(r.At("gear.tau", 0.2), 1.5, 1e-9);
    EXPECT_NEAR(r.At("gear.tau_load", 0.2), 2.25, 1e-9);
    EXPECT_EQ(r.At("load.w", 0.2), 0.0);
  }
  {  // net 2.5 > 2 breaks away; sliding friction 1 + 0.2*1.75 = 1.35 < 2.5
    const RunResult r = run(3, -0.5);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    EXPECT_EQ(r.At("gear.mode", 0.2), 1);
    EXPECT_NEAR(r.At("gear.tau", 0.2), 1.35, 1e-8);
    EXPECT_NEAR(r.At("load.w", 0.2), (2.5 - 1.35) * 0.2, 1e-7);
  }
  {  // net 2.5 > 2, but sliding would need 1 + 0.2*28.75 = 6.75: held
    const RunResult r = run(30, -27.5);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    EXPECT_EQ(r.At("gear.mode", 0.2), 0);
    EXPECT_NEAR(r.At("gear.tau", 0.2), 2.5, 1e-9);
    EXPECT_EQ(r.At("load.w", 0.2), 0.0);
  }
}

// The transmitted load changes sign while the part slides (a drive torque that reverses
// against the inertia of the load): the loss follows |tau_load| and always dissipates.
TEST(LossyInertia, LossFollowsTheSignOfTheTransmittedLoad) {
  Network net;
  net.AddElement("Sine", "command", P({{"amplitude", 40}, {"f", 1}}));
  net.AddElement("Torque", "drive");
  net.AddElement("Inertia", "rotor", P({{"J", 0.1}, {"phi_start", 0}, {"w_start", 30}}));
  net.AddElement("LossyInertia", "gear", P({{"J", 0.1}, {"tau_C", 0.5}, {"eta_GE", 0.7}}));
  net.AddElement("Inertia", "load", P({{"J", 1}}));
  net.Connect("command.y", "drive.tau");
  net.Connect("drive.flange", "rotor.flange_a");
  net.Connect("rotor.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "load.flange_a");
  const RunResult r = Simulate(net, 1.0, 1e-3, 1e-8, true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto load = r.Col("gear.tau_load"), tau = r.Col("gear.tau"), w = r.Col("gear.w");
  bool positive = false, negative = false;
  for (std::size_t i = 0; i < load.size(); ++i) {
    if (w[i] <= 0) continue;
    positive |= load[i] > 1, negative |= load[i] < -1;
    EXPECT_NEAR(tau[i], 0.5 + 0.3 * std::abs(load[i]), 1e-6) << "t = " << r.t()[i];
  }
  EXPECT_TRUE(positive && negative) << "the load should change sign while sliding";
  EXPECT_NEAR(r.report.energy.Residual(), 0.0, 1e-4 * r.report.energy.Scale())
      << r.report.FullReport();
}

// ------------------------------------------------------------------------------------------
// Energy balance

// A reversing motor drives through a lossy gear (stick and slip, load loss), a torque
// limiter (lock-out: spring potential and brake dissipation) and a shaft to a load with an
// airload; a wing-tip brake stops and holds the load. Source work = change of kinetic and
// potential energy + dissipated work (+ impulsive losses at events).
TEST(BrakeFamily, EnergyBalanceClosesOverStickSlipLockoutAndBrakeStop) {
  const SpringSettings s;
  Scalars limiter = s.Parameters();
  limiter["tauB_max"] = 300;
  limiter["J"] = 0.01;
  limiter["d"] = 5;
  Network net;
  net.AddElement("Sine", "command", P({{"amplitude", 180}, {"f", 1.5}}));
  net.AddElement("Torque", "motor");
  net.AddElement("Inertia", "rotor", P({{"J", 0.02}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("LossyInertia", "gear",
                 P({{"J", 0.01}, {"tau_C", 3}, {"tau_S", 2}, {"peak", 1.3}, {"eta_GE", 0.85}}));
  net.AddElement("TorqueLimiter", "stl", P(limiter));
  net.AddElement("Inertia", "output", P({{"J", 0.002}}));
  net.AddElement("SpringDamper", "shaft", P({{"c", 500}, {"d", 0.5}}));
  net.AddElement("Inertia", "load", P({{"J", 0.2}}));
  net.AddElement("ConstantTorque", "airload", P({{"tau_constant", -20}}));
  net.AddElement("WingTipBrake", "wtb",
                 P({{"tauB_max", 150}, {"tauB_lim", 200}, {"t_lat", 0.05}, {"t_B", 0.03}}));
  net.AddElement("Step", "monitor", P({{"startTime", 0.9}}));
  net.Connect("command.y", "motor.tau");
  net.Connect("motor.flange", "rotor.flange_a");
  net.Connect("rotor.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "stl.flange_a");
  net.Connect("stl.flange_b", "output.flange_a");
  net.Connect("output.flange_b", "shaft.flange_a");
  net.Connect("shaft.flange_b", "load.flange_a");
  net.Connect("airload.flange", "load.flange_b");
  net.Connect("load.flange_b", "wtb.flange_a");
  net.Connect("monitor.y", "wtb.apply");
  const RunResult r = Simulate(net, 1.3, 2e-4, 1e-8, true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const EnergyBalance& b = r.report.energy;
  ASSERT_TRUE(b.computed);
  EXPECT_GT(b.source_work, 10.0) << r.report.FullReport();
  EXPECT_GT(b.dissipated, 1.0);
  EXPECT_NEAR(b.Residual(), 0.0, 1e-3 * b.Scale()) << r.report.FullReport();
  for (double x : r.Col("energy.loss_power")) EXPECT_GE(x, -1e-6) << "dissipation is never negative";
  bool stuck = false, sliding = false, lockout = false, wtb_slid = false;
  for (double m : r.Col("gear.mode")) stuck |= m == 0, sliding |= std::abs(m) == 1;
  for (double y : r.Col("stl.y")) lockout |= y > 0;
  for (double m : r.Col("wtb.mode")) wtb_slid |= std::abs(m) == 1;
  EXPECT_TRUE(stuck && sliding) << "the gear should stick and slip";
  EXPECT_TRUE(lockout) << "the limiter should lock out";
  EXPECT_TRUE(wtb_slid) << "the wing-tip brake should slide before it holds";
  EXPECT_EQ(r.At("wtb.mode", 1.3), 0) << "held at the end";
}

}  // namespace
}  // namespace highlift::sim
