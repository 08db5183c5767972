// Brakes, torque limiters and friction of the HighLift library: the laws of brake_elements.h
// and the composites WingTipBrake (BrakeActuation + rotor Inertia + ShaftBrake) and
// TorqueLimiter (Inertia + ShaftBrake + NonlinearSpring, figure 5 of the paper).
#include "brake_elements.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "composites.h"
#include "highlift/core/error.h"
#include "highlift/core/message_number.h"
#include "model.h"

namespace highlift::sim::detail {

using msl::Given;
using msl::Param;

namespace {

std::string Name(const std::string& id, const std::string& type) {
  return "element '" + id + "' (" + type + ")";
}

std::string Number(double x) { return FormatMessageNumber(x); }

void CheckBrakeTorques(const std::string& id, const std::string& type, double tauB_max,
                       double tauB_lim) {
  if (!(tauB_max >= 0.0))
    throw InputError(Name(id, type) + ": parameter 'tauB_max' = " + Number(tauB_max) +
                     " N*m must be >= 0");
  if (!(tauB_lim >= tauB_max))
    throw InputError(Name(id, type) + ": parameter 'tauB_lim' = " + Number(tauB_lim) +
                     " N*m is smaller than tauB_max = " + Number(tauB_max) +
                     " N*m; the static (holding) capacity must be at least the dynamic torque: "
                     "raise tauB_lim or lower tauB_max");
}

// A part of a composite: validated and completed with its defaults by Network::AddElement
// (under a plain id), then renamed into the composite's name space.
NetworkElement Part(const std::string& type, const std::string& id,
                    std::map<std::string, double> scalars) {
  Network scratch;
  scratch.AddElement(type, "part", ElementParameters{std::move(scalars), {}});
  NetworkElement part = scratch.elements().front();
  part.id = id;
  return part;
}

}  // namespace

// ------------------------------------------------------------------------------------------
// ShaftBrake

ShaftBrake::ShaftBrake(const std::string& element_id, const std::string& element_type,
                       double tau_max, double tau_lim)
    : tauB_max(tau_max), tauB_lim(tau_lim) {
  CheckBrakeTorques(element_id, element_type, tauB_max, tauB_lim);
  can_be_free = true;
}

ShaftBrake::ShaftBrake(const NetworkElement& e)
    : ShaftBrake(e.id, e.type, Param(e, "tauB_max"), Param(e, "tauB_lim")) {}

void ShaftBrake::Bind(const std::function<int(const std::string&)>& node_of,
                      const std::function<int(const std::string&)>& signal_of) {
  p = node_of("flange_a");
  m = node_of("support");
  u_signal = signal_of("u");
}

double ShaftBrake::TauSlide(const Eval& e, double w) const {
  (void)w;
  return U(e) * tauB_max;
}

double ShaftBrake::Violation(const Eval& e) const {
  const bool engaged = U(e) > 0.0;
  const bool released = mode == msl::kFree || mode == msl::kUnknown;
  if (!engaged) return released ? 0.0 : 1.0;
  if (released) return 1.0;
  return Friction::Violation(e);
}

void ShaftBrake::Fix(const Eval& e) {
  start_forward = start_backward = false;
  if (U(e) <= 0.0) {
    mode = msl::kFree;
    return;
  }
  if (mode == msl::kFree || mode == msl::kUnknown) {
    const double w = WF(e);
    const double w_eps = 1e-9 * (1.0 + std::abs(e.w[p]) + std::abs(e.w[m]));
    mode = w > w_eps ? msl::kForward : (w < -w_eps ? msl::kBackward : msl::kStuck);
    return;
  }
  Friction::Fix(e);
}

void ShaftBrake::Outputs(const Eval& e, double* out) const {
  out[0] = WF(e);
  out[1] = tau;
  out[2] = U(e);
  out[3] = mode == msl::kUnknown ? msl::kFree : mode;
}

// ------------------------------------------------------------------------------------------
// StribeckFriction and LossyInertia

StribeckFriction::StribeckFriction(const NetworkElement& e, bool with_inertia)
    : tau_C(Param(e, "tau_C")),
      d_vis(Param(e, "d_vis")),
      tau_S(Param(e, "tau_S")),
      f_exp(Param(e, "f_exp")),
      eta_GE(Param(e, "eta_GE")),
      w_small(Param(e, "w_small")) {
  if (with_inertia) J = Param(e, "J");
  else use_eta_input = Param(e, "useEfficiencyInput") != 0.0;
  peak = Param(e, "peak");
  split = use_eta_input || eta_GE < 1.0;
  frictionless = !split && tau_C == 0.0 && tau_S == 0.0 && d_vis == 0.0;
  regularized = !frictionless && w_small > 0.0;
  if (frictionless) mode = msl::kFree;
  if (regularized) mode = msl::kForward;  // always "sliding": the smooth law has no stuck mode
  smooth_one_node_ = regularized && !split;
}

std::vector<std::vector<std::string>> StribeckFriction::RigidFlanges() const {
  if (split) return {};
  return {{"flange_a", "flange_b"}};
}

std::vector<std::string> StribeckFriction::SignalInputs() const {
  if (use_eta_input) return {"eta"};
  return {};
}

void StribeckFriction::Bind(const std::function<int(const std::string&)>& node_of,
                            const std::function<int(const std::string&)>& signal_of) {
  a = node_of("flange_a");
  b = node_of("flange_b");
  m = node_of("support");
  p = a;
  if (use_eta_input) eta_signal = signal_of("eta");
}

std::vector<int> StribeckFriction::Nodes() const {
  if (split) return {a, b, m};
  return {a, m};
}

std::vector<int> StribeckFriction::CoupledNodes() const {
  if (frictionless) return {};
  return Nodes();
}

void StribeckFriction::HolonomicRows(std::vector<InitialEquation>& rows) const {
  if (split) rows.push_back({{{a, 1.0}, {b, -1.0}}, 0.0});
}

double StribeckFriction::Eta(const Eval& e) const {
  if (!use_eta_input) return eta_GE;
  return std::clamp(e.signal[eta_signal], 0.0, 1.0);
}

double StribeckFriction::TauSlide(const Eval& e, double w) const {
  return Stribeck(w) + (split ? (1.0 - Eta(e)) * std::abs(tau_load) : 0.0);
}

// At standstill the breakaway torque is peak*(tau_C + tau_S) (equation 3 at w = 0). The load
// loss acts only in motion, but a part cannot start to slide while the sliding friction, which
// includes it, exceeds the torque that holds it: the capacity is the larger of the two.
double StribeckFriction::Tau0Max(const Eval& e) const {
  const double tau0 = tau_C + tau_S;
  const double slide = split ? tau0 + (1.0 - Eta(e)) * std::abs(tau_load) : 0.0;
  return std::max(peak * tau0, slide);
}

void StribeckFriction::Forces(Eval& e) {
  if (smooth_one_node_) {
    SmoothOneNodeForces(e);
    return;
  }
  tau_stribeck = 0.0;
  if (frictionless) {
    tau = 0.0;
    return;
  }
  // The friction torque acts between the flange node (half at each flange when flange_a and
  // flange_b are separate nodes) and the support.
  auto apply = [&] {
    if (split) {
      e.AddForce(a, -0.5 * tau_stribeck);
      e.AddForce(b, -0.5 * tau_stribeck);
    } else {
      e.AddForce(a, -tau_stribeck);
    }
    e.AddForce(m, tau_stribeck);
    tau = tau_stribeck;
  };
  if (!regularized && !Sliding()) {
    if (mode != msl::kStuck) tau = 0.0;
    return;
  }
  // The law at the last (w, mode) is remembered (Memo): the Jacobian's difference quotients
  // mostly leave this element's flanges alone.
  const double w = WF(e);
  if (!law_memo_.Same({w, static_cast<double>(mode)})) {
    if (regularized)  // tanh(w/w_small) * (tau_C + tau_S*exp(-f_exp*|w|)) + d_vis*w: continuous and odd in w
      law_ = Smooth(e) * (tau_C + StribeckPeak(tau_S, f_exp * std::abs(w))) + d_vis * w;
    else
      law_ = mode == msl::kForward ? Stribeck(w) : -Stribeck(-w);
  }
  tau_stribeck = law_;
  apply();
}

// Multipliers: tau_load for the rigid tie of the two flanges (flange_a.tau = tau/2 + tau_load,
// flange_b.tau = tau/2 - tau_load) and tau for the stuck constraint. While sliding in direction
// s with quadrant q = sign(tau_load), the load loss s*(1 - eta)*q*tau_load is linear in the
// multiplier: it enters the tie's column (k = s*(1 - eta)*q; half on each flange, +k on the
// support).
void StribeckFriction::Constraints(Eval& e) {
  rigid = stuck = -1;
  // One node and no stuck mode (frictionless or regularised: not switching, so the mode never
  // changes): never a constraint, and the system may leave this phase out like a default.
  if (!split && !IsSwitching()) {
    unused_phases |= kConstraintsPhase;
    return;
  }
  if (split) {
    Constraint& c = e.NewConstraint(index);
    c.row = {{a, 1.0}, {b, -1.0}};
    if (regularized || Sliding()) {
      const double k = (regularized ? Smooth(e) : mode) * (1.0 - Eta(e)) * quadrant;
      c.column = {{a, -(1.0 + 0.5 * k)}, {b, 1.0 - 0.5 * k}, {m, k}};
    } else {
      c.column = {{a, -1.0}, {b, 1.0}};
    }
    rigid = e.n_constraints - 1;
  }
  if (mode == msl::kStuck) {
    Constraint& c = e.NewConstraint(index);
    c.row = {{a, 1.0}, {m, -1.0}};
    if (split) c.column = {{a, -0.5}, {b, -0.5}, {m, 1.0}};
    else c.column = {{a, -1.0}, {m, 1.0}};
    stuck = e.n_constraints - 1;
  }
}

void StribeckFriction::AfterSolve(Eval& e) {
  // One node and no stuck mode: Forces has set tau (0 when frictionless, tau_stribeck + 0.0
  // when regularised), and the system may leave this phase out like a default.
  if (!split && !IsSwitching()) {
    tau = frictionless ? 0.0 : tau_stribeck + 0.0;
    unused_phases |= kAfterSolvePhase;
    return;
  }
  if (rigid >= 0) tau_load = e.constraints[rigid].lambda;
  if (stuck >= 0) {
    tau = e.constraints[stuck].lambda;
  } else if (regularized) {
    tau = tau_stribeck + (split ? Smooth(e) * (1.0 - Eta(e)) * quadrant * tau_load : 0.0);
  } else if (Sliding()) {
    tau = tau_stribeck + (split ? mode * (1.0 - Eta(e)) * quadrant * tau_load : 0.0);
  } else {
    tau = 0.0;
  }
}

void StribeckFriction::Roots(const Eval& e, double* g) const {
  Friction::Roots(e, g);
  if (split && Sliding())
    g[3] = tau_load != 0.0 ? tau_load : quadrant * kRootSentinel;
  else
    g[3] = 1.0;
}

void StribeckFriction::RootDirections(int* d) const {
  Friction::RootDirections(d);
  d[3] = 0;
}

void StribeckFriction::PrepareEvent(const Eval& e) {
  Friction::PrepareEvent(e);
  flips = 0;
  if (split) quadrant = tau_load >= 0.0 ? 1 : -1;
}

double StribeckFriction::Violation(const Eval& e) const {
  const double v = Friction::Violation(e);
  if (v > 0.0) return v;
  if (split && Sliding() && flips < 4) {
    const double scale = 1e-10 * (1.0 + std::abs(tau_stribeck) + std::abs(tau_load));
    if (tau_load * quadrant < -scale) return std::max(std::abs(tau_load) / (1.0 + std::abs(tau)), 1e-9);
  }
  return 0.0;
}

void StribeckFriction::Fix(const Eval& e) {
  if (Friction::Violation(e) > 0.0) {
    Friction::Fix(e);
    if (split) quadrant = tau_load >= 0.0 ? 1 : -1;
    return;
  }
  quadrant = -quadrant;  // the load changed sign: the loss law of the other quadrant
  ++flips;
}

// The load loss (1 - eta)*|tau_load| was linearised with quadrant = the assumed sign of
// tau_load; the loss is continuous across tau_load = 0, so either branch is exact there.
bool StribeckFriction::Reassume(const Eval& e) {
  const double scale = 1e-12 * (1.0 + std::abs(tau_stribeck));
  (void)e;
  if (tau_load * quadrant >= -scale) return false;
  quadrant = -quadrant;
  return true;
}

void StribeckFriction::AfterEventRow() {
  Friction::AfterEventRow();
  flips = 0;
}

std::vector<std::string> StribeckFriction::OutputNames() const {
  if (split) return {"phi", "w", "a", "tau", "tau_load", "mode"};
  return {"phi", "w", "a", "tau", "mode"};
}

void StribeckFriction::Outputs(const Eval& e, double* out) const {
  int k = 0;
  out[k++] = e.phi[a] - e.phi[m];
  out[k++] = WF(e);
  out[k++] = AF(e);
  out[k++] = tau;
  if (split) out[k++] = tau_load;
  if (regularized) {
    const double w = WF(e);
    out[k++] = w > w_small ? msl::kForward : (w < -w_small ? msl::kBackward : msl::kStuck);
  } else {
    out[k++] = frictionless ? msl::kFree : OutputMode();
  }
}

// ------------------------------------------------------------------------------------------
// BrakeActuation

BrakeActuation::BrakeActuation(const NetworkElement& e)
    : t_lat(Param(e, "t_lat")), t_rise(Param(e, "t_rise")), latch(Param(e, "latch") != 0.0) {}

void BrakeActuation::Bind(const std::function<int(const std::string&)>&,
                          const std::function<int(const std::string&)>& signal_of) {
  trigger = signal_of("trigger");
}

// The phase (before engagement, rising, full) is chosen by the start of the current segment,
// so that it never changes inside an integration interval; the corners are time events.
double BrakeActuation::Y(const Eval& e) const {
  if (!applied) return 0.0;
  const double t0 = t_on + t_lat;
  if (e.t_segment < t0) return 0.0;
  if (t_rise <= 0.0) return 1.0;
  if (e.t_segment < t0 + t_rise) return std::clamp((e.t - t0) / t_rise, 0.0, 1.0);
  return 1.0;
}

double BrakeActuation::NextTimeEvent(double t) const {
  if (!applied) return INFINITY;
  const double t0 = t_on + t_lat;
  if (t < t0) return t0;
  if (t_rise > 0.0 && t < t0 + t_rise) return t0 + t_rise;
  return INFINITY;
}

void BrakeActuation::Roots(const Eval& e, double* g) const {
  const double x = e.signal[trigger] - 0.5;
  g[0] = x != 0.0 ? x : kRootSentinel;
}

double BrakeActuation::Violation(const Eval& e) const {
  const bool want = Commanded(e) || (latch && applied);
  return want != applied ? 1.0 : 0.0;
}

void BrakeActuation::Update(const Eval& e) {
  const bool want = Commanded(e) || (latch && applied);
  if (want && !applied) t_on = e.t;
  applied = want;
}

void BrakeActuation::Outputs(const Eval& e, double* out) const {
  out[0] = e.signal[signal_offset];
  out[1] = applied ? 1.0 : 0.0;
}

// ------------------------------------------------------------------------------------------
// NonlinearSpring

NonlinearSpring::NonlinearSpring(const NetworkElement& e)
    : Compliant(e),
      tau1_ext(Param(e, "tau1_ext")),
      tau1_ret(Param(e, "tau1_ret")),
      tau2_ext(Param(e, "tau2_ext")),
      tau2_ret(Param(e, "tau2_ret")),
      c1(Param(e, "c1")),
      c2(Param(e, "c2")),
      c3(Param(e, "c3")),
      d(Param(e, "d")) {
  auto check = [&](double tau1, double tau2, const char* n1, const char* n2) {
    if (!(tau2 > tau1))
      throw InputError(Name(e.id, e.type) + ": parameter '" + n2 + "' = " + Number(tau2) +
                       " N*m must exceed '" + n1 + "' = " + Number(tau1) +
                       " N*m (the end stop lies beyond the lock-out); raise " + n2 +
                       " or lower " + n1);
  };
  check(tau1_ext, tau2_ext, "tau1_ext", "tau2_ext");
  check(tau1_ret, tau2_ret, "tau1_ret", "tau2_ret");
  phi1_ext = tau1_ext / c1;
  phi2_ext = phi1_ext + (tau2_ext - tau1_ext) / c2;
  phi1_ret = tau1_ret / c1;
  phi2_ret = phi1_ret + (tau2_ret - tau1_ret) / c2;
}

double NonlinearSpring::TauC(double phi_rel) const {
  if (phi_rel >= phi2_ext) return tau2_ext + c3 * (phi_rel - phi2_ext);
  if (phi_rel >= phi1_ext) return tau1_ext + c2 * (phi_rel - phi1_ext);
  if (phi_rel > -phi1_ret) return c1 * phi_rel;
  if (phi_rel > -phi2_ret) return -tau1_ret + c2 * (phi_rel + phi1_ret);
  return -tau2_ret + c3 * (phi_rel + phi2_ret);
}

double NonlinearSpring::Y(double phi_rel) const {
  if (phi_rel >= phi2_ext || phi_rel <= -phi2_ret) return 1.0;
  if (phi_rel >= phi1_ext) return (phi_rel - phi1_ext) / (phi2_ext - phi1_ext);
  if (phi_rel <= -phi1_ret) return (-phi_rel - phi1_ret) / (phi2_ret - phi1_ret);
  return 0.0;
}

// Integral of tau_c from 0: each direction with its own settings (x = |phi_rel|).
double NonlinearSpring::Potential(double phi_rel) const {
  const bool extend = phi_rel >= 0.0;
  const double x = std::abs(phi_rel);
  const double tau1 = extend ? tau1_ext : tau1_ret, tau2 = extend ? tau2_ext : tau2_ret;
  const double phi1 = extend ? phi1_ext : phi1_ret, phi2 = extend ? phi2_ext : phi2_ret;
  if (x < phi1) return 0.5 * c1 * x * x;
  const double e1 = 0.5 * tau1 * phi1;
  if (x < phi2) return e1 + tau1 * (x - phi1) + 0.5 * c2 * (x - phi1) * (x - phi1);
  const double e2 = e1 + 0.5 * (tau1 + tau2) * (phi2 - phi1);
  return e2 + tau2 * (x - phi2) + 0.5 * c3 * (x - phi2) * (x - phi2);
}

void NonlinearSpring::Signals(const Eval& e, double* out) const {
  // Before the states exist (initial signal pass) the relative angle is its start value.
  if (e.y == nullptr) {
    out[0] = Y(std::isnan(phi_rel_start) ? 0.0 : phi_rel_start);
    return;
  }
  out[0] = Y(PhiRel(e));
}

void NonlinearSpring::Roots(const Eval& e, double* g) const {
  const double phi = PhiRel(e);
  g[0] = phi - phi1_ext;
  g[1] = phi - phi2_ext;
  g[2] = phi + phi1_ret;
  g[3] = phi + phi2_ret;
}

void NonlinearSpring::Outputs(const Eval& e, double* out) const {
  out[0] = PhiRel(e);
  out[1] = WRel(e);
  out[2] = tau;
  out[3] = Y(PhiRel(e));
}

// ------------------------------------------------------------------------------------------
// Factories

std::unique_ptr<Element> MakeBrakeElement(const NetworkElement& element) {
  const std::string& t = element.type;
  if (t == "ShaftBrake") return std::make_unique<ShaftBrake>(element);
  if (t == "StribeckFriction") return std::make_unique<StribeckFriction>(element, false);
  if (t == "LossyInertia") return std::make_unique<StribeckFriction>(element, true);
  if (t == "BrakeActuation") return std::make_unique<BrakeActuation>(element);
  if (t == "NonlinearSpring") return std::make_unique<NonlinearSpring>(element);
  return nullptr;
}

std::optional<Composite> ExpandBrakeComposite(const NetworkElement& e) {
  const std::string& id = e.id;
  if (e.type == "WingTipBrake") {
    const double tauB_max = Param(e, "tauB_max"), tauB_lim = Param(e, "tauB_lim");
    CheckBrakeTorques(id, e.type, tauB_max, tauB_lim);
    Composite c;
    c.inner.Adopt(Part("BrakeActuation", id + ".actuation",
                       {{"t_lat", Param(e, "t_lat")}, {"t_rise", Param(e, "t_B")}, {"latch", 1.0}}));
    c.inner.Adopt(Part("Inertia", id + ".rotor", {{"J", Param(e, "J")}}));
    c.inner.Adopt(Part("ShaftBrake", id, {{"tauB_max", tauB_max}, {"tauB_lim", tauB_lim}}));
    c.inner.Connect(id + ".rotor.flange_b", id + ".flange_a");
    c.inner.Connect(id + ".actuation.y", id + ".u");
    c.ports = {{"flange_a", {id + ".rotor.flange_a"}},
               {"flange_b", {id + ".flange_b"}},
               {"support", {id + ".support"}},
               {"apply", {id + ".actuation.trigger"}}};
    return c;
  }
  if (e.type == "TorqueLimiter") {
    const double tauB_max = Param(e, "tauB_max");
    const double tauB_lim = Given(e, "tauB_lim") ? Param(e, "tauB_lim") : tauB_max;
    CheckBrakeTorques(id, e.type, tauB_max, tauB_lim);
    std::map<std::string, double> spring;
    for (const char* n : {"tau1_ext", "tau1_ret", "tau2_ext", "tau2_ret", "c1", "c2", "c3", "d"})
      spring[n] = Param(e, n);
    if (!(spring["tau2_ext"] > spring["tau1_ext"]) || !(spring["tau2_ret"] > spring["tau1_ret"])) {
      // The spring's own check, with the limiter's name and type.
      NetworkElement named = e;
      NonlinearSpring check(named);
    }
    Composite c;
    c.inner.Adopt(Part("Inertia", id + ".inertia", {{"J", Param(e, "J")}}));
    c.inner.Adopt(Part("ShaftBrake", id + ".brake", {{"tauB_max", tauB_max}, {"tauB_lim", tauB_lim}}));
    c.inner.Adopt(Part("NonlinearSpring", id, std::move(spring)));
    c.inner.Connect(id + ".inertia.flange_b", id + ".brake.flange_a");
    c.inner.Connect(id + ".brake.flange_b", id + ".flange_a");
    c.inner.Connect(id + ".y", id + ".brake.u");
    c.ports = {{"flange_a", {id + ".inertia.flange_a"}},
               {"flange_b", {id + ".flange_b"}},
               {"support", {id + ".brake.support"}},
               {"y", {id + ".y"}}};
    return c;
  }
  return std::nullopt;
}

}  // namespace highlift::sim::detail
