// Initial equations on accelerations (MSL a(start = a_start, fixed = true)) and the steady-state
// start (SimulationOptions::start = kSteadyState): the free start values are solved for them.
// Every case has a closed form:
//   inertia J, damper d to the housing, constant torque tau:  J dw/dt = tau - d w
//     a(0) = a_start  =>  w(0) = (tau - J a_start) / d,  w(t) = tau/d + (w(0) - tau/d) e^(-d t / J)
//     steady state    =>  w = tau / d for all t
//   inertia J, spring c to the housing, constant torque tau:  steady state phi = tau / c
//   inertia J, quadratic load tau_nominal w |w| (tau_nominal < 0), constant drive tau:
//     steady state  =>  w = sqrt(tau / -tau_nominal)
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "highlift/core/error.h"
#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

using Scalars = std::map<std::string, double>;
ElementParameters P(Scalars s) { return {std::move(s), {}}; }

constexpr double kJ = 2.0, kD = 4.0, kTau = 8.0, kC = 100.0;

// Inertia "J" on the housing through `law` ("Damper", "Spring", "SpringDamper"), driven by a
// constant torque kTau.
Network Loaded(const std::string& law, Scalars inertia) {
  Network net;
  net.AddElement("Fixed", "fixed");
  inertia["J"] = kJ;
  net.AddElement("Inertia", "J", P(inertia));
  Scalars law_parameters;
  if (law != "Spring") law_parameters["d"] = kD;
  if (law != "Damper") law_parameters["c"] = kC;
  net.AddElement(law, "law", P(law_parameters));
  net.Connect("fixed.flange", "law.flange_a");
  net.Connect("law.flange_b", "J.flange_a");
  net.AddElement("ConstantTorque", "drive", P({{"tau_constant", kTau}}));
  net.Connect("drive.flange", "J.flange_b");
  return net;
}

MemorySink Simulate(const Network& net, StartKind start = StartKind::kGiven, SimulationReport* report = nullptr) {
  Simulator sim(net);
  SimulationOptions o;
  o.stop_time = 2.0;
  o.output_interval = 1e-2;
  o.relative_tolerance = 1e-9;
  o.absolute_tolerance = 1e-11;
  o.start = start;
  MemorySink sink;
  const SimulationReport r = sim.Run(o, sink);
  EXPECT_TRUE(r.ok()) << r.FullReport();
  if (report) *report = r;
  return sink;
}

std::string ErrorOf(const Network& net, StartKind start = StartKind::kGiven) {
  try {
    Simulate(net, start);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(InitialAccelerations, AStartDeterminesTheFreeSpeed) {
  const double a_start = 2.0, w0 = (kTau - kJ * a_start) / kD;  // 1 rad/s
  SimulationReport report;
  const MemorySink sink = Simulate(Loaded("Damper", {{"a_start", a_start}}), StartKind::kGiven, &report);
  const auto w = sink.Series("J.w"), a = sink.Series("J.a");
  EXPECT_NEAR(a[0], a_start, 1e-9);
  EXPECT_NEAR(w[0], w0, 1e-9);
  double worst = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double t = sink.times()[i];
    worst = std::max(worst, std::abs(w[i] - (kTau / kD + (w0 - kTau / kD) * std::exp(-kD * t / kJ))));
  }
  EXPECT_LT(worst, 1e-7);
  bool accounted = false;
  for (const auto& e : report.events) accounted = accounted || e.what.find("J.w") != std::string::npos;
  EXPECT_TRUE(accounted) << report.FullReport();
}

TEST(InitialAccelerations, AStartZeroIsTheSteadySpeedOfTheDamper) {
  const MemorySink sink = Simulate(Loaded("Damper", {{"a_start", 0.0}, {"w_start", 0.5}, {"w_fixed", 0}}));
  for (double w : sink.Series("J.w")) EXPECT_NEAR(w, kTau / kD, 1e-8);
}

TEST(InitialAccelerations, AFixedFalseIgnoresAStart) {
  const MemorySink sink = Simulate(Loaded("Damper", {{"a_start", 3.0}, {"a_fixed", 0}, {"w_start", 0}}));
  EXPECT_NEAR(sink.Series("J.a")[0], kTau / kJ, 1e-9);  // w(0) = 0: a = tau / J
}

TEST(InitialAccelerations, SpringDeflectionFromAStartZero) {
  // The angle is free (not given), the speed given: phi = tau / c, at rest for the whole run.
  const MemorySink sink = Simulate(Loaded("Spring", {{"a_start", 0.0}, {"w_start", 0.0}}));
  for (double phi : sink.Series("J.phi")) EXPECT_NEAR(phi, kTau / kC, 1e-9);
  for (double phi_rel : sink.Series("law.phi_rel")) EXPECT_NEAR(phi_rel, kTau / kC, 1e-9);
  for (double w : sink.Series("J.w")) EXPECT_NEAR(w, 0.0, 1e-9);
}

TEST(SteadyStateStart, DamperRunsAtTauOverD) {
  const MemorySink sink = Simulate(Loaded("Damper", {}), StartKind::kSteadyState);
  for (double w : sink.Series("J.w")) EXPECT_NEAR(w, kTau / kD, 1e-8);
  for (double a : sink.Series("J.a")) EXPECT_NEAR(a, 0.0, 1e-8);
}

TEST(SteadyStateStart, SpringDamperRestsAtItsDeflection) {
  // Steady state: a = 0 and der(phi_rel) = 0, so w = 0 and phi = tau / c.
  const MemorySink sink = Simulate(Loaded("SpringDamper", {}), StartKind::kSteadyState);
  for (double phi : sink.Series("J.phi")) EXPECT_NEAR(phi, kTau / kC, 1e-9);
  for (double w : sink.Series("J.w")) EXPECT_NEAR(w, 0.0, 1e-9);
}

TEST(SteadyStateStart, NonlinearLoadFromAGuess) {
  // Drive 8 N*m against the load -2 w |w|: w = 2 rad/s, found by Newton from the guess 1 rad/s.
  Network net;
  net.AddElement("Inertia", "J", P({{"J", kJ}, {"w_start", 1.0}, {"w_fixed", 0}}));
  net.AddElement("QuadraticSpeedDependentTorque", "load",
                 P({{"tau_nominal", -2.0}, {"w_nominal", 1.0}, {"TorqueDirection", 0}}));
  net.AddElement("ConstantTorque", "drive", P({{"tau_constant", kTau}}));
  net.Connect("load.flange", "J.flange_a");
  net.Connect("drive.flange", "J.flange_b");
  for (double w : Simulate(net, StartKind::kSteadyState).Series("J.w")) EXPECT_NEAR(w, 2.0, 1e-8);
}

TEST(SteadyStateStart, TranslationalMassAndDamper) {
  // m dv/dt = f - d v: steady state v = f / d.
  Network net;
  net.AddElement("Translational.Fixed", "fixed");
  net.AddElement("Mass", "mass", P({{"m", kJ}, {"s_start", 0.0}}));
  net.AddElement("Translational.Damper", "damper", P({{"d", kD}}));
  net.AddElement("Constant", "f", P({{"k", kTau}}));
  net.AddElement("Translational.Force", "force");
  net.Connect("fixed.flange", "damper.flange_a");
  net.Connect("damper.flange_b", "mass.flange_a");
  net.Connect("force.flange", "mass.flange_b");
  net.Connect("f.y", "force.f");
  for (double v : Simulate(net, StartKind::kSteadyState).Series("mass.v")) EXPECT_NEAR(v, kTau / kD, 1e-8);
}

TEST(InitialAccelerations, OverDeterminedNamesTheElement) {
  // phi and w are fixed: nothing is left for a = a_start to determine.
  const std::string error = ErrorOf(Loaded("Damper", {{"a_start", 1.0}, {"w_start", 0.0}, {"phi_start", 0.0}}));
  EXPECT_NE(error.find("element 'J' (Inertia)"), std::string::npos) << error;
  EXPECT_NE(error.find("over-determined"), std::string::npos) << error;
  EXPECT_NE(error.find("w_fixed = false"), std::string::npos) << error;
  // validate says the same (the shared structural check).
  EXPECT_EQ(CheckStructure(Loaded("Damper", {{"a_start", 1.0}, {"w_start", 0.0}, {"phi_start", 0.0}})), error);
}

TEST(InitialAccelerations, UnderDeterminedAsksToFixOne) {
  // a = (tau - c phi - d w) / J = 0 with phi and w both free: one equation, two unknowns.
  const std::string error = ErrorOf(Loaded("SpringDamper", {{"a_start", 0.0}}));
  EXPECT_NE(error.find("under-determined"), std::string::npos) << error;
  EXPECT_NE(error.find("J.phi"), std::string::npos) << error;
  EXPECT_NE(error.find("J.w"), std::string::npos) << error;
  EXPECT_NE(error.find("fix one of them"), std::string::npos) << error;
}

TEST(SteadyStateStart, ImpossibleWithoutALoadThatDependsOnSpeed) {
  // A free inertia under a constant torque accelerates at tau / J whatever its speed.
  Network net;
  net.AddElement("Inertia", "J", P({{"J", kJ}}));
  net.AddElement("ConstantTorque", "drive", P({{"tau_constant", kTau}}));
  net.Connect("drive.flange", "J.flange_a");
  const std::string error = ErrorOf(net, StartKind::kSteadyState);
  EXPECT_NE(error.find("der(J.w) = 0 does not hold"), std::string::npos) << error;
  EXPECT_NE(error.find("a = 4"), std::string::npos) << error;
  EXPECT_NE(error.find("steady-state start"), std::string::npos) << error;
}

TEST(SteadyStateStart, GivenStartIsUnchanged) {
  // Without a_start and with the given start, nothing is solved: w(0) = 0.
  EXPECT_NEAR(Simulate(Loaded("Damper", {})).Series("J.w")[0], 0.0, 0.0);
}

TEST(StartKind, RoundTripsAndRejectsUnknownNames) {
  for (StartKind k : {StartKind::kGiven, StartKind::kSteadyState}) EXPECT_EQ(ParseStartKind(ToString(k)), k);
  EXPECT_EQ(ParseStartKind("steady-state"), StartKind::kSteadyState);
  try {
    ParseStartKind("equilibrium");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown start 'equilibrium'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("steady_state"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace highlift::sim
