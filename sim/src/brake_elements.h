// Internal: the laws of the HighLift brakes, torque limiters and friction (specification:
// export/modelica/HighLift/Mechanical/{StribeckFriction,LossyInertia,ShaftBrake,NonlinearSpring}
// .mo and Control/BrakeActuation.mo), as classes other families may reuse:
//   - ShaftBrake: brake to the housing commanded by the normalized dynamic brake torque u
//     (the pressure-off brake of a PDU, the brake of a wing-tip brake and of a torque limiter);
//   - StribeckFriction: Stribeck law (3) plus the load-dependent loss (4) of equation, with
//     stick/slip; with an inertia J it is the LossyInertia;
//   - BrakeActuation: Boolean command -> latency -> linear rise;
//   - NonlinearSpring: the three stiffnesses of figure 4 and the output y of equation (2).
// WingTipBrake and TorqueLimiter are composites of these (ExpandBrakeComposite).
// Stick/slip uses the MSL state machine of msl::Friction.
#pragma once

#include <string>
#include <vector>

#include "msl_elements.h"

namespace highlift::sim::detail {

/// Brake between the shaft (flange_a = flange_b) and the support. With u = max(input, 0):
///   free (u <= 0): tau = 0;  sliding: tau = sign(w) * u * tauB_max;  stuck: |tau| <= u * tauB_lim.
/// tau > 0 opposes forward rotation: the shaft feels -tau, the support +tau.
class ShaftBrake : public msl::Friction {
 public:
  bool ReadsNodeAngles() const override { return false; }
  /// Throws InputError (naming `id` and `type`) unless 0 <= tauB_max <= tauB_lim.
  ShaftBrake(const std::string& id, const std::string& type, double tauB_max, double tauB_lim);
  explicit ShaftBrake(const NetworkElement& e);

  std::vector<std::vector<std::string>> RigidFlanges() const override {
    return {{"flange_a", "flange_b"}};
  }
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b", "support"}; }
  std::vector<std::string> SignalInputs() const override { return {"u"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override;

  /// The command in use, max(u, 0).
  double U(const Eval& e) const { return std::max(e.signal[u_signal], 0.0); }
  double Fn(const Eval& e) const override { return U(e); }
  double TauSlide(const Eval& e, double w) const override;
  double Tau0Max(const Eval& e) const override { return U(e) * tauB_lim; }

  // Engagement is checked at every step of the event iteration too: the command may change
  // when another element (BrakeActuation, a monitor) switches at the same event.
  double Violation(const Eval& e) const override;
  void Fix(const Eval& e) override;

  std::vector<std::string> OutputNames() const override { return {"w", "tau", "u", "mode"}; }
  void Outputs(const Eval& e, double* out) const override;

  double tauB_max, tauB_lim;  // N*m
  int u_signal = -1;
};

/// Friction to the support after the Stribeck law (3) plus the load-dependent loss (4):
///   sliding: tau = sign(w) * (tau_C + d_vis*|w| + tau_S*exp(-f_exp*|w|) + (1 - eta)*|tau_load|)
///   stuck:   |tau| <= max(peak*(tau_C + tau_S), tau_C + tau_S + (1 - eta)*|tau_load|)
/// with tau_load = (flange_a.tau - flange_b.tau)/2 the transmitted torque. When the load loss
/// can act (eta_GE < 1 or the eta input), flange_a and flange_b are two nodes tied by a rigid
/// constraint whose multiplier is tau_load; the sign of tau_load (`quadrant`) makes the loss
/// linear in the multiplier and is switched at its zero crossings. Otherwise the two flanges are
/// one node (as MSL BearingFriction). With J > 0 it is the LossyInertia (J on flange_a).
class StribeckFriction final : public msl::Friction {
 public:
  bool ReadsNodeAngles() const override { return false; }
  StribeckFriction(const NetworkElement& e, bool with_inertia);

  std::vector<std::vector<std::string>> RigidFlanges() const override;
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b", "support"}; }
  std::vector<std::string> SignalInputs() const override;
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override;
  void AddInertia(std::vector<Node>& nodes) const override { nodes[a].J += J; }
  std::vector<int> Nodes() const override;
  std::vector<int> CoupledNodes() const override;
  void HolonomicRows(std::vector<InitialEquation>& rows) const override;

  /// Efficiency in use (parameter or input, clipped to [0, 1]).
  double Eta(const Eval& e) const;
  /// The Stribeck law (3) for forward sliding at speed w (signed), without the load loss.
  double Stribeck(double w) const {
    return tau_C + d_vis * w + StribeckPeak(tau_S, f_exp * std::abs(w));
  }
  double TauSlide(const Eval& e, double w) const override;
  double Tau0Max(const Eval& e) const override;

  void Forces(Eval& e) override;
  /// Forces when regularised with one node (smooth_one_node_, the common case: the drags and
  /// bearings of a drive model): the law of the general path with the same operations (the
  /// mode, constant, left out of the memo's key; tanh(w/w_small) computed where the general
  /// path's Smooth memo would miss too, as both are keyed on the last w). tau takes the + 0.0
  /// of AfterSolve here, which then has nothing left to do. Inline: System::Evaluate calls it
  /// directly for these elements.
  void SmoothOneNodeForces(Eval& e) {
    const double w = e.w[a] - e.w[m];
    if (!smooth_law_memo_.Same({w}))
      law_ = SmoothSign(w / w_small) * (tau_C + StribeckPeak(tau_S, f_exp * std::abs(w))) + d_vis * w;
    tau_stribeck = law_;
    e.AddForce(a, -law_);
    e.AddForce(m, law_);
    tau = law_ + 0.0;
  }
  void Constraints(Eval& e) override;
  void AfterSolve(Eval& e) override;

  int NumRoots() const override { return frictionless || regularized ? 0 : 4; }
  void Roots(const Eval& e, double* g) const override;
  void RootDirections(int* d) const override;
  /// Root 3 reads tau_load, the multiplier of the solve, while the split law slides.
  bool RootsNeedSolve() const override { return Friction::RootsNeedSolve() || (split && Sliding()); }
  bool IsSwitching() const override { return !frictionless && !regularized; }
  /// Regularised (w_small > 0): the sign of tau_load is assumed, checked after the solve.
  bool HasAssumptions() const override { return regularized && split; }
  bool Reassume(const Eval& e) override;
  /// Regularised law: tanh(w/w_small), the smooth sign of the sliding speed.
  double Smooth(const Eval& e) const {
    const double w = WF(e);
    if (!smooth_memo_.Same({w})) smooth_ = SmoothSign(w / w_small);
    return smooth_;
  }
  void PrepareEvent(const Eval& e) override;
  double Violation(const Eval& e) const override;
  void Fix(const Eval& e) override;
  void AfterEventRow() override;
  std::string ModeText() const override { return frictionless ? "" : Friction::ModeText(); }

  std::vector<std::string> OutputNames() const override;
  void Outputs(const Eval& e, double* out) const override;

  double J = 0.0;                               // kg*m^2
  double tau_C, d_vis, tau_S, f_exp, eta_GE;    // N*m, N*m*s/rad, N*m, s/rad, 1
  double w_small = 0.0;                         // rad/s, regularisation speed (0: stick/slip)
  bool regularized = false;                     // w_small > 0: no stick/slip state machine
  bool use_eta_input = false;
  bool split = false;        // flange_a and flange_b are separate nodes (load loss active)
  bool frictionless = false;  // no friction at all: a rigid shaft (plus J)
  int a = -1, b = -1;         // flange nodes (p = a, m = support)
  int eta_signal = -1;
  int quadrant = 1;           // sign of tau_load assumed by the sliding law
  int flips = 0;              // quadrant flips in this event iteration
  int rigid = -1, stuck = -1;  // constraint indices of this evaluation
  double tau_load = 0.0;      // N*m
  double tau_stribeck = 0.0;  // N*m, the part of tau from law (3) while sliding
  mutable Memo<1> smooth_memo_;  // Smooth at the last w
  mutable double smooth_ = 0.0;
  Memo<2> law_memo_;  // tau_stribeck at the last (w, mode)
  double law_ = 0.0;
  // Regularised with one node (not split): the law depends on w alone and tau on nothing
  // after the solve, so Forces takes a path of its own with its memo keyed on w.
  bool smooth_one_node_ = false;
  Memo<1> smooth_law_memo_;  // law_ at the last w (smooth_one_node_)
};

/// Boolean command to the normalized brake torque: applied = trigger or (latch and applied);
/// t_on = time the command became true; y = 0 before t_on + t_lat, then
/// min(1, (time - t_on - t_lat)/t_rise) (a step when t_rise = 0).
class BrakeActuation : public Element {
 public:
  explicit BrakeActuation(const NetworkElement& e);
  std::vector<std::string> SignalInputs() const override { return {"trigger"}; }
  std::vector<std::string> SignalOutputs() const override { return {"y"}; }
  /// y depends on time and on the command held since the last event, not on the state.
  bool SignalsFollowState() const override { return false; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override;
  double Y(const Eval& e) const;
  double Signal(const Eval& e) const override { return Y(e); }
  double NextTimeEvent(double t) const override;
  int NumRoots() const override { return 1; }
  void Roots(const Eval& e, double* g) const override;
  bool RootsNeedSolve() const override { return false; }  // the trigger input
  bool IsSwitching() const override { return true; }
  void PrepareEvent(const Eval& e) override { Update(e); }
  double Violation(const Eval& e) const override;
  void Fix(const Eval& e) override { Update(e); }
  std::string ModeText() const override { return applied ? "applied" : "released"; }
  std::vector<std::string> OutputNames() const override { return {"y", "applied"}; }
  void Outputs(const Eval& e, double* out) const override;

  bool Commanded(const Eval& e) const { return e.signal[trigger] > 0.5; }
  void Update(const Eval& e);

  double t_lat, t_rise;  // s
  bool latch;
  bool applied = false;
  double t_on = 0.0;  // s
  int trigger = -1;
};

/// The spring of figure 4 with the output y of equation (2); tau = tau_c(phi_rel) + d*w_rel.
class NonlinearSpring : public msl::Compliant {
 public:
  bool ReadsNodeAngles() const override { return false; }
  explicit NonlinearSpring(const NetworkElement& e);
  /// Spring torque tau_c(phi_rel): c1, then c2 from tau1, then c3 from tau2 (by direction).
  double TauC(double phi_rel) const;
  /// Equation (2): 0 inside +-phi1, rising linearly to 1 at +-phi2.
  double Y(double phi_rel) const;
  double Tau(double phi_rel, double w_rel) const override { return TauC(phi_rel) + d * w_rel; }
  double Potential(double phi_rel) const override;
  double SpringTorque(double phi_rel) const override { return TauC(phi_rel); }
  double TwistStiffness() const override { return std::max({c1, c2, c3}); }
  std::vector<std::string> SignalOutputs() const override { return {"y"}; }
  void Signals(const Eval& e, double* out) const override;
  int NumRoots() const override { return 4; }
  void Roots(const Eval& e, double* g) const override;
  bool RootsNeedSolve() const override { return false; }  // the twist
  std::vector<std::string> OutputNames() const override { return {"phi_rel", "w_rel", "tau", "y"}; }
  void Outputs(const Eval& e, double* out) const override;

  double tau1_ext, tau1_ret, tau2_ext, tau2_ret;  // N*m (retract values as magnitudes)
  double c1, c2, c3, d;                           // N*m/rad, N*m*s/rad
  double phi1_ext, phi2_ext, phi1_ret, phi2_ret;  // rad (retract values as magnitudes)
};

}  // namespace highlift::sim::detail
