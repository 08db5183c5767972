// Analytic and hand-derived checks of the element laws and of the solver: free vibration,
// energy balance with friction, power through an ideal gear, a gear with a moving support,
// IdealPlanetary, OneWayClutch, LossyGear with bearing friction, time events, failure reports; a
// sink that does not read the values (OutputSink::ReadsValues) changes nothing but the work.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "highlift/core/error.h"
#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

using Scalars = std::map<std::string, double>;

ElementParameters P(Scalars s, std::map<std::string, std::vector<std::vector<double>>> t = {}) {
  return {std::move(s), std::move(t)};
}

struct RunResult {
  MemorySink sink;
  SimulationReport report;
  std::vector<double> Col(const std::string& name) const { return sink.Series(name); }
  const std::vector<double>& t() const { return sink.times(); }
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

// Single-DOF oscillator J*phi'' + c*phi = 0, phi(0) = 0.1: phi = 0.1*cos(w0*t), w0 = sqrt(c/J).
TEST(Oscillator, FreeVibrationMatchesCosine) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Spring", "spring", P({{"c", 800}}));
  net.AddElement("Inertia", "inertia", P({{"J", 2}, {"phi_start", 0.1}, {"w_start", 0}}));
  net.Connect("fixed.flange", "spring.flange_a");
  net.Connect("spring.flange_b", "inertia.flange_a");
  const RunResult r = Simulate(net, 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto phi = r.Col("inertia.phi");
  const auto phi_rel = r.Col("spring.phi_rel");
  const double w0 = 20.0;
  double worst = 0.0;
  for (std::size_t i = 0; i < phi.size(); ++i) {
    worst = std::max(worst, std::abs(phi[i] - 0.1 * std::cos(w0 * r.t()[i])));
    EXPECT_NEAR(phi_rel[i], phi[i], 1e-9);  // relative-twist state agrees with the angle
  }
  EXPECT_LT(worst, 1e-6) << "largest deviation from 0.1*cos(20 t)";
}

// A sine torque drives a spring-damper onto an inertia on bearing friction (stick/slip events).
Network DrivenSpringWithBearingFriction(double amplitude, double f) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Sine", "drive", P({{"amplitude", amplitude}, {"f", f}}));
  net.AddElement("Torque", "torque");
  net.AddElement("Inertia", "inertia1", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("SpringDamper", "spring", P({{"c", 400}, {"d", 2}}));
  net.AddElement("Inertia", "inertia2", P({{"J", 0.5}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("BearingFriction", "bearing", P({{"peak", 1.2}}, {{"tau_pos", {{0, 1.0}, {10, 1.5}}}}));
  net.Connect("drive.y", "torque.tau");
  net.Connect("torque.flange", "inertia1.flange_a");
  net.Connect("inertia1.flange_b", "spring.flange_a");
  net.Connect("spring.flange_b", "inertia2.flange_a");
  net.Connect("inertia2.flange_b", "bearing.flange_a");
  net.Connect("bearing.support", "fixed.flange");
  net.Connect("torque.support", "fixed.flange");
  return net;
}

// Work of the source = kinetic + potential energy + dissipation (damper and friction).
TEST(EnergyBalance, WorkEqualsStoredPlusDissipatedWithFriction) {
  const RunResult r = Simulate(DrivenSpringWithBearingFriction(6, 1), 2.0, 1e-4);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto u = r.Col("torque.tau"), w1 = r.Col("inertia1.w"), w2 = r.Col("inertia2.w");
  const auto phi_rel = r.Col("spring.phi_rel"), w_rel = r.Col("spring.w_rel");
  const auto tau_f = r.Col("bearing.tau"), mode = r.Col("bearing.mode");
  double work = 0, dissipated = 0;
  for (std::size_t i = 1; i < u.size(); ++i) {
    const double h = r.t()[i] - r.t()[i - 1];
    if (h == 0) continue;  // event rows
    work += 0.5 * h * (u[i] * w1[i] + u[i - 1] * w1[i - 1]);
    dissipated += 0.5 * h * (2 * w_rel[i] * w_rel[i] + 2 * w_rel[i - 1] * w_rel[i - 1]);
    dissipated += 0.5 * h * (tau_f[i] * w2[i] + tau_f[i - 1] * w2[i - 1]);
  }
  const std::size_t n = u.size() - 1;
  const double stored = 0.5 * 1 * w1[n] * w1[n] + 0.5 * 0.5 * w2[n] * w2[n] + 0.5 * 400 * phi_rel[n] * phi_rel[n];
  bool stuck_seen = false, sliding_seen = false;
  for (double m : mode) stuck_seen |= m == 0, sliding_seen |= std::abs(m) == 1;
  EXPECT_TRUE(stuck_seen && sliding_seen) << "the test should exercise stick and slip";
  EXPECT_GT(work, 1.0);
  EXPECT_NEAR(work, stored + dissipated, 2e-4 * work)
      << "work " << work << " stored " << stored << " dissipated " << dissipated;
}

// The simulator's own energy bookkeeping (SimulationOptions::energy) on a network with every
// kind of term: a motor torque through a lossy gear, a backlash spring, a damper, bearing
// friction that sticks and slips, and a torque load.
TEST(EnergyBalance, SimulatorBookkeepingClosesWithGearsBacklashAndFriction) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Sine", "command", P({{"amplitude", 3}, {"f", 2}}));
  net.AddElement("Torque", "motor");
  net.AddElement("Inertia", "rotor", P({{"J", 0.01}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("Inertia", "pinion", P({{"J", 0.02}}));
  net.AddElement("LossyGear", "gear", P({{"ratio", 4}}, {{"lossTable", {{0, 0.9, 0.8, 0.2, 0.1}}}}));
  net.AddElement("ElastoBacklash", "backlash", P({{"c", 2e3}, {"d", 1}, {"b", 0.02}}));
  net.AddElement("Inertia", "load", P({{"J", 0.5}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("BearingFriction", "bearing", P({{"peak", 1.3}}, {{"tau_pos", {{0, 2.0}}}}));
  net.AddElement("SpringDamper", "tether", P({{"c", 50}, {"d", 0.5}}));
  net.AddElement("ConstantTorque", "airload", P({{"tau_constant", -1.0}}));
  net.Connect("command.y", "motor.tau");
  net.Connect("motor.flange", "rotor.flange_a");
  net.Connect("rotor.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "pinion.flange_a");
  net.Connect("pinion.flange_b", "backlash.flange_a");
  net.Connect("backlash.flange_b", "load.flange_a");
  net.Connect("load.flange_b", "bearing.flange_a");
  net.Connect("load.flange_a", "tether.flange_a");
  net.Connect("tether.flange_b", "fixed.flange");
  net.Connect("airload.flange", "load.flange_b");
  const RunResult r = Simulate(net, 1.5, 1e-4, 1e-8, true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const EnergyBalance& b = r.report.energy;
  ASSERT_TRUE(b.computed);
  EXPECT_GT(b.source_work, 1.0) << r.report.FullReport();
  EXPECT_GT(b.dissipated, 0.1);
  EXPECT_NEAR(b.Residual(), 0.0, 1e-3 * b.Scale()) << r.report.FullReport();
  const auto loss = r.Col("energy.loss_power");
  for (double x : loss) EXPECT_GE(x, -1e-6) << "dissipation is never negative";
  bool stuck = false, sliding = false;
  for (double m : r.Col("bearing.mode")) stuck |= m == 0, sliding |= std::abs(m) == 1;
  EXPECT_TRUE(stuck && sliding) << "the run should exercise stick and slip";
}

// Ideal gear: power in = power out at every instant, and the reflected inertia
// (J2 + i^2 J1) a2 = i u - d w2 gives w2 = (i u / d) (1 - exp(-d t / (J2 + i^2 J1))).
TEST(IdealGear, ConservesPowerAndReflectsInertia) {
  const double i = 4, J1 = 0.1, J2 = 3, d = 5, u = 10;
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "torque", P({{"tau_constant", u}}));
  net.AddElement("Inertia", "inertia1", P({{"J", J1}}));
  net.AddElement("IdealGear", "gear", P({{"ratio", i}}));
  net.AddElement("Inertia", "inertia2", P({{"J", J2}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("Damper", "damper", P({{"d", d}}));
  net.Connect("torque.flange", "inertia1.flange_a");
  net.Connect("inertia1.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "inertia2.flange_a");
  net.Connect("inertia2.flange_b", "damper.flange_a");
  net.Connect("damper.flange_b", "fixed.flange");
  const RunResult r = Simulate(net, 2.0, 1e-2);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto w1 = r.Col("inertia1.w"), w2 = r.Col("inertia2.w");
  const auto ta = r.Col("gear.flange_a.tau"), tb = r.Col("gear.flange_b.tau");
  const double T = (J2 + i * i * J1) / d;
  for (std::size_t k = 0; k < w1.size(); ++k) {
    const double scale = std::abs(ta[k] * w1[k]) + 1e-12;
    EXPECT_NEAR(ta[k] * w1[k] + tb[k] * w2[k], 0.0, 1e-9 * scale) << "power not conserved";
    EXPECT_NEAR(w1[k], i * w2[k], 1e-9 * (1 + std::abs(w1[k])));
    EXPECT_NEAR(w2[k], i * u / d * (1 - std::exp(-r.t()[k] / T)), 1e-6);
  }
}

// Gear with a moving support: the housing is an inertia, not grounded. Angular momentum of the
// three bodies grows with the applied torque only; kinematics relative to the housing hold.
TEST(IdealGear, MovingSupportConservesMomentumAndKinematics) {
  const double i = 3, J1 = 0.2, J2 = 1.5, Jh = 2, u = 4;
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "torque", P({{"tau_constant", u}}));
  net.AddElement("Inertia", "inertia1", P({{"J", J1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("IdealGear", "gear", P({{"ratio", i}}));
  net.AddElement("Inertia", "inertia2", P({{"J", J2}, {"w_start", 0}}));
  net.AddElement("Inertia", "housing", P({{"J", Jh}, {"phi_start", 0}, {"w_start", 0}}));
  net.Connect("torque.flange", "inertia1.flange_a");
  net.Connect("torque.support", "fixed.flange");
  net.Connect("inertia1.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "inertia2.flange_a");
  net.Connect("gear.support", "housing.flange_a");
  const RunResult r = Simulate(net, 1.0, 1e-2);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto w1 = r.Col("inertia1.w"), w2 = r.Col("inertia2.w"), wh = r.Col("housing.w");
  const auto ta = r.Col("gear.flange_a.tau");
  // Hand-derived: with tau_a the gear torque at a, J1 a1 = u - tau_a, J2 a2 = i tau_a,
  // Jh ah = (1 - i) tau_a and a1 - ah = i (a2 - ah).
  const double tau_a = u / (1 + J1 * (i * i / J2 + (1 - i) * (1 - i) / Jh));
  for (std::size_t k = 0; k < w1.size(); ++k) {
    const double t = r.t()[k];
    EXPECT_NEAR(J1 * w1[k] + J2 * w2[k] + Jh * wh[k], u * t, 1e-8);
    EXPECT_NEAR(w1[k] - wh[k], i * (w2[k] - wh[k]), 1e-8);
    EXPECT_NEAR(ta[k], tau_a, 1e-8);
    EXPECT_NEAR(wh[k], (1 - i) * tau_a / Jh * t, 1e-7);
  }
  EXPECT_GT(std::abs(wh.back()), 0.1) << "the housing must move";
}

// IdealPlanetary with the ring fixed: w_carrier = w_sun / (1 + r); inertia at the sun
// Js + Jc/(1+r)^2; carrier torque -(1 + r) * sun torque.
TEST(IdealPlanetary, RingFixedReducesSpeedByOnePlusRatio) {
  const double r_ = 3, Js = 0.1, Jc = 1.6, u = 2;
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "torque", P({{"tau_constant", u}}));
  net.AddElement("Inertia", "sun_inertia", P({{"J", Js}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("IdealPlanetary", "planetary", P({{"ratio", r_}}));
  net.AddElement("Inertia", "carrier_inertia", P({{"J", Jc}}));
  net.Connect("torque.flange", "sun_inertia.flange_a");
  net.Connect("sun_inertia.flange_b", "planetary.sun");
  net.Connect("planetary.carrier", "carrier_inertia.flange_a");
  net.Connect("planetary.ring", "fixed.flange");
  const RunResult r = Simulate(net, 1.0, 0.05);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double a_sun = u / (Js + Jc / ((1 + r_) * (1 + r_)));
  const auto ws = r.Col("sun_inertia.w"), wc = r.Col("carrier_inertia.w");
  const auto ts = r.Col("planetary.sun.tau"), tc = r.Col("planetary.carrier.tau");
  for (std::size_t k = 0; k < ws.size(); ++k) {
    EXPECT_NEAR(ws[k], a_sun * r.t()[k], 1e-7);
    EXPECT_NEAR(wc[k], ws[k] / (1 + r_), 1e-9);
    EXPECT_NEAR(tc[k], -(1 + r_) * ts[k], 1e-9);
    EXPECT_NEAR(tc[k], -Jc * a_sun / (1 + r_), 1e-7);  // carrier accelerates its inertia
  }
}

// OneWayClutch (freewheel, disengaged clutch): a drives b while b would lag (locked); when the
// drive reverses at t = 1 s, b overruns freely.
TEST(OneWayClutch, LocksWhenDrivingAndOverrunsFreely) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("TorqueStep", "drive", P({{"stepTorque", -3}, {"offsetTorque", 2}, {"startTime", 1}}));
  net.AddElement("Inertia", "inertia1", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("OneWayClutch", "freewheel", P({{"fn_max", 100}}));
  net.AddElement("Constant", "engage", P({{"k", 0}}));
  net.AddElement("Inertia", "inertia2", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("TorqueStep", "load", P({{"stepTorque", 1}, {"offsetTorque", -1}, {"startTime", 1}}));
  net.Connect("drive.flange", "inertia1.flange_a");
  net.Connect("inertia1.flange_b", "freewheel.flange_a");
  net.Connect("freewheel.flange_b", "inertia2.flange_a");
  net.Connect("inertia2.flange_b", "load.flange");
  net.Connect("engage.y", "freewheel.f_normalized");
  const RunResult r = Simulate(net, 2.0, 0.01);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto w1 = r.Col("inertia1.w"), w2 = r.Col("inertia2.w"), stuck = r.Col("freewheel.stuck");
  for (std::size_t k = 0; k < w1.size(); ++k) {
    const double t = r.t()[k];
    if (t < 1 - 1e-9) {
      EXPECT_NEAR(w1[k], 0.5 * t, 1e-7) << "locked: both accelerate at (2 - 1) / 2";
      EXPECT_NEAR(w2[k], 0.5 * t, 1e-7);
      EXPECT_EQ(stuck[k], 1.0);
    } else if (t > 1 + 1e-9) {
      EXPECT_NEAR(w1[k], 0.5 - (t - 1), 1e-6) << "free: a decelerates at -1";
      EXPECT_NEAR(w2[k], 0.5, 1e-6) << "free: b keeps its speed (no load, no drag)";
      EXPECT_EQ(stuck[k], 0.0);
    }
  }
}

// LossyGear with bearing friction, hand-derived. Forward rolling with flange_a driving (Q1):
// tau_loss = (1 - eta1) tau_a + tau_bf1 and a_a = i^2 (eta1 u - tau_bf1) / (J2 + i^2 eta1 J1).
// Below the breakaway torque the gear stays stuck.
Network LossyGearRig(double u) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "torque", P({{"tau_constant", u}}));
  net.AddElement("Inertia", "inertia1", P({{"J", 1}}));
  net.AddElement("LossyGear", "gear", P({{"ratio", 2}}, {{"lossTable", {{0, 0.9, 0.8, 2, 1}}}}));
  net.AddElement("Inertia", "inertia2", P({{"J", 4}, {"phi_start", 0}, {"w_start", 0}}));
  net.Connect("torque.flange", "inertia1.flange_a");
  net.Connect("inertia1.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "inertia2.flange_a");
  return net;
}

TEST(LossyGear, RollsForwardWithMeshLossAndBearingFriction) {
  for (double u : {10.0, 3.0}) {
    const RunResult r = Simulate(LossyGearRig(u), 1.0, 0.05);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    const double a_a = 4 * (0.9 * u - 2) / (4 + 4 * 0.9 * 1);
    const double tau_a = u - a_a;
    const auto w1 = r.Col("inertia1.w"), loss = r.Col("gear.tauLoss"), mode = r.Col("gear.mode");
    for (std::size_t k = 1; k < w1.size(); ++k) {
      EXPECT_NEAR(w1[k], a_a * r.t()[k], 1e-7) << "u = " << u;
      EXPECT_NEAR(loss[k], 0.1 * tau_a + 2, 1e-7) << "u = " << u;
      EXPECT_EQ(mode[k], 1.0);
    }
  }
}

TEST(LossyGear, StaysStuckBelowBreakaway) {
  // u = 1: the holding loss torque 1 N*m is below the forward capacity 0.1*1 + 2 = 2.1 N*m.
  const RunResult r = Simulate(LossyGearRig(1.0), 1.0, 0.05);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto w1 = r.Col("inertia1.w"), loss = r.Col("gear.tauLoss"), mode = r.Col("gear.mode");
  for (std::size_t k = 0; k < w1.size(); ++k) {
    EXPECT_EQ(w1[k], 0.0);
    EXPECT_NEAR(loss[k], 1.0, 1e-9);
    EXPECT_EQ(mode[k], 0.0);
  }
}

// Pulse edges are time events: the integrator stops exactly there.
TEST(TimeEvents, PulseEdgesAreHitExactly) {
  Network net;
  net.AddElement("Pulse", "pulse", P({{"amplitude", 3}, {"width", 30}, {"period", 0.1}, {"startTime", 0.05}}));
  net.AddElement("Torque", "torque");
  net.AddElement("Inertia", "inertia", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("Damper", "damper", P({{"d", 1}}));
  net.AddElement("Fixed", "fixed");
  net.Connect("pulse.y", "torque.tau");
  net.Connect("torque.flange", "inertia.flange_a");
  net.Connect("inertia.flange_b", "damper.flange_a");
  net.Connect("damper.flange_b", "fixed.flange");
  const RunResult r = Simulate(net, 0.3, 0.007);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  std::vector<double> expected = {0.05, 0.08, 0.15, 0.18, 0.25, 0.28};
  std::vector<double> found;
  for (const auto& e : r.report.events)
    if (e.kind == "time") found.push_back(e.time);
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t k = 0; k < found.size(); ++k) EXPECT_NEAR(found[k], expected[k], 1e-12);
  // Closed form between edges: w' = u - w.
  const auto w = r.Col("inertia.w");
  double w_exact = 0;  // integrate the piecewise-constant input exactly
  double t_prev = 0;
  std::size_t k = 0;
  for (double edge : {0.05, 0.08, 0.15, 0.18, 0.25, 0.28, 0.3}) {
    const double u = (edge == 0.08 || edge == 0.18 || edge == 0.28) ? 3.0 : 0.0;
    for (; k < w.size() && r.t()[k] <= edge + 1e-12; ++k) {
      if (r.t()[k] < t_prev) continue;
      const double expect = u + (w_exact - u) * std::exp(-(r.t()[k] - t_prev));
      EXPECT_NEAR(w[k], expect, 1e-6) << "t = " << r.t()[k];
    }
    w_exact = u + (w_exact - u) * std::exp(-(edge - t_prev));
    t_prev = edge;
    while (k < w.size() && r.t()[k] == edge) ++k;  // skip the right-limit row
  }
}

TEST(Network, UnknownTypeSuggestsTheClosestName) {
  Network net;
  try {
    net.AddElement("Intertia", "x");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown element type 'Intertia'; did you mean 'Inertia'?"),
              std::string::npos)
        << e.what();
  }
}

TEST(Network, MissingRequiredParameterIsNamed) {
  Network net;
  try {
    net.AddElement("Spring", "spring");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element 'spring' (Spring): parameter 'c'"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("is required"), std::string::npos) << e.what();
  }
}

TEST(Network, UnconnectedSignalInputIsAnError) {
  Network net;
  net.AddElement("Torque", "torque");
  net.AddElement("Inertia", "inertia", P({{"J", 1}}));
  net.Connect("torque.flange", "inertia.flange_a");
  try {
    Simulator sim(net);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("signal input 'tau' is not connected"), std::string::npos)
        << e.what();
  }
}

// A flange without inertia between compliant elements is a static balance (valid, as in MSL);
// a torque source on it leaves its acceleration undetermined.
TEST(Network, MasslessFlangeWithASourceIsReportedWithRemedy) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Spring", "spring", P({{"c", 10}}));
  net.AddElement("ConstantTorque", "torque", P({{"tau_constant", 1}}));
  net.Connect("fixed.flange", "spring.flange_a");
  net.Connect("spring.flange_b", "torque.flange");
  net.Connect("torque.support", "fixed.flange");
  try {
    Simulator sim(net);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has no inertia and no kinematic coupling, and element 'torque'"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("connect an Inertia there"), std::string::npos) << e.what();
  }
}

TEST(Network, ContradictoryInitialValuesAreNamed) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("IdealGear", "gear", P({{"ratio", 2}}));
  net.AddElement("Inertia", "a", P({{"J", 1}, {"w_start", 1}}));
  net.AddElement("Inertia", "b", P({{"J", 1}, {"w_start", 1}}));
  net.Connect("a.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "b.flange_a");
  Simulator sim(net);
  MemorySink sink;
  SimulationOptions o;
  try {
    sim.Run(o, sink);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("initial speeds contradict"), std::string::npos) << e.what();
  }
}

// A failed integration returns a report (time, state, element, flag), it does not throw.
TEST(Failure, ReportNamesTimeFlagAndState) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Spring", "spring", P({{"c", 1e6}}));
  net.AddElement("Inertia", "inertia", P({{"J", 1e-3}, {"phi_start", 1}, {"w_start", 0}}));
  net.Connect("fixed.flange", "spring.flange_a");
  net.Connect("spring.flange_b", "inertia.flange_a");
  Simulator sim(net);
  MemorySink sink;
  SimulationOptions o;
  o.stop_time = 10;
  o.output_interval = 5;
  o.max_steps_per_output = 50;
  const SimulationReport r = sim.Run(o, sink);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status, SimulationStatus::kSolverFailure);
  EXPECT_EQ(r.sundials_flag, "CV_TOO_MUCH_WORK");
  EXPECT_NE(r.message.find("CVode failed with CV_TOO_MUCH_WORK at t = "), std::string::npos) << r.message;
  EXPECT_GT(r.time, 0.0);
  EXPECT_LT(r.time, 10.0);
  EXPECT_FALSE(r.state.empty());
  EXPECT_FALSE(r.element.empty());
}

TEST(Options, DefaultsAreValid) {
  EXPECT_NO_THROW(SimulationOptions{}.Validate());
  SimulationOptions o;
  o.stop_time = -1;
  EXPECT_THROW(o.Validate(), InputError);
}

// Issue 27 item 19 ("J = -nan"): a non-finite element parameter (in a drive network, computed
// from its component's parameters) is named as not finite with its element, not as "outside its
// valid range [0, inf]".
TEST(NetworkElements, ANonFiniteParameterIsNamedAsNotFinite) {
  for (double bad : {std::nan(""), -std::nan(""), static_cast<double>(INFINITY)}) {
    Network net;
    try {
      net.AddElement("Inertia", "shaft_3_m1", P({{"J", bad}}));
      FAIL() << "no error for J = " << bad;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("element 'shaft_3_m1' (Inertia): parameter 'J' = "), std::string::npos) << m;
      EXPECT_NE(m.find(" is not finite; in a drive network it is computed from the parameters of the component the "
                       "element belongs to"),
                std::string::npos)
          << m;
      EXPECT_EQ(m.find("valid range"), std::string::npos) << m;
    }
  }
}

/// Counts the rows and their times; does not read the values (OutputSink::ReadsValues).
class TimesOnlySink : public OutputSink {
 public:
  void Begin(const std::vector<std::string>& columns) override { columns_ = columns.size(); }
  void Row(double time, const std::vector<double>& values) override {
    times.push_back(time);
    sizes_match = sizes_match && values.size() == columns_;
  }
  bool ReadsValues() const override { return false; }
  std::vector<double> times;
  bool sizes_match = true;

 private:
  std::size_t columns_ = 0;
};

// The simulator skips the outputs for a sink that does not read them; nothing else changes.
TEST(OutputSink, ASinkThatDoesNotReadTheValuesGetsTheSameRowsAndResults) {
  SimulationOptions o;
  o.stop_time = 2.0;
  o.output_interval = 1e-2;
  o.energy = true;
  MemorySink memory;
  TimesOnlySink times_only;
  const SimulationReport full = Simulator(DrivenSpringWithBearingFriction(8, 1.5)).Run(o, memory);
  const SimulationReport lean = Simulator(DrivenSpringWithBearingFriction(8, 1.5)).Run(o, times_only);
  ASSERT_TRUE(full.ok()) << full.FullReport();
  ASSERT_TRUE(lean.ok()) << lean.FullReport();
  EXPECT_GT(full.events.size(), 2u);  // stick/slip events: rows at their limits too
  EXPECT_EQ(times_only.times, memory.times());
  EXPECT_TRUE(times_only.sizes_match);
  EXPECT_EQ(lean.statistics.steps, full.statistics.steps);
  EXPECT_EQ(lean.events.size(), full.events.size());
  ASSERT_EQ(lean.peak_torques.size(), full.peak_torques.size());
  for (std::size_t i = 0; i < full.peak_torques.size(); ++i) {
    EXPECT_EQ(lean.peak_torques[i].tau, full.peak_torques[i].tau) << full.peak_torques[i].element;
    EXPECT_EQ(lean.peak_torques[i].time, full.peak_torques[i].time) << full.peak_torques[i].element;
  }
  EXPECT_EQ(lean.energy.dissipated, full.energy.dissipated);
  EXPECT_EQ(lean.energy.source_work, full.energy.source_work);
}

// For a sink that reads the rows, a step that passes output points is evaluated there on the
// interpolant after CVODE's own evaluation of its end; the step end's readings (dissipated
// powers, peak torques, root functions) are taken from that evaluation before the output points
// replace it. The answers follow the step ends only, so a grid finer than every step with a sink
// that reads it (each step end read that way) and one with no point inside the run and a sink
// that reads nothing (no output point evaluated) must give the same steps, events, passivity
// monitor and peaks, to the bit.
TEST(OutputSink, StepEndsReadBeforeTheOutputPointsAreThoseOfTheirOwnEvaluation) {
  SimulationOptions o;
  o.stop_time = 2.0;
  o.relative_tolerance = 1e-6;
  o.passivity_tolerance = 1e-12;  // every sample with negative power starts an episode
  struct ReadingSink : TimesOnlySink {  // reads every row: the output points are evaluated
    bool ReadsValues() const override { return true; }
  } fine_rows;
  TimesOnlySink no_rows;
  o.output_interval = 1e-5;
  const SimulationReport fine = Simulator(DrivenSpringWithBearingFriction(8, 1.5)).Run(o, fine_rows);
  o.output_interval = 10.0;
  const SimulationReport coarse = Simulator(DrivenSpringWithBearingFriction(8, 1.5)).Run(o, no_rows);
  ASSERT_TRUE(fine.ok()) << fine.FullReport();
  ASSERT_TRUE(coarse.ok()) << coarse.FullReport();
  EXPECT_GT(fine_rows.times.size(), 10 * static_cast<std::size_t>(fine.statistics.steps));
  EXPECT_EQ(fine.statistics.steps, coarse.statistics.steps);
  EXPECT_EQ(fine.statistics.rhs_evaluations, coarse.statistics.rhs_evaluations);
  ASSERT_EQ(fine.events.size(), coarse.events.size());
  EXPECT_GT(fine.events.size(), 4u);  // stick/slip: the root functions read at the step ends matter
  for (std::size_t i = 0; i < fine.events.size(); ++i) {
    EXPECT_EQ(fine.events[i].time, coarse.events[i].time) << i;
    EXPECT_EQ(fine.events[i].what, coarse.events[i].what) << i;
  }
  EXPECT_GT(coarse.passivity.power_scale, 0.0);
  EXPECT_EQ(fine.passivity.power_scale, coarse.passivity.power_scale);  // the largest of every step end's
  EXPECT_EQ(fine.passivity.BriefReport(), coarse.passivity.BriefReport());
  ASSERT_EQ(fine.peak_torques.size(), coarse.peak_torques.size());
  for (std::size_t i = 0; i < fine.peak_torques.size(); ++i) {
    EXPECT_EQ(fine.peak_torques[i].tau, coarse.peak_torques[i].tau) << fine.peak_torques[i].element;
    EXPECT_EQ(fine.peak_torques[i].time, coarse.peak_torques[i].time) << fine.peak_torques[i].element;
  }
}

}  // namespace
}  // namespace highlift::sim
