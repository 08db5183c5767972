// Analytic checks of the further MSL elements (sim/src/msl_more_elements.cc, ElastoBacklash2):
// sensors of torque, power and acceleration, RelativeStates, the motion sources Position,
// Speed (exact and filtered), Accelerate, Move, ConstantSpeed, the translational elements
// with IdealGearR2T and IdealRollingWheel, and the tolerance scaling by nominal values.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

using Scalars = std::map<std::string, double>;
constexpr double kPi = std::numbers::pi;

ElementParameters P(Scalars s) { return {std::move(s), {}}; }

struct Result {
  MemorySink sink;
  SimulationReport report;
  std::vector<double> Col(const std::string& name) const { return sink.Series(name); }
  const std::vector<double>& t() const { return sink.times(); }
  /// Largest |column - f(t)| over the rows.
  double Error(const std::string& column, const std::function<double(double)>& f) const {
    const auto v = Col(column);
    double worst = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) worst = std::max(worst, std::abs(v[i] - f(t()[i])));
    return worst;
  }
};

/// The independent reference: classical Runge-Kutta of x' = f(t, x) from t to t_end in steps of
/// at most h.
template <std::size_t N, class F>
void RungeKutta(const F& f, std::array<double, N>& x, double& t, double t_end, double h) {
  using State = std::array<double, N>;
  auto axpy = [](const State& a, double c, const State& b) {
    State r;
    for (std::size_t j = 0; j < N; ++j) r[j] = a[j] + c * b[j];
    return r;
  };
  while (t < t_end - 1e-12) {
    const double dt = std::min(h, t_end - t);
    const State k1 = f(t, x), k2 = f(t + dt / 2, axpy(x, dt / 2, k1)), k3 = f(t + dt / 2, axpy(x, dt / 2, k2)),
                k4 = f(t + dt, axpy(x, dt, k3));
    for (std::size_t j = 0; j < N; ++j) x[j] += dt / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    t += dt;
  }
}

Result Simulate(const Network& net, double stop, double rtol = 1e-9, double atol = 1e-11) {
  Result r;
  Simulator sim(net);
  SimulationOptions o;
  o.stop_time = stop;
  o.output_interval = stop / 200;
  o.relative_tolerance = rtol;
  o.absolute_tolerance = atol;
  r.report = sim.Run(o, r.sink);
  return r;
}

// Torque u = 2 on J1 = 1, rigidly through the sensors to J2 = 3: a = 0.5, the torque through
// is J2 * a = 1.5, the power 1.5 * 0.5 t.
Network SensorChain() {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "drive", P({{"tau_constant", 2}}));
  net.AddElement("Inertia", "inertia1", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("TorqueSensor", "torqueSensor");
  net.AddElement("PowerSensor", "powerSensor");
  net.AddElement("MultiSensor", "multiSensor");
  net.AddElement("Inertia", "inertia2", P({{"J", 3}}));
  net.AddElement("AccSensor", "accSensor");
  net.AddElement("RelAccSensor", "relAccSensor");
  net.AddElement("RelativeStates", "relativeStates");
  net.AddElement("Gain", "gain", P({{"k", 2}}));
  net.Connect("drive.flange", "inertia1.flange_a");
  net.Connect("drive.support", "fixed.flange");
  net.Connect("inertia1.flange_b", "torqueSensor.flange_a");
  net.Connect("torqueSensor.flange_b", "powerSensor.flange_a");
  net.Connect("powerSensor.flange_b", "multiSensor.flange_a");
  net.Connect("multiSensor.flange_b", "inertia2.flange_a");
  net.Connect("accSensor.flange", "inertia2.flange_b");
  net.Connect("relAccSensor.flange_a", "fixed.flange");
  net.Connect("relAccSensor.flange_b", "inertia2.flange_b");
  net.Connect("relativeStates.flange_a", "inertia1.flange_a");
  net.Connect("relativeStates.flange_b", "fixed.flange");
  net.Connect("torqueSensor.tau", "gain.u");  // a post-solve signal into a signal block
  return net;
}

TEST(Sensors, TorquePowerAccelerationAndRelativeStatesOfARigidChain) {
  const Result r = Simulate(SensorChain(), 1.0);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("torqueSensor.tau", [](double) { return 1.5; }), 1e-9);
  EXPECT_LT(r.Error("gain.y", [](double) { return 3.0; }), 1e-9);
  EXPECT_LT(r.Error("powerSensor.power", [](double t) { return 0.75 * t; }), 1e-8);
  EXPECT_LT(r.Error("multiSensor.tau", [](double) { return 1.5; }), 1e-9);
  EXPECT_LT(r.Error("multiSensor.w", [](double t) { return 0.5 * t; }), 1e-8);
  EXPECT_LT(r.Error("multiSensor.power", [](double t) { return 0.75 * t; }), 1e-8);
  EXPECT_LT(r.Error("accSensor.a", [](double) { return 0.5; }), 1e-9);
  EXPECT_LT(r.Error("relAccSensor.a_rel", [](double) { return 0.5; }), 1e-9);
  EXPECT_LT(r.Error("relativeStates.phi_rel", [](double t) { return -0.25 * t * t; }), 1e-8);
  EXPECT_LT(r.Error("relativeStates.w_rel", [](double t) { return -0.5 * t; }), 1e-8);
  EXPECT_LT(r.Error("relativeStates.a_rel", [](double) { return -0.5; }), 1e-9);
}

TEST(Sensors, SolvedTorqueIntoALawIsAnAlgebraicLoopNamedInTheMessage) {
  Network net = SensorChain();
  net.AddElement("Torque", "feedback");
  net.Connect("torqueSensor.tau", "feedback.tau");
  net.Connect("feedback.flange", "inertia2.flange_b");
  try {
    Simulator sim(net);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("element 'feedback' (Torque) reads a signal of 'torqueSensor' (TorqueSensor)"), std::string::npos) << m;
    EXPECT_NE(m.find("algebraic loop"), std::string::npos) << m;
  }
}

// A motion source driving J = 2 against a damper d = 0.5 to the ground: tau = J a + d w.
Result DriveInertia(const std::string& type, Scalars parameters, const std::vector<std::pair<std::string, Scalars>>& inputs,
                 const std::vector<std::string>& ports, double stop = 1.0) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement(type, "source", P(std::move(parameters)));
  net.AddElement("Inertia", "inertia", P({{"J", 2}}));
  net.AddElement("Damper", "damper", P({{"d", 0.5}}));
  net.Connect("source.flange", "inertia.flange_a");
  net.Connect("source.support", "fixed.flange");
  net.Connect("inertia.flange_b", "damper.flange_a");
  net.Connect("damper.flange_b", "fixed.flange");
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const std::string id = "input" + std::to_string(k);
    net.AddElement(inputs[k].first, id, P(inputs[k].second));
    net.Connect(id + ".y", "source." + ports[k]);
  }
  return Simulate(net, stop);
}

TEST(MotionSources, SpeedExactFollowsTheReferenceAndItsDerivative) {
  // w = 2 sin(2 pi t), phi = (1 - cos(2 pi t)) / pi, tau = J w' + d w.
  const Result r = DriveInertia("Speed", {{"exact", 1}}, {{"Sine", {{"amplitude", 2}, {"f", 1}}}}, {"w_ref"});
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia.w", [](double t) { return 2 * std::sin(2 * kPi * t); }), 1e-7);
  EXPECT_LT(r.Error("inertia.phi", [](double t) { return (1 - std::cos(2 * kPi * t)) / kPi; }), 1e-7);
  EXPECT_LT(r.Error("source.tau", [](double t) {
              return 2 * 4 * kPi * std::cos(2 * kPi * t) + 0.5 * 2 * std::sin(2 * kPi * t);
            }),
            1e-6);
}

TEST(MotionSources, SpeedFilteredIsAFirstOrderLagStartingAtTheReference) {
  // w_ref steps 1 -> 3 at 0.2 s; w = 3 - 2 exp(-w_crit (t - 0.2)), w_crit = 2 pi 5.
  const double w_crit = 2 * kPi * 5;
  const Result r = DriveInertia("Speed", {{"f_crit", 5}},
                             {{"Step", {{"offset", 1}, {"height", 2}, {"startTime", 0.2}}}}, {"w_ref"});
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia.w", [&](double t) { return t < 0.2 ? 1.0 : 3 - 2 * std::exp(-w_crit * (t - 0.2)); }), 1e-6);
}

TEST(MotionSources, PositionExactFollowsTheReferenceWithItsTwoDerivatives) {
  const Result r = DriveInertia("Position", {{"exact", 1}}, {{"Sine", {{"amplitude", 0.5}, {"f", 1}}}}, {"phi_ref"});
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia.phi", [](double t) { return 0.5 * std::sin(2 * kPi * t); }), 1e-7);
  EXPECT_LT(r.Error("inertia.w", [](double t) { return kPi * std::cos(2 * kPi * t); }), 1e-6);
  EXPECT_LT(r.Error("source.a", [](double t) { return -2 * kPi * kPi * std::sin(2 * kPi * t); }), 1e-6);
}

TEST(MotionSources, PositionFilteredIsTheBesselFilterStepResponse) {
  // Independent integration of the MSL filter a = ((phi_ref - phi) w_c - af w) w_c / bf
  // (classical Runge-Kutta, 1e-6 s) for a unit step at 0.1 s.
  const double w_c = 2 * kPi * 4, af = 1.3617, bf = 0.6180;
  const Result r = DriveInertia("Position", {{"f_crit", 4}}, {{"Step", {{"height", 1}, {"startTime", 0.1}}}}, {"phi_ref"});
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  auto filter = [&](double, const std::array<double, 2>& x) {
    return std::array<double, 2>{x[1], ((1 - x[0]) * w_c - af * x[1]) * (w_c / bf)};
  };
  const auto phi = r.Col("inertia.phi");
  std::array<double, 2> x{0, 0};
  double t = 0.1, worst = 0;
  for (std::size_t i = 0; i < phi.size(); ++i) {
    if (r.t()[i] <= 0.1) {
      worst = std::max(worst, std::abs(phi[i]));
      continue;
    }
    RungeKutta(filter, x, t, r.t()[i], 1e-6);
    worst = std::max(worst, std::abs(phi[i] - x[0]));
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(MotionSources, AccelerateIntegratesTheReference) {
  // a = sin(2 pi t): w = (1 - cos(2 pi t)) / (2 pi), phi = t / (2 pi) - sin(2 pi t) / (4 pi^2).
  const Result r = DriveInertia("Accelerate", {}, {{"Sine", {{"amplitude", 1}, {"f", 1}}}}, {"a_ref"});
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia.w", [](double t) { return (1 - std::cos(2 * kPi * t)) / (2 * kPi); }), 1e-8);
  EXPECT_LT(r.Error("inertia.phi", [](double t) { return t / (2 * kPi) - std::sin(2 * kPi * t) / (4 * kPi * kPi); }),
            1e-8);
}

TEST(MotionSources, MoveTakesAngleSpeedAndAccelerationFromItsInputs) {
  const Result r = DriveInertia("Move", {},
                             {{"Sine", {{"amplitude", 1}, {"f", 1}}},
                              {"Sine", {{"amplitude", 2 * kPi}, {"f", 1}, {"phase", kPi / 2}}},
                              {"Sine", {{"amplitude", -4 * kPi * kPi}, {"f", 1}}}},
                             {"u[1]", "u[2]", "u[3]"});
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia.phi", [](double t) { return std::sin(2 * kPi * t); }), 1e-7);
  EXPECT_LT(r.Error("inertia.w", [](double t) { return 2 * kPi * std::cos(2 * kPi * t); }), 1e-6);
}

TEST(MotionSources, ConstantSpeedHoldsItsSpeedAgainstTheDamper) {
  const Result r = DriveInertia("ConstantSpeed", {{"w_fixed", 3}}, {}, {});
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia.w", [](double) { return 3.0; }), 1e-9);
  EXPECT_LT(r.Error("inertia.phi", [](double t) { return 3 * t; }), 1e-8);
  EXPECT_LT(r.Error("source.tau", [](double) { return 1.5; }), 1e-8);  // d * w
}

// Torque2 between two free inertias J_a = 1 and J_b = 3 from rest, tau = 2 sin(2 pi t):
// J_b a_b = tau, J_a a_a = -tau (momentum is conserved).
TEST(Torque2, ActsBetweenItsFlanges) {
  Network net;
  net.AddElement("Sine", "sine", P({{"amplitude", 2}, {"f", 1}}));
  net.AddElement("Inertia", "a", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("Torque2", "torque2");
  net.AddElement("Inertia", "b", P({{"J", 3}, {"phi_start", 0}, {"w_start", 0}}));
  net.Connect("a.flange_b", "torque2.flange_a");
  net.Connect("torque2.flange_b", "b.flange_a");
  net.Connect("sine.y", "torque2.tau");
  EXPECT_EQ(CheckStructure(net), "");
  const Result r = Simulate(net, 1.0);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  auto w = [](double J) { return [J](double t) { return 2 * (1 - std::cos(2 * kPi * t)) / (2 * kPi * J); }; };
  EXPECT_LT(r.Error("b.w", w(3)), 1e-8);
  EXPECT_LT(r.Error("a.w", [&](double t) { return -w(1)(t); }), 1e-8);
  EXPECT_LT(r.Error("torque2.tau", [](double t) { return 2 * std::sin(2 * kPi * t); }), 1e-12);
  EXPECT_LT(r.Error("torque2.w_rel", [&](double t) { return w(3)(t) + w(1)(t); }), 1e-7);
}

TEST(MotionSources, ExactSourceRejectsAnInputWithoutDerivatives) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Speed", "source", P({{"exact", 1}}));
  net.AddElement("Inertia", "inertia", P({{"J", 1}}));
  net.AddElement("TimeTable", "table", {.scalars = {}, .tables = {{"table", {{0, 0}, {1, 1}}}}});
  net.Connect("source.flange", "inertia.flange_a");
  net.Connect("table.y", "source.w_ref");
  Simulator sim(net);
  MemorySink sink;
  try {
    sim.Run(SimulationOptions{}, sink);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element 'source' (Speed, exact = true): input 'w_ref' must be differentiable"),
              std::string::npos)
        << e.what();
  }
}

// A ballscrew: motor J = 1e-3 driven by 1 N*m, IdealGearR2T ratio 2 pi / 5 mm, nut mass
// m = 100 kg pushed back by 500 N: a = (u ratio - f) / (m + J ratio^2).
TEST(Translational, BallscrewAcceleratesTheReflectedMass) {
  const double ratio = 2 * kPi / 0.005, J = 1e-3, m = 100, u = 1, f = 500;
  const double a = (u * ratio - f) / (m + J * ratio * ratio);
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "motor", P({{"tau_constant", u}}));
  net.AddElement("Inertia", "rotor", P({{"J", J}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("IdealGearR2T", "screw", P({{"ratio", ratio}}));
  net.AddElement("Mass", "nut", P({{"m", m}}));
  net.AddElement("Translational.Force", "load");
  net.AddElement("Constant", "load_value", P({{"k", -f}}));
  net.AddElement("Translational.PositionSensor", "position");
  net.AddElement("Translational.SpeedSensor", "speed");
  net.Connect("motor.flange", "rotor.flange_a");
  net.Connect("motor.support", "fixed.flange");
  net.Connect("rotor.flange_b", "screw.flangeR");
  net.Connect("screw.flangeT", "nut.flange_a");
  net.Connect("load.flange", "nut.flange_b");
  net.Connect("load_value.y", "load.f");
  net.Connect("position.flange", "nut.flange_b");
  net.Connect("speed.flange", "nut.flange_b");
  const Result r = Simulate(net, 1.0);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("nut.s", [&](double t) { return 0.5 * a * t * t; }), 1e-9);
  EXPECT_LT(r.Error("position.s", [&](double t) { return 0.5 * a * t * t; }), 1e-9);
  EXPECT_LT(r.Error("speed.v", [&](double t) { return a * t; }), 1e-9);
  EXPECT_LT(r.Error("rotor.phi", [&](double t) { return ratio * 0.5 * a * t * t; }), 1e-6);
  // ratio * flangeR.tau + flangeT.f = 0; the nut force is m a + f.
  EXPECT_LT(r.Error("screw.flangeT.f", [&](double) { return -(m * a + f); }), 1e-6);
  EXPECT_LT(r.Error("screw.flangeR.tau", [&](double) { return (m * a + f) / ratio; }), 1e-8);
}

// A rack and pinion as a rolling wheel (radius 0.05 m) against a translational spring-damper:
// an oscillator of effective mass m + J / r^2.
TEST(Translational, RollingWheelOnASpringIsAnOscillatorOfTheEffectiveMass) {
  const double r_w = 0.05, J = 0.01, m = 4, c = 2e4, s0 = 0.01;
  const double m_eff = m + J / (r_w * r_w), omega = std::sqrt(c / m_eff);
  Network net;
  net.AddElement("Translational.Fixed", "ground");
  net.AddElement("Inertia", "pinion", P({{"J", J}}));
  net.AddElement("IdealRollingWheel", "wheel", P({{"radius", r_w}}));
  net.AddElement("Mass", "rack", P({{"m", m}, {"s_start", s0}, {"v_start", 0}}));
  net.AddElement("Translational.Spring", "spring", P({{"c", c}}));
  net.Connect("pinion.flange_b", "wheel.flangeR");
  net.Connect("wheel.flangeT", "rack.flange_a");
  net.Connect("rack.flange_b", "spring.flange_a");
  net.Connect("spring.flange_b", "ground.flange");
  const Result r = Simulate(net, 0.2);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("rack.s", [&](double t) { return s0 * std::cos(omega * t); }), 1e-8);
  EXPECT_LT(r.Error("pinion.phi", [&](double t) { return s0 * std::cos(omega * t) / r_w; }), 1e-7);
  EXPECT_LT(r.Error("spring.f", [&](double t) { return -c * s0 * std::cos(omega * t); }), 1e-4);
}

TEST(Translational, DamperAndSpringDamperDecayAsTheClosedForm) {
  // m s'' + d s' + c s = 0 with s(0) = 0.1, v(0) = 0: underdamped.
  const double m = 2, c = 800, d = 8;
  const double zeta_w = d / (2 * m), wd = std::sqrt(c / m - zeta_w * zeta_w);
  auto s = [&](double t) { return 0.1 * std::exp(-zeta_w * t) * (std::cos(wd * t) + zeta_w / wd * std::sin(wd * t)); };
  for (const bool combined : {true, false}) {
    Network net;
    net.AddElement("Translational.Fixed", "ground", P({{"s0", 0}}));
    net.AddElement("Mass", "mass", P({{"m", m}, {"s_start", 0.1}, {"v_start", 0}}));
    if (combined) {
      net.AddElement("Translational.SpringDamper", "sd", P({{"c", c}, {"d", d}}));
      net.Connect("mass.flange_b", "sd.flange_a");
      net.Connect("sd.flange_b", "ground.flange");
    } else {
      net.AddElement("Translational.Spring", "spring", P({{"c", c}}));
      net.AddElement("Translational.Damper", "damper", P({{"d", d}}));
      net.Connect("mass.flange_b", "spring.flange_a");
      net.Connect("spring.flange_b", "ground.flange");
      net.Connect("mass.flange_a", "damper.flange_b");
      net.Connect("damper.flange_a", "ground.flange");
    }
    const Result r = Simulate(net, 1.0);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    EXPECT_LT(r.Error("mass.s", s), 1e-8) << (combined ? "SpringDamper" : "Spring + Damper");
  }
}

// ElastoBacklash2 in the MSL Backlash example (J = 5 from 90 degrees, c = 2e4, d = 50,
// b = 45 degrees): the state against an independent integration of J phi'' = -tau(phi, w)
// (classical Runge-Kutta at 2e-6 s; the torque jumps at contact, so that reference is first
// order across contacts).
TEST(ElastoBacklash2, BacklashExampleAgainstAnIndependentIntegration) {
  const double J = 5, c = 2e4, d = 50, b = kPi / 4;
  // The example as written from the MSL model (tests/sim/msl/Backlash.json, all three systems).
  const Network net = NetworkFromProject(LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/tests/sim/msl/Backlash.json"));
  const Result r = Simulate(net, 1.0, 1e-8, 1e-10);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  auto tau = [&](double phi, double w) {
    const double g = b / 2;
    if (phi > g) return std::max(c * (phi - g) + d * w, 0.0);
    if (phi < -g) return std::min(c * (phi + g) + d * w, 0.0);
    return 0.0;
  };
  auto motion = [&](double, const std::array<double, 2>& x) {
    return std::array<double, 2>{x[1], -tau(x[0], x[1]) / J};
  };
  const auto phi = r.Col("inertia3.phi");
  std::array<double, 2> x{kPi / 2, 0};
  double t = 0, worst = 0;
  for (std::size_t i = 0; i < phi.size(); ++i) {
    RungeKutta(motion, x, t, r.t()[i], 2e-6);
    worst = std::max(worst, std::abs(phi[i] - x[0]));
  }
  // 2e-3 of the range of the angle (the MSL criterion).
  EXPECT_LT(worst, 2e-3 * kPi) << "largest angle difference, rad";
  std::printf("elastoBacklash2/inertia3: largest angle difference %.3g rad (range pi)\n", worst);
  // The contact only pushes: the element torque never has the sign of a pull.
  const auto phi_rel = r.Col("elastoBacklash2.phi_rel");
  const auto torque = r.Col("elastoBacklash2.tau");
  for (std::size_t i = 0; i < torque.size(); ++i) {
    if (phi_rel[i] > b / 2) {
      EXPECT_GE(torque[i], 0.0);
    } else if (phi_rel[i] < -b / 2) {
      EXPECT_LE(torque[i], 0.0);
    } else if (std::abs(phi_rel[i]) < b / 2 - 1e-9) {
      EXPECT_EQ(torque[i], 0.0);
    }
  }
}

// A gearbox whose housing is held by a stiff spring (a compliant mounting): the housing moves
// by about 1e-5 rad/s. With the housing inertia's nominal speed declared (w_nominal), the error
// test resolves it; the reference is an independent integration of the reduced equations
//   M [w_b, w_h]' = [i u, (1 - i) u] - [d_b w_b, c_h phi_h + d_h w_h]
//   M = [[J2 + i^2 J1, i (1 - i) J1], [i (1 - i) J1, J_h + (1 - i)^2 J1]].
TEST(Tolerances, NominalSpeedResolvesASmallHousingMotion) {
  const double J1 = 0.1, J2 = 2, Jh = 5, i = 10, c_h = 1e7, d_h = 2e3, d_b = 10;
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Sine", "sine", P({{"amplitude", 10}, {"f", 5}}));
  net.AddElement("Torque", "torque");
  net.AddElement("Inertia", "inertia1", P({{"J", J1}}));
  net.AddElement("IdealGear", "gear", P({{"ratio", i}}));
  net.AddElement("Inertia", "inertia2", P({{"J", J2}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("Damper", "load", P({{"d", d_b}}));
  net.AddElement("Inertia", "housing", P({{"J", Jh}, {"phi_start", 0}, {"w_start", 0}, {"w_nominal", 1e-5}, {"phi_nominal", 1e-7}}));
  net.AddElement("SpringDamper", "mount", P({{"c", c_h}, {"d", d_h}, {"phi_nominal", 1e-7}}));
  net.Connect("sine.y", "torque.tau");
  net.Connect("torque.flange", "inertia1.flange_a");
  net.Connect("torque.support", "housing.flange_a");
  net.Connect("inertia1.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "inertia2.flange_a");
  net.Connect("gear.support", "housing.flange_a");
  net.Connect("inertia2.flange_b", "load.flange_a");
  net.Connect("load.flange_b", "fixed.flange");
  net.Connect("housing.flange_b", "mount.flange_a");
  net.Connect("mount.flange_b", "fixed.flange");
  // The torque source's reaction acts on the housing too: Q_h = (1 - i) u - u = -i u.
  auto rhs = [&](double t, const std::array<double, 4>& x) {  // x = phi_b, w_b, phi_h, w_h
    const double u = 10 * std::sin(2 * kPi * 5 * t);
    const double m11 = J2 + i * i * J1, m12 = i * (1 - i) * J1, m22 = Jh + (1 - i) * (1 - i) * J1;
    const double q1 = i * u - d_b * x[1];
    const double q2 = (1 - i) * u - u - c_h * x[2] - d_h * x[3];
    const double det = m11 * m22 - m12 * m12;
    return std::array<double, 4>{x[1], (m22 * q1 - m12 * q2) / det, x[3], (m11 * q2 - m12 * q1) / det};
  };
  double worst_with = 0, worst_without = 0, range = 0;
  for (const bool nominal : {true, false}) {
    Network n = net;
    if (!nominal) {
      n = Network();
      for (const auto& e : net.elements()) {
        ElementParameters p = e.parameters;
        for (auto it = p.scalars.begin(); it != p.scalars.end();)
          it = (it->first.find("nominal") != std::string::npos || !e.given.count(it->first) || !e.given.at(it->first))
                   ? p.scalars.erase(it)
                   : std::next(it);
        n.AddElement(e.type, e.id, p);
      }
      for (const auto& c : net.connections()) n.Connect(c.a.ToString(), c.b.ToString());
    }
    const Result r = Simulate(n, 0.4, 1e-6, 1e-8);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    const auto w_h = r.Col("housing.w");
    std::array<double, 4> x{0, 0, 0, 0};
    double t = 0, worst = 0;
    for (std::size_t k = 0; k < w_h.size(); ++k) {
      RungeKutta(rhs, x, t, r.t()[k], 2e-6);
      worst = std::max(worst, std::abs(w_h[k] - x[3]));
      if (nominal) range = std::max(range, std::abs(x[3]));
    }
    (nominal ? worst_with : worst_without) = worst;
  }
  ASSERT_GT(range, 1e-6);
  ASSERT_LT(range, 1e-3);
  // The MSL criterion, 2e-3 of the range, holds with the nominal value declared.
  EXPECT_LT(worst_with, 2e-3 * range) << "housing speed range " << range << " rad/s";
  std::printf("housing speed range %.3g rad/s; largest error %.3g with w_nominal, %.3g without\n", range,
              worst_with, worst_without);
}

// Two springs in series with no inertia between them: the massless node is the static balance
// c1 phi1 = c2 phi2, the inertia sees c = c1 c2 / (c1 + c2).
TEST(MasslessNode, SeriesSpringsAreTheEquivalentSpring) {
  const double c1 = 1200, c2 = 2400, J = 2, c = c1 * c2 / (c1 + c2), omega = std::sqrt(c / J);
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Spring", "spring1", P({{"c", c1}}));
  net.AddElement("Spring", "spring2", P({{"c", c2}}));
  net.AddElement("Inertia", "inertia", P({{"J", J}, {"phi_start", 0.1}, {"w_start", 0}}));
  net.Connect("fixed.flange", "spring1.flange_a");
  net.Connect("spring1.flange_b", "spring2.flange_a");
  net.Connect("spring2.flange_b", "inertia.flange_a");
  EXPECT_EQ(CheckStructure(net), "");
  const Result r = Simulate(net, 1.0);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia.phi", [&](double t) { return 0.1 * std::cos(omega * t); }), 1e-7);
  EXPECT_LT(r.Error("spring1.phi_rel", [&](double t) { return c / c1 * 0.1 * std::cos(omega * t); }), 1e-7);
  EXPECT_LT(r.Error("spring2.tau", [&](double t) { return c * 0.1 * std::cos(omega * t); }), 1e-4);
}

// A damper in series with a spring (Maxwell element) through a massless node:
//   d w_n = c (phi - phi_n),  J phi'' = -c (phi - phi_n)   (independent Runge-Kutta).
TEST(MasslessNode, DamperInSeriesWithASpringIsAMaxwellElement) {
  const double d = 20, c = 400, J = 1;
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Damper", "damper", P({{"d", d}}));
  net.AddElement("Spring", "spring", P({{"c", c}}));
  net.AddElement("Inertia", "inertia", P({{"J", J}, {"phi_start", 0}, {"w_start", 1}}));
  net.Connect("fixed.flange", "damper.flange_a");
  net.Connect("damper.flange_b", "spring.flange_a");
  net.Connect("spring.flange_b", "inertia.flange_a");
  const Result r = Simulate(net, 1.0);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  auto maxwell = [&](double, const std::array<double, 3>& x) {  // x = phi_n, phi, w
    return std::array<double, 3>{c * (x[1] - x[0]) / d, x[2], -c * (x[1] - x[0]) / J};
  };
  const auto phi = r.Col("inertia.phi");
  std::array<double, 3> x{0, 0, 1};
  double t = 0, worst = 0;
  for (std::size_t k = 0; k < phi.size(); ++k) {
    RungeKutta(maxwell, x, t, r.t()[k], 1e-5);
    worst = std::max(worst, std::abs(phi[k] - x[1]));
  }
  EXPECT_LT(worst, 1e-7);
}

// Angle and speed sensors on the massless node of two series springs read its static balance,
// phi_n = c2 / (c1 + c2) phi; an acceleration sensor there, or a torque sensor joining two
// massless flanges, is an input error (the balance gives no acceleration).
// The ground, then `chain` in series (flange_a to flange_b; spring1 c = 1200, spring2 c = 2400),
// then an inertia J = 2 from phi = 0.1 at rest.
Network InSeries(const std::vector<std::pair<std::string, std::string>>& chain) {
  Network net;
  net.AddElement("Fixed", "fixed");
  std::string previous = "fixed.flange";
  for (const auto& [type, id] : chain) {
    net.AddElement(type, id, type == "Spring" ? P({{"c", id == "spring1" ? 1200.0 : 2400.0}}) : P({}));
    net.Connect(previous, id + ".flange_a");
    previous = id + ".flange_b";
  }
  net.AddElement("Inertia", "inertia", P({{"J", 2}, {"phi_start", 0.1}, {"w_start", 0}}));
  net.Connect(previous, "inertia.flange_a");
  return net;
}

TEST(MasslessNode, SensorsReadTheBalanceOrAreNamed) {
  const double c1 = 1200, c2 = 2400, J = 2, c = c1 * c2 / (c1 + c2), omega = std::sqrt(c / J), k = c2 / (c1 + c2);
  Network net = InSeries({{"Spring", "spring1"}, {"Spring", "spring2"}});
  net.AddElement("AngleSensor", "angle");
  net.AddElement("SpeedSensor", "speed");
  net.AddElement("RelSpeedSensor", "relSpeed");
  net.Connect("angle.flange", "spring1.flange_b");
  net.Connect("speed.flange", "spring1.flange_b");
  net.Connect("relSpeed.flange_a", "spring1.flange_b");
  net.Connect("relSpeed.flange_b", "inertia.flange_b");
  const Result r = Simulate(net, 0.5);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("angle.phi", [&](double t) { return k * 0.1 * std::cos(omega * t); }), 1e-7);
  EXPECT_LT(r.Error("speed.w", [&](double t) { return -k * 0.1 * omega * std::sin(omega * t); }), 1e-6);
  EXPECT_LT(r.Error("relSpeed.w_rel", [&](double t) { return -(1 - k) * 0.1 * omega * std::sin(omega * t); }), 1e-6);

  Network acc = net;
  acc.AddElement("AccSensor", "acc");
  acc.Connect("acc.flange", "spring1.flange_b");
  EXPECT_NE(CheckStructure(acc).find("element 'acc' (AccSensor) measures the acceleration of flange "
                                     "'spring1.flange_b', which has no inertia"),
            std::string::npos)
      << CheckStructure(acc);

  const Network torque = InSeries({{"Spring", "spring1"}, {"TorqueSensor", "sensor"}, {"Spring", "spring2"}});
  EXPECT_NE(CheckStructure(torque).find("element 'sensor' (TorqueSensor) joins flanges spring1.flange_b, "
                                        "sensor.flange_b rigidly"),
            std::string::npos)
      << CheckStructure(torque);
  // Next to the inertia the same sensor reads the spring torque c * phi.
  const Network beside = InSeries({{"Spring", "spring1"}, {"Spring", "spring2"}, {"TorqueSensor", "sensor"}});
  const Result b = Simulate(beside, 0.5);
  ASSERT_TRUE(b.report.ok()) << b.report.FullReport();
  // sensor.flange_a.tau = -spring2.flange_b.tau = -c2 (phi - phi_n) = -c phi.
  EXPECT_LT(b.Error("sensor.tau", [&](double t) { return -c * 0.1 * std::cos(omega * t); }), 1e-4);
}

TEST(MasslessNode, PlanetaryWithAnOpenRingIdles) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "torque", P({{"tau_constant", 1}}));
  net.AddElement("Inertia", "sun", P({{"J", 0.5}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("IdealPlanetary", "planetary", P({{"ratio", 4}}));
  net.AddElement("Inertia", "carrier", P({{"J", 2}}));
  net.Connect("torque.flange", "sun.flange_a");
  net.Connect("torque.support", "fixed.flange");
  net.Connect("sun.flange_b", "planetary.sun");
  net.Connect("planetary.carrier", "carrier.flange_a");
  EXPECT_EQ(CheckStructure(net), "");
  const Result r = Simulate(net, 0.5);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("sun.w", [](double t) { return 2 * t; }), 1e-8);
  EXPECT_LT(r.Error("carrier.w", [](double) { return 0.0; }), 1e-8);
}

TEST(MasslessNode, ATorqueOnAMasslessNodeIsNamed) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Spring", "spring1", P({{"c", 100}}));
  net.AddElement("ConstantTorque", "torque", P({{"tau_constant", 1}}));
  net.AddElement("Spring", "spring2", P({{"c", 100}}));
  net.AddElement("Inertia", "inertia", P({{"J", 1}}));
  net.Connect("fixed.flange", "spring1.flange_a");
  net.Connect("spring1.flange_b", "spring2.flange_a");
  net.Connect("torque.flange", "spring1.flange_b");
  net.Connect("torque.support", "fixed.flange");
  net.Connect("spring2.flange_b", "inertia.flange_a");
  const std::string m = CheckStructure(net);
  EXPECT_NE(m.find("flange 'spring1.flange_b' has no inertia and no kinematic coupling, and element 'torque' "
                   "(ConstantTorque) acts on it"),
            std::string::npos)
      << m;
}

// Start values with fixed = false are guesses: used where the initial equations leave the value
// free (the angles behind a gear), overridden where they determine it (the speed).
TEST(StartValues, GuessesFillWhatTheFixedValuesLeaveFree) {
  Network net;
  net.AddElement("IdealGear", "gear", P({{"ratio", 2}}));
  net.AddElement("Inertia", "a", P({{"J", 1}, {"w_start", 2}}));
  net.AddElement("Inertia", "b", P({{"J", 1}, {"phi_start", 3}, {"phi_fixed", 0}, {"w_start", 5}, {"w_fixed", 0}}));
  net.Connect("a.flange_b", "gear.flange_a");
  net.Connect("gear.flange_b", "b.flange_a");
  EXPECT_EQ(CheckStructure(net), "");
  const Result r = Simulate(net, 0.1);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_NEAR(r.Col("b.w").front(), 1.0, 1e-12);    // the guess 5 contradicts w_a = 2 = 2 w_b
  EXPECT_NEAR(r.Col("b.phi").front(), 3.0, 1e-9);  // the guess fills the free angle
  EXPECT_NEAR(r.Col("a.phi").front(), 6.0, 1e-9);
}

// ------------------------------------------------------------------------------------------
// Examples written from the MSL 4.0 examples the elements appear in (tests/sim/msl/*.json, each
// naming its MSL example in its description), run as `highlift simulate` runs an element
// network: the experiment's times and tolerance, the settings' absolute tolerance and start.

Result RunExample(const std::string& name) {
  const Project project =
      LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "tests" / "sim" / "msl" / (name + ".json"));
  const Experiment& x = project.experiment.value();
  SimulationOptions o;
  o.start_time = x.start_time;
  o.stop_time = x.stop_time;
  o.output_interval = x.interval.value_or(project.settings.output_interval);
  o.relative_tolerance = x.tolerance.value_or(project.settings.relative_tolerance);
  if (project.settings.absolute_tolerance) o.absolute_tolerance = *project.settings.absolute_tolerance;
  EXPECT_EQ(CheckStructure(NetworkFromProject(project), o.start_time), "") << name;
  Result r;
  Simulator sim(NetworkFromProject(project));
  r.report = sim.Run(o, r.sink);
  EXPECT_TRUE(r.report.ok()) << name << ": " << r.report.FullReport();
  return r;
}

/// Largest difference of each named column from an independent solution: the state x, from its
/// value at the first output time, integrated by classical Runge-Kutta (steps of at most h)
/// along the output times, and mapped to the column by `value`. `range` is the largest |value|.
struct Deviation {
  double error = 0.0, range = 0.0;
};
template <std::size_t N, class F>
std::map<std::string, Deviation> DeviationFromIntegration(
    const Result& r, const F& f, std::array<double, N> x, double h,
    const std::map<std::string, std::function<double(double, const std::array<double, N>&)>>& value) {
  std::map<std::string, std::vector<double>> columns;
  for (const auto& [name, unused] : value) columns[name] = r.Col(name);
  std::map<std::string, Deviation> out;
  double t = r.t().front();
  for (std::size_t i = 0; i < r.t().size(); ++i) {
    RungeKutta(f, x, t, r.t()[i], h);
    for (const auto& [name, g] : value) {
      const double v = g(t, x);
      Deviation& d = out[name];
      d.error = std::max(d.error, std::abs(columns[name][i] - v));
      d.range = std::max(d.range, std::abs(v));
    }
  }
  for (const auto& [name, d] : out) std::printf("  %-24s largest error %.2e (range %.2e)\n", name.c_str(), d.error, d.range);
  return out;
}

// Translational.Examples.Damper: v = 10 exp(-25 t) against the damper; the damper with the
// parallel spring and the SpringDamper both give x'' + 25 x' + (x - 3.5) = 0, x(0) = 3.5,
// x'(0) = 10: x = 3.5 + A (exp(r1 t) - exp(r2 t)), r1,2 = (-25 +- sqrt(621)) / 2, A = 10 / sqrt(621).
TEST(MslExamples, TranslationalDamperAsTheClosedForm) {
  const Result r = RunExample("TranslationalDamper");
  const double root = std::sqrt(621.0), r1 = (-25 + root) / 2, r2 = (-25 - root) / 2, A = 10 / root;
  EXPECT_LT(r.Error("mass1.v", [](double t) { return 10 * std::exp(-25 * t); }), 1e-6);
  EXPECT_LT(r.Error("mass1.s", [](double t) { return 3.5 + 0.4 * (1 - std::exp(-25 * t)); }), 1e-8);
  for (const char* mass : {"mass2", "mass3"}) {
    EXPECT_LT(r.Error(std::string(mass) + ".s", [&](double t) { return 3.5 + A * (std::exp(r1 * t) - std::exp(r2 * t)); }),
              1e-8)
        << mass;
    EXPECT_LT(
        r.Error(std::string(mass) + ".v", [&](double t) { return A * (r1 * std::exp(r1 * t) - r2 * std::exp(r2 * t)); }),
        1e-6)
        << mass;
  }
  // The spring force of the parallel pair and of the SpringDamper: c (s_rel - s_rel0) = -(x - 3.5).
  EXPECT_LT(r.Error("spring2.f", [&](double t) { return -A * (std::exp(r1 * t) - std::exp(r2 * t)); }), 1e-8);
}

// Translational.Examples.Sensors: a = 10 sin(8 pi t) from rest.
TEST(MslExamples, TranslationalSensorsAsTheClosedForm) {
  const Result r = RunExample("TranslationalSensors");
  const double w = 8 * kPi, k = 10 / w;
  auto s = [&](double t) { return k * t - k / w * std::sin(w * t); };
  EXPECT_LT(r.Error("positionSensor1.s", s), 1e-7);
  EXPECT_LT(r.Error("positionSensor2.s", s), 1e-7);  // MSL: 1 m ahead (L = 1 m); here the same
  EXPECT_LT(r.Error("speedSensor1.v", [&](double t) { return k * (1 - std::cos(w * t)); }), 1e-7);
  EXPECT_LT(r.Error("mass.a", [&](double t) { return 10 * std::sin(w * t); }), 1e-6);
}

// Rotational.Examples.ElasticBearing against an independent integration of its three inertias
// (the gear's output flange is massless and kinematic: phi_b = phi_h + (phi_s - phi_h) / 3).
TEST(MslExamples, ElasticBearingAgainstAnIndependentIntegration) {
  const Result r = RunExample("ElasticBearing");
  constexpr double Js = 1, Jh = 5, Jl = 50, c = 1e3, c2 = 1e5, d2 = 5, ratio = 3;
  // x = phi_s, w_s, phi_h, w_h, phi_l, w_l
  auto f = [&](double t, const std::array<double, 6>& x) {
    const double tau = 100 * std::min(t / 5, 1.0);
    const double T = c * (x[4] - x[2] - (x[0] - x[2]) / ratio);
    return std::array<double, 6>{x[1], (tau + T / ratio) / Js, x[3], ((1 - 1 / ratio) * T - c2 * x[2] - d2 * x[3]) / Jh,
                                 x[5], -T / Jl};
  };
  std::array<double, 6> x{};
  double t = 0.0;
  const auto ws = r.Col("shaft.w"), wh = r.Col("housing.w"), wl = r.Col("load.w"), tau = r.Col("multiSensor.tau"),
             w_sensor = r.Col("multiSensor.w"), power = r.Col("multiSensor.power");
  double err_s = 0, err_h = 0, err_l = 0, err_tau = 0, range_h = 0, range_tau = 0;
  for (std::size_t i = 0; i < r.t().size(); ++i) {
    RungeKutta(f, x, t, r.t()[i], 1e-4);
    const double sensor_tau = -(c2 * x[2] + d2 * x[3]);  // multiSensor.tau = flange_a.tau = -springDamper.tau
    err_s = std::max(err_s, std::abs(ws[i] - x[1]));
    err_h = std::max(err_h, std::abs(wh[i] - x[3]));
    err_l = std::max(err_l, std::abs(wl[i] - x[5]));
    err_tau = std::max(err_tau, std::abs(tau[i] - sensor_tau));
    range_h = std::max(range_h, std::abs(x[3]));
    range_tau = std::max(range_tau, std::abs(sensor_tau));
    EXPECT_NEAR(w_sensor[i], wh[i], 1e-12);
    EXPECT_NEAR(power[i], tau[i] * wh[i], 1e-9 * (1 + std::abs(power[i])));
  }
  std::printf("ElasticBearing: largest errors shaft.w %.2e, housing.w %.2e (range %.2e), load.w %.2e rad/s, "
              "multiSensor.tau %.2e N*m (range %.2e)\n", err_s, err_h, range_h, err_l, err_tau, range_tau);
  EXPECT_NEAR(x[1], ws.back(), 1e-5);  // the shaft runs at about 280 rad/s at 10 s
  EXPECT_LT(err_s, 1e-5);
  EXPECT_LT(err_l, 1e-5);
  EXPECT_LT(err_h, 1e-4 * range_h);
  EXPECT_LT(err_tau, 1e-4 * range_tau);
}

// Translational.Examples.InitialConditions (first system), with the rest positions solved from
// a_start = 0 (the speeds fixed, as in MSL) instead of given by hand: m3.s = 3 m, m4.s = 7 m, at
// rest throughout; the steady-state start without a_start and v_start finds the same.
TEST(MslExamples, InitialConditionsAtRestFromAStart) {
  const Result r = RunExample("InitialConditions");
  EXPECT_LT(r.Error("m3.s", [](double) { return 3.0; }), 1e-9);
  EXPECT_LT(r.Error("m4.s", [](double) { return 7.0; }), 1e-9);
  EXPECT_LT(r.Error("m3.v", [](double) { return 0.0; }), 1e-9);
  EXPECT_LT(r.Error("m4.v", [](double) { return 0.0; }), 1e-9);
  EXPECT_LT(r.Error("s2.f", [](double) { return 0.0; }), 1e-7);
}

// The examples below run at relative tolerance 1e-8 and absolute tolerance 1e-10 (their
// experiment and settings); CVODE controls the local error. Where a signal follows its input
// (sources, sensors of a driven inertia) the global error stays below 5e-7 of the signal's range,
// and the comparisons allow 1e-6 of the range. In the lightly damped oscillators (First's elastic
// load, the spring-dampers, 12 to 25 periods) the phase error accumulates: 1e-5 to 3e-5 of the
// range at 1e-8, 30 times less at 1e-10, i.e. the difference is integration error converging to
// the reference; these allow 1e-4 of the range. The independent references (closed forms, or
// classical Runge-Kutta at 1e-5 s, truncation error below 1e-10) are far more accurate. The MSL
// criterion is 2e-3 of the range.
constexpr double kFollow = 1e-6, kOscillate = 1e-4;

using State2 = std::array<double, 2>;
using State4 = std::array<double, 4>;

// ModelicaTest.Rotational.TestSpeed: a filtered Speed after a unit step at 0.5 s, an exact Speed
// following sin(2 pi t).
TEST(MslExamples, TestSpeedAsTheClosedForm) {
  const Result r = RunExample("TestSpeed");
  const double wc = 2 * kPi * 5;
  auto lag = [&](double t) { return t < 0.5 ? 0.0 : 1 - std::exp(-wc * (t - 0.5)); };
  EXPECT_LT(r.Error("inertia1.w", lag), kFollow);
  EXPECT_LT(r.Error("inertia1.phi", [&](double t) { return t < 0.5 ? 0.0 : t - 0.5 - lag(t) / wc; }), kFollow);
  // The reference and the torque jump at the step (a time event, stored as a left and a right
  // row at 0.5 s).
  const auto tau = r.Col("speed1.tau"), w_ref = r.Col("speed1.w_ref");
  double worst = 0.0;
  bool right_limit = false;
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const double t = r.t()[i];
    if (t == 0.5 && !right_limit) {  // the left limit: at rest
      EXPECT_NEAR(tau[i], 0.0, 1e-12);
      EXPECT_EQ(w_ref[i], 0.0);
      right_limit = true;
      continue;
    }
    EXPECT_EQ(w_ref[i], t < 0.5 ? 0.0 : 1.0) << "t = " << t;
    worst = std::max(worst, std::abs(tau[i] - (t < 0.5 ? 0.0 : wc * std::exp(-wc * (t - 0.5)))));
  }
  EXPECT_TRUE(right_limit) << "no output row at the step";
  EXPECT_LT(worst, kFollow * wc);
  EXPECT_LT(r.Error("inertia2.w", [](double t) { return std::sin(2 * kPi * t); }), kFollow);
  EXPECT_LT(r.Error("inertia2.phi", [](double t) { return (1 - std::cos(2 * kPi * t)) / (2 * kPi); }), kFollow);
  EXPECT_LT(r.Error("speed2.tau", [](double t) { return 2 * kPi * std::cos(2 * kPi * t); }), kFollow * 2 * kPi);
}

// ModelicaTest.Rotational.AllComponents, the motion sources and sensors: the two filters against
// an independent integration, the rest against closed forms.
TEST(MslExamples, AllComponentsSourcesAndSensors) {
  const Result r = RunExample("AllComponentsSources");
  constexpr double J = 3, af = 1.3617, bf = 0.6180;
  const double wc = 2 * kPi * 50, w = 2 * kPi;
  auto u = [&](double t) { return std::sin(w * t); };
  // x = phi9, w9 (Bessel filter of sine2), phi10, w10 (first-order filter of sine3); all 0 at t = 0.
  auto filters = [&](double t, const State4& x) {
    return State4{x[1], ((u(t) - x[0]) * wc - af * x[1]) * (wc / bf), x[3], (u(t) - x[3]) * wc};
  };
  // The driven inertia13 (sine7 from rest) and the moved inertia12, in closed form.
  auto phi13 = [&](double t) { return (t - std::sin(w * t) / w) / (w * J); };
  auto w13 = [&](double t) { return (1 - std::cos(w * t)) / (w * J); };
  using Value = std::function<double(double, const State4&)>;
  const auto d = DeviationFromIntegration(
      r, filters, State4{}, 1e-5,
      std::map<std::string, Value>{
          {"inertia9.phi", [](double, const State4& x) { return x[0]; }},
          {"inertia9.w", [](double, const State4& x) { return x[1]; }},
          {"inertia10.phi", [](double, const State4& x) { return x[2]; }},
          {"inertia10.w", [](double, const State4& x) { return x[3]; }},
          // The speed source drives inertia10 and takes the reaction of torque2_1 (-sine7).
          {"speed.tau", [&](double t, const State4& x) { return J * (u(t) - x[3]) * wc + u(t); }},
          {"relAngleSensor.phi_rel", [&](double t, const State4& x) { return phi13(t) - x[0]; }}});
  for (const auto& [name, dev] : d) EXPECT_LT(dev.error, kFollow * dev.range) << name;
  EXPECT_LT(r.Error("inertia13.phi", phi13), kFollow / J);
  EXPECT_LT(r.Error("inertia13.w", w13), kFollow / J);
  // Accelerate from rest with its sensors.
  auto phi11 = [&](double t) { return t / w - std::sin(w * t) / (w * w); };
  auto w11 = [&](double t) { return (1 - std::cos(w * t)) / w; };
  EXPECT_LT(r.Error("inertia11.phi", phi11), kFollow);
  EXPECT_LT(r.Error("angleSensor.phi", phi11), kFollow);
  EXPECT_LT(r.Error("speedSensor.w", w11), kFollow);
  EXPECT_LT(r.Error("accSensor.a", u), kFollow);
  // Move with consistent inputs; the relative sensors between inertia13 and inertia12.
  EXPECT_LT(r.Error("inertia12.phi", [&](double t) { return 2 * std::sin(w * t); }), kFollow * 2);
  EXPECT_LT(r.Error("inertia12.w", [&](double t) { return 2 * w * std::cos(w * t); }), kFollow * 2 * w);
  EXPECT_LT(r.Error("relSpeedSensor.w_rel", [&](double t) { return 2 * w * std::cos(w * t) - w13(t); }),
            kFollow * 2 * w);
  EXPECT_LT(r.Error("relAccSensor.a_rel", [&](double t) { return -2 * w * w * std::sin(w * t) - u(t) / J; }),
            kFollow * 2 * w * w);
  // ConstantSpeed: inertia15 and inertia16 turn at 11 rad/s; nothing accelerates, so the torque
  // and the power through the sensors are 0.
  EXPECT_LT(r.Error("inertia15.phi", [](double t) { return 11 * t; }), kFollow * 11);
  EXPECT_LT(r.Error("inertia16.w", [](double) { return 11.0; }), 1e-12);
  EXPECT_LT(r.Error("torqueSensor.tau", [](double) { return 0.0; }), 1e-9);
  EXPECT_LT(r.Error("powerSensor.power", [](double) { return 0.0; }), 1e-8);
}

// Rotational.Examples.First with torque, power and relative sensors: the sensors read the
// solved spring torque and the motion of an independent integration of First's reduced
// equations.
TEST(MslExamples, FirstWithSensorsAgainstAnIndependentIntegration) {
  const Result r = RunExample("FirstSensors");
  constexpr double J1 = 0.1, J2 = 2, J3 = 2, i = 10, c = 1e4, d = 10;
  auto u = [](double t) { return 10 * std::sin(10 * kPi * t); };
  auto accelerations = [&](double t, const State4& x) {  // x = phi2, w2, phi3, w3
    return State2{(i * u(t) - c * (x[0] - x[2]) - d * x[1]) / (J2 + i * i * J1), c * (x[0] - x[2]) / J3};
  };
  auto first = [&](double t, const State4& x) {
    const State2 a = accelerations(t, x);
    return State4{x[1], a[0], x[3], a[1]};
  };
  using Value = std::function<double(double, const State4&)>;
  const auto dev = DeviationFromIntegration(
      r, first, State4{}, 1e-5,
      std::map<std::string, Value>{
          {"inertia2.w", [](double, const State4& x) { return x[1]; }},
          {"inertia3.w", [](double, const State4& x) { return x[3]; }},
          {"torqueSensor.tau", [&](double, const State4& x) { return c * (x[0] - x[2]); }},
          {"powerSensor.power", [&](double, const State4& x) { return c * (x[0] - x[2]) * x[1]; }},
          {"relAngleSensor.phi_rel", [](double, const State4& x) { return x[2] - x[0]; }},
          {"relSpeedSensor.w_rel", [](double, const State4& x) { return x[3] - x[1]; }},
          {"relAccSensor.a_rel",
           [&](double t, const State4& x) {
             const State2 a = accelerations(t, x);
             return a[1] - a[0];
           }},
          {"angleSensor.phi", [&](double, const State4& x) { return i * x[0]; }},
          {"speedSensor.w", [&](double, const State4& x) { return i * x[1]; }},
          {"accSensor.a", [&](double t, const State4& x) { return i * accelerations(t, x)[0]; }}});
  for (const auto& [name, e] : dev) EXPECT_LT(e.error, kOscillate * e.range) << name;
}

// ModelicaTest.Rotational.InitializationConversion.SpringDamper: spring-dampers started from
// fixed and free relative start values, and a RelativeStates carrying the start of a free pair.
TEST(MslExamples, InitializationSpringDamperAsTheClosedForm) {
  const Result r = RunExample("InitializationSpringDamper");
  const double wd = std::sqrt(1e4 - 25.0), W = std::sqrt(2e4);
  // x'' + 10 x' + 1e4 x = 0 from x(0) = x0, x'(0) = v0.
  auto x = [&](double x0, double v0) {
    return [=](double t) { return std::exp(-5 * t) * (x0 * std::cos(wd * t) + (v0 + 5 * x0) / wd * std::sin(wd * t)); };
  };
  EXPECT_LT(r.Error("inertia1.phi", x(1, 2)), kOscillate);
  EXPECT_LT(r.Error("springDamper1.phi_rel", x(1, 2)), kOscillate);
  EXPECT_LT(r.Error("inertia3.phi", x(1, 2)), kOscillate);
  EXPECT_LT(r.Error("inertia4.phi", [](double) { return 0.0; }), 1e-12);
  EXPECT_LT(r.Error("inertia5.phi", x(0, 3)), kOscillate * 3 / wd);
  auto rel = [&](double t) { return std::sin(W * t) / W; };
  EXPECT_LT(r.Error("relativeStates.phi_rel", rel), kOscillate / W);
  EXPECT_LT(r.Error("relativeStates.w_rel", [&](double t) { return std::cos(W * t); }), kOscillate);
  EXPECT_LT(r.Error("inertia6.phi", [&](double t) { return t / 2 - rel(t) / 2; }), kOscillate / W);
  EXPECT_LT(r.Error("inertia7.w", [&](double t) { return 0.5 + std::cos(W * t) / 2; }), kOscillate);
  EXPECT_LT(r.Error("spring.tau", [&](double t) { return 1e4 * rel(t); }), kOscillate * 1e4 / W);
}


// ------------------------------------------------------------------------------------------
// The last MSL Rotational elements (sim/src/msl_extra_elements.cc).

// Disc: torque 2 on J1 = 1, through the disc (deltaPhi = 0.5) to J2 = 3: a = 0.5 for both,
// inertia2.phi = inertia1.phi + 0.5 from the holonomic start row, the torque through J2 * a.
TEST(Disc, TurnsFlangeBByDeltaPhiAndPassesTheTorque) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "drive", P({{"tau_constant", 2}}));
  net.AddElement("Inertia", "inertia1", P({{"J", 1}, {"phi_start", 0.25}, {"w_start", 0}}));
  net.AddElement("Disc", "disc", P({{"deltaPhi", 0.5}}));
  net.AddElement("Inertia", "inertia2", P({{"J", 3}}));
  net.Connect("drive.flange", "inertia1.flange_a");
  net.Connect("drive.support", "fixed.flange");
  net.Connect("inertia1.flange_b", "disc.flange_a");
  net.Connect("disc.flange_b", "inertia2.flange_a");
  EXPECT_EQ(CheckStructure(net), "");
  const Result r = Simulate(net, 1.0);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia1.phi", [](double t) { return 0.25 + 0.25 * t * t; }), 1e-8);
  EXPECT_LT(r.Error("inertia2.phi", [](double t) { return 0.75 + 0.25 * t * t; }), 1e-8);
  EXPECT_LT(r.Error("inertia2.w", [](double t) { return 0.5 * t; }), 1e-8);
  EXPECT_LT(r.Error("disc.phi", [](double t) { return 0.5 + 0.25 * t * t; }), 1e-8);
  EXPECT_LT(r.Error("disc.flange_a.tau", [](double) { return 1.5; }), 1e-8);
}

// A fixed inertia2 start angle that contradicts deltaPhi is named; a Disc between two springs
// joins two flanges without inertia rigidly (undetermined), as a torque sensor there.
TEST(Disc, ContradictingStartsAndAMasslessJointAreNamed) {
  Network net;
  net.AddElement("Inertia", "inertia1", P({{"J", 1}, {"phi_start", 0}}));
  net.AddElement("Disc", "disc", P({{"deltaPhi", 0.5}}));
  net.AddElement("Inertia", "inertia2", P({{"J", 3}, {"phi_start", 0}}));
  net.Connect("inertia1.flange_b", "disc.flange_a");
  net.Connect("disc.flange_b", "inertia2.flange_a");
  EXPECT_NE(CheckStructure(net).find("initial angles contradict"), std::string::npos) << CheckStructure(net);
  Network springs;
  springs.AddElement("Fixed", "fixed");
  springs.AddElement("Spring", "spring1", P({{"c", 1}}));
  springs.AddElement("Disc", "disc");
  springs.AddElement("Spring", "spring2", P({{"c", 1}}));
  springs.AddElement("Inertia", "inertia", P({{"J", 1}}));
  springs.Connect("fixed.flange", "spring1.flange_a");
  springs.Connect("spring1.flange_b", "disc.flange_a");
  springs.Connect("disc.flange_b", "spring2.flange_a");
  springs.Connect("spring2.flange_b", "inertia.flange_a");
  EXPECT_NE(CheckStructure(springs).find("element 'disc' (Disc) joins flanges"), std::string::npos)
      << CheckStructure(springs);
}

// tests/sim/msl/Disc.json: 4 x'' + 16 x = 2 sin(2 pi t) from rest, inertia2 turned by 0.5.
TEST(MslExamples, DiscAsTheClosedForm) {
  const Result r = RunExample("Disc");
  const double A = 0.5 / (4 - 4 * kPi * kPi);
  auto x = [&](double t) { return A * (std::sin(2 * kPi * t) - kPi * std::sin(2 * t)); };
  auto xdd = [&](double t) { return A * (-4 * kPi * kPi * std::sin(2 * kPi * t) + 4 * kPi * std::sin(2 * t)); };
  EXPECT_LT(r.Error("inertia1.phi", x), 1e-7);
  EXPECT_LT(r.Error("inertia2.phi", [&](double t) { return x(t) + 0.5; }), 1e-7);
  EXPECT_LT(r.Error("disc.flange_a.tau", [&](double t) { return 3 * xdd(t) + 16 * x(t); }), 1e-6);
}


// InitializeFlange: phi_start = 1 and w_start = 3 from inputs (a_start not used), torque 4 on
// J = 2: phi = 1 + 3 t + t^2.
TEST(InitializeFlange, SetsTheStartAngleAndSpeedFromItsInputs) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ConstantTorque", "drive", P({{"tau_constant", 4}}));
  net.AddElement("Inertia", "inertia", P({{"J", 2}}));
  net.AddElement("InitializeFlange", "init", P({{"use_a_start", 0}}));
  net.AddElement("Constant", "phi0", P({{"k", 1}}));
  net.AddElement("Constant", "w0", P({{"k", 3}}));
  net.Connect("drive.flange", "inertia.flange_a");
  net.Connect("drive.support", "fixed.flange");
  net.Connect("init.flange", "inertia.flange_b");
  net.Connect("phi0.y", "init.phi_start");
  net.Connect("w0.y", "init.w_start");
  EXPECT_EQ(CheckStructure(net), "");
  const Result r = Simulate(net, 1.0);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia.phi", [](double t) { return 1 + 3 * t + t * t; }), 1e-8);
  EXPECT_LT(r.Error("init.w_flange", [](double t) { return 3 + 2 * t; }), 1e-8);
}

// An enabled input left open is named; a fixed Inertia start angle that differs from the
// input is a contradiction (MSL: an overdetermined initialization).
TEST(InitializeFlange, OpenInputsAndContradictingStartsAreNamed) {
  Network open;
  open.AddElement("Inertia", "inertia", P({{"J", 1}}));
  open.AddElement("InitializeFlange", "init", P({{"use_w_start", 0}, {"use_a_start", 0}}));
  open.Connect("init.flange", "inertia.flange_a");
  EXPECT_NE(CheckStructure(open).find("signal input 'phi_start' is not connected"), std::string::npos)
      << CheckStructure(open);
  Network twice;
  twice.AddElement("Inertia", "inertia", P({{"J", 1}, {"phi_start", 2}}));
  twice.AddElement("InitializeFlange", "init", P({{"use_w_start", 0}, {"use_a_start", 0}}));
  twice.AddElement("Constant", "phi0", P({{"k", 1}}));
  twice.Connect("init.flange", "inertia.flange_a");
  twice.Connect("phi0.y", "init.phi_start");
  EXPECT_NE(CheckStructure(twice).find("initial angles contradict"), std::string::npos) << CheckStructure(twice);
}

// tests/sim/msl/InitializeFlange.json: der(w) = a_start = -2 on the spring c = 4 gives
// phi(0) = 0.5, then phi = 0.5 cos(2 t).
TEST(MslExamples, InitializeFlangeAsTheClosedForm) {
  const Result r = RunExample("InitializeFlange");
  EXPECT_LT(r.Error("inertia.phi", [](double t) { return 0.5 * std::cos(2 * t); }), 1e-7);
  EXPECT_LT(r.Error("inertia.w", [](double t) { return -std::sin(2 * t); }), 1e-7);
  EXPECT_LT(r.Error("initializeFlange.phi_flange", [](double t) { return 0.5 * std::cos(2 * t); }), 1e-7);
}


// InverseSpeedDependentTorque, TorqueDirection = false below w0: tau = tau_nominal * w / w0 =
// -w on J = 1 from w = 0.5 (< w0 = 1): w = 0.5 exp(-t); above w0 -tau_nominal*w_nominal/w.
TEST(InverseSpeedDependentTorque, OddLawBelowAndAboveW0) {
  for (double w_start : {0.5, 4.0}) {
    Network net;
    net.AddElement("Inertia", "inertia", P({{"J", 1}, {"phi_start", 0}, {"w_start", w_start}}));
    net.AddElement("InverseSpeedDependentTorque", "load",
                   P({{"tau_nominal", -1}, {"w_nominal", 2}, {"w0", 1}, {"TorqueDirection", 0}}));
    net.Connect("load.flange", "inertia.flange_a");
    const Result r = Simulate(net, w_start < 1 ? 1.0 : 3.0);
    ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
    if (w_start < 1) {
      EXPECT_LT(r.Error("inertia.w", [](double t) { return 0.5 * std::exp(-t); }), 1e-8);
      EXPECT_LT(r.Error("load.tau", [](double t) { return -0.5 * std::exp(-t); }), 1e-8);
    } else {  // w w' = -2: w = sqrt(16 - 4 t) while w >= 1 (t <= 3.75)
      EXPECT_LT(r.Error("inertia.w", [](double t) { return std::sqrt(16 - 4 * t); }), 1e-6);
    }
  }
}

// tests/sim/msl/InverseSpeedDependentTorque.json: the braking of inertia6 in three pieces.
TEST(MslExamples, InverseSpeedDependentTorqueAsTheClosedForm) {
  const Result r = RunExample("InverseSpeedDependentTorque");
  const double t1 = (1e4 - 1) / 2e4, t2 = t1 + 2e-4;
  auto w = [&](double t) {
    if (t <= t1) return std::sqrt(1e4 - 2e4 * t);
    if (t <= t2) return 1 - 1e4 * (t - t1);
    return -std::sqrt(1 + 2e4 * (t - t2));
  };
  auto phi = [&](double t) {
    if (t <= t1) return (1e6 - std::pow(1e4 - 2e4 * t, 1.5)) / 3e4;
    const double p1 = (1e6 - 1) / 3e4;
    if (t <= t2) return p1 + (t - t1) - 0.5e4 * (t - t1) * (t - t1);
    return p1 - (std::pow(1 + 2e4 * (t - t2), 1.5) - 1) / 3e4;
  };
  // Near t1 the speed falls at 1e4 rad/s^2 (w = 1): a time error of 1e-7 s is 1e-3 rad/s there.
  EXPECT_LT(r.Error("inertia6.w", w), 1e-3);
  EXPECT_LT(r.Error("inertia6.phi", phi), 1e-5);
  EXPECT_LT(r.Error("inverseSpeedDependentTorque.tau", [&](double t) { return -1e4 / std::max(std::abs(w(t)), 1.0); }),
            5.0);  // of 1e4 N*m
}


// Gearbox: the same network written with the MSL Gearbox and with its parts (LossyGear with a
// loss table, then ElastoBacklash with backlash) runs the same, state for state.
Network GearboxDrive(bool composite) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Sine", "sine", P({{"amplitude", 10}, {"f", 1}}));
  net.AddElement("Torque", "torque");
  net.AddElement("Inertia", "inertia1", P({{"J", 0.1}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("Inertia", "inertia2", P({{"J", 2}, {"phi_start", 0}, {"w_start", 0}}));
  net.AddElement("Damper", "load", P({{"d", 5}}));
  const std::vector<std::vector<double>> loss{{0, 0.9, 0.8, 0.2, 0.2}, {10, 0.85, 0.75, 0.3, 0.3}};
  if (composite) {
    net.AddElement("Gearbox", "gearbox", {.scalars = {{"ratio", 4}, {"c", 1e3}, {"d", 10}, {"b", 0.02}},
                                          .tables = {{"lossTable", loss}}});
  } else {
    net.AddElement("LossyGear", "lossyGear", {.scalars = {{"ratio", 4}}, .tables = {{"lossTable", loss}}});
    net.AddElement("ElastoBacklash", "gearbox", P({{"c", 1e3}, {"d", 10}, {"b", 0.02}}));
    net.Connect("lossyGear.flange_b", "gearbox.flange_a");
    net.Connect("lossyGear.support", "fixed.flange");
  }
  net.Connect("sine.y", "torque.tau");
  net.Connect("torque.support", "fixed.flange");
  net.Connect("torque.flange", "inertia1.flange_a");
  net.Connect("inertia1.flange_b", composite ? "gearbox.flange_a" : "lossyGear.flange_a");
  net.Connect("gearbox.flange_b", "inertia2.flange_a");
  if (composite) net.Connect("gearbox.support", "fixed.flange");
  net.Connect("inertia2.flange_b", "load.flange_a");
  net.Connect("load.flange_b", "fixed.flange");
  return net;
}

TEST(Gearbox, IsLossyGearThenElastoBacklash) {
  EXPECT_EQ(CheckStructure(GearboxDrive(true)), "");
  const Result box = Simulate(GearboxDrive(true), 2.0);
  const Result parts = Simulate(GearboxDrive(false), 2.0);
  ASSERT_TRUE(box.report.ok()) << box.report.FullReport();
  ASSERT_TRUE(parts.report.ok()) << parts.report.FullReport();
  ASSERT_EQ(box.t().size(), parts.t().size());
  for (const char* column : {"inertia1.w", "inertia2.w", "inertia2.phi", "gearbox.phi_rel"}) {
    const auto a = box.Col(column), b = parts.Col(column);
    double worst = 0.0, range = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i])), range = std::max(range, std::abs(b[i]));
    EXPECT_LT(worst, 1e-9 * (1 + range)) << column;
    EXPECT_GT(range, 0.0) << column;
  }
}

TEST(Gearbox, RequiresItsStiffness) {
  Network net;
  try {
    net.AddElement("Gearbox", "gearbox", P({{"ratio", 2}}));
    net.AddElement("Inertia", "inertia", P({{"J", 1}}));
    net.Connect("gearbox.flange_b", "inertia.flange_a");
    const std::string error = CheckStructure(net);
    EXPECT_NE(error.find("'c'"), std::string::npos) << error;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'c'"), std::string::npos) << e.what();
  }
}

// tests/sim/msl/Gearbox.json: the ideal gearbox against Runge-Kutta of
// J1 a1 = tau + T / 4, J2 a2 = -T, T = c (phi2 - phi1 / 4) + d (w2 - w1 / 4).
TEST(MslExamples, GearboxAgainstAnIndependentIntegration) {
  const Result r = RunExample("Gearbox");
  auto f = [](double t, const State4& x) {  // phi1, w1, phi2, w2
    const double T = 1e3 * (x[2] - x[0] / 4) + 10 * (x[3] - x[1] / 4);
    return State4{x[1], (10 * std::sin(2 * kPi * t) + T / 4) / 0.1, x[3], -T / 2};
  };
  const auto dev = DeviationFromIntegration<4>(
      r, f, State4{0, 0, 0, 0}, 1e-4,
      {{"inertia1.w", [](double, const State4& x) { return x[1]; }},
       {"inertia2.phi", [](double, const State4& x) { return x[2]; }},
       {"inertia2.w", [](double, const State4& x) { return x[3]; }},
       {"gearbox.phi_rel", [](double, const State4& x) { return x[2] - x[0] / 4; }}});
  for (const auto& [name, e] : dev) EXPECT_LT(e.error, 1e-6 * e.range) << name;
}


// RelativeStates reports a_rel; on a massless node the balance gives no acceleration, so
// validate and simulate name it (the same shared check), as for the acceleration sensors.
TEST(MasslessNode, RelativeStatesAcrossAMasslessNodeIsNamed) {
  Network net = InSeries({{"Spring", "spring1"}, {"Spring", "spring2"}});
  net.AddElement("RelativeStates", "relativeStates");
  net.Connect("relativeStates.flange_a", "spring1.flange_b");
  net.Connect("relativeStates.flange_b", "inertia.flange_b");
  const std::string error = CheckStructure(net);
  EXPECT_NE(error.find("element 'relativeStates' (RelativeStates) measures the acceleration of flange "
                       "'spring1.flange_b', which has no inertia"),
            std::string::npos)
      << error;
  try {
    Simulator sim(net);
    MemorySink sink;
    sim.Run(SimulationOptions{}, sink);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), error);
  }
}


// tests/sim/msl/Adaptors.json: torqueToAngle drives inertia1 by -tau = -10 sin(4 pi t):
// a = -tau / 1.1, w = -10 (1 - cos(4 pi t)) / (4 pi 1.1); angleToTorque moves inertia2 by
// phi = 0.1 sin(2 pi t) and gives tau = 2.2 a.
TEST(MslExamples, AdaptorsAsTheClosedForm) {
  const Result r = RunExample("Adaptors");
  const double w4 = 4 * kPi;
  EXPECT_LT(r.Error("a1.y", [&](double t) { return -10 * std::sin(w4 * t) / 1.1; }), 1e-7);
  EXPECT_LT(r.Error("w1.y", [&](double t) { return -10 * (1 - std::cos(w4 * t)) / (w4 * 1.1); }), 1e-7);
  EXPECT_LT(r.Error("phi1.y", [&](double t) { return -10 * (t - std::sin(w4 * t) / w4) / (w4 * 1.1); }), 1e-7);
  EXPECT_LT(r.Error("inertia1.w", [&](double t) { return -10 * (1 - std::cos(w4 * t)) / (w4 * 1.1); }), 1e-7);
  EXPECT_LT(r.Error("inertia2.phi", [](double t) { return 0.1 * std::sin(2 * kPi * t); }), 1e-8);
  EXPECT_LT(r.Error("tau2.y", [](double t) { return -2.2 * 0.4 * kPi * kPi * std::sin(2 * kPi * t); }), 1e-6);
}

// AngleToTorqueAdaptor with use_a = false follows phi exactly (differentiated, MSL Move_phi).
TEST(AngleToTorqueAdaptor, FollowsTheAngleAloneWithoutA) {
  Network net;
  net.AddElement("Sine", "phiRef", P({{"amplitude", 0.1}, {"f", 1}}));
  net.AddElement("AngleToTorqueAdaptor", "adaptor", P({{"use_w", 0}, {"use_a", 0}}));
  net.AddElement("Inertia", "inertia", P({{"J", 2.2}}));
  net.AddElement("Gain", "tau", P({{"k", 1}}));
  net.Connect("phiRef.y", "adaptor.phi");
  net.Connect("adaptor.flange", "inertia.flange_a");
  net.Connect("adaptor.tau", "tau.u");
  EXPECT_EQ(CheckStructure(net), "");
  const Result r = Simulate(net, 1.0);
  ASSERT_TRUE(r.report.ok()) << r.report.FullReport();
  EXPECT_LT(r.Error("inertia.phi", [](double t) { return 0.1 * std::sin(2 * kPi * t); }), 1e-8);
  EXPECT_LT(r.Error("tau.y", [](double t) { return -2.2 * 0.4 * kPi * kPi * std::sin(2 * kPi * t); }), 1e-6);
}

}  // namespace
}  // namespace highlift::sim
