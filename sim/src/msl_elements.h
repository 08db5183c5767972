// Internal: the laws of the MSL element types, as classes that the laws of the HighLift
// library (drive components, hydraulics) may extend: TwoFlange for the relative quantities,
// Compliant for relative-twist states, Friction for the MSL stick/slip state machine (with
// BearingFriction, Brake, Clutch), GearBase and LossyGear for gears, TorqueSource for the torque
// sources, SignalBlock for Modelica.Blocks sources. MakeElement (elements.cc) creates them.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "highlift/core/error.h"
#include "model.h"

namespace highlift::sim::detail::msl {

constexpr double kPi = std::numbers::pi;

inline double Param(const NetworkElement& e, const std::string& name) {
  auto it = e.parameters.scalars.find(name);
  if (it == e.parameters.scalars.end())
    throw InputError("element '" + e.id + "' (" + e.type + "): parameter '" + name +
                     "' has no value; give it in the element's parameters");
  return it->second;
}
inline bool Given(const NetworkElement& e, const std::string& name) {
  auto it = e.given.find(name);
  return it != e.given.end() && it->second;
}
inline Table TableOr(const NetworkElement& e, const std::string& name, Table fallback, int columns) {
  auto it = e.parameters.tables.find(name);
  Table t = it == e.parameters.tables.end() ? std::move(fallback) : it->second;
  if (t.empty())
    throw InputError("element '" + e.id + "' (" + e.type + "): table '" + name +
                     "' is empty; give at least one row");
  for (std::size_t r = 0; r < t.size(); ++r) {
    if (static_cast<int>(t[r].size()) < columns)
      throw InputError("element '" + e.id + "' (" + e.type + "): table '" + name + "' row " +
                       std::to_string(r + 1) + " has " + std::to_string(t[r].size()) +
                       " columns; it needs " + std::to_string(columns));
    if (r > 0 && t[r][0] < t[r - 1][0])
      throw InputError("element '" + e.id + "' (" + e.type + "): table '" + name +
                       "' first column must not decrease (row " + std::to_string(r + 1) + ")");
  }
  return t;
}

// ------------------------------------------------------------------------------------------
// Fixed and Inertia

class Fixed : public Element {
 public:
  explicit Fixed(const NetworkElement& e) : phi0(Param(e, "phi0")) {}
  std::vector<std::string> Flanges() const override { return {"flange"}; }
  double phi0;
};

class Inertia : public Element {
 public:
  bool ReadsNodeAngles() const override { return false; }
  explicit Inertia(const NetworkElement& e) : J(Param(e, "J")) {
    if (Given(e, "phi_start")) phi_start = Param(e, "phi_start");
    if (Given(e, "w_start")) w_start = Param(e, "w_start");
    // phi_fixed / w_fixed = false: the start value is a guess (translational Mass: s_fixed...).
    phi_guess = Given(e, "phi_fixed") && Param(e, "phi_fixed") == 0;
    w_guess = Given(e, "w_fixed") && Param(e, "w_fixed") == 0;
    // a_start holds as an initial equation unless a_fixed = false (a is no state: then unused).
    if (Given(e, "a_start") && !(Given(e, "a_fixed") && Param(e, "a_fixed") == 0)) a_start = Param(e, "a_start");
    if (Given(e, "phi_nominal")) phi_nominal = Param(e, "phi_nominal");
    if (Given(e, "w_nominal")) w_nominal = Param(e, "w_nominal");
  }
  std::vector<std::vector<std::string>> RigidFlanges() const override {
    return {{"flange_a", "flange_b"}};
  }
  bool HasReadings() const override { return false; }  // its kinetic energy is the node's
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    n = node_of("flange_a");
  }
  /// Adds J; the smallest nominal values declared on a node scale its tolerances.
  void AddInertia(std::vector<Node>& nodes) const override {
    Node& node = nodes[n];
    node.J += J;
    if (!std::isnan(phi_nominal)) node.phi_nominal = std::fmin(node.phi_nominal, phi_nominal);
    if (!std::isnan(w_nominal)) node.w_nominal = std::fmin(node.w_nominal, w_nominal);
  }
  std::vector<int> Nodes() const override { return {n}; }
  void InitialEquations(std::vector<InitialEquation>& position,
                        std::vector<InitialEquation>& speed) const override {
    if (!std::isnan(phi_start) && !phi_guess) position.push_back({{{n, 1.0}}, phi_start});
    if (!std::isnan(w_start) && !w_guess) speed.push_back({{{n, 1.0}}, w_start});
  }
  void InitialGuesses(std::vector<std::pair<int, double>>& position,
                      std::vector<std::pair<int, double>>& speed) const override {
    if (!std::isnan(phi_start) && phi_guess) position.push_back({n, phi_start});
    if (!std::isnan(w_start) && w_guess) speed.push_back({n, w_start});
  }
  void InitialAccelerations(std::vector<std::pair<int, double>>& acceleration) const override {
    if (!std::isnan(a_start)) acceleration.push_back({n, a_start});
  }
  std::vector<std::string> OutputNames() const override { return {"phi", "w", "a"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = e.phi[n];
    out[1] = e.w[n];
    out[2] = e.acc[n];
  }
  double J;
  double phi_start = NAN, w_start = NAN;
  double a_start = NAN;  ///< rad/s^2, the initial equation a = a_start (NaN: none)
  double phi_nominal = NAN, w_nominal = NAN;
  bool phi_guess = false, w_guess = false;  ///< the start values are guesses (fixed = false)
  int n = -1;
};

// ------------------------------------------------------------------------------------------
// Two-flange base: phi_rel = phi_b - phi_a, w_rel = w_b - w_a; the element torque tau is
// flange_b.tau and acts as +tau on node a and -tau on node b.

class TwoFlange : public Element {
 public:
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    a = node_of("flange_a");
    b = node_of("flange_b");
  }
  std::vector<int> Nodes() const override { return {a, b}; }
  double WRel(const Eval& e) const { return e.w[b] - e.w[a]; }
  void ApplyTorque(Eval& e, double tau) const {
    e.AddForce(a, tau);
    e.AddForce(b, -tau);
  }
  int a = -1, b = -1;
};

/// Compliant elements: the relative angle phi_rel is a state of its own.
class Compliant : public TwoFlange {
 public:
  explicit Compliant(const NetworkElement& e) {
    if (Given(e, "phi_rel_start")) phi_rel_start = Param(e, "phi_rel_start");
    if (Given(e, "w_rel_start")) w_rel_start = Param(e, "w_rel_start");
    if (Given(e, "phi_nominal")) phi_nominal = Param(e, "phi_nominal");
  }
  void StateNominals(double* nominal) const override { nominal[0] = phi_nominal; }
  /// The law: element torque from relative angle and speed.
  virtual double Tau(double phi_rel, double w_rel) const = 0;
  /// The conservative part: potential energy and its derivative (the spring torque).
  virtual double Potential(double phi_rel) const {
    (void)phi_rel;
    return 0.0;
  }
  virtual double SpringTorque(double phi_rel) const {
    (void)phi_rel;
    return 0.0;
  }
  double StoredEnergy(const Eval& e) const override { return Potential(PhiRel(e)); }
  MasslessRole RoleAt(int) const override { return MasslessRole::kCompliant; }
  /// +tau on node a, -tau on node b, with w_rel from the node's speed w_node.
  double WRelAt(const Eval& e, int node, double w_node, int& other) const {
    other = node == a ? b : a;
    return node == a ? e.w[b] - w_node : w_node - e.w[a];
  }
  double BalanceTorque(const Eval& e, int node, double w_node, int& other) const override {
    const double t = Tau(PhiRel(e), WRelAt(e, node, w_node, other));
    return node == a ? t : -t;
  }
  double BalanceRate(const Eval& e, int node, double w_node, int& other) const override {
    const double w_rel = WRelAt(e, node, w_node, other);
    const double phi = PhiRel(e), h = 1e-7 * (1e-3 + std::abs(phi));
    const double k = (Tau(phi + h, w_rel) - Tau(phi - h, w_rel)) / (2 * h);
    return (node == a ? k : -k) * w_rel;
  }
  /// Power taken from the flanges, tau * w_rel, less the rate of the potential energy.
  double LossPower(const Eval& e) const override {
    return (tau - SpringTorque(PhiRel(e))) * WRel(e);
  }

  int NumStates() const override { return 1; }
  std::vector<std::string> StateNames() const override { return {id + ".phi_rel"}; }
  /// The relative angle, unless it was given (phi_rel_start fixes it).
  std::vector<int> TwistStates() const override {
    return std::isnan(phi_rel_start) ? std::vector<int>{0} : std::vector<int>{};
  }
  /// The stiffness that turns a twist error into a torque error (0: no spring).
  virtual double TwistStiffness() const { return 0.0; }
  void StateStiffness(double* stiffness) const override { stiffness[0] = TwistStiffness(); }
  void InitialEquations(std::vector<InitialEquation>& position,
                        std::vector<InitialEquation>& speed) const override {
    if (!std::isnan(phi_rel_start)) position.push_back({{{b, 1.0}, {a, -1.0}}, phi_rel_start});
    if (!std::isnan(w_rel_start)) speed.push_back({{{b, 1.0}, {a, -1.0}}, w_rel_start});
  }
  void InitStates(const Eval& e, double* y) const override {
    y[state_offset] = std::isnan(phi_rel_start) ? e.phi[b] - e.phi[a] : phi_rel_start;
  }
  void TwistRows(const double* y, std::vector<InitialEquation>& rows) const override {
    rows.push_back({{{b, 1.0}, {a, -1.0}}, y[state_offset]});
  }
  double PhiRel(const Eval& e) const { return e.y[state_offset]; }
  void Forces(Eval& e) override {
    tau = Tau(PhiRel(e), WRel(e));
    ApplyTorque(e, tau);
  }
  void Derivatives(Eval& e) override { e.ydot[state_offset] = WRel(e); }
  std::vector<int> StateSpeedNodes(int k) const override { return k == 0 ? std::vector<int>{a, b} : std::vector<int>{}; }
  std::vector<std::string> OutputNames() const override { return {"phi_rel", "w_rel", "tau"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = PhiRel(e);
    out[1] = WRel(e);
    out[2] = tau;
  }
  double PeakTorque(const Eval&) const override { return tau; }

  double phi_rel_start = NAN, w_rel_start = NAN;
  double phi_nominal = NAN;  ///< rad, scales the absolute tolerance of phi_rel (NaN: 1)
  mutable double tau = 0.0;
};

class Spring : public Compliant {
 public:
  bool ReadsNodeAngles() const override { return false; }
  explicit Spring(const NetworkElement& e)
      : Compliant(e), c(Param(e, "c")), phi_rel0(Param(e, "phi_rel0")) {}
  double Tau(double phi_rel, double) const override { return c * (phi_rel - phi_rel0); }
  double TwistStiffness() const override { return c; }
  double Potential(double phi_rel) const override {
    return 0.5 * c * (phi_rel - phi_rel0) * (phi_rel - phi_rel0);
  }
  double SpringTorque(double phi_rel) const override { return c * (phi_rel - phi_rel0); }
  double c, phi_rel0;
};

class Damper : public Compliant {
 public:
  bool ReadsNodeAngles() const override { return false; }
  explicit Damper(const NetworkElement& e) : Compliant(e), d(Param(e, "d")) {}
  double Tau(double, double w_rel) const override { return d * w_rel; }
  double d;
};

class SpringDamper : public Compliant {
 public:
  bool ReadsNodeAngles() const override { return false; }
  explicit SpringDamper(const NetworkElement& e)
      : Compliant(e), c(Param(e, "c")), d(Param(e, "d")), phi_rel0(Param(e, "phi_rel0")) {}
  double Tau(double phi_rel, double w_rel) const final {
    return c * (phi_rel - phi_rel0) + d * w_rel;
  }
  // Compliant's Forces and LossPower with this law called directly, not through the virtual Tau
  // and SpringTorque: the elements of the torque shafts are the most numerous of a drive model.
  // (Tau and SpringTorque are final: a class derived from this one keeps the law.)
  void Forces(Eval& e) override {
    tau = SpringDamper::Tau(PhiRel(e), WRel(e));
    ApplyTorque(e, tau);
  }
  double LossPower(const Eval& e) const override {
    return (tau - SpringDamper::SpringTorque(PhiRel(e))) * WRel(e);
  }
  double TwistStiffness() const override { return c; }
  double Potential(double phi_rel) const override {
    return 0.5 * c * (phi_rel - phi_rel0) * (phi_rel - phi_rel0);
  }
  double SpringTorque(double phi_rel) const final { return c * (phi_rel - phi_rel0); }
  double c, d, phi_rel0;
};

/// MSL 4.0.0 ElastoBacklash: contact only pushes, damping never exceeds the spring torque.
class ElastoBacklash : public Compliant {
 public:
  explicit ElastoBacklash(const NetworkElement& e)
      : Compliant(e),
        c(Param(e, "c")),
        d(Param(e, "d")),
        b_total(Param(e, "b")),
        phi_rel0(Param(e, "phi_rel0")) {}
  double Tau(double phi_rel, double w_rel) const override {
    const double delta = phi_rel - phi_rel0;
    if (b_total <= 1e-10) return c * delta + d * w_rel;
    const double g = b_total / 2;
    if (delta > g) {
      const double tau_c = c * (delta - g), tau_d = d * w_rel;
      return tau_c + tau_d <= 0 ? 0.0 : tau_c + std::min(tau_c, tau_d);
    }
    if (delta < -g) {
      const double tau_c = c * (delta + g), tau_d = d * w_rel;
      return tau_c + tau_d >= 0 ? 0.0 : tau_c + std::max(tau_c, tau_d);
    }
    return 0.0;
  }
  /// Penetration beyond the free play (0 inside the gap).
  double Penetration(double phi_rel) const {
    const double delta = phi_rel - phi_rel0;
    if (b_total <= 1e-10) return delta;
    const double g = b_total / 2;
    return delta > g ? delta - g : (delta < -g ? delta + g : 0.0);
  }
  double Potential(double phi_rel) const override {
    const double x = Penetration(phi_rel);
    return 0.5 * c * x * x;
  }
  double SpringTorque(double phi_rel) const override { return c * Penetration(phi_rel); }
  double TwistStiffness() const override { return c; }
  int NumRoots() const override { return b_total <= 1e-10 ? 0 : 2; }
  void Roots(const Eval& e, double* g) const override {
    const double delta = PhiRel(e) - phi_rel0;
    g[0] = delta - b_total / 2;
    g[1] = delta + b_total / 2;
  }
  bool RootsNeedSolve() const override { return false; }  // the twist (ElastoBacklash2: and its rate)
  double c, d, b_total, phi_rel0;
};

/// MSL 4.0.0 ElastoBacklash2: in contact tau = tau_c + tau_d (the damping acts in full, so the
/// torque jumps by d*w_rel when contact begins), clipped to 0 where it would pull. Contact and
/// release are events that restart the integrator (the torque jumps); the clipping is
/// continuous (roots 2 and 3 only locate its kinks).
class ElastoBacklash2 : public ElastoBacklash {
 public:
  explicit ElastoBacklash2(const NetworkElement& e) : ElastoBacklash(e) {}
  double Tau(double phi_rel, double w_rel) const override {
    const double delta = phi_rel - phi_rel0;
    if (b_total <= 1e-10) return c * delta + d * w_rel;
    const double g = b_total / 2;
    if (delta > g) return std::max(c * (delta - g) + d * w_rel, 0.0);
    if (delta < -g) return std::min(c * (delta + g) + d * w_rel, 0.0);
    return 0.0;
  }
  int NumRoots() const override { return b_total <= 1e-10 ? 0 : 4; }
  void Roots(const Eval& e, double* g) const override {
    ElastoBacklash::Roots(e, g);
    const double delta = PhiRel(e) - phi_rel0, w_rel = WRel(e), half = b_total / 2;
    g[2] = delta > half ? c * (delta - half) + d * w_rel : 1.0;
    g[3] = delta < -half ? c * (delta + half) + d * w_rel : -1.0;
  }
  /// The torque jumps at contact (roots 0 and 1) unless d = 0.
  bool RootRestarts(int k) const override { return k < 2 && d > 0; }
};

// ------------------------------------------------------------------------------------------
// Ideal gears

// The two-flange-plus-support bookkeeping of a gear: the ratio (checked once) and the kinematic
// row w_a - ratio * w_b + (ratio - 1) * w_support = 0. IdealGear and LossyGear add their laws.
class GearBase : public Element {
 public:
  GearBase(const NetworkElement& e, const char* type) : ratio(Param(e, "ratio")) {
    if (ratio == 0.0)
      throw InputError("element '" + e.id + "' (" + type + "): ratio = 0 is not a gear; give the "
                       "speed ratio w_a / w_b (non-zero)");
  }
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b", "support"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    a = node_of("flange_a");
    b = node_of("flange_b");
    s = node_of("support");
  }
  std::vector<int> Nodes() const override { return {a, b, s}; }
  std::vector<int> CoupledNodes() const override { return {a, b, s}; }
  std::vector<std::pair<int, double>> Row() const {
    return {{a, 1.0}, {b, -ratio}, {s, ratio - 1.0}};
  }
  /// The row into an existing constraint (reuses its storage: no allocation per evaluation).
  void SetRow(ConstraintEntries& row) const { row.assign({{a, 1.0}, {b, -ratio}, {s, ratio - 1.0}}); }
  void HolonomicRows(std::vector<InitialEquation>& rows) const override {
    rows.push_back({Row(), 0.0});
  }
  double ratio;
  int a = -1, b = -1, s = -1;
};

class IdealGear : public GearBase {
 public:
  bool ReadsNodeAngles() const override { return false; }
  explicit IdealGear(const NetworkElement& e) : GearBase(e, "IdealGear") {}
  void Constraints(Eval& e) override {
    Constraint& c = e.NewConstraint(index);
    SetRow(c.row);
    c.column = {{a, -1.0}, {b, ratio}, {s, 1.0 - ratio}};  // multiplier = flange_a.tau
    constraint = e.n_constraints - 1;
  }
  void AfterSolve(Eval& e) override { tau_a = e.constraints[constraint].lambda; }
  std::vector<std::string> OutputNames() const override { return {"flange_a.tau", "flange_b.tau"}; }
  void Outputs(const Eval&, double* out) const override {
    out[0] = tau_a;
    out[1] = -ratio * tau_a;
  }
  double PeakTorque(const Eval&) const override {
    return std::abs(ratio) >= 1 ? -ratio * tau_a : tau_a;
  }
  int constraint = -1;
  double tau_a = 0.0;
};

class IdealPlanetary : public Element {
 public:
  explicit IdealPlanetary(const NetworkElement& e) : ratio(Param(e, "ratio")) {}
  std::vector<std::string> Flanges() const override { return {"sun", "carrier", "ring"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    sun = node_of("sun");
    carrier = node_of("carrier");
    ring = node_of("ring");
  }
  std::vector<int> Nodes() const override { return {sun, carrier, ring}; }
  std::vector<int> CoupledNodes() const override { return {sun, carrier, ring}; }
  std::vector<std::pair<int, double>> Row() const {
    return {{sun, -1.0}, {ring, -ratio}, {carrier, 1.0 + ratio}};
  }
  void SetRow(ConstraintEntries& row) const {
    row.assign({{sun, -1.0}, {ring, -ratio}, {carrier, 1.0 + ratio}});
  }
  void HolonomicRows(std::vector<InitialEquation>& rows) const override {
    rows.push_back({Row(), 0.0});
  }
  void Constraints(Eval& e) override {
    Constraint& c = e.NewConstraint(index);
    SetRow(c.row);
    SetRow(c.column);  // multiplier = sun.tau; ring.tau = ratio*sun.tau
    constraint = e.n_constraints - 1;
  }
  void AfterSolve(Eval& e) override { tau_sun = e.constraints[constraint].lambda; }
  std::vector<std::string> OutputNames() const override {
    return {"sun.tau", "ring.tau", "carrier.tau"};
  }
  void Outputs(const Eval&, double* out) const override {
    out[0] = tau_sun;
    out[1] = ratio * tau_sun;
    out[2] = -(1 + ratio) * tau_sun;
  }
  double PeakTorque(const Eval&) const override { return -(1 + ratio) * tau_sun; }
  double ratio;
  int sun = -1, carrier = -1, ring = -1, constraint = -1;
  double tau_sun = 0.0;
};

// ------------------------------------------------------------------------------------------
// Friction: the MSL 4.0.0 state machine shared by BearingFriction, Brake, Clutch and
// OneWayClutch. Sliding speed w_f = w[p] - w[m]; the friction torque tau acts -tau on p and +tau
// on m (Brake/BearingFriction: p = shaft, m = support; Clutch: p = flange_b, m = flange_a).

enum Mode { kBackward = -1, kStuck = 0, kForward = 1, kFree = 2, kUnknown = 3 };

inline std::string ModeName(int m) {
  switch (m) {
    case kBackward: return "Backward";
    case kStuck: return "Stuck";
    case kForward: return "Forward";
    case kFree: return "Free";
    default: return "Unknown";
  }
}

class Friction : public Element {
 public:
  /// Kinetic friction torque (>= 0 for sliding forward) at sliding speed w (table read at w).
  virtual double TauSlide(const Eval& e, double w) const = 0;
  /// Normal force (> 0 engaged); elements that cannot be free return 1.
  virtual double Fn(const Eval& e) const {
    (void)e;
    return 1.0;
  }
  virtual double Tau0Max(const Eval& e) const { return peak * TauSlide(e, 0.0); }
  double WF(const Eval& e) const { return e.w[p] - e.w[m]; }
  double AF(const Eval& e) const { return e.acc[p] - e.acc[m]; }
  bool Sliding() const { return mode == kForward || mode == kBackward; }

  std::vector<int> Nodes() const override { return {p, m}; }
  std::vector<int> CoupledNodes() const override { return {p, m}; }

  void Forces(Eval& e) override {
    if (mode == kFree || mode == kUnknown) {
      tau = 0.0;
    } else if (Sliding()) {
      const double w = WF(e);
      tau = mode == kForward ? TauSlide(e, w) : -TauSlide(e, -w);
      if (one_way && Fn(e) <= 0) tau = 0.0;
      e.AddForce(p, -tau);
      e.AddForce(m, tau);
    }
  }
  void Constraints(Eval& e) override {
    constraint = -1;
    if (mode != kStuck) return;
    Constraint& c = e.NewConstraint(index);
    c.row = {{p, 1.0}, {m, -1.0}};
    c.column = {{p, -1.0}, {m, 1.0}};
    constraint = e.n_constraints - 1;
  }
  void AfterSolve(Eval& e) override {
    if (constraint >= 0) tau = e.constraints[constraint].lambda;
  }

  int NumRoots() const override { return 3; }
  void Roots(const Eval& e, double* g) const override {
    // Sliding: the slip, located where it reaches 0 against the mode. Starting from rest (case 6
    // of docs/simulation.md, MSL startForward/startBackward) the slip is 0 within roundoff and
    // may sit on either side of 0, so its crossing says nothing; the relative acceleration in
    // the sliding direction is watched instead, as MSL keeps startForward only while
    // sa > tau0: where it turns against the mode before the element has moved clear, the
    // element sticks (a capacity rising from 0 overtakes a holding torque of roundoff size).
    g[0] = Sliding() ? (starting ? mode * AF(e) : WF(e)) : 1.0;
    if (mode == kStuck) {
      // The event iteration accepts a stuck element whose torque exceeds its capacity by up to
      // 1e-12 of it; the root keeps a margin of 1e-10 so that it starts positive even then and
      // a torque that rises beyond the capacity is located (CVODE sees only sign changes).
      const double cap = Tau0Max(e) + kCapacityMargin * std::abs(Tau0Max(e)) + settled_allowance;
      g[1] = one_way ? cap - tau : cap - std::abs(tau);
    } else {
      g[1] = 1.0;
    }
    // A normal force that sits at exactly 0 is reported just below 0 while the element is free
    // (so that its rise from 0, e.g. a ramp starting at t = 0, is a root) and just above 0 once
    // engaged (so that the engagement at that very instant is not located again); CVODE then
    // never sees a root function that is identically zero.
    const double fn = can_be_free ? Fn(e) : 1.0;
    const bool free = mode == kFree || mode == kUnknown;
    g[2] = fn == 0.0 ? (free ? -1.0 : 1.0) * kRootSentinel : fn;
  }
  /// Stuck, root 1 reads the constraint torque; starting, root 0 the acceleration. Otherwise
  /// the roots read the slip speed and the normal force (Fn: a signal input or the element's
  /// own actuation, never a result of the solve).
  bool RootsNeedSolve() const override { return mode == kStuck || (Sliding() && starting); }
  void RootDirections(int* d) const override {
    d[0] = starting ? 0 : (mode == kForward ? -1 : (mode == kBackward ? 1 : 0));
    d[1] = -1;
    d[2] = 0;
  }

  void PrepareEvent(const Eval& e) override {
    start_forward = start_backward = false;
    settled_allowance = 0.0;
    const double w = WF(e);
    const double w_eps = 1e-9 * (1.0 + std::abs(e.w[p]) + std::abs(e.w[m]));
    // A start that has moved clear of rest is an ordinary slide: root 0 was its acceleration,
    // not its slip reaching 0.
    const bool clear = starting && Sliding() && w * mode > w_eps;
    if (clear || !Sliding()) starting = false;
    const bool slip_root = Fired(0) && !clear;
    // Root 2 located the rise of the normal force: engaged from this instant on (the right
    // limit), even where the force evaluates to exactly 0 at the located time.
    const bool rising = Fired(2) && (mode == kFree || mode == kUnknown) && Fn(e) >= 0;
    if (can_be_free && !one_way && Fn(e) <= 0 && !rising) {
      mode = kFree;
      return;
    }
    if (one_way) {
      if (mode == kUnknown || mode == kFree) mode = w > w_eps ? kForward : kStuck;
      else if (mode == kForward && (w <= w_eps || slip_root)) mode = kStuck;
      if (mode != kForward) starting = false;
      return;
    }
    if (mode == kFree || mode == kUnknown) {
      if (w > w_eps) mode = kForward;
      else if (w < -w_eps) mode = kBackward;
      else mode = kStuck;
      return;
    }
    if (mode == kForward && (w <= w_eps || slip_root)) mode = kStuck;
    if (mode == kBackward && (w >= -w_eps || slip_root)) mode = kStuck;
    if (!Sliding()) starting = false;
  }
  double Violation(const Eval& e) const override {
    if (mode == kStuck) {
      const double cap = Tau0Max(e);
      const double excess = one_way ? tau - cap : std::abs(tau) - cap;
      const double scale = std::max(std::abs(cap), 1e-12);
      // Crossed at a located root: accept a margin within the root-finding accuracy.
      const double threshold = Fired(1) ? -1e-7 * scale : 1e-12 * scale;
      return excess > threshold ? std::max(excess / scale, 1e-9) : 0.0;
    }
    if (Sliding() && !one_way) {
      const double w = WF(e);
      const double w_eps = 1e-9 * (1.0 + std::abs(e.w[p]) + std::abs(e.w[m]));
      // Sliding against its slip (beyond roundoff): the friction torque would push along the
      // motion and feed energy. MSL's mode is Forward only while w_relfric > 0 (and Backward
      // only while < 0): Fix() takes the direction of the slip.
      if (w * mode < -w_eps) return 1.0;
      // Just released at zero speed but driven the other way: it must stick again.
      const double a = AF(e);
      const double a_eps = 1e-9 * (1.0 + std::abs(e.acc[p]) + std::abs(e.acc[m]));
      if (std::abs(w) <= w_eps && a * mode < -a_eps) return 1.0;
    }
    return 0.0;
  }
  void Fix(const Eval& e) override {
    if (Sliding() && !one_way) {
      const double w = WF(e);
      const double w_eps = 1e-9 * (1.0 + std::abs(e.w[p]) + std::abs(e.w[m]));
      if (w * mode < -w_eps) {  // against its slip: slide the way it moves
        mode = w > 0 ? kForward : kBackward;
        start_forward = start_backward = false;
        starting = false;
        return;
      }
    }
    if (mode == kStuck) {
      const int direction = (one_way || tau > 0) ? kForward : kBackward;
      mode = direction;
      start_forward = direction == kForward;
      start_backward = direction == kBackward;
      starting = true;
    } else {
      mode = kStuck;
      start_forward = start_backward = false;
      starting = false;
      // Released on the located capacity root but driven the other way once sliding: the
      // torque sits at the capacity within the root tolerance. The element stays stuck for this
      // event (the relaxed threshold of the fired root no longer applies), else the iteration
      // would alternate between the two modes. Its capacity root is re-armed as for a settled
      // element (Settle): a holding torque that keeps rising towards the capacity crosses the
      // 1e-10 margin again within ~1e-13 s, the event's projection pulls it back below the
      // capacity by roundoff, and the run crawls from one such event to the next at the same
      // instant (the A320-class slats' station limiter brakes after a shaft rupture, with the
      // actuators' load inertia). With the allowance the next event finds the torque clearly
      // above the capacity and the element breaks away, or no event follows. A stuck element
      // does no work: the allowance creates no energy.
      if (Fired(1)) {
        fired[1] = 0;
        settled_allowance = kSettledAllowance * std::abs(Tau0Max(e));
      }
    }
  }
  void AfterEventRow() override {
    start_forward = start_backward = false;
    ClearFired();
  }
  /// Stuck at its capacity within roundoff (and sliding as inconsistent): the capacity root is
  /// re-armed kSettledAllowance above the capacity until the next event of the element. Without
  /// it a torque that keeps rising with the capacity (a limiter's brake, whose normal force grows
  /// with the spring's twist) crosses the 1e-10 margin again within 1e-14 s, and the run crawls
  /// from one such event to the next; with it the next event finds the torque clearly above the
  /// capacity and the element breaks away, or no event follows.
  void Settle(const Eval& e) override {
    if (mode == kForward || mode == kBackward) mode = kStuck;
    start_forward = start_backward = false;
    starting = false;
    settled_allowance = kSettledAllowance * std::abs(Tau0Max(e));
  }
  bool IsSwitching() const override { return true; }
  std::string ModeText() const override { return ModeName(mode); }

  int OutputMode() const { return mode == kUnknown ? kStuck : mode; }
  double PeakTorque(const Eval&) const override { return tau; }
  /// The friction torque acts -tau on p and +tau on m: it takes tau * w_f from the nodes.
  double LossPower(const Eval& e) const override { return tau * WF(e); }

  static constexpr double kCapacityMargin = 1e-10;  ///< relative, of the stuck roots
  static constexpr double kSettledAllowance = 1e-6;  ///< relative, of a settled element's root
  double settled_allowance = 0.0;  ///< N*m above the capacity, from Settle() to the next event
  double peak = 1.0;
  bool can_be_free = false;
  bool one_way = false;
  int p = -1, m = -1;
  int mode = kUnknown;
  bool start_forward = false, start_backward = false;
  /// Broke away from Stuck and has not moved clear of rest yet: root 0 watches its acceleration
  /// instead of its slip. Unlike start_forward/start_backward (MSL's flags, true at the event
  /// instant only) it lasts until an event finds the slip beyond roundoff in the sliding
  /// direction, or the element sticks or is released.
  bool starting = false;
  int constraint = -1;
  mutable double tau = 0.0;
};

class BearingFriction : public Friction {
 public:
  explicit BearingFriction(const NetworkElement& e)
      : tau_pos(TableOr(e, "tau_pos", {{0.0, 1.0}}, 2)) {
    peak = Param(e, "peak");
  }
  std::vector<std::vector<std::string>> RigidFlanges() const override {
    return {{"flange_a", "flange_b"}};
  }
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b", "support"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    p = node_of("flange_a");
    m = node_of("support");
  }
  double TauSlide(const Eval&, double w) const override { return Interpolate(tau_pos, 1, w); }
  std::vector<std::string> OutputNames() const override {
    return {"w", "tau", "mode", "startForward", "startBackward"};
  }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = WF(e);
    out[1] = tau;
    out[2] = OutputMode();
    out[3] = start_forward;
    out[4] = start_backward;
  }
  Table tau_pos;
};

/// Brake and Clutch: tau_slide = cgeo * fn * mu(w), fn = fn_max * f_normalized.
class SurfaceFriction : public Friction {
 public:
  explicit SurfaceFriction(const NetworkElement& e)
      : mu_pos(TableOr(e, "mu_pos", {{0.0, 0.5}}, 2)),
        cgeo(Param(e, "cgeo")),
        fn_max(Param(e, "fn_max")) {
    peak = Param(e, "peak");
    can_be_free = true;
  }
  std::vector<std::string> SignalInputs() const override { return {"f_normalized"}; }
  double Fn(const Eval& e) const override { return fn_max * e.signal[f_signal]; }
  double TauSlide(const Eval& e, double w) const override {
    const double fn = Fn(e);
    return fn <= 0 ? 0.0 : cgeo * fn * Interpolate(mu_pos, 1, w);
  }
  Table mu_pos;
  double cgeo, fn_max;
  int f_signal = -1;
};

class Brake : public SurfaceFriction {
 public:
  explicit Brake(const NetworkElement& e) : SurfaceFriction(e) {}
  std::vector<std::vector<std::string>> RigidFlanges() const override {
    return {{"flange_a", "flange_b"}};
  }
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b", "support"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    p = node_of("flange_a");
    m = node_of("support");
    f_signal = signal_of("f_normalized");
  }
  std::vector<std::string> OutputNames() const override {
    return {"w", "tau", "fn", "mode", "startForward", "startBackward"};
  }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = WF(e);
    out[1] = tau;
    out[2] = Fn(e);
    out[3] = OutputMode();
    out[4] = start_forward;
    out[5] = start_backward;
  }
};

/// Clutch and OneWayClutch carry the relative angle as a state.
class Clutch : public SurfaceFriction {
 public:
  explicit Clutch(const NetworkElement& e, bool one_way_clutch) : SurfaceFriction(e) {
    one_way = one_way_clutch;
    if (Given(e, "phi_rel_start")) phi_rel_start = Param(e, "phi_rel_start");
    if (Given(e, "w_rel_start")) w_rel_start = Param(e, "w_rel_start");
    if (Given(e, "phi_nominal")) phi_nominal = Param(e, "phi_nominal");
  }
  void StateNominals(double* nominal) const override { nominal[0] = phi_nominal; }
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    m = node_of("flange_a");
    p = node_of("flange_b");
    f_signal = signal_of("f_normalized");
  }
  double Tau0Max(const Eval& e) const override {
    if (!one_way) return Friction::Tau0Max(e);
    const double mu0 = Interpolate(mu_pos, 1, 0.0);
    const double fn = Fn(e);
    if (fn <= 0) return 1e-4 * mu0 * cgeo * fn_max;
    return std::max(peak, 1.0 + 1e-4) * cgeo * fn * mu0;
  }
  int NumStates() const override { return 1; }
  std::vector<std::string> StateNames() const override { return {id + ".phi_rel"}; }
  /// The relative angle, unless it was given (phi_rel_start fixes it).
  std::vector<int> TwistStates() const override {
    return std::isnan(phi_rel_start) ? std::vector<int>{0} : std::vector<int>{};
  }
  void InitialEquations(std::vector<InitialEquation>& position,
                        std::vector<InitialEquation>& speed) const override {
    if (!std::isnan(phi_rel_start)) position.push_back({{{p, 1.0}, {m, -1.0}}, phi_rel_start});
    if (!std::isnan(w_rel_start)) speed.push_back({{{p, 1.0}, {m, -1.0}}, w_rel_start});
  }
  void InitStates(const Eval& e, double* y) const override {
    y[state_offset] = std::isnan(phi_rel_start) ? e.phi[p] - e.phi[m] : phi_rel_start;
  }
  void TwistRows(const double* y, std::vector<InitialEquation>& rows) const override {
    rows.push_back({{{p, 1.0}, {m, -1.0}}, y[state_offset]});
  }
  void Derivatives(Eval& e) override { e.ydot[state_offset] = WF(e); }
  std::vector<int> StateSpeedNodes(int k) const override { return k == 0 ? std::vector<int>{m, p} : std::vector<int>{}; }
  std::vector<std::string> OutputNames() const override {
    if (one_way) return {"phi_rel", "w_rel", "tau", "fn", "stuck", "startForward"};
    return {"phi_rel", "w_rel", "tau", "fn", "mode", "startForward", "startBackward"};
  }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = e.y[state_offset];
    out[1] = WF(e);
    out[2] = tau;
    out[3] = Fn(e);
    if (one_way) {
      out[4] = mode == kStuck;
      out[5] = start_forward;
    } else {
      out[4] = OutputMode();
      out[5] = start_forward;
      out[6] = start_backward;
    }
  }
  double phi_rel_start = NAN, w_rel_start = NAN;
  double phi_nominal = NAN;
};

// ------------------------------------------------------------------------------------------
// LossyGear (MSL 4.0.0): mesh efficiency and bearing friction by power-flow quadrant, stuck
// mode. Multiplier of the kinematic constraint = flange_a.tau; when stuck a second constraint
// w_a = 0 with multiplier tauLoss.

class LossyGear : public GearBase {
 public:
  /// `type_name` names the element type in messages (laws derived from LossyGear).
  explicit LossyGear(const NetworkElement& e, const char* type_name = "LossyGear")
      : GearBase(e, type_name), table(TableOr(e, "lossTable", {{0, 1, 1, 0, 0}}, 5)) {
    ideal = true;
    for (const auto& r : table) {
      if (r[1] <= 0 || r[1] > 1 || r[2] <= 0 || r[2] > 1)
        throw InputError("element '" + e.id + "' (LossyGear): lossTable efficiencies must lie "
                         "in (0, 1]; fix columns 2 and 3");
      if (r[1] != 1 || r[2] != 1 || r[3] != 0 || r[4] != 0) ideal = false;
    }
  }
  double WA(const Eval& e) const { return e.w[a] - e.w[s]; }

  struct Coefficients {
    double eta1, eta2, bf1, bf2, bf_a;
  };
  /// Efficiencies and bearing friction of the two quadrants, with the quadrant boundary bf_a
  /// at which the loss is continuous.
  static Coefficients Make(double eta1, double eta2, double bf1, double bf2) {
    Coefficients c{eta1, eta2, bf1, bf2, 0.0};
    c.bf_a = std::abs(c.eta1 - 1.0 / c.eta2) < 1e-15 ? c.bf1 / 2
                                                    : (c.bf1 - c.bf2) / (c.eta1 - 1.0 / c.eta2);
    return c;
  }
  Coefficients At(double w_abs) const {
    return Make(Interpolate(table, 1, w_abs), Interpolate(table, 2, w_abs),
                std::abs(Interpolate(table, 3, w_abs)), std::abs(Interpolate(table, 4, w_abs)));
  }
  /// Coefficients of the rolling law (MSL: the loss table at |w_a|). Laws derived from
  /// LossyGear (HighLift GearedRotaryActuator) make them depend on the state.
  virtual Coefficients RollingCoefficients(const Eval& e) const { return At(std::abs(WA(e))); }
  /// Coefficients of the start thresholds of the stuck gear (MSL: the loss table at w = 0).
  virtual Coefficients RestCoefficients() const { return At(0.0); }
  /// Regularised (w_small > 0, HighLift laws only): always rolling, in the direction of the
  /// input speed, with the loss of that direction scaled by |tanh(w_a/w_small)|; continuous
  /// in the state, no stuck mode and no stick/slip events.
  bool Regularized() const { return w_small > 0; }
  double Smooth(const Eval& e) const {
    const double w = WA(e);
    if (!smooth_memo_.Same({w})) smooth_ = SmoothSign(w / w_small);
    return smooth_;
  }
  /// Direction of rolling: the mode, or the sign of the speed when regularised.
  int Direction(const Eval& e) const {
    if (!Regularized()) return mode;
    return WA(e) >= 0 ? kForward : kBackward;
  }
  // tau_loss = k * tau_a + c0 in the active quadrant. The forces, the constraint and the loss
  // after the solve all need it at the same point: computed once per point, mode and quadrant
  // (the quadrant may change between the passes of one evaluation, Reassume).
  void Law(const Eval& e, double& k, double& c0) const {
    if (e.point != 0 && e.point == law_point_ && mode == law_mode_ && quadrant == law_quadrant_) {
      k = law_k_;
      c0 = law_c0_;
      return;
    }
    LawAt(e, k, c0);
    law_point_ = e.point;
    law_mode_ = mode;
    law_quadrant_ = quadrant;
    law_k_ = k;
    law_c0_ = c0;
  }
  void LawAt(const Eval& e, double& k, double& c0) const {
    const Coefficients c = RollingCoefficients(e);
    law_bf_a_ = c.bf_a;
    law_bf_a_point_ = e.point;
    law_bf_a_mode_ = mode;
    const bool q_pos = quadrant >= 0;
    if (Direction(e) == kForward) {
      k = q_pos ? 1 - c.eta1 : 1 - 1 / c.eta2;
      c0 = q_pos ? c.bf1 : c.bf2;
    } else {
      k = q_pos ? 1 - 1 / c.eta2 : 1 - c.eta1;
      c0 = q_pos ? -c.bf2 : -c.bf1;
    }
    if (Regularized()) {
      const double r = std::abs(Smooth(e));
      k *= r;
      c0 *= r;
    }
  }
  bool Rolling() const { return mode == kForward || mode == kBackward; }
  void Forces(Eval& e) override {
    if (!Rolling()) return;
    double k, c0;
    Law(e, k, c0);
    e.AddForce(b, -ratio * c0);
    e.AddForce(s, ratio * c0);
  }
  void Constraints(Eval& e) override {
    Constraint& c = e.NewConstraint(index);
    SetRow(c.row);
    kinematic = e.n_constraints - 1;
    if (Rolling()) {
      double k, c0;
      Law(e, k, c0);
      c.column = {{a, -1.0}, {b, ratio * (1 - k)}, {s, 1 - ratio * (1 - k)}};
    } else {
      c.column = {{a, -1.0}, {b, ratio}, {s, 1 - ratio}};
    }
    stuck_constraint = -1;
    if (mode == kStuck) {
      Constraint& st = e.NewConstraint(index);
      st.row = {{a, 1.0}, {s, -1.0}};
      st.column = {{b, -ratio}, {s, ratio}};
      stuck_constraint = e.n_constraints - 1;
    }
  }
  void AfterSolve(Eval& e) override {
    tau_a = e.constraints[kinematic].lambda;
    if (mode == kStuck) {
      tau_loss = e.constraints[stuck_constraint].lambda;
    } else if (Rolling()) {
      double k, c0;
      Law(e, k, c0);
      tau_loss = k * tau_a + c0;
    } else {
      tau_loss = 0.0;
    }
  }
  double TauEta(const Eval& e) const { return TauEta(e, RollingCoefficients(e).bf_a); }
  double TauEta(const Eval& e, double bf_a) const {
    const int direction = Direction(e);
    if (direction == kForward) return tau_a - bf_a;
    if (direction == kBackward) return tau_a + bf_a;
    return tau_a;
  }
  /// Regularised: the quadrant (side of the quadrant boundary of TauEta) is assumed before the
  /// solve and corrected after it; the loss is continuous across the boundary.
  bool HasAssumptions() const override { return Regularized() && !ideal; }
  bool Reassume(const Eval& e) override {
    // After the solve of the evaluation whose forces read the law at this point: its quadrant
    // boundary as LawAt read it (the same coefficients; nothing between the two changes them).
    const bool read = e.point != 0 && e.point == law_bf_a_point_ && mode == law_bf_a_mode_;
    const double te = read ? TauEta(e, law_bf_a_) : TauEta(e);
    if (te * quadrant >= -1e-12 * (1.0 + std::abs(tau_a))) return false;
    quadrant = -quadrant;
    return true;
  }
  // Start thresholds (zero-speed values, current tau_a).
  double LossMaxForward() const {
    const Coefficients c = RestCoefficients();
    return tau_a - c.bf_a > 0 ? (1 - c.eta1) * tau_a + c.bf1 : (1 - 1 / c.eta2) * tau_a + c.bf2;
  }
  double LossMinBackward() const {
    const Coefficients c = RestCoefficients();
    return tau_a + c.bf_a > 0 ? (1 - 1 / c.eta2) * tau_a - c.bf2 : (1 - c.eta1) * tau_a - c.bf1;
  }

  double AA(const Eval& e) const { return e.acc[a] - e.acc[s]; }
  int NumRoots() const override { return ideal ? 0 : 4; }
  void Roots(const Eval& e, double* g) const override {
    // Rolling: w_a, located where it reaches 0 against the mode. Starting from rest (MSL
    // startForward/startBackward; case G4 of docs/simulation.md) w_a is 0 within roundoff on
    // either side, so its crossing says nothing: the acceleration in the rolling direction is
    // watched instead until the gear has moved clear of rest (MSL keeps startForward only while
    // sa > tauLossMax_p, i.e. while that acceleration is positive).
    g[0] = Rolling() ? (starting ? mode * AA(e) : WA(e)) : 1.0;
    // A margin of 1e-10 (as Friction's stuck root): the roots start positive at the event.
    const double margin = 1e-10 * (1.0 + std::abs(tau_a) + std::abs(tau_loss)) + settled_allowance;
    g[1] = mode == kStuck ? LossMaxForward() - tau_loss + margin : 1.0;
    g[2] = mode == kStuck ? tau_loss - LossMinBackward() + margin : 1.0;
    g[3] = Rolling() ? TauEta(e) : 1.0;
  }
  void RootDirections(int* d) const override {
    d[0] = starting ? 0 : (mode == kForward ? -1 : (mode == kBackward ? 1 : 0));
    d[1] = -1;
    d[2] = -1;
    d[3] = 0;
  }
  bool IsSwitching() const override { return !ideal; }
  void PrepareEvent(const Eval& e) override {
    start_forward = start_backward = false;
    settled_allowance = 0.0;
    if (ideal) {
      mode = kFree;
      return;
    }
    const double w = WA(e);
    const double w_eps = 1e-9 * (1.0 + std::abs(e.w[a]) + std::abs(e.w[s]));
    // A start that has moved clear of rest rolls on: root 0 was its acceleration, not w_a.
    const bool clear = starting && Rolling() && w * mode > w_eps;
    if (clear || !Rolling()) starting = false;
    const bool slip_root = Fired(0) && !clear;
    if (mode == kFree || mode == kUnknown) {
      mode = w > w_eps ? kForward : (w < -w_eps ? kBackward : kStuck);
    } else if (mode == kForward && (w <= w_eps || slip_root)) {
      mode = kStuck;
    } else if (mode == kBackward && (w >= -w_eps || slip_root)) {
      mode = kStuck;
    }
    if (!Rolling()) starting = false;
    if (Rolling()) {
      const double te = TauEta(e);
      if (te > 0) quadrant = 1;
      else if (te < 0) quadrant = -1;
    }
  }
  double Violation(const Eval& e) const override {
    const double scale = 1e-12 * (1.0 + std::abs(tau_a) + std::abs(tau_loss));
    if (mode == kStuck) {
      const double up = tau_loss - LossMaxForward();
      const double down = LossMinBackward() - tau_loss;
      const double relaxed = -1e-7 * (1.0 + std::abs(tau_a) + std::abs(tau_loss));
      const double v_up = up > (Fired(1) ? relaxed : scale) ? std::max(up, 1e-12) : 0.0;
      const double v_down = down > (Fired(2) ? relaxed : scale) ? std::max(down, 1e-12) : 0.0;
      const double v = std::max(v_up, v_down);
      return v > 0 ? v / (1.0 + std::abs(tau_a)) : 0.0;
    }
    if (Rolling()) {
      const double w = WA(e);
      const double w_eps = 1e-9 * (1.0 + std::abs(e.w[a]) + std::abs(e.w[s]));
      // Rolling against w_a beyond roundoff: the loss would push along the motion (negative
      // lossPower). MSL's mode is Forward only while w_a > 0: Fix() takes the direction of w_a.
      if (w * mode < -w_eps) return 1.0;
      const double te = TauEta(e);
      if (te * quadrant < -scale) return std::abs(te) / (1.0 + std::abs(tau_a));
      const double acc = e.acc[a] - e.acc[s];
      const double a_eps = 1e-9 * (1.0 + std::abs(e.acc[a]) + std::abs(e.acc[s]));
      if (std::abs(w) <= w_eps && acc * mode < -a_eps) return 1.0;
    }
    return 0.0;
  }
  void Fix(const Eval& e) override {
    if (mode == kStuck) {
      const double up = tau_loss - LossMaxForward();
      const double down = LossMinBackward() - tau_loss;
      const bool forward = (Fired(1) && !Fired(2)) || (!(Fired(2) && !Fired(1)) && up > down);
      if (forward) {
        mode = kForward;
        start_forward = true;
      } else {
        mode = kBackward;
        start_backward = true;
      }
      starting = true;
      quadrant = 1;
      return;
    }
    const double w = WA(e);
    const double w_eps = 1e-9 * (1.0 + std::abs(e.w[a]) + std::abs(e.w[s]));
    if (Rolling() && w * mode < -w_eps) {  // against its speed: roll the way it moves
      mode = w > 0 ? kForward : kBackward;
      start_forward = start_backward = false;
      starting = false;
      quadrant = 1;
      return;
    }
    const double te = TauEta(e);
    if (te * quadrant < 0) {
      quadrant = -quadrant;
      if (++flips > 4) {  // both quadrants inconsistent: the gear is held at zero speed
        mode = kStuck;
        flips = 0;
      }
      return;
    }
    mode = kStuck;
    start_forward = start_backward = false;
    starting = false;
  }
  void AfterEventRow() override {
    start_forward = start_backward = false;
    flips = 0;
    ClearFired();
  }
  /// Stuck and rolling each inconsistent by roundoff (the loss sits at its threshold): stuck,
  /// with the threshold roots re-armed kSettledAllowance of the torque scale beyond it until the
  /// next event (as Friction::Settle).
  void Settle(const Eval&) override {
    if (Rolling()) mode = kStuck;
    start_forward = start_backward = false;
    starting = false;
    settled_allowance = kSettledAllowance * (1.0 + std::abs(tau_a) + std::abs(tau_loss));
  }
  std::string ModeText() const override { return ModeName(mode); }
  std::vector<std::string> OutputNames() const override {
    return {"w_a", "flange_a.tau", "flange_b.tau", "tauLoss", "lossPower", "mode",
            "startForward", "startBackward"};
  }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = WA(e);
    out[1] = tau_a;
    out[2] = -ratio * (tau_a - tau_loss);
    out[3] = tau_loss;
    out[4] = tau_loss * WA(e);
    out[5] = mode == kUnknown ? kStuck : mode;
    out[6] = start_forward;
    out[7] = start_backward;
  }
  double PeakTorque(const Eval&) const override {
    return std::abs(ratio) >= 1 ? -ratio * (tau_a - tau_loss) : tau_a;
  }
  double LossPower(const Eval& e) const override { return tau_loss * WA(e); }

  Table table;
  bool ideal = false;
  double w_small = 0.0;  ///< rad/s, regularisation speed (0: the MSL stick/slip law)
  int mode = kFree;
  int quadrant = 1;
  int flips = 0;
  bool start_forward = false, start_backward = false;
  /// Broke away from Stuck and not yet clear of rest (|w_a| <= roundoff): root 0 watches the
  /// acceleration in the rolling direction (Friction::starting).
  bool starting = false;
  static constexpr double kSettledAllowance = 1e-6;  ///< relative, of a settled gear's roots
  double settled_allowance = 0.0;  ///< N*m beyond the thresholds, from Settle() to the next event
  int kinematic = -1, stuck_constraint = -1;
  double tau_a = 0.0, tau_loss = 0.0;
  mutable Memo<1> smooth_memo_;  ///< Smooth at the last w_a
  mutable double smooth_ = 0.0;
  mutable std::uint64_t law_point_ = 0;  ///< Law at this point (Eval::point), mode and quadrant
  mutable int law_mode_ = 0, law_quadrant_ = 0;
  mutable double law_k_ = 0.0, law_c0_ = 0.0;
  mutable std::uint64_t law_bf_a_point_ = 0;  ///< LawAt's quadrant boundary at this point and mode
  mutable int law_bf_a_mode_ = 0;
  mutable double law_bf_a_ = 0.0;
};

// ------------------------------------------------------------------------------------------
// Torque and speed sources: u accelerates the flange (+u on the flange, -u on the support).

class TorqueSource : public Element {
 public:
  std::vector<std::string> Flanges() const override { return {"flange", "support"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    n = node_of("flange");
    s = node_of("support");
    BindSignals(signal_of);
  }
  virtual void BindSignals(const std::function<int(const std::string&)>&) {}
  std::vector<int> Nodes() const override { return {n, s}; }
  double W(const Eval& e) const { return e.w[n] - e.w[s]; }
  virtual double U(const Eval& e) const = 0;
  void Forces(Eval& e) override {
    tau = U(e);
    e.AddForce(n, tau);
    e.AddForce(s, -tau);
  }
  std::vector<std::string> OutputNames() const override { return {"tau", "w"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = tau;
    out[1] = W(e);
  }
  double PeakTorque(const Eval&) const override { return tau; }
  double SourcePower(const Eval& e) const override { return tau * W(e); }
  int n = -1, s = -1;
  mutable double tau = 0.0;
};

class TorqueInput : public TorqueSource {
 public:
  bool ReadsNodeAngles() const override { return false; }
  std::vector<std::string> SignalInputs() const override { return {"tau"}; }
  void BindSignals(const std::function<int(const std::string&)>& signal_of) override {
    u = signal_of("tau");
  }
  double U(const Eval& e) const override { return e.signal[u]; }
  int u = -1;
};

class ConstantTorque : public TorqueSource {
 public:
  explicit ConstantTorque(const NetworkElement& e) : value(Param(e, "tau_constant")) {}
  double U(const Eval&) const override { return value; }
  double value;
};

class TorqueStep : public TorqueSource {
 public:
  explicit TorqueStep(const NetworkElement& e)
      : step(Param(e, "stepTorque")), offset(Param(e, "offsetTorque")), t0(Param(e, "startTime")) {}
  double U(const Eval& e) const override { return offset + (e.t_segment < t0 ? 0.0 : step); }
  double NextTimeEvent(double t) const override { return t < t0 ? t0 : INFINITY; }
  double step, offset, t0;
};

class SpeedDependentTorque : public TorqueSource {
 public:
  SpeedDependentTorque(const NetworkElement& e, bool quadratic)
      : tau_nominal(Param(e, "tau_nominal")),
        w_nominal(Param(e, "w_nominal")),
        same_direction(Param(e, "TorqueDirection") != 0),
        quadratic(quadratic) {}
  double U(const Eval& e) const override {
    const double x = W(e) / w_nominal;
    if (quadratic) return same_direction ? tau_nominal * x * x : tau_nominal * x * std::abs(x);
    return same_direction ? tau_nominal * std::abs(x) : tau_nominal * x;
  }
  double tau_nominal, w_nominal;
  bool same_direction, quadratic;
};

class SignTorque : public TorqueSource {
 public:
  explicit SignTorque(const NetworkElement& e)
      : tau_nominal(Param(e, "tau_nominal")), w0(Param(e, "w0")) {}
  double U(const Eval& e) const override {
    return tau_nominal * (2 / (1 + std::exp(-W(e) / (0.01 * w0))) - 1);
  }
  double tau_nominal, w0;
};

class EddyCurrentTorque : public TorqueSource {
 public:
  explicit EddyCurrentTorque(const NetworkElement& e)
      : tau_nominal(Param(e, "tau_nominal")),
        w_nominal(Param(e, "w_nominal")),
        TRef(Param(e, "TRef")),
        alpha20(Param(e, "alpha20")),
        use_heat_port(Param(e, "useHeatPort") != 0),
        T_fixed(Param(e, "T")),
        C(Param(e, "C_heatPort")),
        T_start(Param(e, "T_heatPort_start")) {}
  double Temperature(const Eval& e) const { return use_heat_port ? e.y[state_offset] : T_fixed; }
  double BrakingTorque(const Eval& e) const {
    const double alpha_ref = alpha20 / (1 + alpha20 * (TRef - 293.15));
    const double w_n = W(e) / (w_nominal * (1 + alpha_ref * (Temperature(e) - TRef)));
    return 2 * tau_nominal * w_n / (1 + w_n * w_n);
  }
  double U(const Eval& e) const override { return -BrakingTorque(e); }
  int NumStates() const override { return use_heat_port ? 1 : 0; }
  std::vector<std::string> StateNames() const override { return {id + ".T_heatPort"}; }
  void InitStates(const Eval&, double* y) const override {
    if (use_heat_port) y[state_offset] = T_start;
  }
  void Derivatives(Eval& e) override {
    if (use_heat_port) e.ydot[state_offset] = BrakingTorque(e) * W(e) / C;
  }
  std::vector<std::string> OutputNames() const override {
    return {"tau", "w", "lossPower", "T_heatPort"};
  }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = tau;
    out[1] = W(e);
    out[2] = BrakingTorque(e) * W(e);
    out[3] = Temperature(e);
  }
  double tau_nominal, w_nominal, TRef, alpha20;
  bool use_heat_port;
  double T_fixed, C, T_start;
};

// ------------------------------------------------------------------------------------------
// Signal blocks (Modelica.Blocks). Branches (before/after startTime, ramp phases, pulse
// states) are chosen from e.t_segment, the right limit of the last event, so that a branch
// never changes inside an integration interval: time events stop the integrator exactly.

class SignalBlock : public Element {
 public:
  bool IsSignalBlock() const override { return true; }
  bool HasReadings() const override { return false; }  // signals: no torque, no power
  std::vector<std::string> OutputNames() const override { return {"y"}; }
  void Outputs(const Eval& e, double* out) const override { out[0] = e.signal[signal_offset]; }
};

class Constant : public SignalBlock {
 public:
  explicit Constant(const NetworkElement& e) : k(Param(e, "k")) {}
  double Signal(const Eval&) const override { return k; }
  void SignalDerivatives(const Eval&, double* d1, double* d2) const override { *d1 = *d2 = 0.0; }
  double k;
};

class Step : public SignalBlock {
 public:
  explicit Step(const NetworkElement& e)
      : height(Param(e, "height")), offset(Param(e, "offset")), t0(Param(e, "startTime")) {}
  double Signal(const Eval& e) const override {
    return offset + (e.t_segment < t0 ? 0.0 : height);
  }
  void SignalDerivatives(const Eval&, double* d1, double* d2) const override { *d1 = *d2 = 0.0; }
  double NextTimeEvent(double t) const override { return t < t0 ? t0 : INFINITY; }
  double height, offset, t0;
};

class Ramp : public SignalBlock {
 public:
  explicit Ramp(const NetworkElement& e)
      : height(Param(e, "height")),
        duration(Param(e, "duration")),
        offset(Param(e, "offset")),
        t0(Param(e, "startTime")) {}
  double Signal(const Eval& e) const override {
    if (e.t_segment < t0) return offset;
    if (e.t_segment < t0 + duration) return offset + height * (e.t - t0) / duration;
    return offset + height;
  }
  void SignalDerivatives(const Eval& e, double* d1, double* d2) const override {
    *d1 = e.t_segment >= t0 && e.t_segment < t0 + duration ? height / duration : 0.0;
    *d2 = 0.0;
  }
  double NextTimeEvent(double t) const override {
    if (t < t0) return t0;
    if (t < t0 + duration) return t0 + duration;
    return INFINITY;
  }
  double height, duration, offset, t0;
};

class Sine : public SignalBlock {
 public:
  explicit Sine(const NetworkElement& e)
      : amplitude(Param(e, "amplitude")),
        f(Param(e, "f")),
        phase(Param(e, "phase")),
        offset(Param(e, "offset")),
        t0(Param(e, "startTime")) {}
  double Signal(const Eval& e) const override {
    if (e.t_segment < t0) return offset;
    return offset + amplitude * std::sin(2 * kPi * f * (e.t - t0) + phase);
  }
  void SignalDerivatives(const Eval& e, double* d1, double* d2) const override {
    if (e.t_segment < t0) {
      *d1 = *d2 = 0.0;
      return;
    }
    const double w = 2 * kPi * f, x = w * (e.t - t0) + phase;
    *d1 = amplitude * w * std::cos(x);
    *d2 = -amplitude * w * w * std::sin(x);
  }
  double NextTimeEvent(double t) const override { return t < t0 ? t0 : INFINITY; }
  double amplitude, f, phase, offset, t0;
};

class Pulse : public SignalBlock {
 public:
  explicit Pulse(const NetworkElement& e)
      : amplitude(Param(e, "amplitude")),
        width(Param(e, "width")),
        period(Param(e, "period")),
        nperiod(static_cast<long>(Param(e, "nperiod"))),
        offset(Param(e, "offset")),
        t0(Param(e, "startTime")) {}
  // Index of the period holding t (from t0), with a tolerance so that an event time computed
  // as t0 + k*period lands in period k.
  long PeriodIndex(double t) const {
    return static_cast<long>(std::floor((t - t0) / period + 1e-9));
  }
  double Signal(const Eval& e) const override {
    const double t = e.t_segment;
    if (t < t0) return offset;
    const long k = PeriodIndex(t);
    if (nperiod >= 0 && k >= nperiod) return offset;
    const double in_period = t - (t0 + k * period);
    return offset + (in_period < width / 100 * period * (1 - 1e-12) ? amplitude : 0.0);
  }
  void SignalDerivatives(const Eval&, double* d1, double* d2) const override { *d1 = *d2 = 0.0; }
  double NextTimeEvent(double t) const override {
    if (t < t0) return t0;
    const long k = PeriodIndex(t);
    if (nperiod >= 0 && k >= nperiod) return INFINITY;
    const double rise = t0 + k * period, fall = rise + width / 100 * period;
    if (t < fall * (1 - 1e-15) - 1e-15) return fall;
    return rise + period;
  }
  double amplitude, width, period;
  long nperiod;
  double offset, t0;
};

class TimeTable : public SignalBlock {
 public:
  explicit TimeTable(const NetworkElement& e)
      : table(TableOr(e, "table", {}, 2)), offset(Param(e, "offset")), t0(Param(e, "startTime")) {}
  double Signal(const Eval& e) const override {
    if (e.t_segment < t0) return offset + table.front()[1];
    // Interval chosen by the segment start, value interpolated at the current time.
    const double ts = e.t_segment - t0;
    std::size_t i = 0;
    while (i + 2 < table.size() && ts >= table[i + 1][0]) ++i;
    if (table.size() == 1) return offset + table[0][1];
    if (ts >= table.back()[0]) return offset + table.back()[1];
    const double x0 = table[i][0], x1 = table[i + 1][0];
    if (x1 == x0) return offset + table[i + 1][1];
    return offset + table[i][1] + (table[i + 1][1] - table[i][1]) * (e.t - t0 - x0) / (x1 - x0);
  }
  double NextTimeEvent(double t) const override {
    if (t < t0) return t0;
    for (const auto& r : table)
      if (t0 + r[0] > t * (1 + 1e-15) + 1e-15) return t0 + r[0];
    return INFINITY;
  }
  Table table;
  double offset, t0;
};

class Product : public SignalBlock {
 public:
  std::vector<std::string> SignalInputs() const override { return {"u1", "u2"}; }
  void Bind(const std::function<int(const std::string&)>&,
            const std::function<int(const std::string&)>& signal_of) override {
    u1 = signal_of("u1");
    u2 = signal_of("u2");
  }
  double Signal(const Eval& e) const override { return e.signal[u1] * e.signal[u2]; }
  void SignalDerivatives(const Eval& e, double* d1, double* d2) const override {
    const double a = e.signal[u1], b = e.signal[u2];
    const double a1 = e.signal_d1[u1], b1 = e.signal_d1[u2], a2 = e.signal_d2[u1], b2 = e.signal_d2[u2];
    *d1 = a1 * b + a * b1;
    *d2 = a2 * b + 2 * a1 * b1 + a * b2;
  }
  int u1 = -1, u2 = -1;
};

class Feedback : public Product {
 public:
  double Signal(const Eval& e) const override { return e.signal[u1] - e.signal[u2]; }
  void SignalDerivatives(const Eval& e, double* d1, double* d2) const override {
    *d1 = e.signal_d1[u1] - e.signal_d1[u2];
    *d2 = e.signal_d2[u1] - e.signal_d2[u2];
  }
};

}  // namespace highlift::sim::detail::msl
