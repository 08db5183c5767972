// Hydraulic components and the hydraulic PDU (sim/src/hydraulic_elements.cc,
// sim/src/hydraulic_pdu.cc): analytic steady states of the orifice, the cylinder and the motor,
// the PDU's speed step and one motor lost, the energy balance of a hydraulic drive, and the
// messages for bad parameters and ill-posed hydraulic nodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"
#include "hydraulic_pdu.h"

namespace highlift::sim {
namespace {

using Scalars = std::map<std::string, double>;

ElementParameters P(Scalars s) { return {std::move(s), {}}; }

struct RunResult {
  MemorySink sink;
  SimulationReport report;
  std::vector<double> Col(const std::string& name) const { return sink.Series(name); }
  double Last(const std::string& name) const { return sink.Series(name).back(); }
  /// Value of column `name` at the output row nearest to time t.
  double At(const std::string& name, double t) const {
    const auto& times = sink.times();
    std::size_t best = 0;
    for (std::size_t i = 0; i < times.size(); ++i)
      if (std::abs(times[i] - t) < std::abs(times[best] - t)) best = i;
    return sink.Series(name)[best];
  }
};

RunResult Simulate(const Network& net, double stop, double dt, bool energy = false, double rtol = 1e-7) {
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
  return "";
}

// Turbulent law: V = Cd*A*sqrt(2*dp/rho). Two equal orifices in series between 200 bar and
// 5 bar around a line volume: in the steady state the volume sits at the mean pressure and each
// orifice carries Cd*A*sqrt(2*(dp/2)/rho). The regularisation changes the flow by a relative
// 1/4*(dp_small/dp)^2 = 1e-8 here.
TEST(TurbulentResistance, SteadyFlowMatchesTurbulentLaw) {
  Network net;
  net.AddElement("PressureSource", "supply", P({{"p_supply", 200e5}}));
  net.AddElement("TurbulentResistance", "r1", P({{"A", 1e-6}}));
  net.AddElement("Volume", "line", P({{"V", 1e-5}}));
  net.AddElement("TurbulentResistance", "r2", P({{"A", 1e-6}}));
  net.AddElement("Tank", "tank", P({{"p_return", 5e5}}));
  net.Connect("supply.port", "r1.port_a");
  net.Connect("r1.port_b", "line.port");
  net.Connect("line.port", "r2.port_a");
  net.Connect("r2.port_b", "tank.port");
  const RunResult r = Simulate(net, 0.05, 1e-3);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double dp = (200e5 - 5e5) / 2;
  const double expected = 0.7 * 1e-6 * std::sqrt(2 * dp / 850.0);
  EXPECT_NEAR(r.Last("line.p"), (200e5 + 5e5) / 2, 1.0);
  EXPECT_NEAR(r.Last("r1.V_flow"), expected, 1e-6 * expected);
  EXPECT_NEAR(r.Last("r2.V_flow"), expected, 1e-6 * expected);
  EXPECT_NEAR(r.Last("supply.V_flow"), expected, 1e-6 * expected);  // delivered = consumed
  EXPECT_NEAR(r.Last("tank.V_flow"), -expected, 1e-6 * expected);
}

// Near zero pressure drop the regularised law is linear: V = Cd*A*sqrt(2/rho)*dp/sqrt(dp_small).
TEST(TurbulentResistance, RegularisedNearZeroIsLinear) {
  Network net;
  net.AddElement("PressureSource", "supply", P({{"p_supply", 5e5 + 100}}));
  net.AddElement("TurbulentResistance", "r1", P({{"A", 1e-6}}));
  net.AddElement("Volume", "line", P({{"V", 1e-7}, {"p_start", 5e5 + 50}}));
  net.AddElement("TurbulentResistance", "r2", P({{"A", 1e-6}}));
  net.AddElement("Tank", "tank", P({{"p_return", 5e5}}));
  net.Connect("supply.port", "r1.port_a");
  net.Connect("r1.port_b", "line.port");
  net.Connect("line.port", "r2.port_a");
  net.Connect("r2.port_b", "tank.port");
  const RunResult r = Simulate(net, 1e-3, 1e-4);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double dp = 50.0, k = 0.7 * 1e-6 * std::sqrt(2 / 850.0);
  const double linear = k * dp / std::sqrt(1e4);
  EXPECT_NEAR(r.Last("r1.V_flow"), linear, 1e-4 * linear);  // (dp/dp_small)^2 = 2.5e-5
  EXPECT_NEAR(r.Last("r1.dp"), dp, 1e-6);
}

// Closed chambers: p(s) = p0 - E*ln(V(s)/V(s0)) per chamber, so the hydraulic spring has the
// stiffness k = E*A_A^2/V_A + E*A_B^2/V_B. A force step F on the damped rod moves it by F/k.
TEST(DifferentialCylinder, StiffnessFromBulkModulus) {
  Network net;
  net.AddElement("DifferentialCylinder", "cyl", P({{"s_start", 0.05}, {"d", 1.2e4}}));
  net.AddElement("Mass", "rod", P({{"m", 1.0}}));
  net.AddElement("TorqueStep", "force", P({{"stepTorque", 2000}, {"startTime", 0.02}}));
  net.Connect("cyl.flange", "rod.flange_a");
  net.Connect("force.flange", "rod.flange_b");
  const RunResult r = Simulate(net, 0.04, 1e-4);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double E = 1.2e9, A_A = 1e-3, A_B = 5e-4, V0 = 1e-5, s_max = 0.1;
  // Equilibrium before the step (the 1 bar start pushes with p0*(A_A - A_B)) from the exact law.
  auto net_force = [&](double s, double F) {
    const double pA = 1e5 - E * std::log((V0 + A_A * s) / (V0 + A_A * 0.05));
    const double pB = 1e5 - E * std::log((V0 + A_B * (s_max - s)) / (V0 + A_B * (s_max - 0.05)));
    return pA * A_A - pB * A_B + F;
  };
  auto equilibrium = [&](double F) {
    double lo = 0.04, hi = 0.06;
    for (int i = 0; i < 200; ++i) ((net_force(0.5 * (lo + hi), F) > 0) ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  };
  const double s1 = r.At("cyl.s", 0.0199), s2 = r.Last("cyl.s");
  EXPECT_NEAR(s1, equilibrium(0.0), 1e-9);
  EXPECT_NEAR(s2, equilibrium(2000.0), 1e-9);
  const double V_A = V0 + A_A * 0.05, V_B = V0 + A_B * 0.05;
  const double k = E * A_A * A_A / V_A + E * A_B * A_B / V_B;  // 2.857e7 N/m
  EXPECT_NEAR(2000.0 / (s2 - s1), k, 2e-3 * k);
  EXPECT_NEAR(r.Last("cyl.f"), -2000.0, 1e-3);  // the cylinder holds the load
}

// A mass on the closed chambers of an undamped cylinder oscillates at w_n = sqrt(k/m) with the
// hydraulic stiffness k = E*(A_A^2/V_A + A_B^2/V_B): 1690 rad/s (269 Hz) for 10 kg on the
// default cylinder at mid-stroke. The 1-bar start pushes with p0*(A_A - A_B) = 50 N, a 1.8 um
// oscillation about the equilibrium, where the chamber laws are linear within 1e-6.
TEST(DifferentialCylinder, MassOscillatesAtTheHydraulicNaturalFrequency) {
  Network net;
  net.AddElement("DifferentialCylinder", "cyl", P({{"s_start", 0.05}, {"d", 0.0}}));
  net.AddElement("Mass", "rod", P({{"m", 10.0}}));
  net.Connect("cyl.flange", "rod.flange_a");
  const RunResult r = Simulate(net, 0.04, 2e-6, false, 1e-9);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double E = 1.2e9, A_A = 1e-3, A_B = 5e-4, V0 = 1e-5;
  const double V_A = V0 + A_A * 0.05, V_B = V0 + A_B * 0.05;
  const double k = E * (A_A * A_A / V_A + A_B * A_B / V_B);
  const double w_n = std::sqrt(k / 10.0);
  // Downward zero crossings of the velocity, interpolated between output rows.
  const auto v = r.Col("cyl.v");
  const auto& t = r.sink.times();
  std::vector<double> crossings;
  for (std::size_t i = 1; i < t.size(); ++i)
    if (v[i - 1] > 0 && v[i] <= 0) crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * v[i - 1] / (v[i - 1] - v[i]));
  ASSERT_GE(crossings.size(), 8u);
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  EXPECT_NEAR(2 * std::numbers::pi / period, w_n, 1e-4 * w_n);
  // Amplitude of the velocity: w_n * (50 N / k), undamped.
  double v_max = 0;
  for (double x : v) v_max = std::max(v_max, std::abs(x));
  EXPECT_NEAR(v_max, w_n * 1e5 * (A_A - A_B) / k, 1e-3 * v_max);
}

// A motor at displacement eps fed through an orifice, driving a damped inertia: in the steady
// state w = (V_flow - G_leak*dp)/(eps*D_max) and eta_m*eps*D_max*dp = d*w.
TEST(VariableDisplacementMotor, SpeedFromDisplacementAndFlow) {
  Network net;
  net.AddElement("PressureSource", "supply", P({{"p_supply", 200e5}}));
  net.AddElement("TurbulentResistance", "line", P({{"A", 2e-6}}));
  net.AddElement("Volume", "inlet", P({{"V", 1e-5}}));
  net.AddElement("VariableDisplacementMotor", "motor", P({{"D_max", 1e-6}, {"G_leak", 1e-12}}));
  net.AddElement("Tank", "tank");
  net.AddElement("Constant", "swash", P({{"k", 0.5}}));
  net.AddElement("Inertia", "rotor", P({{"J", 1e-3}}));
  net.AddElement("Damper", "load", P({{"d", 0.01}}));
  net.AddElement("Fixed", "ground");
  net.Connect("supply.port", "line.port_a");
  net.Connect("line.port_b", "inlet.port");
  net.Connect("inlet.port", "motor.port_A");
  net.Connect("motor.port_B", "tank.port");
  net.Connect("swash.y", "motor.eps");
  net.Connect("motor.flange", "rotor.flange_a");
  net.Connect("rotor.flange_b", "load.flange_a");
  net.Connect("load.flange_b", "ground.flange");
  const RunResult r = Simulate(net, 3.0, 1e-2);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double q = r.Last("line.V_flow"), dp = r.Last("motor.dp"), w = r.Last("rotor.w");
  EXPECT_GT(w, 100.0);
  // The steady state solved on its own: with the inlet pressure p, dp = p - p_r, the motor
  // speed w = eta_m*eps*D_max*dp/d (torque balance), and the line delivers what the motor takes:
  // Cd*A*sqrt(2*(p_s - p)/rho) = eps*D_max*w + G_leak*dp (regularisation: relative 1e-8 here).
  const double p_s = 200e5, p_r = 5e5, k_line = 0.7 * 2e-6 * std::sqrt(2 / 850.0);
  auto speed = [&](double p) { return 0.95 * 0.5 * 1e-6 * (p - p_r) / 0.01; };
  auto excess = [&](double p) { return k_line * std::sqrt(p_s - p) - 0.5 * 1e-6 * speed(p) - 1e-12 * (p - p_r); };
  double lo = p_r, hi = p_s;
  for (int i = 0; i < 200; ++i) (excess(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double w_analytic = speed(0.5 * (lo + hi));
  EXPECT_NEAR(w, w_analytic, 1e-5 * w_analytic);
  EXPECT_NEAR(w, (q - 1e-12 * dp) / (0.5 * 1e-6), 1e-5 * w);
  EXPECT_NEAR(0.95 * 0.5 * 1e-6 * dp, 0.01 * w, 1e-5 * 0.01 * w);
  EXPECT_NEAR(r.Last("motor.tau"), 0.01 * w, 1e-5 * 0.01 * w);
}

// A servo valve with every port on a fixed pressure (P 200 bar, T 5 bar, A 100 bar, B 50 bar):
// each edge carries the turbulent flow of its opening, V = Cd*A_max*(max(+-x, 0) + leakage)*
// sqrt(2*dp/rho) (the regularisation changes it by a relative (dp_small/dp)^2/4 < 2e-6).
Network ValveOnFixedPressures(const Scalars& valve, const std::string& command, const Scalars& command_parameters) {
  Network net;
  net.AddElement("PressureSource", "supply", P({{"p_supply", 200e5}}));
  net.AddElement("Tank", "tank", P({{"p_return", 5e5}}));
  net.AddElement("PressureSource", "load_a", P({{"p_supply", 100e5}}));
  net.AddElement("PressureSource", "load_b", P({{"p_supply", 50e5}}));
  net.AddElement("ServoValve", "valve", P(valve));
  net.AddElement(command, "command", P(command_parameters));
  net.Connect("supply.port", "valve.port_P");
  net.Connect("valve.port_T", "tank.port");
  net.Connect("valve.port_A", "load_a.port");
  net.Connect("valve.port_B", "load_b.port");
  net.Connect("command.y", "valve.u");
  // A state for the integrator when the valve has none (order 0).
  net.AddElement("Integrator", "clock", P({}));
  net.AddElement("Constant", "one", P({{"k", 1.0}}));
  net.Connect("one.y", "clock.u");
  return net;
}

struct EdgeFlows {
  double PA, PB, AT, BT;
};

/// The four edge flows of ValveOnFixedPressures at spool position x (A_max 2e-6 m^2).
EdgeFlows ExpectedEdgeFlows(double x, double leakage) {
  const double k = 0.7 * 2e-6 * std::sqrt(2 / 850.0);
  const double open_pos = std::max(std::min(x, 1.0), 0.0) + leakage;
  const double open_neg = std::max(std::min(-x, 1.0), 0.0) + leakage;
  return {k * open_pos * std::sqrt(100e5), k * open_neg * std::sqrt(150e5), k * open_neg * std::sqrt(95e5),
          k * open_pos * std::sqrt(45e5)};
}

void ExpectEdgeFlows(const RunResult& r, std::size_t row, double x, double leakage) {
  const EdgeFlows f = ExpectedEdgeFlows(x, leakage);
  const double scale = 1e-5 * ExpectedEdgeFlows(1.0, 0.0).PA;
  const double t = r.sink.times()[row];
  EXPECT_NEAR(r.Col("valve.V_PA")[row], f.PA, scale) << "t = " << t;
  EXPECT_NEAR(r.Col("valve.V_PB")[row], f.PB, scale) << "t = " << t;
  EXPECT_NEAR(r.Col("valve.V_AT")[row], f.AT, scale) << "t = " << t;
  EXPECT_NEAR(r.Col("valve.V_BT")[row], f.BT, scale) << "t = " << t;
}

// order 0: the command is the spool position, limited to +-1 (full stroke). A ramp of the
// command from -1.5 to 1.5 passes through both end stops, both flow directions and the centre.
TEST(ServoValve, SpoolPositionAsInputGivesTheTurbulentEdgeFlows) {
  const RunResult r = Simulate(
      ValveOnFixedPressures({{"order", 0}, {"leakage", 1e-3}}, "Ramp",
                            {{"height", 3.0}, {"duration", 1.0}, {"offset", -1.5}, {"startTime", 0.0}}),
      1.0, 0.05);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto& t = r.sink.times();
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double x = std::max(-1.0, std::min(1.0, -1.5 + 3.0 * t[i]));
    EXPECT_NEAR(r.Col("valve.x")[i], x, 1e-12) << "t = " << t[i];
    EXPECT_EQ(r.Col("valve.v_x")[i], 0.0);
    ExpectEdgeFlows(r, i, x, 1e-3);
  }
}

// order 1: after a command step 0 -> 0.8 at t0 the spool follows x = 0.8*(1 - exp(-(t - t0)/T_v)).
TEST(ServoValve, FirstOrderSpoolFollowsTheExponential) {
  const double T_v = 0.004, t0 = 0.01;
  const RunResult r = Simulate(ValveOnFixedPressures({{"order", 1}, {"T_v", T_v}, {"leakage", 0.0}}, "Step",
                                                     {{"height", 0.8}, {"startTime", t0}}),
                               0.04, 1e-4, false, 1e-9);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto& t = r.sink.times();
  int checked = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double x = t[i] <= t0 ? 0.0 : 0.8 * (1 - std::exp(-(t[i] - t0) / T_v));
    EXPECT_NEAR(r.Col("valve.x")[i], x, 1e-6) << "t = " << t[i];
    if (t[i] > t0) {
      EXPECT_NEAR(r.Col("valve.v_x")[i], (0.8 - x) / T_v, 1e-6 / T_v) << "t = " << t[i];
    }
    ExpectEdgeFlows(r, i, r.Col("valve.x")[i], 0.0);
    checked += t[i] > t0;
  }
  EXPECT_GT(checked, 100);
  EXPECT_NEAR(r.At("valve.x", t0 + T_v), 0.8 * (1 - std::exp(-1.0)), 1e-6);  // 63 % after T_v
}

// order 2: after a command step 0 -> 0.9 at t0 the spool is the damped oscillator
//   x = 0.9*(1 - exp(-D_v*w_v*s)*(cos(w_d*s) + D_v/sqrt(1 - D_v^2)*sin(w_d*s))),  s = t - t0,
// w_d = w_v*sqrt(1 - D_v^2). With D_v = 0.3 it overshoots full stroke (peak 0.9*(1 + 0.372) at
// s = pi/w_d); the edges then open no further than A_max.
TEST(ServoValve, SecondOrderSpoolIsTheDampedOscillatorAndOpensAtMostFully) {
  const double w_v = 280.0, D_v = 0.3, t0 = 0.01;
  const RunResult r =
      Simulate(ValveOnFixedPressures({{"order", 2}, {"w_v", w_v}, {"D_v", D_v}, {"leakage", 0.0}}, "Step",
                                     {{"height", 0.9}, {"startTime", t0}}),
               0.06, 5e-5, false, 1e-9);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const double root = std::sqrt(1 - D_v * D_v), w_d = w_v * root;
  auto x_of = [&](double t) {
    if (t <= t0) return 0.0;
    const double s = t - t0;
    return 0.9 * (1 - std::exp(-D_v * w_v * s) * (std::cos(w_d * s) + D_v / root * std::sin(w_d * s)));
  };
  auto v_of = [&](double t) {
    if (t <= t0) return 0.0;
    const double s = t - t0;
    return 0.9 * w_v / root * std::exp(-D_v * w_v * s) * std::sin(w_d * s);
  };
  const auto& t = r.sink.times();
  double x_max = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(r.Col("valve.x")[i], x_of(t[i]), 1e-6) << "t = " << t[i];
    EXPECT_NEAR(r.Col("valve.v_x")[i], v_of(t[i]), 1e-6 * w_v) << "t = " << t[i];
    ExpectEdgeFlows(r, i, r.Col("valve.x")[i], 0.0);
    x_max = std::max(x_max, r.Col("valve.x")[i]);
  }
  const double peak = 0.9 * (1 + std::exp(-std::numbers::pi * D_v / root));
  EXPECT_NEAR(x_max, peak, 1e-3);  // the output row nearest the peak time
  EXPECT_GT(x_max, 1.2);
  const std::size_t at_peak = std::min_element(t.begin(), t.end(), [&](double a, double b) {
                                return std::abs(a - t0 - std::numbers::pi / w_d) < std::abs(b - t0 - std::numbers::pi / w_d);
                              }) - t.begin();
  EXPECT_NEAR(r.Col("valve.V_PA")[at_peak], ExpectedEdgeFlows(1.0, 0.0).PA, 1e-5 * ExpectedEdgeFlows(1.0, 0.0).PA);
}

TEST(ServoValve, BadSpoolSettingsAreRejectedWithMessages) {
  auto message_of = [](const Scalars& valve) {
    return ErrorOf([&] {
      Network net = ValveOnFixedPressures(valve, "Constant", {{"k", 0.0}});
      Simulator sim(net);
    });
  };
  const std::string half = message_of({{"order", 1.5}});
  EXPECT_NE(half.find("element 'valve' (ServoValve): parameter 'order' = 1.5 is not a spool model"), std::string::npos)
      << half;
  EXPECT_NE(half.find("use 0 (the command u is the spool position), 1 (first-order spool, T_v) or 2"),
            std::string::npos)
      << half;
  const std::string three = message_of({{"order", 3}});
  EXPECT_NE(three.find("element 'valve' (ServoValve): parameter 'order' = 3"), std::string::npos) << three;
  EXPECT_NE(three.find("outside its valid range"), std::string::npos) << three;
  const std::string frequency = message_of({{"order", 2}, {"w_v", 0.0}});
  EXPECT_NE(frequency.find("parameter 'w_v' = 0"), std::string::npos) << frequency;
  const std::string damping = message_of({{"order", 2}, {"D_v", -0.1}});
  EXPECT_NE(damping.find("parameter 'D_v' = -0.1"), std::string::npos) << damping;
}

// Energy balance of a valve-controlled motor drive (servo valve opening, motor accelerating a
// load, then reversing): supply work = kinetic + stored (oil, springs) + losses.
TEST(HydraulicDrive, EnergyBalances) {
  Network net;
  net.AddElement("PressureSource", "supply", P({{"p_supply", 207e5}}));
  net.AddElement("TurbulentResistance", "line", P({{"A", 2e-5}}));
  net.AddElement("Volume", "p_line", P({{"V", 2e-5}, {"p_start", 207e5}}));
  net.AddElement("ServoValve", "valve", P({{"A_max", 5e-6}}));
  net.AddElement("Volume", "a_line", P({{"V", 1e-5}}));
  net.AddElement("Volume", "b_line", P({{"V", 1e-5}}));
  net.AddElement("Tank", "tank");
  net.AddElement("Sine", "command", P({{"amplitude", 1.0}, {"f", 2.0}}));
  net.AddElement("VariableDisplacementMotor", "motor", P({}));
  net.AddElement("Constant", "swash", P({{"k", 1.0}}));
  net.AddElement("Inertia", "rotor", P({{"J", 0.01}}));
  net.AddElement("SpringDamper", "load", P({{"c", 50}, {"d", 0.02}}));
  net.AddElement("Fixed", "ground");
  net.Connect("supply.port", "line.port_a");
  net.Connect("line.port_b", "p_line.port");
  net.Connect("p_line.port", "valve.port_P");
  net.Connect("valve.port_T", "tank.port");
  net.Connect("valve.port_A", "a_line.port");
  net.Connect("valve.port_B", "b_line.port");
  net.Connect("a_line.port", "motor.port_A");
  net.Connect("b_line.port", "motor.port_B");
  net.Connect("command.y", "valve.u");
  net.Connect("swash.y", "motor.eps");
  net.Connect("motor.flange", "rotor.flange_a");
  net.Connect("rotor.flange_b", "load.flange_a");
  net.Connect("load.flange_b", "ground.flange");
  const RunResult r = Simulate(net, 0.5, 1e-4, true, 1e-8);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const EnergyBalance& e = r.report.energy;
  ASSERT_TRUE(e.computed);
  EXPECT_GT(e.source_work, 10.0);
  EXPECT_GT(e.dissipated, 1.0);
  EXPECT_LT(std::abs(e.Residual()), 1e-3 * e.Scale())
      << "source " << e.source_work << " dissipated " << e.dissipated << " kinetic "
      << e.kinetic_end - e.kinetic_start << " potential " << e.potential_end - e.potential_start;
}

// The cylinder's chambers store V*p^2/(2E); the work of the linear law with a varying volume
// is reported as the cylinder's source power, so a cylinder stroked by a valve balances too.
TEST(DifferentialCylinder, EnergyBalancesWhenStroked) {
  Network net;
  net.AddElement("PressureSource", "supply", P({{"p_supply", 345e5}}));
  net.AddElement("ServoValve", "valve", P({{"A_max", 1e-6}}));
  net.AddElement("Tank", "tank");
  net.AddElement("Sine", "command", P({{"amplitude", 0.5}, {"f", 5.0}}));
  net.AddElement("DifferentialCylinder", "cyl",
                 P({{"A_A", 1e-4}, {"A_B", 5e-5}, {"s_max", 0.02}, {"V0_A", 1e-6}, {"V0_B", 1e-6},
                    {"s_start", 0.01}}));
  net.AddElement("Mass", "rod", P({{"m", 0.1}}));
  net.Connect("supply.port", "valve.port_P");
  net.Connect("valve.port_T", "tank.port");
  net.Connect("valve.port_A", "cyl.port_A");
  net.Connect("valve.port_B", "cyl.port_B");
  net.Connect("command.y", "valve.u");
  net.Connect("cyl.flange", "rod.flange_a");
  const RunResult r = Simulate(net, 0.3, 1e-4, true, 1e-8);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const EnergyBalance& e = r.report.energy;
  EXPECT_GT(e.dissipated, 0.1);
  EXPECT_LT(std::abs(e.Residual()), 1e-3 * e.Scale()) << "residual " << e.Residual();
}

TEST(Hydraulics, NodeWithoutVolumeIsRejectedByName) {
  Network net;
  net.AddElement("PressureSource", "supply");
  net.AddElement("TurbulentResistance", "r1");
  net.AddElement("TurbulentResistance", "r2");
  net.AddElement("Tank", "tank");
  net.Connect("supply.port", "r1.port_a");
  net.Connect("r1.port_b", "r2.port_a");
  net.Connect("r2.port_b", "tank.port");
  const std::string message = ErrorOf([&] { Simulator sim(net); });
  EXPECT_NE(message.find("r1.port_b, r2.port_a"), std::string::npos) << message;
  EXPECT_NE(message.find("no volume and no source"), std::string::npos) << message;
  EXPECT_NE(message.find("connect a Volume"), std::string::npos) << message;
}

TEST(Hydraulics, TwoSourcesOnOneNodeAreRejected) {
  Network net;
  net.AddElement("PressureSource", "supply");
  net.AddElement("Tank", "tank");
  net.Connect("supply.port", "tank.port");
  const std::string message = ErrorOf([&] { Simulator sim(net); });
  EXPECT_NE(message.find("two pressure sources, 'supply' and 'tank'"), std::string::npos) << message;
}

TEST(Hydraulics, HydraulicPortCannotJoinFlange) {
  Network net;
  net.AddElement("Tank", "tank");
  net.AddElement("Inertia", "rotor", P({{"J", 1}}));
  const std::string message = ErrorOf([&] { net.Connect("tank.port", "rotor.flange_a"); });
  EXPECT_NE(message.find("a hydraulic port cannot be connected to a flange port"), std::string::npos)
      << message;
}

TEST(Hydraulics, BadParametersAreRejectedWithMessages) {
  {
    Network net;
    const std::string message =
        ErrorOf([&] { net.AddElement("TurbulentResistance", "orifice", P({{"A", -1e-6}})); });
    EXPECT_NE(message.find("orifice"), std::string::npos) << message;
    EXPECT_NE(message.find("'A'"), std::string::npos) << message;
  }
  {
    Network net;
    const std::string message = ErrorOf([&] { net.AddElement("Volume", "line", P({{"V", 0.0}})); });
    EXPECT_NE(message.find("'V'"), std::string::npos) << message;
  }
  {
    Network net;
    const std::string message =
        ErrorOf([&] { net.AddElement("VariableDisplacementMotor", "motor", P({{"eta_m", 1.2}})); });
    EXPECT_NE(message.find("'eta_m'"), std::string::npos) << message;
  }
  {
    Network net;
    net.AddElement("DifferentialCylinder", "cyl", P({{"s_start", 0.2}}));
    net.AddElement("Mass", "rod", P({{"m", 1}}));
    net.Connect("cyl.flange", "rod.flange_a");
    const std::string message = ErrorOf([&] { Simulator sim(net); });
    EXPECT_NE(message.find("element 'cyl' (DifferentialCylinder): parameter 's_start' = 0.2"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("outside the stroke"), std::string::npos) << message;
  }
  {
    Network net;
    net.AddElement("ServoValve", "valve", P({{"leakage", 2.0}}));
    net.AddElement("Constant", "u", P({{"k", 0}}));
    net.Connect("u.y", "valve.u");
    const std::string message = ErrorOf([&] { Simulator sim(net); });
    EXPECT_NE(message.find("element 'valve' (ServoValve): parameter 'leakage' = 2"), std::string::npos)
        << message;
  }
}

// A PDU with the A380-class numbers (345 bar) driving both wings: each wing a root shaft
// (1900 N*m/rad) to an inertia carrying 360 N*m of opposing airload (domain.md s3).
Component HydraulicPduComponent() {
  Component pdu;
  pdu.id = "pdu";
  pdu.type = "pdu";
  pdu.texts["drive"] = "hydraulic";
  pdu.parameters["supply_pressure"].nominal = 345e5;
  return pdu;
}

Network PduRig(const Component& pdu, double w_step, double t_step,
               std::optional<double> motor_lost_time = std::nullopt) {
  Network net;
  const detail::PduPorts ports = detail::AddHydraulicPdu(net, pdu, motor_lost_time);
  net.AddElement("Step", "command", P({{"height", w_step}, {"startTime", t_step}}));
  net.Connect("command.y", ports.w_ref);
  net.AddElement("Fixed", "ground");
  for (const std::string side : {"left", "right"}) {
    // Wing: shaft stiffness to the lumped wing inertia, which carries the opposing airload
    // (applied with the command, so the drive holds it from standstill).
    net.AddElement("SpringDamper", "shaft_" + side, P({{"c", 1900}, {"d", 2}}));
    net.AddElement("Inertia", "wing_" + side, P({{"J", 0.15}}));
    net.AddElement("TorqueStep", "airload_" + side, P({{"stepTorque", -360}, {"startTime", t_step}}));
    net.Connect(side == "left" ? ports.flange_left : ports.flange_right, "shaft_" + side + ".flange_a");
    net.Connect("shaft_" + side + ".flange_b", "wing_" + side + ".flange_a");
    net.Connect("wing_" + side + ".flange_b", "airload_" + side + ".flange");
  }
  return net;
}

// Stated response: after a step of the command from 0 to w_max = 25.3 rad/s the output speed is
// within 2 % of it 0.6 s later and stays there, against 720 N*m of airload applied with the
// step (back-driven at first: the worst case; the scenarios ramp the command over 0.4 s).
TEST(HydraulicPdu, FollowsSpeedStepWithinStatedTime) {
  const Component pdu = HydraulicPduComponent();
  ASSERT_TRUE(detail::IsHydraulicPdu(pdu));
  const RunResult r = Simulate(PduRig(pdu, 25.3, 0.05), 1.0, 1e-3, false, 1e-6);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  const auto w = r.Col("pdu.w");
  const auto& t = r.sink.times();
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < 0.05) {
      EXPECT_NEAR(w[i], 0.0, 0.01) << "t = " << t[i];  // settling of the 1-bar start
    }
    if (t[i] >= 0.65) {
      EXPECT_NEAR(w[i], 25.3, 0.02 * 25.3) << "t = " << t[i];
    }
  }
  EXPECT_NEAR(w.back(), 25.3, 1e-3 * 25.3);  // the integral action removes the load error
  // Torque at the output: both wings' airload, through the motors at a part displacement.
  EXPECT_NEAR(r.Last("shaft_left.tau") + r.Last("shaft_right.tau"), -720.0, 2.0);  // MSL flange_b.tau
  const double eps = r.Last("pdu.motor1.eps");
  EXPECT_GT(eps, 0.3);
  EXPECT_LT(eps, 1.0);
  EXPECT_NEAR(r.Last("pdu.motor1.w"), 20 * 25.3, 0.01 * 20 * 25.3);
}

// One motor lost: its displacement goes to 0 and its pressure-off brake holds it; the remaining
// motor keeps its speed, so the differential delivers half the output speed at the same torque.
TEST(HydraulicPdu, OneMotorLostGivesHalfSpeed) {
  const Component pdu = HydraulicPduComponent();
  const RunResult r = Simulate(PduRig(pdu, 25.3, 0.05, 0.8), 1.6, 1e-3, false, 1e-6);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.At("pdu.w", 0.75), 25.3, 0.01 * 25.3);
  EXPECT_NEAR(r.Last("pdu.w"), 25.3 / 2, 0.02 * 25.3 / 2);
  EXPECT_NEAR(r.Last("pdu.rotor2.w"), 0.0, 1e-3);
  EXPECT_NEAR(r.Last("pdu.motor1.w"), 20 * 25.3, 0.02 * 20 * 25.3);
  // The same airload: the remaining motor delivers the torque it delivered before (the
  // differential splits the output torque equally) and the brake reacts the lost motor's half.
  const double before = r.At("pdu.motor1.tau", 0.75);
  EXPECT_NEAR(r.Last("pdu.motor1.tau"), before, 0.03 * before);
  EXPECT_NEAR(std::abs(r.Last("pdu.pob2.tau")), before, 0.03 * before);  // ideal differential
}

TEST(HydraulicPdu, FullTorqueWithOneMotor) {
  // Stall: a stiff load and a large command; with one motor braked the remaining motor at full
  // displacement holds the same output torque as two motors (the differential halves speed,
  // not torque).
  auto stall_torque = [](bool lost) {
    const Component pdu = HydraulicPduComponent();
    Network net;
    const detail::PduPorts ports =
        detail::AddHydraulicPdu(net, pdu, lost ? std::optional<double>(0.0) : std::nullopt);
    net.AddElement("Constant", "command", P({{"k", 25.3}}));
    net.Connect("command.y", ports.w_ref);
    net.AddElement("Fixed", "ground");
    net.AddElement("SpringDamper", "jam", P({{"c", 2e4}, {"d", 500}}));
    net.Connect(ports.flange_left, "jam.flange_a");
    net.Connect("jam.flange_b", "ground.flange");
    const RunResult r = Simulate(net, 0.6, 1e-2, false, 1e-6);
    EXPECT_TRUE(r.report.ok()) << r.report.FullReport();
    return -r.Last("jam.tau");
  };
  const double both = stall_torque(false), one = stall_torque(true);
  EXPECT_NEAR(both, 1000.0, 50.0);  // sized from stall_torque = 1000 N*m
  EXPECT_NEAR(one, both, 0.02 * both);
}

// The drive network of a drive-system project hands a scenario's `motor_lost_time` to the
// hydraulic PDU (as to the speed-controlled one): the last motor's `active` steps to 0 and its
// pressure-off brake is applied at that time; without the value every motor runs throughout.
TEST(HydraulicPdu, DriveNetworkTakesMotorLostTimeFromTheScenario) {
  const Project project = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/hydraulic_pdu_flaps.json");
  const Scenario* extension = project.FindScenario("extension");
  ASSERT_NE(extension, nullptr);
  Scenario lost = *extension;
  lost.name = "one_motor_lost";
  lost.values["motor_lost_time"] = 2.5;
  DriveNetworkOptions options;
  options.resolution = DriveResolution::kReduced;
  const DriveModel with = BuildDriveNetwork(project, &lost, options);
  const NetworkElement* step = with.network.Find("pdu.motor_lost");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->type, "Step");
  EXPECT_EQ(step->parameters.scalars.at("startTime"), 2.5);
  EXPECT_EQ(step->parameters.scalars.at("height"), -1.0);
  // The lost motor's operation is 1 before the loss (and before a shutdown): a product of the
  // step and the shutdown's "running"; its pressure-off brake is commanded 1 - active.
  const NetworkElement* active = with.network.Find("pdu.active2");
  ASSERT_NE(active, nullptr);
  EXPECT_EQ(active->type, "Product");
  const NetworkElement* brake_command = with.network.Find("pdu.pob_command2");
  ASSERT_NE(brake_command, nullptr);
  EXPECT_EQ(brake_command->type, "Add");
  ASSERT_NE(with.network.Find("pdu.pob2"), nullptr);
  EXPECT_EQ(with.component_of.at("pdu.motor_lost"), "pdu");

  const DriveModel without = BuildDriveNetwork(project, extension, options);
  EXPECT_EQ(without.network.Find("pdu.motor_lost"), nullptr);
  EXPECT_EQ(without.network.Find("pdu.active2"), nullptr);
  ASSERT_NE(without.network.Find("pdu.valve2"), nullptr);
  // The example has wing-tip brakes: the monitor's command shuts the PDU down (both motors'
  // pressure-off brakes, displacement to 0).
  ASSERT_NE(without.network.Find("pdu.pob1"), nullptr);
  ASSERT_NE(without.network.Find("pdu.pob2"), nullptr);
  bool connected = false;
  for (const auto& c : without.network.connections())
    connected = connected || (c.a.ToString() == "monitor.wtb" && c.b.ToString() == "pdu.stop.u") ||
                (c.b.ToString() == "monitor.wtb" && c.a.ToString() == "pdu.stop.u");
  EXPECT_TRUE(connected);
}

// After a rupture the monitor applies the wing-tip brakes and shuts the hydraulic PDU down: its
// pressure-off brakes stop the healthy side without driving it into its wing-tip brake, and the
// largest torque on the ruptured side is at its WTB.
TEST(HydraulicPdu, ShutsDownWithTheWingTipBrakesAfterARupture) {
  const Project project = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/hydraulic_pdu_flaps.json");
  const Scenario& scenario = *project.FindScenario("rupture_wtb");
  DriveNetworkOptions options;
  const DriveModel model = BuildDriveNetwork(project, &scenario, options);
  Simulator simulator(model.network);
  MemorySink sink;
  DerivedColumnSink derived(model.derived, sink);
  const SimulationReport report = simulator.Run(model.Options(project), derived);
  ASSERT_TRUE(report.ok()) << report.FullReport();
  double wtb = 0, stl_right = 0, shaft_l6 = 0;
  for (const auto& p : ComponentPeakTorques(model, project, report)) {
    if (p.element == "wtb_left") wtb = std::abs(p.tau);
    if (p.element == "stl_right") stl_right = std::abs(p.tau);
    if (p.element == "shaft_l6") shaft_l6 = std::abs(p.tau);
  }
  EXPECT_GT(wtb, 200.0);
  EXPECT_GT(wtb, shaft_l6);
  EXPECT_LT(stl_right, 470.0) << "the healthy side is not driven into its brake";
  const int w = sink.Column("pdu.w");
  ASSERT_GE(w, 0);
  EXPECT_LT(std::abs(sink.rows().back()[w]), 1e-3) << "held by the pressure-off brakes";
}

TEST(HydraulicPdu, BadSettingsAreRejected) {
  Component pdu = HydraulicPduComponent();
  pdu.texts["drive"] = "hydrolic";
  EXPECT_NE(ErrorOf([&] { detail::IsHydraulicPdu(pdu); })
                .find("component 'pdu' (pdu): parameter 'drive' = \"hydrolic\" is not a drive kind"),
            std::string::npos);
  pdu = HydraulicPduComponent();
  pdu.parameters.erase("supply_pressure");
  Network net;
  EXPECT_NE(ErrorOf([&] { detail::AddHydraulicPdu(net, pdu); })
                .find("needs parameter 'supply_pressure'; give the aircraft system pressure"),
            std::string::npos);
  pdu = HydraulicPduComponent();
  pdu.parameters["motor_count"].nominal = 3;
  Network net3;
  EXPECT_NE(ErrorOf([&] { detail::AddHydraulicPdu(net3, pdu); }).find("'motor_count' = 3"),
            std::string::npos);
  Network net4;
  EXPECT_NE(ErrorOf([&] { detail::AddHydraulicPdu(net4, HydraulicPduComponent(), NAN); })
                .find("component 'pdu' (pdu): scenario value 'motor_lost_time' is not a finite time"),
            std::string::npos);
}

}  // namespace
}  // namespace highlift::sim
