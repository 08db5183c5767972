// Friction that never creates energy (issue 26, item 1): the failure patterns of the issue, each
// against an independent integration of MSL's friction semantics (PartialFriction: a stuck
// element holds while the torque that holds it is within its capacity and otherwise starts to
// slide in the direction of that torque, startForward/startBackward; a sliding element sticks
// when its slip reaches zero and the holding torque is within the capacity), at every relative
// tolerance from 1e-4 to 1e-9.
//
// Every case is one degree of freedom in the slip d of the element (or of the friction elements
// acting in parallel on one shaft): d' = A(t) - B tau, with A the slip acceleration of the loads
// with the friction torque tau = 0 and B > 0 (1/J for a brake on a shaft, 2 for a clutch
// between two unit inertias). Sliding in direction s: tau = s Ck(t); stuck: tau = A/B while
// |A/B| <= Cs(t). The reference integrates this in closed form between switches (Ik = integral
// of Ck, Aint = integral of A) and finds the switches by scanning and bisection. The lossy gear
// (issue 26 item 1, its leftover: MSL's LossyGear) is one degree of freedom in its input speed
// w_a too, but its loss depends on the torque it transmits: its reference integrates the rolling
// acceleration of each direction numerically and takes MSL's startForward/startBackward
// thresholds (GearLaw).
//
// Checked: the slip against the reference away from the switches; the power tau * w of every
// friction element never below zero (a sliding element never pushes along its slip); the
// simulator's own passivity monitor agrees (no violation); a bounded number of events.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

using Scalars = std::map<std::string, double>;
using Fn = std::function<double(double)>;

ElementParameters P(Scalars s) { return {std::move(s), {}}; }
constexpr double kPi = std::numbers::pi;

/// The one-degree-of-freedom friction problem d' = A(t) - B tau of a case.
struct Reference {
  Fn A, Aint;     // slip acceleration without friction, and its integral from 0
  double B = 1.0;  // 1/s^2 per N*m
  Fn Cs, Ck, Ik;  // static and kinetic capacity (N*m), integral of the kinetic one
  double d0 = 0.0;
  double stop = 0.9;
  // A friction law whose sliding acceleration is not A - B s Ck (a lossy gear, whose loss depends
  // on the torque it transmits): the slip acceleration when sliding in direction s, and at rest
  // 0 while it holds or the direction +-1 in which it breaks away. The slip is then integrated
  // numerically (Gauss-Legendre on a grid of 1e-5 s: exact to roundoff where the law is smooth,
  // 1e-10 of the acceleration's kink at a quadrant change).
  std::function<double(double, int)> rolling;
  std::function<int(double)> breakaway;
  std::vector<double> grid_forward, grid_backward;  // integral of rolling(t, +-1) from 0, per grid point
  static constexpr double kGrid = 1e-5;

  struct Segment {
    double t0, d0;
    int s;  // -1, +1 sliding; 0 stuck
  };
  std::vector<Segment> segments;

  double Slide(const Segment& g, double t) const {
    if (rolling) return g.d0 + RollingIntegral(g.s, t) - RollingIntegral(g.s, g.t0);
    return g.d0 + (Aint(t) - Aint(g.t0)) - B * g.s * (Ik(t) - Ik(g.t0));
  }
  bool Holds(double t) const {
    if (breakaway) return breakaway(t) == 0;
    return std::abs(A(t)) <= B * Cs(t) * (1 + 1e-12);
  }
  int Sign(double x) const { return x > 0 ? 1 : (x < 0 ? -1 : 0); }
  int StartDirection(double t) const { return breakaway ? breakaway(t) : Sign(A(t)); }

  // Integral of rolling(., s) over [a, b] by 3-point Gauss-Legendre.
  double Gauss(int s, double a, double b) const {
    const double m = 0.5 * (a + b), h = 0.5 * (b - a), x = std::sqrt(0.6);
    return h * (5.0 / 9 * rolling(m - h * x, s) + 8.0 / 9 * rolling(m, s) + 5.0 / 9 * rolling(m + h * x, s));
  }
  void Tabulate() {
    const int n = static_cast<int>(std::ceil(stop / kGrid)) + 2;
    for (int s : {1, -1}) {
      std::vector<double>& g = s > 0 ? grid_forward : grid_backward;
      g.assign(static_cast<std::size_t>(n) + 1, 0.0);
      for (int k = 0; k < n; ++k) g[k + 1] = g[k] + Gauss(s, k * kGrid, (k + 1) * kGrid);
    }
  }
  double RollingIntegral(int s, double t) const {
    const std::vector<double>& g = s > 0 ? grid_forward : grid_backward;
    const auto k = std::min(static_cast<std::size_t>(std::max(0.0, t / kGrid)), g.size() - 2);
    return g[k] + Gauss(s, static_cast<double>(k) * kGrid, t);
  }

  // First t in (t0, stop] where pred turns true (scan of 1e-5 s, then bisection).
  double Find(double t0, const std::function<bool(double)>& pred) const {
    const double h = 1e-5;
    double lo = t0;
    for (double t = t0 + h; t <= stop + h; t += h) {
      if (pred(t)) {
        double hi = t;
        for (int i = 0; i < 100; ++i) {
          const double m = 0.5 * (lo + hi);
          (pred(m) ? hi : lo) = m;
        }
        return hi;
      }
      lo = t;
    }
    return INFINITY;
  }

  void Solve() {
    if (rolling) Tabulate();
    segments.clear();
    Segment g{0.0, d0, 0};
    if (d0 != 0.0) g.s = Sign(d0);
    else if (!Holds(0.0)) g.s = StartDirection(0.0);
    while (g.t0 < stop) {
      segments.push_back(g);
      if (g.s != 0) {
        const Segment cur = g;
        const double tc = Find(cur.t0, [&](double t) { return cur.s * Slide(cur, t) <= 0; });
        if (!std::isfinite(tc)) break;
        g = {tc, 0.0, Holds(tc) ? 0 : StartDirection(tc)};
        if (g.s == cur.s) break;  // cannot happen for these cases: the slip would not cross
      } else {
        const double tb = Find(g.t0, [&](double t) { return !Holds(t); });
        if (!std::isfinite(tb)) break;
        g = {tb, 0.0, StartDirection(tb)};
      }
    }
  }
  double D(double t) const {
    const Segment* g = &segments.front();
    for (const auto& s : segments)
      if (s.t0 <= t) g = &s;
    return g->s == 0 ? 0.0 : Slide(*g, t);
  }
  std::vector<double> Switches() const {
    std::vector<double> t;
    for (const auto& s : segments) t.push_back(s.t0);
    return t;
  }
};

struct Case {
  std::string name;
  std::function<Network()> build;
  std::string slip;                                             // column of the slip d
  std::vector<std::pair<std::string, std::string>> friction;  // (speed, torque) columns
  std::function<Reference()> reference;
  SimulationOptions options;
};

// A ramp f = t or a sine f = sin(pi t) from 0, as a block "f".
enum class Signal { kRamp, kSine };
void AddSignal(Network& net, Signal s) {
  if (s == Signal::kRamp) net.AddElement("Ramp", "f", P({{"height", 1}, {"duration", 1}}));
  else net.AddElement("Sine", "f", P({{"amplitude", 1}, {"f", 0.5}}));
}
double F(Signal s, double t) { return s == Signal::kRamp ? std::min(t, 1.0) : std::sin(kPi * t); }
double FInt(Signal s, double t) { return s == Signal::kRamp ? 0.5 * t * t : (1 - std::cos(kPi * t)) / kPi; }

/// A network with the ground "fixed".
Network Grounded() {
  Network net;
  net.AddElement("Fixed", "fixed");
  return net;
}
void Ground(Network& net, const std::string& port) { net.Connect(port, "fixed.flange"); }
/// A constant torque "load" of `tau` N*m on `flange`.
void AddConstantLoad(Network& net, const std::string& flange, double tau) {
  net.AddElement("ConstantTorque", "load", P({{"tau_constant", tau}}));
  net.Connect("load.flange", flange);
  Ground(net, "load.support");
}

Fn Constant(double a) {
  return [a](double) { return a; };
}
Fn Linear(double a) {
  return [a](double t) { return a * t; };
}

std::string SignalName(Signal s) { return s == Signal::kRamp ? "Ramp" : "Sine"; }

// A Brake (mu 0.5, cgeo 1: capacity 0.5 fn_max f) on a unit inertia, with a load of 5 N*m from
// rest or free at 10 rad/s.
Case BrakeCase(Signal sig, double fn_max, bool loaded) {
  Case c;
  c.name = "Brake" + SignalName(sig) + "Fn" + std::to_string(static_cast<int>(fn_max)) + (loaded ? "Loaded" : "Unloaded");
  c.build = [=] {
    Network net = Grounded();
    AddSignal(net, sig);
    net.AddElement("Inertia", "shaft", P({{"J", 1}, {"phi_start", 0}, {"w_start", loaded ? 0.0 : 10.0}}));
    net.AddElement("Brake", "brake", P({{"fn_max", fn_max}}));
    net.Connect("shaft.flange_b", "brake.flange_a");
    Ground(net, "brake.support");
    net.Connect("f.y", "brake.f_normalized");
    if (loaded) AddConstantLoad(net, "shaft.flange_a", 5);
    return net;
  };
  c.slip = "brake.w";
  c.friction = {{"brake.w", "brake.tau"}};
  c.reference = [=] {
    Reference r;
    r.A = Constant(loaded ? 5.0 : 0.0);
    r.Aint = Linear(loaded ? 5.0 : 0.0);
    r.Cs = r.Ck = [=](double t) { return 0.5 * fn_max * F(sig, t); };
    r.Ik = [=](double t) { return 0.5 * fn_max * FInt(sig, t); };
    r.d0 = loaded ? 0.0 : 10.0;
    return r;
  };
  return c;
}

// A Clutch (capacity 50 sin(pi t)) between two unit inertias whose slip w_b - w_a starts at
// -7e-15 (roundoff): unloaded it sticks at once; a load of 5 N*m on flange_a's inertia drives
// the slip negative (the sign of the roundoff), on flange_b's positive (against it).
enum class ClutchLoad { kNone, kOnA, kOnB };
Case ClutchCase(ClutchLoad load, double fn_max) {
  Case c;
  const char* where = load == ClutchLoad::kNone ? "Unloaded" : (load == ClutchLoad::kOnA ? "LoadedOnA" : "LoadedOnB");
  c.name = std::string("ClutchSineSlipMinus7e15Fn") + std::to_string(static_cast<int>(fn_max)) + where;
  const double slip0 = -7e-15;
  c.build = [=] {
    Network net = Grounded();
    AddSignal(net, Signal::kSine);
    net.AddElement("Inertia", "a", P({{"J", 1}, {"phi_start", 0}, {"w_start", 1.0}}));
    net.AddElement("Inertia", "b", P({{"J", 1}, {"phi_start", 0}, {"w_start", 1.0 + slip0}}));
    net.AddElement("Clutch", "clutch", P({{"fn_max", fn_max}}));
    net.Connect("a.flange_b", "clutch.flange_a");
    net.Connect("clutch.flange_b", "b.flange_a");
    net.Connect("f.y", "clutch.f_normalized");
    if (load != ClutchLoad::kNone) AddConstantLoad(net, load == ClutchLoad::kOnA ? "a.flange_a" : "b.flange_b", 5);
    return net;
  };
  c.slip = "clutch.w_rel";
  c.friction = {{"clutch.w_rel", "clutch.tau"}};
  c.reference = [=] {
    Reference r;
    // w_a' = L_a + tau, w_b' = L_b - tau: d' = (L_b - L_a) - 2 tau.
    const double a = load == ClutchLoad::kNone ? 0.0 : (load == ClutchLoad::kOnA ? -5.0 : 5.0);
    r.A = Constant(a);
    r.Aint = Linear(a);
    r.B = 2.0;
    r.Cs = r.Ck = [=](double t) { return 0.5 * fn_max * F(Signal::kSine, t); };
    r.Ik = [=](double t) { return 0.5 * fn_max * FInt(Signal::kSine, t); };
    r.d0 = slip0;
    return r;
  };
  return c;
}

// A ShaftBrake (dynamic 40, static 50 N*m at u = 1) whose command u is a ramp or a sine from 0,
// on a unit inertia loaded with 5 N*m from rest (fn_max as the pattern: a scale of u).
Case ShaftBrakeCase(Signal sig, double scale) {
  Case c;
  c.name = "ShaftBrake" + SignalName(sig) + "Scale" + std::to_string(static_cast<int>(scale)) + "Loaded";
  c.build = [=] {
    Network net = Grounded();
    AddSignal(net, sig);
    net.AddElement("Gain", "gain", P({{"k", scale}}));
    net.Connect("f.y", "gain.u");
    net.AddElement("Inertia", "shaft", P({{"J", 1}, {"phi_start", 0}, {"w_start", 0}}));
    net.AddElement("ShaftBrake", "brake", P({{"tauB_max", 40}, {"tauB_lim", 50}}));
    net.Connect("shaft.flange_b", "brake.flange_a");
    Ground(net, "brake.support");
    net.Connect("gain.y", "brake.u");
    AddConstantLoad(net, "shaft.flange_a", 5);
    return net;
  };
  c.slip = "brake.w";
  c.friction = {{"brake.w", "brake.tau"}};
  c.reference = [=] {
    Reference r;
    r.A = Constant(5.0);
    r.Aint = Linear(5.0);
    r.Cs = [=](double t) { return 50 * scale * F(sig, t); };
    r.Ck = [=](double t) { return 40 * scale * F(sig, t); };
    r.Ik = [=](double t) { return 40 * scale * FInt(sig, t); };
    return r;
  };
  return c;
}

// Two Brakes (a ramp with fn_max 2 and a sine with fn_max 100) and a BearingFriction of 1 N*m on
// one unit inertia, all engaging at t = 0, loaded with 5 N*m from rest or free at 10 rad/s: in
// parallel they act as one element of the summed capacity.
Case SeveralBrakesCase(bool loaded) {
  Case c;
  c.name = std::string("TwoBrakesAndBearingFriction") + (loaded ? "Loaded" : "Unloaded");
  c.build = [=] {
    Network net = Grounded();
    net.AddElement("Ramp", "ramp", P({{"height", 1}, {"duration", 1}}));
    net.AddElement("Sine", "sine", P({{"amplitude", 1}, {"f", 0.5}}));
    net.AddElement("Inertia", "shaft", P({{"J", 1}, {"phi_start", 0}, {"w_start", loaded ? 0.0 : 10.0}}));
    net.AddElement("Brake", "brake1", P({{"fn_max", 2}}));
    net.AddElement("Brake", "brake2", P({{"fn_max", 100}}));
    net.AddElement("BearingFriction", "bearing");
    net.Connect("shaft.flange_b", "brake1.flange_a");
    net.Connect("brake1.flange_b", "brake2.flange_a");
    net.Connect("brake2.flange_b", "bearing.flange_a");
    for (const char* s : {"brake1.support", "brake2.support", "bearing.support"}) Ground(net, s);
    net.Connect("ramp.y", "brake1.f_normalized");
    net.Connect("sine.y", "brake2.f_normalized");
    if (loaded) AddConstantLoad(net, "shaft.flange_a", 5);
    return net;
  };
  c.slip = "brake1.w";
  c.friction = {{"brake1.w", "brake1.tau"}, {"brake2.w", "brake2.tau"}, {"bearing.w", "bearing.tau"}};
  c.reference = [=] {
    Reference r;
    r.A = Constant(loaded ? 5.0 : 0.0);
    r.Aint = Linear(loaded ? 5.0 : 0.0);
    r.Cs = r.Ck = [](double t) { return 1.0 * F(Signal::kRamp, t) + 50.0 * F(Signal::kSine, t) + 1.0; };
    r.Ik = [](double t) { return 1.0 * FInt(Signal::kRamp, t) + 50.0 * FInt(Signal::kSine, t) + t; };
    r.d0 = loaded ? 0.0 : 10.0;
    return r;
  };
  return c;
}

// A WingTipBrake (dynamic 100, static 120 N*m; applied at 0.4 s, engaged after t_lat = 0.1 s,
// full after t_B = 0.03 s) on a unit shaft at rest with a residual speed of +-1e-10 rad/s; a load
// step at 0.7 s of +-50 N*m (held) or +-150 N*m (slips).
Case WingTipBrakeCase(double residual, double load) {
  Case c;
  c.name = std::string("WingTipBrakeResidual") + (residual > 0 ? "Plus" : "Minus") + "1e10Load" +
           (load > 0 ? "Plus" : "Minus") + std::to_string(static_cast<int>(std::abs(load)));
  const double J = 1.0 + 5e-4;  // shaft and rotor
  c.build = [=] {
    Network net = Grounded();
    net.AddElement("Inertia", "shaft", P({{"J", 1}, {"phi_start", 0}, {"w_start", residual}}));
    net.AddElement("WingTipBrake", "wtb",
                   P({{"tauB_max", 100}, {"tauB_lim", 120}, {"t_lat", 0.1}, {"t_B", 0.03}, {"J", 5e-4}}));
    net.AddElement("Step", "apply", P({{"startTime", 0.4}}));
    net.Connect("shaft.flange_b", "wtb.flange_a");
    Ground(net, "wtb.support");
    net.Connect("apply.y", "wtb.apply");
    net.AddElement("TorqueStep", "load", P({{"stepTorque", load}, {"startTime", 0.7}}));
    net.Connect("load.flange", "shaft.flange_a");
    Ground(net, "load.support");
    return net;
  };
  c.slip = "wtb.w";
  c.friction = {{"wtb.w", "wtb.tau"}};
  c.reference = [=] {
    Reference r;
    r.A = [=](double t) { return t >= 0.7 ? load / J : 0.0; };
    r.Aint = [=](double t) { return t >= 0.7 ? load / J * (t - 0.7) : 0.0; };
    r.B = 1.0 / J;
    auto u = [](double t) { return std::clamp((t - 0.5) / 0.03, 0.0, 1.0); };
    auto u_int = [](double t) {
      if (t <= 0.5) return 0.0;
      if (t <= 0.53) return (t - 0.5) * (t - 0.5) / 0.06;
      return 0.015 + (t - 0.53);
    };
    r.Cs = [=](double t) { return 120 * u(t); };
    r.Ck = [=](double t) { return 100 * u(t); };
    r.Ik = [=](double t) { return 100 * u_int(t); };
    r.d0 = residual;
    return r;
  };
  return c;
}

// A LossyGear (ratio 2; eta_mf1 0.8, eta_mf2 0.6, tau_bf1 0.5, tau_bf2 0.4 N*m at every speed)
// between a unit inertia at flange_a (speed w_a, the slip) and an inertia of 2 at flange_b, the
// support fixed; a torque Ta(t) on the input inertia and Tb(t) on the output one.
//
// MSL's LossyGear (4.0.0), independently: with tau_a = flange_a.tau and tauLoss = k tau_a + c0
// in the active quadrant (rolling forward: k = 1 - eta_mf1, c0 = tau_bf1 while tau_a - tau_bf_a
// >= 0, else k = 1 - 1/eta_mf2, c0 = tau_bf2; backward: k = 1 - 1/eta_mf2, c0 = -tau_bf2 while
// tau_a + tau_bf_a >= 0, else 1 - eta_mf1, -tau_bf1), Ja w_a' = Ta - tau_a and
// Jb w_a' / i = Tb + i (tau_a - tauLoss) give w_a' = (Tb + i ((1 - k) Ta - c0)) / (Jb / i + i (1 - k) Ja).
// Stuck (w_a' = 0): tau_a = Ta and tauLoss = sa = Ta + Tb / i; it starts forward when sa >
// tauLossMax_p (quadrant 1 if Ta - tau_bf_a > 0, else 2), backward when sa < tauLossMin_m
// (quadrant 4 if Ta + tau_bf_a > 0, else 3) -- MSL's startForward / startBackward.
struct GearLaw {
  double ratio = 2, Ja = 1, Jb = 2, eta1 = 0.8, eta2 = 0.6, bf1 = 0.5, bf2 = 0.4;
  double bf_a() const { return (bf1 - bf2) / (eta1 - 1.0 / eta2); }
  double Acceleration(double Ta, double Tb, double k, double c0) const {
    return (Tb + ratio * ((1 - k) * Ta - c0)) / (Jb / ratio + ratio * (1 - k) * Ja);
  }
  double Rolling(double Ta, double Tb, int s) const {
    // The quadrant whose tau_eta has its sign (the loss is continuous at the boundary).
    const double k_pos = s > 0 ? 1 - eta1 : 1 - 1 / eta2, c_pos = s > 0 ? bf1 : -bf2;
    const double a_pos = Acceleration(Ta, Tb, k_pos, c_pos);
    if (Ta - Ja * a_pos - s * bf_a() >= 0) return a_pos;
    return Acceleration(Ta, Tb, s > 0 ? 1 - 1 / eta2 : 1 - eta1, s > 0 ? bf2 : -bf1);
  }
  int Breakaway(double Ta, double Tb) const {
    const double sa = Ta + Tb / ratio;
    const double loss_max = Ta - bf_a() > 0 ? (1 - eta1) * Ta + bf1 : (1 - 1 / eta2) * Ta + bf2;
    const double loss_min = Ta + bf_a() > 0 ? (1 - 1 / eta2) * Ta - bf2 : (1 - eta1) * Ta - bf1;
    return sa > loss_max ? 1 : (sa < loss_min ? -1 : 0);
  }
};

/// `loads` adds the torque sources on "a.flange_a" (Ta) and "b.flange_b" (Tb).
Case LossyGearCase(const std::string& name, const std::function<void(Network&)>& loads, const Fn& Ta, const Fn& Tb,
                   double w0 = 0.0) {
  Case c;
  c.name = "LossyGear" + name;
  const GearLaw law;
  c.build = [=] {
    Network net = Grounded();
    net.AddElement("Inertia", "a", P({{"J", law.Ja}, {"phi_start", 0}, {"w_start", w0}}));
    net.AddElement("Inertia", "b", P({{"J", law.Jb}}));
    ElementParameters gear = P({{"ratio", law.ratio}});
    gear.tables["lossTable"] = {{0.0, law.eta1, law.eta2, law.bf1, law.bf2}};
    net.AddElement("LossyGear", "gear", gear);
    net.Connect("a.flange_b", "gear.flange_a");
    net.Connect("gear.flange_b", "b.flange_a");
    Ground(net, "gear.support");
    loads(net);
    return net;
  };
  c.slip = "gear.w_a";
  c.friction = {{"gear.w_a", "gear.tauLoss"}};
  c.reference = [=] {
    Reference r;
    r.rolling = [=](double t, int s) { return law.Rolling(Ta(t), Tb(t), s); };
    r.breakaway = [=](double t) { return law.Breakaway(Ta(t), Tb(t)); };
    r.d0 = w0;
    return r;
  };
  return c;
}

/// A torque from the signal block `signal` on `flange`.
void AddSignalTorque(Network& net, const std::string& id, const std::string& flange, const std::string& signal) {
  net.AddElement("Torque", id);
  net.Connect(signal + ".y", id + ".tau");
  net.Connect(id + ".flange", flange);
  Ground(net, id + ".support");
}

std::vector<Case> LossyGearCases() {
  std::vector<Case> cases;
  // Driven from rest by a rising torque (Ta = 10 t) against a load of -3 N*m: stuck until sa =
  // 10 t - 1.5 passes tauLossMax_p = 2 t + 0.5 (t = 0.25), then rolling forward in quadrant 1.
  cases.push_back(LossyGearCase(
      "DrivenFromRestByARisingTorque",
      [](Network& net) {
        net.AddElement("Ramp", "f", P({{"height", 10}, {"duration", 1}}));
        AddSignalTorque(net, "drive", "a.flange_a", "f");
        AddConstantLoad(net, "b.flange_b", -3);
      },
      Linear(10.0), Constant(-3.0)));
  // Back-driven from rest by a rising load on flange_b (Tb = 10 t): stuck until Tb / 2 passes
  // tauLossMax_p = 0.5 at t = 0.1, then forward; the driving side changes (tau_a = -w_a' turns
  // below tau_bf_a): quadrant 1, then 2 (eta_mf2).
  cases.push_back(LossyGearCase(
      "BackDrivenFromRestByARisingLoad",
      [](Network& net) {
        net.AddElement("Ramp", "f", P({{"height", 10}, {"duration", 1}}));
        AddSignalTorque(net, "drive", "b.flange_b", "f");
      },
      Constant(0.0), Linear(10.0)));
  // A sine drive Ta = 8 sin(2 pi t): forward, slows against its loss, sticks, starts backward.
  cases.push_back(LossyGearCase(
      "SineDriveForwardStuckBackward",
      [](Network& net) {
        net.AddElement("Sine", "f", P({{"amplitude", 8}, {"f", 1}}));
        AddSignalTorque(net, "drive", "a.flange_a", "f");
      },
      [](double t) { return 8 * std::sin(2 * kPi * t); }, Constant(0.0)));
  // A sine drive whose peak passes the breakaway torque (Ta = 0.625 N*m: 0.8 Ta > 0.5) by 0.16 %:
  // it starts forward at t = 0.2306, moves by less than 1e-5 rad/s and sticks again (G4, G5).
  cases.push_back(LossyGearCase(
      "SineDrivePeakJustAboveBreakaway",
      [](Network& net) {
        net.AddElement("Sine", "f", P({{"amplitude", 0.626}, {"f", 1}}));
        AddSignalTorque(net, "drive", "a.flange_a", "f");
      },
      [](double t) { return 0.626 * std::sin(2 * kPi * t); }, Constant(0.0)));
  // At rest with a roundoff speed of +-1e-12 rad/s, held by its loss against Ta = +-0.3 N*m (of
  // either sign relative to the roundoff), then a step to +-5 N*m at 0.5 s breaks it away.
  for (double residual : {1e-12, -1e-12})
    for (double drive : {1.0, -1.0})
      cases.push_back(LossyGearCase(
          std::string("RoundoffSpeed") + (residual > 0 ? "Plus" : "Minus") + "Drive" + (drive > 0 ? "Plus" : "Minus"),
          [=](Network& net) {
            net.AddElement("TorqueStep", "drive",
                           P({{"offsetTorque", 0.3 * drive}, {"stepTorque", 4.7 * drive}, {"startTime", 0.5}}));
            net.Connect("drive.flange", "a.flange_a");
            Ground(net, "drive.support");
          },
          [=](double t) { return drive * (t < 0.5 ? 0.3 : 5.0); }, Constant(0.0), residual));
  return cases;
}

std::vector<Case> AllCases() {
  std::vector<Case> cases;
  for (double fn : {1.0, 2.0, 100.0})
    for (bool loaded : {false, true}) cases.push_back(BrakeCase(Signal::kRamp, fn, loaded));
  for (double fn : {1.0, 100.0})
    for (bool loaded : {false, true}) cases.push_back(BrakeCase(Signal::kSine, fn, loaded));
  for (ClutchLoad l : {ClutchLoad::kNone, ClutchLoad::kOnA, ClutchLoad::kOnB})
    for (double fn : {1.0, 100.0}) cases.push_back(ClutchCase(l, fn));
  for (Signal s : {Signal::kRamp, Signal::kSine})
    for (double scale : {1.0, 100.0}) cases.push_back(ShaftBrakeCase(s, scale));
  for (bool loaded : {false, true}) cases.push_back(SeveralBrakesCase(loaded));
  for (double residual : {1e-10, -1e-10})
    for (double load : {50.0, -50.0, 150.0, -150.0}) cases.push_back(WingTipBrakeCase(residual, load));
  for (Case& c : LossyGearCases()) cases.push_back(std::move(c));
  return cases;
}

struct Param {
  int index;
  double rtol;
};

class FrictionPassivity : public ::testing::TestWithParam<Param> {};

TEST_P(FrictionPassivity, FollowsMslFrictionSemanticsAndNeverCreatesEnergy) {
  const Param param = GetParam();
  const Case c = AllCases()[param.index];
  Reference ref = c.reference();
  ref.Solve();
  Simulator sim(c.build());
  SimulationOptions o;
  o.stop_time = ref.stop;
  o.output_interval = 1e-3;
  o.relative_tolerance = param.rtol;
  o.absolute_tolerance = param.rtol * 1e-2;
  MemorySink sink;
  const SimulationReport r = sim.Run(o, sink);
  ASSERT_TRUE(r.ok()) << c.name << ": " << r.FullReport();
  EXPECT_LE(r.events.size(), 40u) << c.name << ": " << r.FullReport();
  EXPECT_TRUE(r.passivity.violations.empty()) << c.name << ": " << r.FullReport();

  // The slip against the reference, away from the switches.
  const auto d = sink.Series(c.slip);
  const auto switches = ref.Switches();
  double scale = 0.0;
  for (double t : sink.times()) scale = std::max(scale, std::abs(ref.D(t)));
  const double tol = 100 * param.rtol * (1.0 + scale);
  double worst = 0.0, worst_t = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double t = sink.times()[i];
    bool near = false;
    for (double s : switches) near = near || (s > 0 && std::abs(t - s) < 2e-3);
    if (near) continue;
    const double err = std::abs(d[i] - ref.D(t));
    if (err > worst) worst = err, worst_t = t;
  }
  std::string switch_text;
  for (double s : switches) switch_text += " " + std::to_string(s);
  EXPECT_LE(worst, tol) << c.name << " rtol " << param.rtol << ": slip error " << worst << " at t = " << worst_t
                        << " (simulated " << d[0] << " ...; reference switches at" << switch_text << ")\n"
                        << r.FullReport();

  // Power tau * w of every friction element: never below zero beyond roundoff.
  for (const auto& [wc, tc] : c.friction) {
    const auto w = sink.Series(wc), tau = sink.Series(tc);
    double p_scale = 0.0, p_min = 0.0, p_min_t = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      const double p = tau[i] * w[i];
      p_scale = std::max(p_scale, std::abs(p));
      if (p < p_min) p_min = p, p_min_t = sink.times()[i];
    }
    EXPECT_GE(p_min, -1e-6 * p_scale - 1e-8)
        << c.name << " rtol " << param.rtol << ": " << tc << " * " << wc << " = " << p_min << " W at t = " << p_min_t;
  }
}

std::vector<Param> AllParams() {
  std::vector<Param> p;
  const int n = static_cast<int>(AllCases().size());
  for (int i = 0; i < n; ++i)
    for (double rtol : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9}) p.push_back({i, rtol});
  return p;
}

INSTANTIATE_TEST_SUITE_P(Patterns, FrictionPassivity, ::testing::ValuesIn(AllParams()),
                         [](const ::testing::TestParamInfo<Param>& info) {
                           const int e = static_cast<int>(std::lround(-std::log10(info.param.rtol)));
                           return AllCases()[info.param.index].name + "Rtol1e" + std::to_string(e);
                         });

// A run of `net` from 0 to `stop_time` with the default options.
SimulationReport RunTo(const Network& net, double stop_time) {
  Simulator sim(net);
  SimulationOptions o;
  o.stop_time = stop_time;
  MemorySink sink;
  return sim.Run(o, sink);
}

// The monitor itself: a BearingFriction whose friction table is negative (-1 N*m at every
// speed) pushes a unit inertia along its motion from 2 rad/s: w = 2 + t, dissipated power
// -(2 + t) W from the start to the end. The monitor names it, from t = 0, with the most negative
// power at the end; the source-free run's power scale is that element's own power.
TEST(PassivityMonitor, NamesAnElementThatFeedsEnergyWithTimeAndPower) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Inertia", "shaft", P({{"J", 1}, {"phi_start", 0}, {"w_start", 2}}));
  ElementParameters bearing = P({});
  bearing.tables["tau_pos"] = {{0.0, -1.0}};
  net.AddElement("BearingFriction", "bearing", bearing);
  net.AddElement("BearingFriction", "sound");  // +1 N*m: dissipates
  net.Connect("shaft.flange_b", "bearing.flange_a");
  net.Connect("bearing.flange_b", "sound.flange_a");
  net.Connect("bearing.support", "fixed.flange");
  net.Connect("sound.support", "fixed.flange");
  // The two cancel: w stays 2, the bad one feeds 2 W, the sound one dissipates 2 W.
  const SimulationReport r = RunTo(net, 0.5);
  ASSERT_TRUE(r.ok()) << r.FullReport();
  ASSERT_EQ(r.passivity.violations.size(), 1u) << r.FullReport();
  const PassivityViolation& v = r.passivity.violations.front();
  EXPECT_EQ(v.element, "bearing");
  EXPECT_NEAR(v.time, 0.0, 1e-12);
  EXPECT_NEAR(v.power, -2.0, 1e-9);
  EXPECT_NEAR(v.duration, 0.5, 1e-9);
  EXPECT_EQ(v.episodes, 1);
  EXPECT_NEAR(r.passivity.power_scale, 4.0, 1e-9);  // |-2| + |2|
  EXPECT_FALSE(r.passivity.passive());
  EXPECT_NE(r.passivity.BriefReport().find("1 element with negative dissipation: bearing at 0 s (-2 W"),
            std::string::npos)
      << r.passivity.BriefReport();
  EXPECT_NE(r.FullReport().find("passivity (tolerance 1e-06 of 4 W): 1 element"), std::string::npos) << r.FullReport();
}

// Episodes that open and close: a speed source drives a shaft at w = 1 + 0.8 sin(2 pi t) through
// a BearingFriction whose table is negative below 0.6 rad/s (-1 N*m up to 0.5 rad/s, +1 N*m from
// 0.7). It feeds energy while w < 0.6, for t in (7/12, 11/12) of every second: two episodes in
// 2.5 s, each about 1/3 s long (from the first to the last step end inside: a step or two
// less), at least -0.5 W (w = 0.5). Between them no power is below the threshold, where the
// monitor looks at the elements only when one is.
TEST(PassivityMonitor, CountsEpisodesThatOpenAndClose) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Inertia", "shaft", P({{"J", 1}}));
  net.AddElement("Speed", "drive", P({{"f_crit", 200}}));
  net.AddElement("Sine", "profile", P({{"amplitude", 0.8}, {"f", 1}, {"offset", 1}}));
  ElementParameters bearing = P({});
  bearing.tables["tau_pos"] = {{0.0, -1.0}, {0.5, -1.0}, {0.7, 1.0}, {2.0, 1.0}};
  net.AddElement("BearingFriction", "bearing", bearing);
  net.Connect("drive.flange", "shaft.flange_a");
  net.Connect("shaft.flange_b", "bearing.flange_a");
  net.Connect("bearing.support", "fixed.flange");
  net.Connect("profile.y", "drive.w_ref");
  const SimulationReport r = RunTo(net, 2.5);
  ASSERT_TRUE(r.ok()) << r.FullReport();
  ASSERT_EQ(r.passivity.violations.size(), 1u) << r.FullReport();
  const PassivityViolation& v = r.passivity.violations.front();
  EXPECT_EQ(v.element, "bearing");
  EXPECT_EQ(v.episodes, 2) << r.FullReport();
  EXPECT_NEAR(v.duration, 1.0 / 3.0, 0.05) << r.FullReport();
  const double start = v.time < 1.0 ? 7.0 / 12.0 : 19.0 / 12.0;
  EXPECT_NEAR(v.time, start, 0.03) << r.FullReport();
  EXPECT_NEAR(v.power, -0.5, 0.02) << r.FullReport();
}

TEST(PassivityMonitor, ToleranceMustBePositive) {
  SimulationOptions o;
  o.passivity_tolerance = 0.0;
  try {
    o.Validate();
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("passivity_tolerance must be > 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace highlift::sim
