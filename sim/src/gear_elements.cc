// Gears and failure elements of the HighLift library (export/modelica/HighLift/Mechanical):
//
// - GearedRotaryActuator: a LossyGear (msl_elements.h) whose quadrant law takes the efficiency
//   eta_op when the power flows from the input to the output (opposing load) and eta_ai when it
//   flows back (aiding load), each built up over the input angle after a start or reversal and
//   falling back to 1 below the speed w_eta (figure 7 of the paper); the bearing friction of
//   both quadrants is the Stribeck law of equation (3), the stuck gear breaks away at
//   peak*(tau_C + tau_S). The load-dependent loss is (1 - eta)*|torque on the driving side|,
//   equation (4) with tau_load the torque that brings the power in. With elastic = true it is
//   a composite: ElastoBacklash "<id>.elastoBacklash" in front of the actuator "<id>".
// - GeneralRotationalElement: composite ElastoBacklash "<id>.elastoBacklash" + LossyInertia
//   "<id>.lossyInertia" (brake family) + IdealGear "<id>"; the LossyInertia is left out when it
//   is a massless lossless link (J = 0, no friction, eta_GE = 1).
// - BranchGearbox: composite, a GeneralRotationalElement "<id>" whose flange_a is the 1:1
//   through-drive (flange_a and flange_b of the gearbox) and whose flange_b is flange_branch.
// - Disconnector: stiff spring-damper that breaks for good at t_disconnect or on its input.
// - Jam: ties the flange to the housing through c and d from t_jam or on its input (latched).
#include <algorithm>
#include <cmath>

#include "composites.h"
#include "highlift/core/error.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {
namespace {

using namespace msl;

std::string Where(const NetworkElement& e) { return "element '" + e.id + "' (" + e.type + ")"; }

/// Event-time tolerance: a time event stops the integrator at t_event, up to roundoff.
bool Reached(double t, double t_event) {
  return t >= t_event - 1e-12 * std::max(1.0, std::abs(t_event));
}

double OptionalTime(const NetworkElement& e, const std::string& name) {
  return Given(e, name) ? Param(e, name) : INFINITY;
}

void RequireNonZeroRatio(const NetworkElement& e) {
  if (Param(e, "ratio") == 0.0)
    throw InputError(Where(e) + ": parameter 'ratio' = 0 is not a gear; give the speed ratio "
                     "input / output (non-zero, e.g. 200 for an actuator)");
}

void RequireStiffness(const NetworkElement& e) {
  if (!Given(e, "c"))
    throw InputError(Where(e) + ": parameter 'c' (torsional stiffness, N*m/rad) is required when "
                     "elastic = true; give c or set elastic = false");
}

// ------------------------------------------------------------------------------------------
// GearedRotaryActuator (the elastic = false core)

const NetworkElement& CheckedActuator(const NetworkElement& e) {
  RequireNonZeroRatio(e);
  HIGHLIFT_CHECK(Param(e, "elastic") == 0.0,
                 "an elastic GearedRotaryActuator is a composite and is expanded before assembly");
  return e;
}

class GearedRotaryActuator : public LossyGear {
 public:
  explicit GearedRotaryActuator(const NetworkElement& e)
      : LossyGear(CheckedActuator(e), "GearedRotaryActuator"),
        eta_op(Param(e, "eta_op")),
        eta_ai(Param(e, "eta_ai")),
        phi_eta(Param(e, "phi_eta")),
        w_eta(Param(e, "w_eta")),
        J_in(Param(e, "J_in")),
        J_load(Param(e, "J_load")),
        tau_C(Param(e, "tau_C")),
        d_vis(Param(e, "d_vis")),
        tau_S(Param(e, "tau_S")),
        f_exp(Param(e, "f_exp")),
        peak(Param(e, "peak")) {
    ideal = eta_op == 1.0 && eta_ai == 1.0 && tau_C == 0.0 && tau_S == 0.0 && d_vis == 0.0;
    w_small = Param(e, "w_small");
    if (Regularized() && !ideal) mode = kForward;  // always rolling, direction from the speed
  }

  void AddInertia(std::vector<Node>& nodes) const override {
    nodes[a].J += J_in;
    nodes[b].J += J_load * ratio * ratio;  // J_load is referred to the input
  }

  /// Input angle relative to the housing.
  double Phi(const Eval& e) const { return e.phi[a] - e.phi[s]; }
  /// Stribeck law, equation (3), at the input speed w.
  double Stribeck(double w) const {
    const double w_abs = std::abs(w);
    return tau_C + d_vis * w_abs + StribeckPeak(tau_S, f_exp * w_abs);
  }
  /// Mesh engagement min(e_angle, e_speed) of figure 7: 0 at standstill and right after a
  /// start, 1 once the input has turned phi_eta and runs faster than w_eta.
  double Engagement(const Eval& e) const {
    if (!Rolling()) return 0.0;
    const double e_angle = std::min(1.0, std::abs(Phi(e) - phi_start) / phi_eta);
    const double e_speed = std::min(1.0, std::abs(WA(e)) / w_eta);
    return std::min(e_angle, e_speed);
  }
  /// Quadrant 1 (power from flange_a to flange_b): eta_op; quadrant 2: eta_ai.
  /// Called by every phase of an evaluation (forces, constraints, the loss after the solve, the
  /// quadrant check): computed once per point and mode (Memo).
  Coefficients RollingCoefficients(const Eval& e) const override {
    if (rolling_memo_.Same({Phi(e), WA(e), phi_start, static_cast<double>(mode)})) return rolling_;
    const double m = Engagement(e);
    const double bf = Stribeck(WA(e));
    rolling_ = Make(1.0 - m * (1.0 - eta_op), 1.0 - m * (1.0 - eta_ai), bf, bf);
    return rolling_;
  }
  /// At standstill eta_GE = 1: the stuck actuator breaks away at peak*(tau_C + tau_S).
  Coefficients RestCoefficients() const override {
    const double bf = peak * (tau_C + tau_S);
    return Make(1.0, 1.0, bf, bf);
  }
  /// True while the power flows back from the load (rolling against the sign of tau_a).
  bool Aiding(const Eval& e) const { return Rolling() && Direction(e) * quadrant < 0; }
  double EtaGE(const Eval& e) const {
    return 1.0 - Engagement(e) * (1.0 - (Aiding(e) ? eta_ai : eta_op));
  }

  // Regularised: one root, the input speed crossing zero (a start from rest or a reversal),
  // where the angle of figure 7 restarts; the law is continuous there (e_speed = 0).
  bool RegularizedLaw() const { return Regularized() && !ideal; }
  int NumRoots() const override { return RegularizedLaw() ? 1 : LossyGear::NumRoots(); }
  void Roots(const Eval& e, double* g) const override {
    if (RegularizedLaw()) g[0] = WA(e);
    else LossyGear::Roots(e, g);
  }
  void RootDirections(int* d) const override {
    if (RegularizedLaw()) d[0] = 0;
    else LossyGear::RootDirections(d);
  }
  bool IsSwitching() const override { return !RegularizedLaw() && LossyGear::IsSwitching(); }
  bool RootRestarts(int k) const override { return !RegularizedLaw() && LossyGear::RootRestarts(k); }
  bool RootFromStates(int k) const override { return RegularizedLaw() && k == 0; }  // WA: node speeds
  bool RootsNeedSolve() const override { return !RegularizedLaw() && LossyGear::RootsNeedSolve(); }
  void ContinuousRoot(int k, const Eval& e) override {
    if (RegularizedLaw() && k == 0) phi_start = Phi(e);
  }
  void InitStates(const Eval& e, double*) const override { phi_start = Phi(e); }

  std::vector<std::string> SignalOutputs() const override { return {"eta_GE"}; }
  void Signals(const Eval& e, double* out) const override { out[0] = EtaGE(e); }

  // phi_start: the input angle at the last change of mode (start, stop, reversal).
  void PrepareEvent(const Eval& e) override {
    mode_before = mode;
    phi_event = Phi(e);
    if (e.initial) phi_start = phi_event;
    LossyGear::PrepareEvent(e);
  }
  void AfterEventRow() override {
    if (!RegularizedLaw() && mode != mode_before) phi_start = phi_event;
    mode_before = mode;
    LossyGear::AfterEventRow();
  }

  std::vector<std::string> OutputNames() const override {
    return {"phi", "w", "tau", "tau_out", "tauLoss", "lossPower", "eta_GE", "mode"};
  }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = Phi(e);
    out[1] = WA(e);
    out[2] = tau_a;
    out[3] = ratio * (tau_a - tau_loss);
    out[4] = tau_loss;
    out[5] = tau_loss * WA(e);
    out[6] = EtaGE(e);
    out[7] = mode == kUnknown || mode == kFree ? kStuck : mode;
    if (ideal) out[7] = WA(e) > 0 ? kForward : (WA(e) < 0 ? kBackward : kStuck);
    if (RegularizedLaw()) out[7] = WA(e) > w_small ? kForward : (WA(e) < -w_small ? kBackward : kStuck);
  }
  /// The input torque (the torque the transmission sees).
  double PeakTorque(const Eval&) const override { return tau_a; }

  double eta_op, eta_ai, phi_eta, w_eta, J_in, J_load, tau_C, d_vis, tau_S, f_exp;
  double peak;  ///< breakaway factor: static friction = peak*(tau_C + tau_S)
  mutable double phi_start = 0.0;  // set by InitStates (const) and at events
  double phi_event = 0.0;
  int mode_before = kUnknown;
  mutable Memo<4> rolling_memo_;  ///< RollingCoefficients at the last (phi, w, phi_start, mode)
  mutable Coefficients rolling_{};
};

// ------------------------------------------------------------------------------------------
// Disconnector

class Disconnector : public Compliant {
 public:
  explicit Disconnector(const NetworkElement& e)
      : Compliant(e),
        c(Param(e, "c")),
        d(Param(e, "d")),
        t_disconnect(OptionalTime(e, "t_disconnect")),
        use_input(Param(e, "useDisconnectInput") != 0.0) {}

  std::vector<std::string> SignalInputs() const override {
    return use_input ? std::vector<std::string>{"disconnect"} : std::vector<std::string>{};
  }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    Compliant::Bind(node_of, signal_of);
    if (use_input) {
      u = signal_of("disconnect");
      return;
    }
    bool connected = true;
    try {
      signal_of("disconnect");
    } catch (const InputError&) {
      connected = false;
    }
    if (connected)
      throw InputError("element '" + id + "' (Disconnector): input 'disconnect' is connected but "
                       "useDisconnectInput = false; set useDisconnectInput = true or remove the "
                       "connection");
  }

  double Tau(double phi_rel, double w_rel) const override {
    return broken ? 0.0 : c * phi_rel + d * w_rel;
  }
  double SpringTorque(double phi_rel) const override { return broken ? 0.0 : c * phi_rel; }
  double TwistStiffness() const override { return c; }
  /// After the rupture, the strain energy the coupling held at that instant: it leaves the
  /// mechanical network (into the structure), and stays in this term so that the balance
  /// source work = stored + dissipated holds without an impulsive-loss channel for elements.
  double Potential(double phi_rel) const override {
    return broken ? released : 0.5 * c * phi_rel * phi_rel;
  }

  bool IsSwitching() const override { return true; }
  int NumRoots() const override { return use_input ? 1 : 0; }
  void Roots(const Eval& e, double* g) const override {
    g[0] = broken ? 1.0 : e.signal[u] - 0.5;
  }
  bool RootsNeedSolve() const override { return false; }  // the trigger input
  void RootDirections(int* direction) const override { direction[0] = 1; }
  double NextTimeEvent(double t) const override {
    return !broken && t < t_disconnect ? t_disconnect : INFINITY;
  }
  void PrepareEvent(const Eval& e) override {
    if (broken) return;
    if (Reached(e.t, t_disconnect) || (use_input && e.signal[u] > 0.5)) {
      released = Potential(PhiRel(e));
      broken = true;
      t_broken = e.t;
    }
  }
  std::string ModeText() const override { return broken ? "broken" : "intact"; }

  std::vector<std::string> OutputNames() const override {
    return {"phi_rel", "w_rel", "tau", "broken"};
  }
  void Outputs(const Eval& e, double* out) const override {
    Compliant::Outputs(e, out);
    out[3] = broken ? 1.0 : 0.0;
  }

  double c, d, t_disconnect;
  bool use_input;
  int u = -1;
  bool broken = false;
  double released = 0.0;  ///< strain energy at the rupture, J
  double t_broken = NAN;
};

// ------------------------------------------------------------------------------------------
// Jam: one state, the twist of the jammed load path phi - phi_jam (held at 0 before the jam,
// so that the error test sees a small relative quantity, not the absolute flange angle).

class Jam : public Element {
 public:
  explicit Jam(const NetworkElement& e)
      : c(Param(e, "c")),
        d(Param(e, "d")),
        t_jam(OptionalTime(e, "t_jam")),
        use_input(Param(e, "useJamInput") != 0.0) {}

  std::vector<std::string> Flanges() const override { return {"flange", "support"}; }
  std::vector<std::string> SignalInputs() const override {
    return use_input ? std::vector<std::string>{"jam"} : std::vector<std::string>{};
  }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    n = node_of("flange");
    s = node_of("support");
    if (use_input) {
      u = signal_of("jam");
      return;
    }
    bool connected = true;
    try {
      signal_of("jam");
    } catch (const InputError&) {
      connected = false;
    }
    if (connected)
      throw InputError("element '" + id + "' (Jam): input 'jam' is connected but useJamInput = "
                       "false; set useJamInput = true or remove the connection");
  }
  std::vector<int> Nodes() const override { return {n, s}; }
  int NumStates() const override { return 1; }
  std::vector<std::string> StateNames() const override { return {id + ".phi_twist"}; }
  void InitStates(const Eval&, double* y) const override { y[state_offset] = 0.0; }
  void StateStiffness(double* stiffness) const override { stiffness[0] = c; }

  double Phi(const Eval& e) const { return e.phi[n] - e.phi[s]; }
  double W(const Eval& e) const { return e.w[n] - e.w[s]; }
  double Twist(const Eval& e) const { return e.y[state_offset]; }
  void Forces(Eval& e) override {
    // flange.tau = tau: the jam holds the flange back, the housing takes the reaction.
    tau = jammed ? c * Twist(e) + d * W(e) : 0.0;
    e.AddForce(n, -tau);
    e.AddForce(s, tau);
  }
  void Derivatives(Eval& e) override { e.ydot[state_offset] = jammed ? W(e) : 0.0; }

  bool IsSwitching() const override { return true; }
  int NumRoots() const override { return use_input ? 1 : 0; }
  void Roots(const Eval& e, double* g) const override {
    g[0] = jammed ? 1.0 : e.signal[u] - 0.5;
  }
  bool RootsNeedSolve() const override { return false; }  // the trigger input
  void RootDirections(int* direction) const override { direction[0] = 1; }
  double NextTimeEvent(double t) const override {
    return !jammed && t < t_jam ? t_jam : INFINITY;
  }
  void PrepareEvent(const Eval& e) override {
    if (jammed) return;
    if (Reached(e.t, t_jam) || (use_input && e.signal[u] > 0.5)) {
      jammed = true;
      phi_jam = Phi(e);
    }
  }
  std::string ModeText() const override { return jammed ? "jammed" : "free"; }

  std::vector<std::string> OutputNames() const override {
    return {"phi", "w", "tau", "jammed", "phi_jam"};
  }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = Phi(e);
    out[1] = W(e);
    out[2] = tau;
    out[3] = jammed ? 1.0 : 0.0;
    out[4] = jammed ? phi_jam : 0.0;  // Modelica: phi_jam(start = 0)
  }
  double PeakTorque(const Eval&) const override { return tau; }
  double StoredEnergy(const Eval& e) const override {
    return jammed ? 0.5 * c * Twist(e) * Twist(e) : 0.0;
  }
  double LossPower(const Eval& e) const override { return jammed ? d * W(e) * W(e) : 0.0; }

  double c, d, t_jam;
  bool use_input;
  int n = -1, s = -1, u = -1;
  bool jammed = false;
  double phi_jam = NAN;
  mutable double tau = 0.0;
};

// ------------------------------------------------------------------------------------------
// Composites

/// An element of type `type` named "<owner>.<part>" (or "<owner>" for an empty part), with
/// the catalogue defaults filled in.
NetworkElement Part(const NetworkElement& owner, const std::string& type, const std::string& part,
                    std::map<std::string, double> scalars) {
  Network scratch;
  try {
    ElementParameters parameters;
    parameters.scalars = std::move(scalars);
    scratch.AddElement(type, "part", std::move(parameters));
  } catch (const InputError& error) {
    throw InputError(Where(owner) + ": its part '" + part + "' (" + type +
                     ") is invalid: " + error.message());
  }
  NetworkElement element = scratch.elements().front();
  element.id = part.empty() ? owner.id : owner.id + "." + part;
  return element;
}

std::optional<Composite> ExpandActuator(const NetworkElement& e) {
  if (Param(e, "elastic") == 0.0) return std::nullopt;
  RequireNonZeroRatio(e);
  RequireStiffness(e);
  Composite out;
  const std::string eb = e.id + ".elastoBacklash";
  out.inner.Adopt(Part(e, "ElastoBacklash", "elastoBacklash",
                       {{"c", Param(e, "c")}, {"d", Param(e, "d")}, {"b", Param(e, "b")}}));
  NetworkElement core = e;
  core.parameters.scalars["elastic"] = 0.0;
  out.inner.Adopt(core);
  out.inner.Connect(eb + ".flange_b", e.id + ".flange_a");
  out.ports["flange_a"] = {eb + ".flange_a"};
  out.ports["flange_b"] = {e.id + ".flange_b"};
  out.ports["support"] = {e.id + ".support"};
  out.ports["eta_GE"] = {e.id + ".eta_GE"};
  return out;
}

std::optional<Composite> ExpandGeneral(const NetworkElement& e) {
  RequireNonZeroRatio(e);
  const bool elastic = Param(e, "elastic") != 0.0;
  if (elastic) RequireStiffness(e);
  const double J = Param(e, "J"), eta_GE = Param(e, "eta_GE");
  const bool lossy = J > 0.0 || Param(e, "tau_C") > 0.0 || Param(e, "tau_S") > 0.0 ||
                     Param(e, "d_vis") > 0.0 || eta_GE < 1.0;
  Composite out;
  std::vector<std::string> chain;  // "element" ids from flange_a to flange_b, in series
  std::vector<std::string> supports{e.id + ".support"};
  if (elastic) {
    out.inner.Adopt(Part(e, "ElastoBacklash", "elastoBacklash",
                         {{"c", Param(e, "c")}, {"d", Param(e, "d")}, {"b", Param(e, "b")}}));
    chain.push_back(e.id + ".elastoBacklash");
  }
  if (lossy) {
    const ComponentTypeSpec* spec = FindElementType("LossyInertia");
    if (spec == nullptr)
      throw InputError(Where(e) + ": J > 0, friction or eta_GE < 1 need the element type "
                       "'LossyInertia', which this build does not have; set J = 0, tau_C = "
                       "tau_S = d_vis = 0 and eta_GE = 1 (a massless lossless gear) or use an "
                       "Inertia and a LossyGear");
    out.inner.Adopt(Part(e, "LossyInertia", "lossyInertia",
                         {{"J", J},
                          {"tau_C", Param(e, "tau_C")},
                          {"d_vis", Param(e, "d_vis")},
                          {"tau_S", Param(e, "tau_S")},
                          {"f_exp", Param(e, "f_exp")},
                          {"peak", Param(e, "peak")},
                          {"w_small", Param(e, "w_small")},
                          {"eta_GE", eta_GE}}));
    chain.push_back(e.id + ".lossyInertia");
    if (spec->FindPort("support") != nullptr) supports.push_back(e.id + ".lossyInertia.support");
  }
  out.inner.Adopt(Part(e, "IdealGear", "", {{"ratio", Param(e, "ratio")}}));
  chain.push_back(e.id);
  for (std::size_t k = 0; k + 1 < chain.size(); ++k)
    out.inner.Connect(chain[k] + ".flange_b", chain[k + 1] + ".flange_a");
  out.ports["flange_a"] = {chain.front() + ".flange_a"};
  out.ports["flange_b"] = {e.id + ".flange_b"};
  // The housing of every part: when the composite's support is left open, each part's support
  // stays open too (grounded); when it is connected, all of them join it.
  out.ports["support"] = supports;
  return out;
}

std::optional<Composite> ExpandBranch(const NetworkElement& e) {
  RequireNonZeroRatio(e);
  if (Param(e, "elastic") != 0.0) RequireStiffness(e);
  std::map<std::string, double> p;
  for (const char* name : {"ratio", "elastic", "d", "b", "J", "tau_C", "d_vis", "tau_S", "f_exp",
                           "w_small", "eta_GE"})
    p[name] = Param(e, name);
  if (Given(e, "c")) p["c"] = Param(e, "c");
  Composite out;
  out.inner.Adopt(Part(e, "GeneralRotationalElement", "", std::move(p)));
  // The through-drive is rigid: flange_a and flange_b are the branch's input flange.
  out.ports["flange_a"] = {e.id + ".flange_a"};
  out.ports["flange_b"] = {e.id + ".flange_a"};
  out.ports["flange_branch"] = {e.id + ".flange_b"};
  out.ports["support"] = {e.id + ".support"};
  return out;
}

}  // namespace

std::unique_ptr<Element> MakeGearElement(const NetworkElement& element) {
  const std::string& t = element.type;
  if (t == "GearedRotaryActuator") return std::make_unique<GearedRotaryActuator>(element);
  if (t == "Disconnector") return std::make_unique<Disconnector>(element);
  if (t == "Jam") return std::make_unique<Jam>(element);
  return nullptr;
}

std::optional<Composite> ExpandGearComposite(const NetworkElement& element) {
  const std::string& t = element.type;
  if (t == "GearedRotaryActuator") return ExpandActuator(element);
  if (t == "GeneralRotationalElement") return ExpandGeneral(element);
  if (t == "BranchGearbox") return ExpandBranch(element);
  return std::nullopt;
}

}  // namespace highlift::sim::detail
