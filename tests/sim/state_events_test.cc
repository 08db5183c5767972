// The state events the simulator finds itself (sim/src/simulator.cc): the root functions are
// compared at every step end and a crossing is located on CVODE's interpolant; a kink lets
// CVODE go on with the rest of its step, an event that changes the equations restarts it.
// Against closed forms: an inertia that bounces between the two contacts of a backlash.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

ElementParameters P(std::map<std::string, double> s) { return {std::move(s), {}}; }

struct Bounce {
  double J = 0.5, c = 2000.0, b = 0.02, w0 = 1.0;
  double omega() const { return std::sqrt(c / J); }
  /// The contact times: a free flight from the middle to b/2, then alternately half a period
  /// of the spring in contact and a flight of b / w0 across the gap.
  std::vector<double> Times(double stop) const {
    std::vector<double> times;
    double t = 0.5 * b / w0;
    for (int k = 0; t < stop; ++k) {
      times.push_back(t);
      t += k % 2 == 0 ? std::numbers::pi / omega() : b / w0;
    }
    return times;
  }
};

Network BounceNetwork(const Bounce& s) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("ElastoBacklash", "backlash", P({{"c", s.c}, {"d", 0.0}, {"b", s.b}}));
  net.AddElement("Inertia", "mass", P({{"J", s.J}, {"phi_start", 0.0}, {"w_start", s.w0}}));
  net.Connect("fixed.flange", "backlash.flange_a");
  net.Connect("backlash.flange_b", "mass.flange_a");
  return net;
}

SimulationReport RunBounce(const Network& net, double stop, double dt, double rtol, MemorySink& sink) {
  Simulator sim(net);
  SimulationOptions o;
  o.stop_time = stop;
  o.output_interval = dt;
  o.relative_tolerance = rtol;
  o.absolute_tolerance = 1e-3 * rtol;
  return sim.Run(o, sink);
}

std::vector<double> ContactTimes(const SimulationReport& report) {
  std::vector<double> times;
  for (const SimulationEvent& e : report.events)
    if (e.what.find("backlash") != std::string::npos) times.push_back(e.time);
  return times;
}

// Every contact and every separation is found, at its time to the integration's accuracy, as a
// kink: no restart of the integrator, and the bounce keeps its energy.
TEST(StateEvents, BacklashContactsAreLocatedAtTheirTimesWithoutARestart) {
  const Bounce s;
  const double stop = 0.49;  // in flight after the 14th event
  const std::vector<double> expected = s.Times(stop);
  ASSERT_EQ(expected.size(), 14u);
  for (double dt : {1e-3, 0.1}) {  // the output step does not matter: the roots follow the steps
    MemorySink sink;
    const SimulationReport report = RunBounce(BounceNetwork(s), stop, dt, 1e-10, sink);
    ASSERT_TRUE(report.ok()) << report.FullReport();
    const std::vector<double> found = ContactTimes(report);
    ASSERT_EQ(found.size(), expected.size()) << report.FullReport();
    for (std::size_t i = 0; i < found.size(); ++i)
      EXPECT_NEAR(found[i], expected[i], 1e-8) << "contact event " << i << " (dt " << dt << ")";
    EXPECT_EQ(report.statistics.reinitialisations, 0) << "a contact is a kink, not a restart";
    EXPECT_EQ(report.statistics.continuous_roots, static_cast<long>(expected.size()));
    EXPECT_NEAR(std::abs(sink.Series("mass.w").back()), s.w0, 1e-7) << "in flight at the stop time";
  }
}

// The default tolerance finds the same contacts; their times are as accurate as the integration.
TEST(StateEvents, TheDefaultToleranceFindsEveryContact) {
  const Bounce s;
  const double stop = 0.5;
  const std::vector<double> expected = s.Times(stop);
  MemorySink sink;
  const SimulationReport report = RunBounce(BounceNetwork(s), stop, 1e-3, 1e-5, sink);
  ASSERT_TRUE(report.ok()) << report.FullReport();
  const std::vector<double> found = ContactTimes(report);
  ASSERT_EQ(found.size(), expected.size()) << report.FullReport();
  for (std::size_t i = 0; i < found.size(); ++i) EXPECT_NEAR(found[i], expected[i], 1e-4) << "contact event " << i;
}

}  // namespace
}  // namespace highlift::sim
