// Internal: the assembled model of an element network. Nodes (merged flanges), elements with
// their laws, the KKT solve of the node accelerations, the mode logic of switching elements.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "highlift/sim/network.h"

namespace highlift::sim::detail {

using Table = std::vector<std::vector<double>>;

/// tanh(x), the smooth sign of the regularised friction laws (every element, every evaluation:
/// about a million calls in a shaft rupture). Cody and Waite's method (Software Manual for the
/// Elementary Functions, 1980, ch. 13): above |x| = ln(3)/2, 1 - 2/(exp(2|x|) + 1), where the
/// quotient is at most 1/2 and no digits cancel; below, |x| + |x| g P(g)/Q(g) with g = x^2, their
/// rational approximation for 53 bits; |x| itself below 2^-27, where x^3/3 is below half an ulp of
/// x. The sign of x restored; +-1 beyond |x| = 20, where 1 - tanh is below 1e-17. Within two ulps
/// of std::tanh and monotone across the branches (tests/sim/evaluation_caches_test.cc); faster
/// than the library's tanh, whose expm1 took 4 to 5 % of a shaft rupture's time.
inline double SmoothSign(double x) {
  if (x > 20.0) return 1.0;
  if (x < -20.0) return -1.0;
  const double ax = std::abs(x);
  double z;
  if (ax > 0.54930614433405484570) {  // ln(3)/2
    z = 1.0 - 2.0 / (std::exp(2.0 * ax) + 1.0);
  } else if (ax >= 0x1p-27) {
    const double g = ax * ax;
    const double p = ((-0.96437492777225469787e+0 * g - 0.99225929672236083313e+2) * g - 0.16134119023996228053e+4) * g;
    const double q = ((g + 0.11274474380534949335e+3) * g + 0.22337720718962312926e+4) * g + 0.48402357071988688686e+4;
    z = ax + ax * (p / q);
  } else {
    return x;  // also +-0 and NaN
  }
  return std::signbit(x) ? -z : z;
}
/// exp(-x) for x >= 0 (the Stribeck decay), 0 beyond x = 40 where it is below 5e-18.
inline double Decay(double x) { return x > 40.0 ? 0.0 : std::exp(-x); }
/// tau_S * Decay(x), the Stribeck peak's share of a friction law. Without the library call for a
/// law with no peak (tau_S = 0: the drags of the shaft elements, most bearings), where the
/// product is tau_S itself, its sign of zero included, for every x but NaN (a law at a NaN
/// speed is NaN through its other terms).
inline double StribeckPeak(double tau_S, double x) { return tau_S == 0.0 ? tau_S : tau_S * Decay(x); }

/// The value a root function reports in place of an exact 0 (so that CVODE never sees one that
/// is identically zero), signed by the side the element is on. Not DBL_MIN: CVODE flags a root
/// only where g_lo * g_hi < 0, and DBL_MIN times the 1e-16 a rising normal force reaches at the
/// located time underflows to -0, so CVODE returned a root with no root flagged and the rise was
/// lost (a brake ramped from 0 stayed free, or the run looped at t = 0). 1e-100 keeps the
/// product normal for any partner above 1e-200 and is still far below every physical scale.
inline constexpr double kRootSentinel = 1e-100;

/// Remembers the arguments of the last call of a pure function of N doubles: a law evaluated
/// again at the same arguments (the phases of one evaluation, the Jacobian's difference
/// quotients that leave an element's flanges alone) reuses its value instead of calling the
/// library again. The arguments compare bit for bit, so the reused value is exactly the one the
/// function would return.
template <std::size_t N>
class Memo {
 public:
  /// True when `args` are the arguments of the last call; otherwise they become it.
  bool Same(const std::array<double, N>& args) {
    std::array<std::uint64_t, N> bits;
    for (std::size_t i = 0; i < N; ++i) bits[i] = std::bit_cast<std::uint64_t>(args[i]);
    if (valid_ && bits == key_) return true;
    key_ = bits;
    valid_ = true;
    return false;
  }

 private:
  std::array<std::uint64_t, N> key_{};
  bool valid_ = false;
};

/// Modelica.Math.Vectors.interpolate over n points (x_at(i), y_at(i)), the abscissas
/// nondecreasing: piecewise linear with linear extrapolation through the outer two points; one
/// point is constant, none 0. The accessors let a table in rows and one in columns share it.
template <class XAt, class YAt>
double InterpolatePoints(std::size_t n, XAt x_at, YAt y_at, double x) {
  if (n == 0) return 0.0;
  if (n == 1) return y_at(0);
  std::size_t i = 0;
  while (i + 2 < n && x > x_at(i + 1)) ++i;
  const double x0 = x_at(i), x1 = x_at(i + 1);
  const double y0 = y_at(i), y1 = y_at(i + 1);
  if (x1 == x0) return y1;
  return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

/// InterpolatePoints, its search started at the interval `hint` of the last call (and left
/// there for the next): a table read at every evaluation is read at nearby points. The same
/// interval, hence the same value bit for bit: the search walks back while x is not past the
/// interval's left end, then on as InterpolatePoints does.
template <class XAt, class YAt>
double InterpolatePointsNear(std::size_t n, XAt x_at, YAt y_at, double x, std::size_t& hint) {
  if (n == 0) return 0.0;
  if (n == 1) return y_at(0);
  std::size_t i = hint + 2 < n ? hint : n - 2;
  while (i > 0 && !(x > x_at(i))) --i;
  while (i + 2 < n && x > x_at(i + 1)) ++i;
  hint = i;
  const double x0 = x_at(i), x1 = x_at(i + 1);
  const double y0 = y_at(i), y1 = y_at(i + 1);
  if (x1 == x0) return y1;
  return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

/// InterpolatePoints on column `column` of `table` against column 0.
double Interpolate(const Table& table, int column, double x);

/// A node: flanges connected to each other (and flanges tied rigidly inside an element).
struct Node {
  std::string name;     ///< first flange, "element.port", for messages
  bool ground = false;  ///< fixed in the housing (Fixed element or unconnected support)
  double phi0 = 0.0;    ///< angle of a ground node
  double J = 0.0;       ///< total inertia attached
  int s_phi = -1;       ///< state index of the angle (-1 for ground)
  int s_w = -1;         ///< state index of the speed
  /// Nominal values of the angle and speed states (rad, rad/s; NaN: 1), declared by the
  /// inertias on the node (MSL `phi(nominal=...)`, `w(nominal=...)`): the absolute tolerance
  /// of a state is SimulationOptions::absolute_tolerance times its nominal value.
  double phi_nominal = NAN, w_nominal = NAN;
  /// No inertia and no kinematic coupling, only compliant elements (and sensors): the node is
  /// the static balance of their torques, its speed solved at each evaluation (System).
  bool massless = false;
};

/// A hydraulic node: hydraulic ports connected to each other (sim/src/hydraulic_elements.cc).
/// Its pressure is fixed by a source (PressureSource, Tank) or is a state with
/// dp/dt = sum(V_flow into the node) / sum(V/E) over the volumes attached (Volume, cylinder
/// chambers); a node with neither is an input error.
struct HydraulicNode {
  std::string name;            ///< first port, "element.port", for messages
  bool fixed = false;          ///< pressure imposed by a source
  double p_fixed = 0.0;        ///< that pressure, Pa
  std::string fixed_by;        ///< the element imposing it
  bool has_volume = false;     ///< some element attaches a compressible volume
  double p_start = NAN;        ///< initial pressure, Pa (NaN: 1 bar)
  std::string start_by;        ///< the element that gave p_start
  int s_p = -1;                ///< state index of the pressure (-1 for a fixed node)
};

/// The entries (node, coefficient) of a constraint's row or column. Elements set them at every
/// evaluation, so up to kInline of them (a gear, a planetary: 3; a rack: 4) live in the
/// constraint itself; more spill into a vector.
class ConstraintEntries {
 public:
  using value_type = std::pair<int, double>;
  static constexpr std::size_t kInline = 4;
  ConstraintEntries() = default;
  ConstraintEntries(std::initializer_list<value_type> list) { assign(list); }
  ConstraintEntries& operator=(std::initializer_list<value_type> list) {
    assign(list);
    return *this;
  }
  void assign(std::initializer_list<value_type> list) {
    size_ = list.size();
    if (size_ <= kInline) std::copy(list.begin(), list.end(), inline_.begin());
    else spill_.assign(list);
  }
  void push_back(const value_type& v) {
    if (size_ < kInline) {
      inline_[size_] = v;
    } else {
      if (size_ == kInline) spill_.assign(inline_.begin(), inline_.end());
      spill_.push_back(v);
    }
    ++size_;
  }
  void clear() { size_ = 0; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const value_type* begin() const { return size_ <= kInline ? inline_.data() : spill_.data(); }
  const value_type* end() const { return begin() + size_; }
  value_type* begin() { return size_ <= kInline ? inline_.data() : spill_.data(); }
  value_type* end() { return begin() + size_; }
  const value_type& operator[](std::size_t i) const { return begin()[i]; }
  value_type& operator[](std::size_t i) { return begin()[i]; }

 private:
  std::array<value_type, kInline> inline_{};
  std::vector<value_type> spill_;  ///< every entry, once there are more than kInline
  std::size_t size_ = 0;
};

/// One linear constraint on node accelerations: sum(row) = rhs, with the torque it exerts on
/// the nodes per unit multiplier (column). Ideal constraints have column = -row or +row.
struct Constraint {
  ConstraintEntries row;
  ConstraintEntries column;
  double rhs = 0.0;
  bool velocity_level = true;  ///< the same relation holds for the speeds (projected at events)
  double velocity_rhs = 0.0;   ///< the speed relation sum(row * w) = velocity_rhs (velocity_level)
  int owner = -1;              ///< element index
  double lambda = 0.0;         ///< solution: the multiplier (constraint torque)
};

/// Evaluation context: the state seen as node angles/speeds, forces, signals, constraints.
struct Eval {
  double t = 0.0;
  double t_segment = 0.0;  ///< right limit of the last event: selects branches of sources
  bool initial = false;
  const double* y = nullptr;
  double* ydot = nullptr;  ///< may be null (output evaluation)
  /// The number of the point: System counts its evaluation points from 1 (each setting of the
  /// angles and speeds from a state); within one point the phases of an evaluation may reuse a
  /// value an element computed in an earlier phase from the same inputs. 0: not counted (an
  /// Eval set up by hand), nothing is reused.
  std::uint64_t point = 0;
  std::vector<double> phi, w, acc, force;  ///< per node
  std::vector<double> signal;              ///< per signal output slot (Element::signal_offset)
  /// First and second time derivatives of the signals, per slot (NaN where a block cannot
  /// give them); computed only when an element needs them (Element::NeedsSignalDerivatives).
  std::vector<double> signal_d1, signal_d2;
  std::vector<Constraint> constraints;
  int n_constraints = 0;  ///< used entries of `constraints`

  Constraint& NewConstraint(int owner) {
    if (n_constraints == static_cast<int>(constraints.size())) constraints.emplace_back();
    Constraint& c = constraints[n_constraints++];
    c.row.clear();
    c.column.clear();
    c.rhs = 0.0;
    c.velocity_level = true;
    c.velocity_rhs = 0.0;
    c.owner = owner;
    c.lambda = 0.0;
    return c;
  }
  void AddForce(int node, double tau) { force[node] += tau; }

  // Hydraulic nodes (pressures read by the laws; flows and capacitances added in Forces()).
  std::vector<double> p;    ///< per hydraulic node: pressure, Pa
  std::vector<double> q;    ///< per hydraulic node: net volume flow into the node, m^3/s
  std::vector<double> cap;  ///< per hydraulic node: capacitance sum(V/E), m^3/Pa
  /// An element's port takes `V_flow` (m^3/s) out of the node (Modelica port.V_flow).
  void AddPortFlow(int hnode, double V_flow) { q[hnode] -= V_flow; }
  void AddCapacitance(int hnode, double c) { cap[hnode] += c; }
};

class Model;

/// What an element contributes. Defaults do nothing, so each law overrides only what it uses.
class Element {
 public:
  virtual ~Element() = default;

  std::string id;
  std::string type;
  int index = -1;

  // --- structure ---
  /// Groups of this element's flange ports that are one rigid node (e.g. Inertia a/b).
  virtual std::vector<std::vector<std::string>> RigidFlanges() const { return {}; }
  /// Flange ports (each gets a node).
  virtual std::vector<std::string> Flanges() const { return {}; }
  /// Signal input ports.
  virtual std::vector<std::string> SignalInputs() const { return {}; }
  virtual bool IsSignalBlock() const { return false; }
  /// Signal output ports. A signal block has the one output "y"; any element may declare
  /// outputs that depend on time, node angles and speeds, its own states and its inputs
  /// (a sensor, a limiter's lock-out indicator, a monitor's brake command).
  virtual std::vector<std::string> SignalOutputs() const {
    return IsSignalBlock() ? std::vector<std::string>{"y"} : std::vector<std::string>{};
  }
  /// Whether the signal outputs may change continuously with the state (sensors, tables of a
  /// measured angle). False for outputs that change only at events or with time (a monitor's
  /// latched command, a brake actuation): they do not couple the Jacobian.
  virtual bool SignalsFollowState() const { return true; }
  /// Whether the signal outputs are computed from the signal inputs at the same instant (direct
  /// feedthrough). False for outputs taken from the element's own nodes or states (a PDU's
  /// angle) or held between events (a monitor): they do not form an algebraic loop with the
  /// elements they feed.
  virtual bool DirectFeedthrough() const { return true; }
  /// First slot of this element's outputs in Eval::signal (-1 if it has none).
  int signal_offset = -1;
  /// Called once ports are resolved: node index per flange, signal source element per input.
  virtual void Bind(const std::function<int(const std::string&)>& node_of,
                    const std::function<int(const std::string&)>& signal_of) {
    (void)node_of;
    (void)signal_of;
  }
  /// Inertia attached to nodes.
  virtual void AddInertia(std::vector<Node>& nodes) const { (void)nodes; }
  /// How the element's torque on `node` enters the balance of a massless node: kOther (it
  /// cannot: a source, friction, a gear), kNoTorque (a sensor), kCompliant (tau(phi_rel, w_rel)
  /// of its own twist state, Element::BalanceTorque).
  enum class MasslessRole { kOther, kNoTorque, kCompliant };
  virtual MasslessRole RoleAt(int node) const {
    (void)node;
    return MasslessRole::kOther;
  }
  /// kCompliant elements: the torque T on `node` when that node turns at w_node (the other
  /// flange at its evaluated speed), and the other flange's node in `other`.
  virtual double BalanceTorque(const Eval& e, int node, double w_node, int& other) const {
    (void)e;
    (void)node;
    (void)w_node;
    other = -1;
    return 0.0;
  }
  /// kCompliant elements: the rate dT/dt = dT/dphi_rel * w_rel of that torque from the twist
  /// alone (the balance of springs without damping).
  virtual double BalanceRate(const Eval& e, int node, double w_node, int& other) const {
    (void)e;
    (void)node;
    (void)w_node;
    other = -1;
    return 0.0;
  }
  /// Whether the element's laws (Forces, Constraints, AfterSolve, Derivatives, Reassume,
  /// Signals and SignalDerivatives) read the angles e.phi of its nodes. Only its outputs and
  /// start values may read them when false: the sparse Jacobian's colouring then leaves the
  /// angles of its nodes out (System::ModeJacobianPattern). The default claims nothing.
  virtual bool ReadsNodeAngles() const { return true; }
  /// Nodes this element may couple by a constraint (for the KKT grouping and bandwidth).
  virtual std::vector<int> CoupledNodes() const { return {}; }
  /// Nodes this element reads or acts on.
  virtual std::vector<int> Nodes() const { return {}; }
  virtual int NumStates() const { return 0; }
  int state_offset = -1;
  // --- hydraulic structure (defaults: no hydraulic ports) ---
  /// Hydraulic ports (each joins a hydraulic node).
  virtual std::vector<std::string> HydraulicPorts() const { return {}; }
  /// Called once hydraulic ports are resolved: hydraulic node index per port.
  virtual void BindHydraulic(const std::function<int(const std::string&)>& node_of) { (void)node_of; }
  /// Hydraulic nodes this element reads or acts on.
  virtual std::vector<int> HydraulicNodes() const { return {}; }
  /// Marks fixed pressures, attached volumes and initial pressures on the nodes (throws
  /// InputError for a conflict, e.g. two sources on one node).
  virtual void DeclareHydraulic(std::vector<HydraulicNode>& nodes) const { (void)nodes; }
  virtual std::vector<std::string> StateNames() const { return {}; }
  /// Own states (offsets from state_offset) that are twists of a spring: the unknowns of the
  /// static equilibrium at rest (SimulationOptions::initial_equilibrium).
  virtual std::vector<int> TwistStates() const { return {}; }
  /// The nodes whose speeds alone give the derivative of own state k, in every mode (a relative
  /// angle: der(phi_rel) = w_b - w_a); empty when it depends on anything else. The linear solver
  /// eliminates such states before it factors (System::SpeedRows, reduced_klu.h).
  virtual std::vector<int> StateSpeedNodes(int k) const {
    (void)k;
    return {};
  }
  /// The torque per unit of each own state that is a spring twist (its stiffness, N*m/rad),
  /// 0 for other states: the absolute tolerance of a twist follows from a torque tolerance
  /// (SimulationOptions::torque_tolerance). `stiffness` has NumStates() entries, all 0 on entry.
  virtual void StateStiffness(double* stiffness) const { (void)stiffness; }
  /// Nominal values of the own states (MSL `nominal`; NaN: 1). The absolute tolerance of a
  /// state is SimulationOptions::absolute_tolerance times its nominal value, so a small signal
  /// (a housing speed of 1e-5 rad/s) is resolved relative to its own size. `nominal` has
  /// NumStates() entries, all NaN on entry.
  virtual void StateNominals(double* nominal) const { (void)nominal; }

  // --- initial conditions ---
  /// Equations sum(coef*phi[node]) = value that fix initial angles (and the speed version).
  struct InitialEquation {
    std::vector<std::pair<int, double>> row;
    double value = 0.0;
  };
  virtual void InitialEquations(std::vector<InitialEquation>& position,
                                std::vector<InitialEquation>& speed) const {
    (void)position;
    (void)speed;
  }
  /// Start values that are guesses (MSL start with fixed = false), as (node, value): the
  /// initial angles and speeds are the solution of the initial equations nearest to them.
  virtual void InitialGuesses(std::vector<std::pair<int, double>>& position,
                              std::vector<std::pair<int, double>>& speed) const {
    (void)position;
    (void)speed;
  }
  /// Initial equations on accelerations, as (node, a_start): MSL a(start = a_start, fixed =
  /// true) of an Inertia or Mass. They determine start values the equations above leave free
  /// (System::SolveInitialAccelerations).
  virtual void InitialAccelerations(std::vector<std::pair<int, double>>& acceleration) const {
    (void)acceleration;
  }
  /// The same with the evaluated signals at the start time (a source whose initial angle or
  /// speed follows its input); by default InitialEquations().
  virtual void InitialEquationsAt(const Eval& e, std::vector<InitialEquation>& position,
                                  std::vector<InitialEquation>& speed) const {
    (void)e;
    InitialEquations(position, speed);
  }
  /// Holonomic constraints that hold for the angles too (gears).
  virtual void HolonomicRows(std::vector<InitialEquation>& rows) const { (void)rows; }
  /// The relative angles of the element's own twist states at the state y as equations on the
  /// node angles (a spring: phi[b] - phi[a] = phi_rel), whether the start value was given or
  /// not: with them the node angles agree with the twists (the start written to Modelica).
  virtual void TwistRows(const double* y, std::vector<InitialEquation>& rows) const {
    (void)y;
    (void)rows;
  }
  /// Initial values of the element's own states, given node angles and speeds.
  virtual void InitStates(const Eval& e, double* y) const {
    (void)e;
    (void)y;
  }

  // --- continuous evaluation ---
  virtual double Signal(const Eval& e) const {
    (void)e;
    return 0.0;
  }
  /// Values of the outputs of SignalOutputs(), in order; by default the one output Signal().
  virtual void Signals(const Eval& e, double* out) const { out[0] = Signal(e); }
  /// First and second time derivatives of the outputs (Modelica's differentiation of an input
  /// for an exact source); NaN (the default) where the block cannot give them.
  virtual void SignalDerivatives(const Eval& e, double* d1, double* d2) const {
    (void)e;
    const std::size_t n = SignalOutputs().size();
    std::fill(d1, d1 + n, NAN);
    std::fill(d2, d2 + n, NAN);
  }
  /// Whether the element reads Eval::signal_d1 / signal_d2 of its inputs.
  virtual bool NeedsSignalDerivatives() const { return false; }
  /// Whether the signal outputs are computed from the solved accelerations or constraint
  /// torques (torque, power and acceleration sensors): evaluated after the solve; they may feed
  /// signal blocks and outputs, not a law that acts in the same solve (an algebraic loop).
  virtual bool SignalsAfterSolve() const { return false; }
  // The defaults do nothing and say so (unused_phases): after the first evaluation the system
  // calls each phase only on the elements that implement it. A law that does nothing in a phase
  // for good (by its parameters, in every mode it can reach) may say so too.
  virtual void Forces(Eval& e) {
    (void)e;
    unused_phases |= kForcesPhase;
  }
  virtual void Constraints(Eval& e) {
    (void)e;
    unused_phases |= kConstraintsPhase;
  }
  virtual void AfterSolve(Eval& e) {
    (void)e;
    unused_phases |= kAfterSolvePhase;
  }
  virtual void Derivatives(Eval& e) {
    (void)e;
    unused_phases |= kDerivativesPhase;
  }
  static constexpr unsigned kForcesPhase = 1, kConstraintsPhase = 2, kAfterSolvePhase = 4, kDerivativesPhase = 8;
  unsigned unused_phases = 0;  ///< phases whose default (no-op) ran

  // --- events ---
  virtual int NumRoots() const { return 0; }
  int root_offset = -1;
  virtual void Roots(const Eval& e, double* g) const {
    (void)e;
    (void)g;
  }
  virtual void RootDirections(int* direction) const { (void)direction; }
  /// Earliest time event strictly after t (infinity if none). The answer may change only at an
  /// event (through the element's discrete state): the simulator asks again after each event,
  /// and until then its steps stop at the time given.
  virtual double NextTimeEvent(double t) const {
    (void)t;
    return INFINITY;
  }
  virtual bool IsSwitching() const { return false; }
  /// Whether root k of this element needs the full event treatment (mode iteration, speed
  /// projection, integrator restart). A root where the right-hand side stays continuous (a
  /// backlash contact, a spring breakpoint, a regularised gear reversing) does not: the
  /// integrator goes on, after ContinuousRoot() has updated the element.
  virtual bool RootRestarts(int k) const {
    (void)k;
    return IsSwitching();
  }
  /// Whether root k (one for which RootRestarts() is false) is a function of the node angles
  /// and speeds alone (e.phi, e.w and e.y; no torque, acceleration or signal): the simulator
  /// then locates its crossings without evaluating the model (System::KinematicRoots).
  virtual bool RootFromStates(int k) const {
    (void)k;
    return false;
  }
  /// Whether Roots() in the element's present mode reads a result of the solve: a constraint
  /// torque, an acceleration, or a torque or other member its laws set in Forces or AfterSolve.
  /// True, the safe default. An element returns false only while its roots read nothing but
  /// time, its states and discrete variables, the node angles and speeds, and its signal inputs
  /// (those a law may read are computed before the solve): the simulator then checks its roots
  /// at the output points inside a long step without the solve (System::RootsWithoutSolve).
  virtual bool RootsNeedSolve() const { return true; }
  /// Root k (one for which RootRestarts() is false) was crossed at the state of `e`; the
  /// element may update discrete variables that leave the right-hand side continuous there.
  virtual void ContinuousRoot(int k, const Eval& e) {
    (void)k;
    (void)e;
  }
  /// Elements whose law assumes a branch of a piecewise-linear relation in a constraint torque
  /// (the sign of a transmitted torque, a quadrant of a lossy gear) before the solve.
  virtual bool HasAssumptions() const { return false; }
  /// After the solve: true when the assumption contradicts the solution; the element has then
  /// switched to the other branch and the forces, constraints and solve are redone. The result
  /// is a function of the state alone (the consistent branch), not of the history.
  virtual bool Reassume(const Eval& e) {
    (void)e;
    return false;
  }
  /// Root k of this element fired at the current event (set before PrepareEvent, cleared by
  /// AfterEventRow): a threshold it located is taken as crossed even when the margin at the
  /// returned time is within roundoff.
  void MarkRootFired(int k) {
    if (fired.size() < static_cast<std::size_t>(NumRoots())) fired.assign(NumRoots(), 0);
    fired[k] = 1;
  }
  bool Fired(int k) const { return k < static_cast<int>(fired.size()) && fired[k]; }
  void ClearFired() { std::fill(fired.begin(), fired.end(), 0); }
  std::vector<char> fired;
  /// At the start of an event: modes from the state (a sliding element whose speed reached
  /// zero sticks; engagement and release of brakes/clutches; the initial modes).
  virtual void PrepareEvent(const Eval& e) { (void)e; }
  /// After a solve inside the event iteration: > 0 measures how strongly the current mode is
  /// inconsistent (a stuck element whose locking torque exceeds its capacity, a rolling gear
  /// in the wrong quadrant); Fix() switches to the consistent mode.
  virtual double Violation(const Eval& e) const {
    (void)e;
    return 0.0;
  }
  virtual void Fix(const Eval& e) { (void)e; }
  /// Called when Fix() has alternated this element's mode too often in one event (a friction
  /// torque at its capacity within roundoff: stuck and sliding each look inconsistent by a
  /// rounding error): settle in the mode that is consistent within the tolerances (stuck).
  virtual void Settle(const Eval& e) { (void)e; }
  /// At the end of an event, after the modes are consistent: the element may re-initialise
  /// its own states in y (a controller's integral when a brake opens). The integrator restarts
  /// from the new state.
  virtual void EventStates(const Eval& e, double* y) {
    (void)e;
    (void)y;
  }
  /// Resets the flags that are true only at the event instant (startForward, ...).
  virtual void AfterEventRow() {}
  /// A short description of the discrete state, for the event log ("" if none).
  virtual std::string ModeText() const { return ""; }

  // --- outputs ---
  virtual std::vector<std::string> OutputNames() const { return {}; }
  virtual void Outputs(const Eval& e, double* out) const {
    (void)e;
    (void)out;
  }
  // --- energy (evaluated after a solve; the kinetic energy of node inertias is the system's) ---
  /// Potential energy stored in the element's springs (J).
  virtual double StoredEnergy(const Eval& e) const {
    (void)e;
    return 0.0;
  }
  /// Power dissipated by friction, damping, brakes and losses (W, >= 0).
  virtual double LossPower(const Eval& e) const {
    (void)e;
    return 0.0;
  }
  /// Power the element puts into the network: motors, torque and speed sources, airloads (W;
  /// negative when it absorbs, like a load or an eddy-current brake).
  virtual double SourcePower(const Eval& e) const {
    (void)e;
    return 0.0;
  }

  /// The element torque for the peak statistics (NaN if the element carries none).
  virtual double PeakTorque(const Eval& e) const {
    (void)e;
    return NAN;
  }
  /// Whether the readings of every step end (PeakTorque, LossPower, SourcePower) may say
  /// anything of this element. False only for a type that overrides none of the three (its
  /// readings are NaN, 0 and 0 whatever the state): the run then skips it at every step, and
  /// checks once at the start that it reads so. True unless a type says otherwise.
  virtual bool HasReadings() const { return true; }
};

/// Creates the element law for a network element (throws InputError for unsupported options).
std::unique_ptr<Element> MakeElement(const NetworkElement& element);

/// The laws of the HighLift library, by family; each returns nullptr for a type not its own.
/// Brakes, limiters and friction (brake_elements.cc): StribeckFriction, LossyInertia,
/// ShaftBrake, WingTipBrake, BrakeActuation, NonlinearSpring, TorqueLimiter.
std::unique_ptr<Element> MakeBrakeElement(const NetworkElement& element);
/// Gears and failures (gear_elements.cc): GearedRotaryActuator, BranchGearbox,
/// GeneralRotationalElement, Disconnector, Jam.
std::unique_ptr<Element> MakeGearElement(const NetworkElement& element);
/// Drive and control (drive_elements.cc): PDU, Monitoring, Airload.
std::unique_ptr<Element> MakeDriveElement(const NetworkElement& element);
/// Hydraulics (hydraulic_elements.cc).
std::unique_ptr<Element> MakeHydraulicElement(const NetworkElement& element);
/// The further MSL elements (msl_more_elements.cc): Rotational sensors with torque, power and
/// acceleration, RelativeStates, the motion sources Position, Speed (exact), Accelerate, Move,
/// ConstantSpeed, and the translational elements a ballscrew or rack needs.
std::unique_ptr<Element> MakeMoreMslElement(const NetworkElement& element);
/// The last MSL Rotational elements (msl_extra_elements.cc): Disc, InitializeFlange,
/// InverseSpeedDependentTorque.
std::unique_ptr<Element> MakeExtraMslElement(const NetworkElement& element);

}  // namespace highlift::sim::detail
