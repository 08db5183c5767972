// Hydraulic components of the HighLift library (HighLift.Hydraulics): pressure source and
// tank, turbulent resistance, servo valve, differential cylinder, variable-displacement motor,
// compressible volume, the speed loop of a secondary-controlled motor. The translational Mass a
// displacement cylinder needs is in msl_more_elements.cc.
//
// Hydraulic nodes (system.cc, BuildHydraulicNodes): connected hydraulic ports share one
// pressure p; a source fixes it, otherwise dp/dt = sum(V_flow into the node) / sum(V/E) over
// the volumes attached. Elements add the flows they take from each node (Eval::AddPortFlow,
// the Modelica port.V_flow) and their capacitance (Eval::AddCapacitance) in Forces().
//
// Energy: pressure sources report p * (flow delivered) as source power; orifices, valve edges,
// motor losses and piston friction are losses; volumes store V p^2/(2E). A chamber whose volume
// changes (V0 + A*s) with the linear law dp/dt = E/V*(q - dV/dt) does p^2/(2E)*dV/dt of work
// that the stored energy V p^2/(2E) does not account for (the law is not the derivative of an
// energy when V varies); the cylinder reports it as source power, so the balance closes exactly
// and the size of this modelling defect is visible (about p/(2E) = 1.4 % of the piston work at
// 345 bar).
#include <algorithm>
#include <cmath>
#include <string>

#include "composites.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "highlift/core/message_number.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {
namespace {

using namespace msl;

std::string Where(const NetworkElement& e) { return "element '" + e.id + "' (" + e.type + ")"; }

double Clamp(double x, double lo, double hi) { return std::max(lo, std::min(hi, x)); }

/// The regularised turbulent orifice of HighLift.Hydraulics.Interfaces.Orifice:
///   V_flow = k * dp / (dp^2 + dp_small^2)^(1/4),  k = Cd*A*sqrt(2/rho).
/// Odd and smooth; equals k*sign(dp)*sqrt(|dp|) within a relative 1/4*(dp_small/dp)^2 for
/// |dp| >> dp_small (0.25 % at dp = 10 dp_small), linear with slope k/sqrt(dp_small) near 0.
template <class T>
T OrificeFlow(const T& dp, double k, double dp_small) {
  using std::pow;
  return k * dp / pow(dp * dp + dp_small * dp_small, 0.25);
}

double OrificeCoefficient(const NetworkElement& e, double area) {
  return Param(e, "Cd") * area * std::sqrt(2.0 / Param(e, "rho"));
}

/// Marks a fixed pressure on a node (one source per node).
void FixPressure(std::vector<HydraulicNode>& nodes, int n, double p, const std::string& id) {
  HydraulicNode& h = nodes[n];
  if (h.fixed)
    throw InputError("hydraulic node of '" + h.name + "' has two pressure sources, '" + h.fixed_by +
                     "' and '" + id + "'; remove one or connect them through a TurbulentResistance");
  h.fixed = true;
  h.p_fixed = p;
  h.fixed_by = id;
}

// ------------------------------------------------------------------------------------------
// PressureSource and Tank: port.p = constant.

class PressureSource : public Element {
 public:
  PressureSource(const NetworkElement& e, const char* parameter) : p(Param(e, parameter)) {}
  std::vector<std::string> HydraulicPorts() const override { return {"port"}; }
  void BindHydraulic(const std::function<int(const std::string&)>& node_of) override {
    n = node_of("port");
  }
  std::vector<int> HydraulicNodes() const override { return {n}; }
  void DeclareHydraulic(std::vector<HydraulicNode>& nodes) const override { FixPressure(nodes, n, p, id); }
  /// Flow delivered into the node: the others' flows into it are all it receives.
  double Delivered(const Eval& e) const { return -e.q[n]; }
  std::vector<std::string> OutputNames() const override { return {"p", "V_flow"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = p;
    out[1] = Delivered(e);
  }
  double SourcePower(const Eval& e) const override { return p * Delivered(e); }
  double p;
  int n = -1;
};

// ------------------------------------------------------------------------------------------
// TurbulentResistance: V_flow = Orifice(port_a.p - port_b.p).

class TurbulentResistance : public Element {
 public:
  explicit TurbulentResistance(const NetworkElement& e)
      : k(OrificeCoefficient(e, Param(e, "A"))), dp_small(Param(e, "dp_small")) {}
  std::vector<std::string> HydraulicPorts() const override { return {"port_a", "port_b"}; }
  void BindHydraulic(const std::function<int(const std::string&)>& node_of) override {
    a = node_of("port_a");
    b = node_of("port_b");
  }
  std::vector<int> HydraulicNodes() const override { return {a, b}; }
  double Dp(const Eval& e) const { return e.p[a] - e.p[b]; }
  void Forces(Eval& e) override {
    const double v = OrificeFlow(Dp(e), k, dp_small);
    e.AddPortFlow(a, v);
    e.AddPortFlow(b, -v);
  }
  std::vector<std::string> OutputNames() const override { return {"V_flow", "dp"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = OrificeFlow(Dp(e), k, dp_small);
    out[1] = Dp(e);
  }
  double LossPower(const Eval& e) const override { return Dp(e) * OrificeFlow(Dp(e), k, dp_small); }
  double k, dp_small;
  int a = -1, b = -1;
};

// ------------------------------------------------------------------------------------------
// ServoValve: the spool position x as the command itself (order 0), with a first-order lag
// (order 1) or a second-order spool (order 2); four turbulent metering edges with leakage.
//   order 0:  x = limit(u, -1, 1)                                   (no state)
//   order 1:  T_v*der(x) = limit(u, -1, 1) - x                      (state x)
//   order 2:  der(x) = v_x,  der(v_x) = w_v^2*(limit(u, -1, 1) - x) - 2*D_v*w_v*v_x  (x, v_x)
// The edges open with limit(x, -1, 1): a second-order spool that overshoots full stroke
// uncovers no more than the full port.

class ServoValve : public Element {
 public:
  explicit ServoValve(const NetworkElement& e)
      : k(OrificeCoefficient(e, Param(e, "A_max"))),
        leakage(Param(e, "leakage")),
        T_v(Param(e, "T_v")),
        w_v(Param(e, "w_v")),
        D_v(Param(e, "D_v")),
        dp_small(Param(e, "dp_small")) {
    if (leakage > 1.0)
      throw InputError(Where(e) + ": parameter 'leakage' = " + FormatMessageNumber(leakage) +
                       " must be <= 1 (a fraction of A_max); typical values are 1e-4 to 1e-2");
    const double order_value = Param(e, "order");
    if (order_value != 0.0 && order_value != 1.0 && order_value != 2.0)
      throw InputError(Where(e) + ": parameter 'order' = " + FormatNumber(order_value, 10) +
                       " is not a spool model; use 0 (the command u is the spool position), 1 "
                       "(first-order spool, T_v) or 2 (second-order spool, w_v and D_v)");
    order = static_cast<int>(order_value);
  }
  std::vector<std::string> SignalInputs() const override { return {"u"}; }
  std::vector<std::string> HydraulicPorts() const override { return {"port_P", "port_T", "port_A", "port_B"}; }
  void Bind(const std::function<int(const std::string&)>&,
            const std::function<int(const std::string&)>& signal_of) override {
    u = signal_of("u");
  }
  void BindHydraulic(const std::function<int(const std::string&)>& node_of) override {
    P = node_of("port_P");
    T = node_of("port_T");
    A = node_of("port_A");
    B = node_of("port_B");
  }
  std::vector<int> HydraulicNodes() const override { return {P, T, A, B}; }
  int NumStates() const override { return order; }
  std::vector<std::string> StateNames() const override {
    if (order == 0) return {};
    if (order == 1) return {id + ".x"};
    return {id + ".x", id + ".v_x"};
  }
  void InitStates(const Eval&, double* y) const override {
    for (int i = 0; i < order; ++i) y[state_offset + i] = 0.0;
  }
  double Command(const Eval& e) const { return Clamp(e.signal[u], -1.0, 1.0); }
  /// Spool position (normalized) and velocity (1/s; 0 when the command is the position).
  double X(const Eval& e) const { return order == 0 ? Command(e) : e.y[state_offset]; }
  double V(const Eval& e) const {
    if (order == 1) return (Command(e) - e.y[state_offset]) / T_v;
    return order == 2 ? e.y[state_offset + 1] : 0.0;
  }
  struct Flows {
    double PA, PB, AT, BT;
  };
  Flows Edges(const Eval& e) const {
    const double x = Clamp(X(e), -1.0, 1.0);
    const double open_pos = k * (std::max(x, 0.0) + leakage), open_neg = k * (std::max(-x, 0.0) + leakage);
    return {OrificeFlow(e.p[P] - e.p[A], open_pos, dp_small), OrificeFlow(e.p[P] - e.p[B], open_neg, dp_small),
            OrificeFlow(e.p[A] - e.p[T], open_neg, dp_small), OrificeFlow(e.p[B] - e.p[T], open_pos, dp_small)};
  }
  void Forces(Eval& e) override {
    const Flows f = Edges(e);
    e.AddPortFlow(P, f.PA + f.PB);
    e.AddPortFlow(T, -(f.AT + f.BT));
    e.AddPortFlow(A, f.AT - f.PA);
    e.AddPortFlow(B, f.BT - f.PB);
  }
  void Derivatives(Eval& e) override {
    if (order == 1) {
      e.ydot[state_offset] = (Command(e) - e.y[state_offset]) / T_v;
    } else if (order == 2) {
      const double x = e.y[state_offset], v_x = e.y[state_offset + 1];
      e.ydot[state_offset] = v_x;
      e.ydot[state_offset + 1] = w_v * w_v * (Command(e) - x) - 2.0 * D_v * w_v * v_x;
    }
  }
  std::vector<std::string> OutputNames() const override {
    return {"x", "V_PA", "V_PB", "V_AT", "V_BT", "v_x"};
  }
  void Outputs(const Eval& e, double* out) const override {
    const Flows f = Edges(e);
    out[0] = X(e);
    out[1] = f.PA;
    out[2] = f.PB;
    out[3] = f.AT;
    out[4] = f.BT;
    out[5] = V(e);
  }
  double LossPower(const Eval& e) const override {
    const Flows f = Edges(e);
    return (e.p[P] - e.p[A]) * f.PA + (e.p[P] - e.p[B]) * f.PB + (e.p[A] - e.p[T]) * f.AT +
           (e.p[B] - e.p[T]) * f.BT;
  }
  double k, leakage, T_v, w_v, D_v, dp_small;
  int order = 1;
  int u = -1, P = -1, T = -1, A = -1, B = -1;
};

// ------------------------------------------------------------------------------------------
// DifferentialCylinder: chambers A and B are the capacitances of their nodes; the rod end is a
// mechanical node read as position s (m) and velocity v (m/s).

class DifferentialCylinder : public Element {
 public:
  explicit DifferentialCylinder(const NetworkElement& e)
      : A_A(Param(e, "A_A")),
        A_B(Param(e, "A_B")),
        s_max(Param(e, "s_max")),
        V0_A(Param(e, "V0_A")),
        V0_B(Param(e, "V0_B")),
        E(Param(e, "E")),
        d(Param(e, "d")),
        c_stop(Param(e, "c_stop")),
        s_start(Param(e, "s_start")) {
    if (s_start < 0.0 || s_start > s_max)
      throw InputError(Where(e) + ": parameter 's_start' = " + FormatMessageNumber(s_start) +
                       " m lies outside the stroke [0, s_max = " + FormatMessageNumber(s_max) +
                       " m]; give an initial rod position within the stroke");
  }
  std::vector<std::string> Flanges() const override { return {"flange"}; }
  std::vector<std::string> HydraulicPorts() const override { return {"port_A", "port_B"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    r = node_of("flange");
  }
  void BindHydraulic(const std::function<int(const std::string&)>& node_of) override {
    na = node_of("port_A");
    nb = node_of("port_B");
  }
  std::vector<int> Nodes() const override { return {r}; }
  std::vector<int> HydraulicNodes() const override { return {na, nb}; }
  void DeclareHydraulic(std::vector<HydraulicNode>& nodes) const override {
    nodes[na].has_volume = true;
    nodes[nb].has_volume = true;
  }
  void InitialEquations(std::vector<InitialEquation>& position,
                        std::vector<InitialEquation>& speed) const override {
    position.push_back({{{r, 1.0}}, s_start});
    speed.push_back({{{r, 1.0}}, 0.0});
  }
  // Chamber volumes, kept above a thousandth of the dead volume when the rod is driven far into
  // an end stop (the Modelica class does not guard this).
  double VA(double s) const { return std::max(V0_A + A_A * s, 1e-3 * V0_A); }
  double VB(double s) const { return std::max(V0_B + A_B * (s_max - s), 1e-3 * V0_B); }
  double Stop(double s) const { return s > s_max ? c_stop * (s - s_max) : (s < 0.0 ? c_stop * s : 0.0); }
  double Force(const Eval& e) const {
    const double s = e.phi[r], v = e.w[r];
    return e.p[na] * A_A - e.p[nb] * A_B - d * v - Stop(s);
  }
  void Forces(Eval& e) override {
    const double s = e.phi[r], v = e.w[r];
    e.AddCapacitance(na, VA(s) / E);
    e.AddCapacitance(nb, VB(s) / E);
    e.AddPortFlow(na, A_A * v);   // the chamber grows by A_A*v
    e.AddPortFlow(nb, -A_B * v);  // and B shrinks by A_B*v
    e.AddForce(r, Force(e));
  }
  std::vector<std::string> OutputNames() const override { return {"s", "v", "p_A", "p_B", "f"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = e.phi[r];
    out[1] = e.w[r];
    out[2] = e.p[na];
    out[3] = e.p[nb];
    out[4] = Force(e);
  }
  double StoredEnergy(const Eval& e) const override {
    const double s = e.phi[r];
    const double over = s > s_max ? s - s_max : (s < 0.0 ? s : 0.0);
    return VA(s) * e.p[na] * e.p[na] / (2 * E) + VB(s) * e.p[nb] * e.p[nb] / (2 * E) +
           0.5 * c_stop * over * over;
  }
  double LossPower(const Eval& e) const override { return d * e.w[r] * e.w[r]; }
  /// The work of the linear compressibility law with a varying volume (see the file comment).
  double SourcePower(const Eval& e) const override {
    const double s = e.phi[r], v = e.w[r];
    const double dVA = V0_A + A_A * s > 1e-3 * V0_A ? A_A * v : 0.0;
    const double dVB = V0_B + A_B * (s_max - s) > 1e-3 * V0_B ? -A_B * v : 0.0;
    return (dVA * e.p[na] * e.p[na] + dVB * e.p[nb] * e.p[nb]) / (2 * E);
  }
  double A_A, A_B, s_max, V0_A, V0_B, E, d, c_stop, s_start;
  int r = -1, na = -1, nb = -1;
};

// ------------------------------------------------------------------------------------------
// VariableDisplacementMotor.

class VariableDisplacementMotor : public Element {
 public:
  explicit VariableDisplacementMotor(const NetworkElement& e)
      : D_max(Param(e, "D_max")), G_leak(Param(e, "G_leak")), eta_m(Param(e, "eta_m")) {}
  std::vector<std::string> Flanges() const override { return {"flange", "support"}; }
  std::vector<std::string> SignalInputs() const override { return {"eps"}; }
  std::vector<std::string> HydraulicPorts() const override { return {"port_A", "port_B"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    n = node_of("flange");
    s = node_of("support");
    eps = signal_of("eps");
  }
  void BindHydraulic(const std::function<int(const std::string&)>& node_of) override {
    A = node_of("port_A");
    B = node_of("port_B");
  }
  std::vector<int> Nodes() const override { return {n, s}; }
  std::vector<int> HydraulicNodes() const override { return {A, B}; }
  double W(const Eval& e) const { return e.w[n] - e.w[s]; }
  double Dp(const Eval& e) const { return e.p[A] - e.p[B]; }
  double Eps(const Eval& e) const { return Clamp(e.signal[eps], -1.0, 1.0); }
  double TauIdeal(const Eval& e) const { return Eps(e) * D_max * Dp(e); }
  /// tau = eta_m*tau_i driving and at standstill (the Modelica law at w = 0: a stalled motor
  /// delivers eta_m*tau_i), tau_i/eta_m driven. The switch is made continuous on the driven
  /// side: with x = w*sign(tau_i) < 0 (driven), the factor rises from eta_m to 1/eta_m as
  /// |x|/sqrt(x^2 + w_small^2); exact within 0.5 % of the factor's span above 10*w_small. (The
  /// Modelica switch chatters when a loaded motor stalls.) Inside the band the loss may be
  /// negative by at most (1 - eta_m)*|tau_i|*w_small, about 0.4 W for a PDU motor.
  static constexpr double w_small = 0.1;  // rad/s, about 0.02 % of the motor's rated speed
  double Tau(const Eval& e) const {
    const double tau_i = TauIdeal(e);
    const double x = tau_i >= 0.0 ? W(e) : -W(e);
    if (x >= 0.0) return eta_m * tau_i;
    const double blend = -x / std::sqrt(x * x + w_small * w_small);
    return tau_i * (eta_m + (1.0 / eta_m - eta_m) * blend);
  }
  double Flow(const Eval& e) const { return Eps(e) * D_max * W(e) + G_leak * Dp(e); }
  void Forces(Eval& e) override {
    const double tau = Tau(e);
    e.AddForce(n, tau);
    e.AddForce(s, -tau);
    const double v = Flow(e);
    e.AddPortFlow(A, v);
    e.AddPortFlow(B, -v);
  }
  std::vector<std::string> OutputNames() const override { return {"tau", "w", "V_flow", "dp", "eps"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = Tau(e);
    out[1] = W(e);
    out[2] = Flow(e);
    out[3] = Dp(e);
    out[4] = Eps(e);
  }
  double PeakTorque(const Eval& e) const override { return Tau(e); }
  /// Hydraulic power in, dp*V_flow, less the shaft power tau*w: (1 - eta_m)-losses and leakage.
  double LossPower(const Eval& e) const override { return Dp(e) * Flow(e) - Tau(e) * W(e); }
  double D_max, G_leak, eta_m;
  int n = -1, s = -1, eps = -1, A = -1, B = -1;
};

// ------------------------------------------------------------------------------------------
// Volume: a compressible line volume, the capacitance V/E of its node.

class Volume : public Element {
 public:
  explicit Volume(const NetworkElement& e) : V(Param(e, "V")), E(Param(e, "E")) {
    if (Given(e, "p_start")) p_start = Param(e, "p_start");
  }
  std::vector<std::string> HydraulicPorts() const override { return {"port"}; }
  void BindHydraulic(const std::function<int(const std::string&)>& node_of) override {
    n = node_of("port");
  }
  std::vector<int> HydraulicNodes() const override { return {n}; }
  void DeclareHydraulic(std::vector<HydraulicNode>& nodes) const override {
    HydraulicNode& h = nodes[n];
    h.has_volume = true;
    if (std::isnan(p_start)) return;
    if (!h.start_by.empty() && h.p_start != p_start)
      throw InputError("hydraulic node of '" + h.name + "': initial pressures " +
                       FormatMessageNumber(h.p_start) + " Pa ('" + h.start_by + "') and " +
                       FormatMessageNumber(p_start) + " Pa ('" + id + "') differ; give p_start once");
    h.p_start = p_start;
    h.start_by = id;
  }
  void Forces(Eval& e) override { e.AddCapacitance(n, V / E); }
  std::vector<std::string> OutputNames() const override { return {"p"}; }
  void Outputs(const Eval& e, double* out) const override { out[0] = e.p[n]; }
  double StoredEnergy(const Eval& e) const override { return V * e.p[n] * e.p[n] / (2 * E); }
  double V, E, p_start = NAN;
  int n = -1;
};

// ------------------------------------------------------------------------------------------
// MotorSpeedControl: PI speed loop of a secondary-controlled motor commanding the displacement,
// proportional position loop of the displacement cylinder through the servo valve.
//   e_w     = ratio*w_ref - w_m                            motor speed error (rad/s)
//   raw     = k_w*(e_w + z/T_i);  eps_ref = limit(raw, +-eps_max)  (0 when the motor is lost)
//   dz/dt   = e_w + (eps_ref - raw)/k_w                    back-calculation anti-windup
//   eps     = 2*s/s_max - 1;  u = limit(k_s*(eps_ref - eps), +-1)

class MotorSpeedControl : public Element {
 public:
  explicit MotorSpeedControl(const NetworkElement& e)
      : ratio(Param(e, "ratio")),
        k_w(Param(e, "k_w")),
        T_i(Param(e, "T_i")),
        k_s(Param(e, "k_s")),
        s_max(Param(e, "s_max")),
        eps_max(Param(e, "eps_max")) {}
  std::vector<std::string> Flanges() const override { return {"flange_m", "flange_s"}; }
  std::vector<std::string> SignalInputs() const override { return {"w_ref", "active"}; }
  std::vector<std::string> SignalOutputs() const override { return {"u", "eps"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    m = node_of("flange_m");
    r = node_of("flange_s");
    w_ref = signal_of("w_ref");
    try {
      active = signal_of("active");
    } catch (const InputError&) {
      active = -1;  // optional input: the motor is in operation
    }
  }
  std::vector<int> Nodes() const override { return {m, r}; }
  int NumStates() const override { return 1; }
  std::vector<std::string> StateNames() const override { return {id + ".z"}; }
  void InitStates(const Eval&, double* y) const override { y[state_offset] = 0.0; }
  bool Active(const Eval& e) const { return active < 0 || e.signal[active] > 0.5; }
  double Error(const Eval& e) const { return ratio * e.signal[w_ref] - e.w[m]; }
  /// The integral state (0 before the first state vector exists: initial signal evaluation).
  double Z(const Eval& e) const { return e.y != nullptr ? e.y[state_offset] : 0.0; }
  double Raw(const Eval& e) const { return k_w * (Error(e) + Z(e) / T_i); }
  double EpsRef(const Eval& e) const { return Active(e) ? Clamp(Raw(e), -eps_max, eps_max) : 0.0; }
  double Eps(const Eval& e) const { return 2.0 * e.phi[r] / s_max - 1.0; }
  void Signals(const Eval& e, double* out) const override {
    out[0] = Clamp(k_s * (EpsRef(e) - Eps(e)), -1.0, 1.0);
    out[1] = Eps(e);
  }
  void Derivatives(Eval& e) override {
    double& dz = e.ydot[state_offset];
    if (!Active(e)) {
      dz = 0.0;
      return;
    }
    dz = Error(e);
    if (k_w > 0) dz += (EpsRef(e) - Raw(e)) / k_w;
  }
  std::vector<std::string> OutputNames() const override { return {"eps_ref", "eps", "u", "w_m", "z"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = EpsRef(e);
    out[1] = Eps(e);
    out[2] = e.signal[signal_offset];
    out[3] = e.w[m];
    out[4] = Z(e);
  }
  double ratio, k_w, T_i, k_s, s_max, eps_max;
  int m = -1, r = -1, w_ref = -1, active = -1;
};

}  // namespace

std::unique_ptr<Element> MakeHydraulicElement(const NetworkElement& e) {
  const std::string& t = e.type;
  if (t == "PressureSource") return std::make_unique<PressureSource>(e, "p_supply");
  if (t == "Tank") return std::make_unique<PressureSource>(e, "p_return");
  if (t == "TurbulentResistance") return std::make_unique<TurbulentResistance>(e);
  if (t == "ServoValve") return std::make_unique<ServoValve>(e);
  if (t == "DifferentialCylinder") return std::make_unique<DifferentialCylinder>(e);
  if (t == "VariableDisplacementMotor") return std::make_unique<VariableDisplacementMotor>(e);
  if (t == "Volume") return std::make_unique<Volume>(e);
  if (t == "MotorSpeedControl") return std::make_unique<MotorSpeedControl>(e);
  return nullptr;
}

std::optional<Composite> ExpandHydraulicComposite(const NetworkElement& element) {
  (void)element;
  return std::nullopt;
}

}  // namespace highlift::sim::detail
