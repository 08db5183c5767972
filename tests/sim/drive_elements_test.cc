// HighLift PDU, monitoring, sensors and tables (sim/src/drive_elements.cc): the PDU's speed
// loop, stall and power limits, pressure-off brakes and loss of a motor against analytic
// values; each monitor's detection, latency and latch; the tables against the examples of the
// MSL 4.0.0 documentation; the energy balance of a PDU run with brake slip and stick and an
// airload from a table of the output angle; bad parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

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
  /// Value of a column at the last row with time <= at (the right limit at an event).
  double At(const std::string& name, double at) const {
    const auto v = Col(name);
    std::size_t best = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (t()[i] <= at + 1e-12) best = i;
    return v[best];
  }
  /// Time of the first row where column `name` is > 0.5 (NaN if never).
  double FirstTrue(const std::string& name) const {
    const auto v = Col(name);
    for (std::size_t i = 0; i < v.size(); ++i)
      if (v[i] > 0.5) return t()[i];
    return NAN;
  }
};

RunResult Simulate(const Network& net, double stop, double dt, bool energy = false) {
  RunResult r;
  Simulator sim(net);
  SimulationOptions o;
  o.energy = energy;
  o.stop_time = stop;
  o.output_interval = dt;
  o.relative_tolerance = 1e-8;
  o.absolute_tolerance = 1e-10;
  r.report = sim.Run(o, r.sink);
  return r;
}

// Default PDU: J = 2*3e-4*20^2 + 0.02 = 0.26 kg*m^2, T_w = 0.02 s, ramp w_max/t_ramp.
constexpr double kJ = 0.26;

// A PDU commanded by a constant speed.
Network PduNetwork(double w_ref, Scalars pdu = {}) {
  Network net;
  net.AddElement("Constant", "command", P({{"k", w_ref}}));
  net.AddElement("PDU", "pdu", P(std::move(pdu)));
  net.Connect("command.y", "pdu.w_ref");
  return net;
}

// The unloaded output follows the ramped set point through the first-order (proportional,
// T_i = 0) speed loop: during the ramp w_set = a*t, w = a*(t - T_w*(1 - exp(-t/T_w))),
// a = w_max/t_ramp.
TEST(PDU, FollowsTheSpeedRampWithTheLagOfTheSpeedLoop) {
  const RunResult r = Simulate(PduNetwork(10.0, {{"T_i", 0.0}}), 0.6, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double a = 25.3 / 0.4, T_w = 0.02;
  const double t_ramp_end = (10.0 - a * T_w) / a;  // the ramp limit ends where (10 - w_set)/T_w = a
  const auto w = r.Col("pdu.w"), w_set = r.Col("pdu.w_set");
  double worst = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double t = r.t()[i];
    if (t > t_ramp_end) break;
    worst = std::max(worst, std::abs(w[i] - a * (t - T_w * (1 - std::exp(-t / T_w)))));
    EXPECT_NEAR(w_set[i], a * t, 1e-6 * a) << "t = " << t;
  }
  EXPECT_LT(worst, 1e-5 * 10.0) << "largest deviation from the first-order lag of the ramp";
  EXPECT_NEAR(r.At("pdu.w", 0.1) , a * (0.1 - T_w * (1 - std::exp(-5.0))), 1e-4);
  EXPECT_NEAR(r.Col("pdu.w").back(), 10.0, 1e-4);       // settled on the command
  EXPECT_DOUBLE_EQ(r.Col("pdu.brake").back(), 0.0);     // driving: brakes released
  EXPECT_NEAR(r.Col("pdu.tau").back(), 0.0, 1e-6);      // nothing to drive at constant speed
}

// A stiff, damped load to the housing: the output stops where the spring holds tau_stall; the
// saturated speed loop delivers exactly tau_stall (the loop asks k_w*w_set = 13*25 > 200).
Network StallNetwork(Scalars pdu) {
  Network net = PduNetwork(25.0, std::move(pdu));
  net.AddElement("SpringDamper", "load", P({{"c", 1e5}, {"d", 300}}));
  net.AddElement("Fixed", "housing");
  net.Connect("pdu.flange_left", "load.flange_a");
  net.Connect("load.flange_b", "housing.flange");
  return net;
}

TEST(PDU, StallsAtTauStallAgainstAStiffLoad) {
  const RunResult r = Simulate(StallNetwork({{"tau_stall", 200}}), 1.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.Col("pdu.tau_drive").back(), 200.0, 1e-9);
  EXPECT_NEAR(r.Col("load.tau").back(), -200.0, 1e-3);  // phi_rel = -phi_pdu
  EXPECT_NEAR(r.Col("pdu.phi").back(), 200.0 / 1e5, 1e-8);
  EXPECT_NEAR(r.Col("pdu.w").back(), 0.0, 1e-6);
  EXPECT_NEAR(r.Col("pdu.tau").back(), 200.0, 1e-3);  // delivered into the transmission
  // The peak output torque is reported for the PDU.
  bool reported = false;
  for (const auto& p : r.report.peak_torques)
    if (p.element == "pdu") reported = std::abs(p.tau) >= 200.0 - 1e-3;
  EXPECT_TRUE(reported) << r.report.FullReport();
}

// A constant load torque tau_L (within the limits): the proportional loop (T_i = 0) droops by
// tau_L/k_w, k_w = J/T_w; the PI loop (the default T_i) removes the droop.
TEST(PDU, IntegralActionRemovesTheDroopUnderLoad) {
  for (const double T_i : {0.0, 0.08}) {
    Network net = PduNetwork(20.0, {{"T_i", T_i}});
    net.AddElement("ConstantTorque", "airload", P({{"tau_constant", -300}}));
    net.Connect("airload.flange", "pdu.flange_right");
    const RunResult r = Simulate(net, 2.0, 1e-3);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    const double droop = T_i > 0 ? 0.0 : 300.0 / (kJ / 0.02);
    EXPECT_NEAR(r.Col("pdu.w").back(), 20.0 - droop, 1e-4) << "T_i = " << T_i;
    EXPECT_NEAR(r.Col("pdu.tau_drive").back(), 300.0, 1e-3) << "T_i = " << T_i;
  }
}

// The pressure-off brakes build up over t_POB when they are applied in motion; the motors hold
// the output on the set point until they are fully built up, then the drive torque is removed.
TEST(PDU, MotorsHoldWhileTheBrakesBuildUp) {
  Network net;
  net.AddElement("CombiTimeTable", "command",
                 P({{"extrapolation", 1}}, {{"table", {{0, 5}, {0.2, 5}, {0.2, 0}, {0.6, 0}}}}));
  net.AddElement("PDU", "pdu");
  net.AddElement("ConstantTorque", "airload", P({{"tau_constant", -200}}));
  net.Connect("command.y", "pdu.w_ref");
  net.Connect("airload.flange", "pdu.flange_right");
  const RunResult r = Simulate(net, 0.6, 1e-4);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double t_on = r.FirstTrue("pdu.brake");
  ASSERT_GT(t_on, 0.2);
  EXPECT_NEAR(r.At("pdu.f_brake", t_on + 0.025), 0.5, 5e-3);  // half built up after t_POB/2 (1e-4 s rows)
  EXPECT_GT(std::abs(r.At("pdu.tau_drive", t_on + 0.025)), 100.0);  // the motors still hold
  EXPECT_DOUBLE_EQ(r.At("pdu.tau_drive", t_on + 0.06), 0.0);         // then the brakes alone
  EXPECT_NEAR(r.Col("pdu.tau_brake").back(), -200.0, 1e-6);
  EXPECT_LT(std::abs(r.At("pdu.phi", 0.6) - r.At("pdu.phi", t_on)), 0.01);  // no back-driving
}

// A load torque tau_L above P_max/w_max: the output settles where the power limit allows it,
// w = P_max/tau_L (a fast loop, k_w = 500 N*m*s/rad, so that droop does not limit first).
TEST(PDU, PowerLimitsTheSpeedAtHighTorque) {
  Network net = PduNetwork(25.0, {{"J_g", 0.26}, {"T_w", 0.001}, {"T_i", 0.0}, {"P_max", 9000}});
  net.AddElement("TorqueStep", "airload", P({{"stepTorque", -600}, {"startTime", 0.5}}));
  net.Connect("airload.flange", "pdu.flange_right");
  const RunResult r = Simulate(net, 1.5, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.At("pdu.w", 0.5), 25.0, 1e-3);  // unloaded: on the command
  EXPECT_NEAR(r.Col("pdu.w").back(), 9000.0 / 600.0, 1e-4);
  EXPECT_NEAR(r.Col("pdu.tau_drive").back() * r.Col("pdu.w").back(), 9000.0, 1e-2);
}

// With the command at zero from the start the drive is parked: the pressure-off brakes hold
// with their full torque tauPOB (built up before the start); a back-driving load below tauPOB
// is held, one above it slips at (load - tauPOB)/J.
TEST(PDU, PressureOffBrakesHoldABackDrivingLoadUpToTauPOB) {
  for (const double factor : {0.95, 1.02}) {
    Network net = PduNetwork(0.0);
    net.AddElement("TorqueStep", "airload", P({{"stepTorque", factor * 1100}, {"startTime", 0.1}}));
    net.Connect("airload.flange", "pdu.flange_left");
    const RunResult r = Simulate(net, 0.3, 1e-3);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    EXPECT_DOUBLE_EQ(r.At("pdu.brake", 0.0), 1.0);
    EXPECT_DOUBLE_EQ(r.At("pdu.f_brake", 0.0), 1.0);  // parked: fully applied at the start
    EXPECT_DOUBLE_EQ(r.At("pdu.f_brake", 0.09), 1.0);
    if (factor < 1) {
      EXPECT_EQ(r.Col("pdu.mode").back(), 0) << "stuck";
      EXPECT_NEAR(r.Col("pdu.w").back(), 0.0, 1e-9);
      EXPECT_NEAR(r.Col("pdu.tau_brake").back(), factor * 1100, 1e-6);
      EXPECT_NEAR(r.Col("pdu.tau").back(), -factor * 1100, 1e-6);  // the airload reaches the POB
    } else {
      EXPECT_EQ(r.Col("pdu.mode").back(), 1) << "sliding forward";
      EXPECT_NEAR(r.Col("pdu.w").back(), (factor - 1) * 1100 / kJ * 0.2, 1e-4);
      EXPECT_NEAR(r.Col("pdu.tau_brake").back(), 1100, 1e-9);
    }
  }
}

// One motor lost: the differential delivers half the speed (w_max/2 no-load) and the same
// stall torque.
TEST(PDU, OneMotorLostHalvesTheNoLoadSpeedAtTheSameTorqueCapacity) {
  const RunResult r = Simulate(PduNetwork(30.0, {{"t_motor_lost", 1.0}}), 2.0, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.At("pdu.w", 1.0), 25.3, 1e-4);
  EXPECT_NEAR(r.Col("pdu.w").back(), 25.3 / 2, 1e-4);
  EXPECT_EQ(r.At("pdu.n_active", 0.99), 2);
  EXPECT_EQ(r.Col("pdu.n_active").back(), 1);
  bool logged = false;
  for (const auto& e : r.report.events)
    if (e.element == "pdu" && e.what.find("1 of 2 motors") != std::string::npos) logged = std::abs(e.time - 1.0) < 1e-12;
  EXPECT_TRUE(logged) << r.report.FullReport();

  for (const double lost : {static_cast<double>(INFINITY), 0.0}) {
    Scalars pdu = {{"tau_stall", 200}, {"T_w", 0.005}};
    if (std::isfinite(lost)) pdu["t_motor_lost"] = lost;
    const RunResult s = Simulate(StallNetwork(pdu), 1.0, 1e-3);
    ASSERT_TRUE(s.report.ok()) << s.report.FullReport();
    EXPECT_NEAR(s.Col("pdu.tau_drive").back(), 200.0, 1e-9) << "t_motor_lost = " << lost;
  }
}

// Run up, hold, stop: the brakes apply when the set point reaches w_hold, slip while the output
// still turns (back-driven by the airload: the proportional loop droops) and then stick; the airload is a Torque driven by a CombiTable1Ds of the output
// angle (AngleSensor), the path of the drive-system translation. Work of the PDU and the airload
// = kinetic + potential energy + friction loss.
TEST(PDU, EnergyBalanceWithBrakeSlipAndStickAndAnAngleDependentAirload) {
  Network net;
  net.AddElement("CombiTimeTable", "command",
                 P({{"extrapolation", 1}}, {{"table", {{0, 0}, {0.05, 10}, {0.3, 10}, {0.35, 0}}}}));
  net.AddElement("PDU", "pdu");
  net.AddElement("SpringDamper", "shaft", P({{"c", 2e4}, {"d", 50}}));
  net.AddElement("Inertia", "flap", P({{"J", 0.5}}));
  net.AddElement("AngleSensor", "angle");
  net.AddElement("CombiTable1Ds", "airloadTable",
                 P({{"extrapolation", 1}}, {{"table", {{0, -50}, {10, -150}}}}));
  net.AddElement("Torque", "airload");
  net.Connect("command.y", "pdu.w_ref");
  net.Connect("pdu.flange_right", "shaft.flange_a");
  net.Connect("shaft.flange_b", "flap.flange_a");
  net.Connect("flap.flange_b", "angle.flange");
  net.Connect("angle.phi", "airloadTable.u");
  net.Connect("airloadTable.y", "airload.tau");
  net.Connect("airload.flange", "flap.flange_b");
  const RunResult r = Simulate(net, 0.8, 1e-4, true);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  // The mode sequence: driving (brakes free), brakes applied while turning (slip), stuck.
  const auto mode = r.Col("pdu.mode"), brake = r.Col("pdu.brake"), w = r.Col("pdu.w");
  bool slipped = false, stuck_after = false;
  for (std::size_t i = 0; i < mode.size(); ++i) {
    if (brake[i] > 0.5 && (mode[i] == 1 || mode[i] == -1) && std::abs(w[i]) > 1e-6) slipped = true;
    if (slipped && mode[i] == 0) stuck_after = true;
  }
  EXPECT_TRUE(slipped) << r.report.FullReport();
  EXPECT_TRUE(stuck_after) << r.report.FullReport();
  EXPECT_NEAR(r.Col("pdu.w").back(), 0.0, 1e-12);
  EXPECT_NEAR(r.Col("flap.w").back(), 0.0, 1e-4);  // the flap rings out on the shaft
  // The airload follows the table at the flap angle.
  const double phi = r.Col("angle.phi").back();
  ASSERT_LT(phi, 10.0);
  EXPECT_NEAR(r.Col("airload.tau").back(), -50 - 10 * phi, 1e-9);
  const EnergyBalance& b = r.report.energy;
  EXPECT_GT(b.dissipated, 0.0);
  EXPECT_LT(std::abs(b.Residual()), 1e-4 * b.Scale()) << r.report.FullReport();
}

// Stop and go: the brakes apply when command and set point are at rest and release as soon as
// the command leaves w_hold; the drive then runs the output up again.
TEST(PDU, BrakesReleaseWhenCommandedAgain) {
  Network net;
  net.AddElement("CombiTimeTable", "command",
                 P({{"extrapolation", 1}},
                   {{"table", {{0, 5}, {0.2, 5}, {0.2, 0}, {0.5, 0}, {0.5, -5}}}}));
  net.AddElement("PDU", "pdu", P({{"T_i", 0.0}}));
  net.Connect("command.y", "pdu.w_ref");
  const RunResult r = Simulate(net, 0.9, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_DOUBLE_EQ(r.At("pdu.brake", 0.19), 0.0);
  EXPECT_DOUBLE_EQ(r.At("pdu.brake", 0.45), 1.0);
  EXPECT_EQ(r.At("pdu.mode", 0.45), 0) << "stuck";
  const double held = r.At("pdu.phi", 0.45);
  EXPECT_NEAR(r.At("pdu.phi", 0.5), held, 1e-12);  // held until the new command
  EXPECT_DOUBLE_EQ(r.Col("pdu.brake").back(), 0.0);
  EXPECT_EQ(r.Col("pdu.mode").back(), 2) << "free";
  // The speed loop's tail: w approaches -5 by a factor of about 10 every 0.05 s (1e-4 short at
  // 0.8 s, 1e-6 at 0.9 s), the integration error at rtol 1e-8 being some 1e-9.
  EXPECT_NEAR(r.Col("pdu.w").back(), -5.0, 1e-5);
  EXPECT_LT(std::abs(r.Col("pdu.w").back() + 5.0), 0.2 * std::abs(r.At("pdu.w", 0.85) + 5.0));
  // The brake applied at the instant w_set fell to w_hold: w_set = 5*exp(-(t - t0)/T_w) after
  // the ramp, so it is applied once and released once.
  int applications = 0, releases = 0;
  const auto brake = r.Col("pdu.brake");
  for (std::size_t i = 1; i < brake.size(); ++i) {
    applications += brake[i] > brake[i - 1];
    releases += brake[i] < brake[i - 1];
  }
  EXPECT_EQ(applications, 1);
  EXPECT_EQ(releases, 1);
}

TEST(PDU, RejectsBadParametersNamingTheElementAndParameter) {
  auto message = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_NE(message([] { PduNetwork(1, {{"n_m", 0}}); }).find("'n_m'"), std::string::npos);
  const std::string whole = message([] { Simulator s(PduNetwork(1, {{"n_m", 1.5}})); });
  EXPECT_NE(whole.find("element 'pdu' (PDU): parameter 'n_m' = 1.5"), std::string::npos) << whole;
  EXPECT_NE(whole.find("whole number"), std::string::npos) << whole;
  const std::string inertia = message([] { Simulator s(PduNetwork(1, {{"J_m", 0}, {"J_g", 0}})); });
  EXPECT_NE(inertia.find("element 'pdu' (PDU)"), std::string::npos) << inertia;
  EXPECT_NE(inertia.find("give the motor inertia J_m or the gear inertia J_g"), std::string::npos);
  EXPECT_NE(message([] { PduNetwork(1, {{"T_w", 0}}); }).find("'T_w' = 0"), std::string::npos);
  const std::string unconnected = message([] {
    Network net;
    net.AddElement("PDU", "pdu");
    Simulator s(net);
  });
  EXPECT_NE(unconnected.find("signal input 'w_ref' is not connected"), std::string::npos) << unconnected;
}

// --- Monitoring -----------------------------------------------------------------------------

// Inputs as tables (zero unless given), a dummy inertia for the state vector. The tested input
// rises as 2*t to 2 at t = 1 and falls back to 0 at t = 2: it crosses the threshold 0.5 at
// t = 0.25 and falls below it at t = 1.75.
Network MonitorNetwork(const std::string& input, Scalars monitor) {
  Network net;
  net.AddElement("Inertia", "mass", P({{"J", 1}}));
  monitor.emplace("phi_asym", 0.5);
  monitor.emplace("w_over", 0.5);
  monitor.emplace("phi_unc", 0.5);
  monitor.emplace("t_detect", 0.1);
  net.AddElement("Monitoring", "monitor", P(monitor));
  for (const char* in : {"phi_left", "phi_right", "phi_pdu", "phi_cmd", "w_left", "w_right"}) {
    const std::string id = std::string("in_") + in;
    const Rows rows = in == input ? Rows{{0, 0}, {1, 2}, {2, 0}} : Rows{{0, 0}};
    net.AddElement("CombiTimeTable", id, P({{"extrapolation", 1}}, {{"table", rows}}));
    net.Connect(id + ".y", std::string("monitor.") + in);
  }
  return net;
}

TEST(Monitoring, EachMonitorFiresAfterExactlyTDetectAndLatches) {
  // The tested input and the monitors it trips (the PDU angle is also compared with the command).
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"phi_left", {"asymmetry"}}, {"phi_right", {"asymmetry"}},
      {"phi_pdu", {"asymmetry", "uncommanded"}}, {"w_left", {"overspeed"}},
      {"w_right", {"overspeed"}}, {"phi_cmd", {"uncommanded"}}};
  for (const auto& [input, monitors] : cases) {
    SCOPED_TRACE(input);
    const RunResult r = Simulate(MonitorNetwork(input, {}), 2.5, 1e-2);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    EXPECT_NEAR(r.FirstTrue("monitor.fault"), 0.25, 1e-9);
    EXPECT_NEAR(r.FirstTrue("monitor.wtb") - r.FirstTrue("monitor.fault"), 0.1, 1e-12);
    EXPECT_DOUBLE_EQ(r.Col("monitor.wtb").back(), 1.0);  // latched
    for (const std::string other : {"asymmetry", "overspeed", "uncommanded"}) {
      if (std::find(monitors.begin(), monitors.end(), other) == monitors.end()) {
        EXPECT_TRUE(std::isnan(r.FirstTrue("monitor." + other))) << other;
        continue;
      }
      // Detected at the crossing; it falls when the input does, the brake command stays.
      EXPECT_NEAR(r.FirstTrue("monitor." + other), 0.25, 1e-9) << other;
      EXPECT_DOUBLE_EQ(r.At("monitor." + other, 1.7), 1.0) << other;
      EXPECT_DOUBLE_EQ(r.Col("monitor." + other).back(), 0.0) << other;
    }
  }
}

TEST(Monitoring, DisabledMonitorNeverCommandsTheBrakes) {
  const RunResult r = Simulate(MonitorNetwork("w_left", {{"enableOverspeed", 0}}), 2.5, 1e-2);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_TRUE(std::isnan(r.FirstTrue("monitor.overspeed")));
  EXPECT_TRUE(std::isnan(r.FirstTrue("monitor.wtb")));
}

// With t_detect = 0 the command follows the detection at once; a command drives a brake.
TEST(Monitoring, ZeroLatencyCommandsAtTheDetection) {
  const RunResult r = Simulate(MonitorNetwork("phi_left", {{"t_detect", 0}}), 1.0, 1e-2);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.FirstTrue("monitor.wtb"), 0.25, 1e-9);
}

// --- Sensors, tables, blocks ----------------------------------------------------------------

TEST(Sensors, ReadAngleSpeedRelativeAngleAndRelativeSpeed) {
  Network net;
  net.AddElement("Inertia", "a", P({{"J", 1}, {"w_start", 2}, {"phi_start", 0.5}}));
  net.AddElement("Inertia", "b", P({{"J", 1}, {"w_start", -1}, {"phi_start", 0}}));
  for (const char* s : {"AngleSensor", "SpeedSensor"}) net.AddElement(s, std::string("s") + s);
  net.AddElement("RelAngleSensor", "rel");
  net.AddElement("RelSpeedSensor", "relw");
  net.Connect("a.flange_a", "sAngleSensor.flange");
  net.Connect("a.flange_b", "sSpeedSensor.flange");
  for (const char* s : {"rel", "relw"}) {
    net.Connect("a.flange_a", std::string(s) + ".flange_a");
    net.Connect("b.flange_a", std::string(s) + ".flange_b");
  }
  const RunResult r = Simulate(net, 1.0, 0.1);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.Col("sAngleSensor.phi").back(), 2.5, 1e-8);
  EXPECT_NEAR(r.Col("sSpeedSensor.w").back(), 2.0, 1e-10);
  EXPECT_NEAR(r.Col("rel.phi_rel").back(), -1.0 - 2.5, 1e-8);
  EXPECT_NEAR(r.Col("relw.w_rel").back(), -3.0, 1e-10);
}

// A table block alone, with a dummy inertia for the state vector.
RunResult RunTimeTable(Scalars s, Rows table, double stop, double dt) {
  Network net;
  net.AddElement("Inertia", "mass", P({{"J", 1}}));
  net.AddElement("CombiTimeTable", "table", P(std::move(s), {{"table", std::move(table)}}));
  return Simulate(net, stop, dt);
}

// The example of the CombiTimeTable documentation (MSL 4.0.0): table [0,0; 1,0; 1,1; 2,4;
// 3,9; 4,16], extrapolation = LastTwoPoints: y(1) = 0 before and 1 after the event, y(1.5) =
// 2.5, y(2) = 4, y(5) = 23.
TEST(CombiTimeTable, ReproducesTheMslDocumentationExample) {
  const Rows table = {{0, 0}, {1, 0}, {1, 1}, {2, 4}, {3, 9}, {4, 16}};
  for (const double events : {1.0, 2.0}) {
    const RunResult r = RunTimeTable({{"timeEvents", events}}, table, 5.0, 0.5);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    std::vector<double> at_one;
    for (std::size_t i = 0; i < r.t().size(); ++i)
      if (r.t()[i] == 1.0) at_one.push_back(r.Col("table.y")[i]);
    ASSERT_GE(at_one.size(), 2u);
    EXPECT_DOUBLE_EQ(at_one.front(), 0.0);  // left limit
    EXPECT_DOUBLE_EQ(at_one.back(), 1.0);   // right limit
    EXPECT_NEAR(r.At("table.y", 1.5), 2.5, 1e-12);
    EXPECT_NEAR(r.At("table.y", 2.0), 4.0, 1e-12);
    EXPECT_NEAR(r.At("table.y", 0.5), 0.0, 1e-12);
    EXPECT_NEAR(r.Col("table.y").back(), 23.0, 1e-9);
  }
}

TEST(CombiTimeTable, ExtrapolationSmoothnessOffsetStartShiftAndScale) {
  const Rows table = {{0, 0}, {1, 0}, {1, 1}, {2, 4}, {3, 9}, {4, 16}};
  const RunResult hold = RunTimeTable({{"extrapolation", 1}}, table, 5.0, 0.5);
  EXPECT_NEAR(hold.Col("table.y").back(), 16.0, 1e-12);
  const RunResult periodic = RunTimeTable({{"extrapolation", 3}}, table, 6.0, 0.5);
  ASSERT_TRUE(periodic.report.ok()) << periodic.report.FullReport();
  EXPECT_NEAR(periodic.At("table.y", 4.5), 0.0, 1e-12);  // table(0.5)
  EXPECT_NEAR(periodic.At("table.y", 5.5), 2.5, 1e-12);  // table(1.5)
  EXPECT_NEAR(periodic.At("table.y", 6.0), 4.0, 1e-9);   // table(2)
  const RunResult constant = RunTimeTable({{"smoothness", 3}, {"extrapolation", 1}}, table, 5.0, 0.5);
  ASSERT_TRUE(constant.report.ok()) << constant.report.FullReport();
  EXPECT_DOUBLE_EQ(constant.At("table.y", 1.5), 1.0);
  EXPECT_DOUBLE_EQ(constant.At("table.y", 2.5), 4.0);
  EXPECT_DOUBLE_EQ(constant.At("table.y", 4.5), 16.0);
  // offset for time < startTime; then the table shifted by shiftTime (default startTime) and
  // stretched by timeScale.
  const RunResult shifted =
      RunTimeTable({{"offset", 1}, {"startTime", 1}, {"timeScale", 2}}, table, 6.0, 0.5);
  ASSERT_TRUE(shifted.report.ok()) << shifted.report.FullReport();
  EXPECT_DOUBLE_EQ(shifted.At("table.y", 0.5), 1.0);
  EXPECT_NEAR(shifted.At("table.y", 5.0), 1 + 4.0, 1e-12);  // table((5 - 1)/2)
  EXPECT_NEAR(shifted.At("table.y", 6.0), 1 + 6.5, 1e-12);  // table(2.5)
  const RunResult early = RunTimeTable({{"startTime", 1}, {"shiftTime", 0}}, table, 2.5, 0.5);
  EXPECT_DOUBLE_EQ(early.At("table.y", 0.5), 0.0);
  EXPECT_NEAR(early.At("table.y", 2.5), 6.5, 1e-12);  // table(2.5), not shifted
}

// The example of the CombiTable1Ds documentation: table [0,0; 1,1; 2,4; 4,16]: y(1) = 1,
// y(1.5) = 2.5, y(2) = 4, y(-1) = -1 (LastTwoPoints); held and periodic too. Input u = t - 1.
TEST(CombiTable1Ds, ReproducesTheMslDocumentationExampleAndExtrapolations) {
  auto run = [](double extrapolation) {
    Network net;
    net.AddElement("Inertia", "mass", P({{"J", 1}}));
    net.AddElement("Ramp", "u", P({{"height", 6}, {"duration", 6}, {"offset", -1}}));
    net.AddElement("CombiTable1Ds", "table", P({{"extrapolation", extrapolation}},
                                                {{"table", {{0, 0}, {1, 1}, {2, 4}, {4, 16}}}}));
    net.Connect("u.y", "table.u");
    return Simulate(net, 6.0, 0.5);
  };
  const RunResult linear = run(2);
  ASSERT_TRUE(linear.report.ok()) << linear.report.FullReport();
  EXPECT_NEAR(linear.At("table.y", 0.0), -1.0, 1e-12);
  EXPECT_NEAR(linear.At("table.y", 2.0), 1.0, 1e-12);
  EXPECT_NEAR(linear.At("table.y", 2.5), 2.5, 1e-12);
  EXPECT_NEAR(linear.At("table.y", 3.0), 4.0, 1e-12);
  EXPECT_NEAR(linear.At("table.y", 6.0), 22.0, 1e-9);  // 16 + 6*(5 - 4)
  const RunResult hold = run(1);
  EXPECT_NEAR(hold.At("table.y", 0.0), 0.0, 1e-12);
  EXPECT_NEAR(hold.At("table.y", 6.0), 16.0, 1e-12);
  const RunResult periodic = run(3);
  EXPECT_NEAR(periodic.At("table.y", 6.0), 1.0, 1e-9);  // u = 5 -> 1
  EXPECT_NEAR(periodic.At("table.y", 0.0), 10.0, 1e-9);  // u = -1 -> 3
}

TEST(Blocks, GainAddAndIntegrator) {
  Network net;
  net.AddElement("Inertia", "mass", P({{"J", 1}}));
  net.AddElement("Ramp", "ramp", P({{"height", 2}, {"duration", 1}}));
  net.AddElement("Constant", "one", P({{"k", 1}}));
  net.AddElement("Gain", "gain", P({{"k", -3}}));
  net.AddElement("Add", "add", P({{"k1", 2}, {"k2", 0.5}}));
  net.AddElement("Integrator", "integral", P({{"k", 2}, {"y_start", 1}}));
  net.Connect("ramp.y", "gain.u");
  net.Connect("gain.y", "add.u1");
  net.Connect("one.y", "add.u2");
  net.Connect("ramp.y", "integral.u");
  const RunResult r = Simulate(net, 1.0, 0.1);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.Col("gain.y").back(), -6.0, 1e-12);
  EXPECT_NEAR(r.Col("add.y").back(), -12.0 + 0.5, 1e-12);
  EXPECT_NEAR(r.Col("integral.y").back(), 1 + 2 * 1.0, 1e-7);  // 1 + 2 * integral of 2t
}

TEST(Tables, RejectUnsupportedOptionsAndBadTables) {
  auto message = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "no exception";
  };
  const std::string smooth = message([] {
    RunTimeTable({{"smoothness", 2}}, {{0, 0}, {1, 1}}, 1, 0.1);
  });
  EXPECT_NE(smooth.find("element 'table' (CombiTimeTable): parameter 'smoothness' = 2 is not "
                        "supported"), std::string::npos) << smooth;
  const std::string triple = message([] {
    RunTimeTable({}, {{0, 0}, {1, 1}, {1, 2}, {1, 3}}, 1, 0.1);
  });
  EXPECT_NE(triple.find("more than twice"), std::string::npos) << triple;
  const std::string increasing = message([] {
    Network net;
    net.AddElement("Inertia", "mass", P({{"J", 1}}));
    net.AddElement("Constant", "u", P({{"k", 0}}));
    net.AddElement("CombiTable1Ds", "load", P({}, {{"table", {{0, 0}, {1, 1}, {1, 2}}}}));
    net.Connect("u.y", "load.u");
    Simulator s(net);
  });
  EXPECT_NE(increasing.find("element 'load' (CombiTable1Ds): table 'table' first column must be "
                            "strictly increasing (row 3)"), std::string::npos) << increasing;
  EXPECT_NE(message([] { RunTimeTable({}, {}, 1, 0.1); }).find("table 'table' is empty"),
            std::string::npos);
  const std::string gain = message([] {
    Network net;
    net.AddElement("Gain", "g");
  });
  EXPECT_NE(gain.find("element 'g' (Gain): parameter 'k'"), std::string::npos) << gain;
}

}  // namespace
}  // namespace highlift::sim
