// Events at and near t = 0: a Brake, Clutch or OneWayClutch whose normal force f_normalized is
// exactly 0 at t = 0 and rises from there (a sine or a ramp), on a loaded and on an unloaded
// shaft. Regression tests of issue 14: the normal-force root was located at a negative time,
// which then stopped the run with `CVodeSetStopTime failed with CV_ILL_INPUT` or looped
// through 100 000 events. Each case has a closed-form solution (J = 1, fn_max*cgeo*mu = 50 N*m
// at f_normalized = 1):
//   capacity C(t) = 50 f(t),  I(t) = integral of C from 0 to t
//   ramp f = t:          I = 25 t^2
//   sine f = sin(pi t):  I = (50/pi) (1 - cos(pi t))
// The difference of the two speeds the element couples, d(t) = d0 + L t - k I(t) (k = 1 for a
// brake, the shaft against the housing; k = 2 for a clutch between two unit inertias), falls to
// zero at t*, after which the element sticks and holds.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

using Scalars = std::map<std::string, double>;

ElementParameters P(Scalars s) { return {std::move(s), {}}; }

enum class Kind { kBrake, kClutch, kOneWayClutch };
enum class Signal { kRamp, kSine };

struct Case {
  Kind kind;
  Signal signal;
  bool loaded;
};

std::string Name(const Case& c) {
  const char* kind = c.kind == Kind::kBrake ? "Brake" : (c.kind == Kind::kClutch ? "Clutch" : "OneWayClutch");
  return std::string(kind) + (c.signal == Signal::kRamp ? "Ramp" : "Sine") + (c.loaded ? "Loaded" : "Unloaded");
}

constexpr double kPi = std::numbers::pi;
constexpr double kLoad = 5.0;   // N*m, the load torque of the loaded cases
constexpr double kSpeed = 10.0;  // rad/s, the initial slip of the unloaded cases

double I(Signal s, double t) {
  return s == Signal::kRamp ? 25 * t * t : 50 / kPi * (1 - std::cos(kPi * t));
}

// Speed difference d(t) before sticking, and the sum of the two speeds (clutches).
double D(const Case& c, double t) {
  const double k = c.kind == Kind::kBrake ? 1.0 : 2.0;
  return (c.loaded ? kLoad * t : kSpeed) - k * I(c.signal, t);
}
double Sum(const Case& c, double t) { return c.loaded ? kLoad * t : kSpeed; }

// The time the slip reaches zero (bisection on d, which has one sign change in (0, 0.9)).
double StickTime(const Case& c) {
  double lo = 1e-6, hi = 0.9;
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (lo + hi);
    (D(c, m) > 0 ? lo : hi) = m;
  }
  return 0.5 * (lo + hi);
}

Network Build(const Case& c) {
  Network net;
  net.AddElement("Fixed", "fixed");
  if (c.signal == Signal::kRamp) net.AddElement("Ramp", "f", P({{"height", 1}, {"duration", 1}}));
  else net.AddElement("Sine", "f", P({{"amplitude", 1}, {"f", 0.5}}));
  const Scalars friction{{"fn_max", 100}};  // mu = 0.5, cgeo = 1, peak = 1: C = 50 f
  if (c.kind == Kind::kBrake) {
    // fast = the shaft, slow = the housing.
    net.AddElement("Inertia", "fast", P({{"J", 1}, {"phi_start", 0}, {"w_start", c.loaded ? 0 : kSpeed}}));
    net.AddElement("Brake", "element", P(friction));
    net.Connect("fast.flange_b", "element.flange_a");
    net.Connect("element.support", "fixed.flange");
  } else {
    // Clutch: flange_a = fast (it slips ahead); OneWayClutch: flange_b = fast (overrunning).
    net.AddElement("Inertia", "fast", P({{"J", 1}, {"phi_start", 0}, {"w_start", c.loaded ? 0 : kSpeed}}));
    net.AddElement("Inertia", "slow", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
    net.AddElement(c.kind == Kind::kClutch ? "Clutch" : "OneWayClutch", "element", P(friction));
    const bool fast_is_a = c.kind == Kind::kClutch;
    net.Connect(fast_is_a ? "fast.flange_b" : "slow.flange_b", "element.flange_a");
    net.Connect("element.flange_b", fast_is_a ? "slow.flange_a" : "fast.flange_a");
  }
  net.Connect("f.y", "element.f_normalized");
  if (c.loaded) {
    net.AddElement("ConstantTorque", "load", P({{"tau_constant", kLoad}}));
    net.Connect("load.flange", "fast.flange_a");
    net.Connect("load.support", "fixed.flange");
  }
  return net;
}

class StartEvents : public ::testing::TestWithParam<Case> {};

TEST_P(StartEvents, EngagesFromZeroNormalForceAsTheClosedForm) {
  const Case c = GetParam();
  Simulator sim(Build(c));
  SimulationOptions o;
  o.stop_time = 0.9;
  o.output_interval = 1e-3;
  o.relative_tolerance = 1e-8;
  o.absolute_tolerance = 1e-10;
  MemorySink sink;
  const SimulationReport r = sim.Run(o, sink);
  ASSERT_TRUE(r.ok()) << Name(c) << ": " << r.FullReport();
  // No root before the start, no storm of events: the start, the engagement, the sticking.
  for (const auto& e : r.events) EXPECT_GE(e.time, 0.0) << Name(c) << ": event at negative time\n" << r.FullReport();
  for (double t : sink.times()) ASSERT_GE(t, 0.0) << Name(c) << ": output row at negative time";
  EXPECT_LE(r.events.size(), 8u) << Name(c) << ": " << r.FullReport();

  const double t_stick = StickTime(c);
  const auto w_fast = sink.Series("fast.w");
  const bool brake = c.kind == Kind::kBrake;
  const auto w_slow = brake ? std::vector<double>(w_fast.size(), 0.0) : sink.Series("slow.w");
  double worst = 0.0, worst_t = 0.0;
  for (std::size_t i = 0; i < sink.times().size(); ++i) {
    const double t = sink.times()[i];
    if (std::abs(t - t_stick) < 2e-3) continue;  // the kink: compared on both sides, not across
    const double d = t < t_stick ? D(c, t) : 0.0;
    const double s = brake ? d : Sum(c, t);
    const double fast = brake ? d : 0.5 * (s + d), slow = brake ? 0.0 : 0.5 * (s - d);
    const double err = std::max(std::abs(w_fast[i] - fast), std::abs(w_slow[i] - slow));
    if (err > worst) worst = err, worst_t = t;
  }
  // 1e-6 of the speed scale (the initial slip of 10 rad/s, or 1 rad/s).
  const double scale = c.loaded ? 1.0 : kSpeed;
  EXPECT_LT(worst, 1e-6 * scale) << Name(c) << ": largest speed error at t = " << worst_t << " (stick at " << t_stick
                                 << ")";
  std::printf("%s: %zu events, largest speed error %.2e rad/s, stick at %.6f s\n", Name(c).c_str(), r.events.size(),
              worst, t_stick);
  // The element sticks at t* (the last mode change is within 1e-4 s of it).
  double last_change = -1;
  for (const auto& e : r.events)
    if (e.element == "element") last_change = e.time;
  EXPECT_NEAR(last_change, t_stick, 1e-4) << Name(c) << ": " << r.FullReport();
}

std::vector<Case> AllCases() {
  std::vector<Case> cases;
  for (Kind k : {Kind::kBrake, Kind::kClutch, Kind::kOneWayClutch})
    for (Signal s : {Signal::kRamp, Signal::kSine})
      for (bool loaded : {false, true}) cases.push_back({k, s, loaded});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Patterns, StartEvents, ::testing::ValuesIn(AllCases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return Name(info.param); });

}  // namespace
}  // namespace highlift::sim
