// The further MSL 4.0.0 elements: Rotational sensors that read the solved torque or
// acceleration (TorqueSensor, PowerSensor, MultiSensor, AccSensor, RelAccSensor),
// RelativeStates, the motion sources (Position, Speed, Accelerate, Move, ConstantSpeed) and the
// translational elements a ballscrew or rack needs (Mass, Translational.Spring/Damper/
// SpringDamper/Fixed/Force/PositionSensor/SpeedSensor, IdealGearR2T, IdealRollingWheel).
//
// A translational element is the rotational law with (s, v, f) for (phi, w, tau): the network
// is one-dimensional either way, so the laws of msl_elements.h serve both under the MSL
// translational names of ports, parameters and outputs.
#include <cmath>
#include <utility>

#include "highlift/core/error.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {
namespace {

using namespace msl;

// ------------------------------------------------------------------------------------------
// Sensors that read the solve: the torque through a rigid joint of flange_a and flange_b
// (a constraint whose multiplier is flange_a.tau), or a solved acceleration.

class RigidSensor : public Element {
 public:
  explicit RigidSensor(std::vector<std::string> outputs) : outputs_(std::move(outputs)) {}
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b"}; }
  std::vector<std::string> SignalOutputs() const override { return outputs_; }
  bool SignalsAfterSolve() const override { return true; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    a = node_of("flange_a");
    b = node_of("flange_b");
  }
  std::vector<int> Nodes() const override { return {a, b}; }
  std::vector<int> CoupledNodes() const override { return {a, b}; }
  void HolonomicRows(std::vector<InitialEquation>& rows) const override {
    rows.push_back({{{a, 1.0}, {b, -1.0}}, 0.0});
  }
  void Constraints(Eval& e) override {
    Constraint& c = e.NewConstraint(index);
    c.row.assign({{a, 1.0}, {b, -1.0}});
    c.column.assign({{a, -1.0}, {b, 1.0}});  // multiplier = flange_a.tau
    constraint = e.n_constraints - 1;
  }
  void AfterSolve(Eval& e) override { tau = e.constraints[constraint].lambda; }
  /// Output `name`: tau = flange_a.tau, w = der(flange_a.phi), power = tau * w.
  double Value(const Eval& e, const std::string& name) const {
    if (name == "tau") return tau;
    if (name == "w") return e.w[a];
    return tau * e.w[a];
  }
  void Signals(const Eval& e, double* out) const override {
    for (std::size_t k = 0; k < outputs_.size(); ++k) out[k] = Value(e, outputs_[k]);
  }
  std::vector<std::string> OutputNames() const override { return outputs_; }
  void Outputs(const Eval& e, double* out) const override { Signals(e, out); }
  std::vector<std::string> outputs_;
  int a = -1, b = -1, constraint = -1;
  double tau = 0.0;
};

/// AccSensor (one flange: a) and RelAccSensor (a_rel = der(w_b - w_a)).
class AccelerationSensor : public Element {
 public:
  explicit AccelerationSensor(bool relative) : relative(relative) {}
  std::vector<std::string> Flanges() const override {
    return relative ? std::vector<std::string>{"flange_a", "flange_b"} : std::vector<std::string>{"flange"};
  }
  std::vector<std::string> SignalOutputs() const override { return {relative ? "a_rel" : "a"}; }
  bool SignalsAfterSolve() const override { return true; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    a = node_of(relative ? "flange_a" : "flange");
    if (relative) b = node_of("flange_b");
  }
  std::vector<int> Nodes() const override { return relative ? std::vector<int>{a, b} : std::vector<int>{a}; }
  MasslessRole RoleAt(int) const override { return MasslessRole::kNoTorque; }
  void Signals(const Eval& e, double* out) const override { out[0] = relative ? e.acc[b] - e.acc[a] : e.acc[a]; }
  std::vector<std::string> OutputNames() const override { return SignalOutputs(); }
  void Outputs(const Eval& e, double* out) const override { Signals(e, out); }
  bool relative;
  int a = -1, b = -1;
};

/// RelativeStates: phi_rel = phi_b - phi_a as a state of its own, no torque.
class RelativeStates : public Compliant {
 public:
  explicit RelativeStates(const NetworkElement& e) : Compliant(e) {}
  double Tau(double, double) const override { return 0.0; }
  std::vector<std::string> OutputNames() const override { return {"phi_rel", "w_rel", "a_rel"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = PhiRel(e);
    out[1] = WRel(e);
    out[2] = e.acc[b] - e.acc[a];
  }
  double PeakTorque(const Eval&) const override { return NAN; }
};

// ------------------------------------------------------------------------------------------
// Motion sources (MSL PartialElementaryOneFlangeAndSupport2): phi = flange.phi - support.phi
// is forced by a constraint on the relative acceleration, whose multiplier is the torque
// driving the flange (-flange.tau). The acceleration comes from the law of each source.

class MotionSource : public Element {
 public:
  std::vector<std::string> Flanges() const override { return {"flange", "support"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    n = node_of("flange");
    s = node_of("support");
    for (const auto& in : SignalInputs()) inputs.push_back(signal_of(in));
  }
  std::vector<int> Nodes() const override { return {n, s}; }
  std::vector<int> CoupledNodes() const override { return {n, s}; }
  double Phi(const Eval& e) const { return e.phi[n] - e.phi[s]; }
  double W(const Eval& e) const { return e.w[n] - e.w[s]; }
  /// The forced relative acceleration.
  virtual double Acceleration(const Eval& e) const = 0;
  /// Whether the speed is forced too (exact sources): then the speed relation is projected at
  /// events like the speed of a gear, with this value.
  virtual bool SpeedForced() const { return false; }
  virtual double ForcedSpeed(const Eval& e) const {
    (void)e;
    return 0.0;
  }
  void Constraints(Eval& e) override {
    Constraint& c = e.NewConstraint(index);
    c.row.assign({{n, 1.0}, {s, -1.0}});
    c.column.assign({{n, 1.0}, {s, -1.0}});  // multiplier = torque driving the flange
    c.rhs = Acceleration(e);
    c.velocity_level = SpeedForced();
    c.velocity_rhs = SpeedForced() ? ForcedSpeed(e) : 0.0;
    constraint = e.n_constraints - 1;
  }
  void AfterSolve(Eval& e) override { tau = e.constraints[constraint].lambda; }
  std::vector<std::string> OutputNames() const override { return {"phi", "w", "a", "tau"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = Phi(e);
    out[1] = W(e);
    out[2] = e.acc[n] - e.acc[s];
    out[3] = tau;
  }
  double PeakTorque(const Eval&) const override { return tau; }
  double SourcePower(const Eval& e) const override { return tau * W(e); }
  /// Throws when an exact source's input cannot be differentiated (checked at the start).
  void RequireDerivatives(const Eval& e, int input, const char* name, int order) const {
    const bool ok = !std::isnan(e.signal_d1[input]) && (order < 2 || !std::isnan(e.signal_d2[input]));
    if (!ok)
      throw InputError("element '" + id + "' (" + type + ", exact = true): input '" + name +
                       "' must be differentiable " + (order == 2 ? "twice" : "once") +
                       " (Constant, Step, Ramp, Sine, Pulse and the Gain, Add, Product and "
                       "Feedback of them are); use exact = false (a filter of f_crit) for other "
                       "signals");
  }
  std::vector<int> inputs;
  int n = -1, s = -1, constraint = -1;
  double tau = 0.0;
};

/// Position: exact = true forces phi = phi_ref (its derivatives from the input block); false
/// filters phi_ref by the critically damped second-order Bessel filter of MSL:
///   a = ((phi_ref - phi) * w_crit - af * w) * (w_crit / bf),  af = 1.3617, bf = 0.6180,
/// with phi = phi_ref at the start.
class Position : public MotionSource {
 public:
  explicit Position(const NetworkElement& e)
      : exact(Param(e, "exact") != 0), w_crit(2 * kPi * Param(e, "f_crit")) {}
  std::vector<std::string> SignalInputs() const override { return {"phi_ref"}; }
  bool NeedsSignalDerivatives() const override { return exact; }
  double Acceleration(const Eval& e) const override {
    const int u = inputs[0];
    if (exact) return e.signal_d2[u];
    return ((e.signal[u] - Phi(e)) * w_crit - kAf * W(e)) * (w_crit / kBf);
  }
  bool SpeedForced() const override { return exact; }
  double ForcedSpeed(const Eval& e) const override { return e.signal_d1[inputs[0]]; }
  void InitialEquationsAt(const Eval& e, std::vector<InitialEquation>& position,
                          std::vector<InitialEquation>& speed) const override {
    const int u = inputs[0];
    position.push_back({{{n, 1.0}, {s, -1.0}}, e.signal[u]});
    if (!exact) return;
    RequireDerivatives(e, u, "phi_ref", 2);
    speed.push_back({{{n, 1.0}, {s, -1.0}}, e.signal_d1[u]});
  }
  static constexpr double kAf = 1.3617, kBf = 0.6180;
  bool exact;
  double w_crit;
};

/// Speed: exact = true forces w = w_ref; false filters it, a = (w_ref - w) * w_crit, with
/// w = w_ref at the start (MSL initial equation). phi starts at phi_start (MSL phi(start = 0,
/// fixed = true)) when given.
class Speed : public MotionSource {
 public:
  explicit Speed(const NetworkElement& e)
      : exact(Param(e, "exact") != 0), w_crit(2 * kPi * Param(e, "f_crit")) {
    if (Given(e, "phi_start")) phi_start = Param(e, "phi_start");
  }
  std::vector<std::string> SignalInputs() const override { return {"w_ref"}; }
  bool NeedsSignalDerivatives() const override { return exact; }
  double Acceleration(const Eval& e) const override {
    const int u = inputs[0];
    return exact ? e.signal_d1[u] : (e.signal[u] - W(e)) * w_crit;
  }
  bool SpeedForced() const override { return exact; }
  double ForcedSpeed(const Eval& e) const override { return e.signal[inputs[0]]; }
  void InitialEquationsAt(const Eval& e, std::vector<InitialEquation>& position,
                          std::vector<InitialEquation>& speed) const override {
    if (!std::isnan(phi_start)) position.push_back({{{n, 1.0}, {s, -1.0}}, phi_start});
    if (exact) RequireDerivatives(e, inputs[0], "w_ref", 1);
    speed.push_back({{{n, 1.0}, {s, -1.0}}, e.signal[inputs[0]]});
  }
  std::vector<std::string> OutputNames() const override { return {"phi", "w", "a", "tau", "w_ref"}; }
  void Outputs(const Eval& e, double* out) const override {
    MotionSource::Outputs(e, out);
    out[4] = e.signal[inputs[0]];
  }
  bool exact;
  double w_crit;
  double phi_start = NAN;
};

/// Accelerate: a = a_ref, phi and w from phi_start and w_start (MSL: start 0, fixed).
class Accelerate : public MotionSource {
 public:
  explicit Accelerate(const NetworkElement& e) : phi_start(Param(e, "phi_start")), w_start(Param(e, "w_start")) {}
  std::vector<std::string> SignalInputs() const override { return {"a_ref"}; }
  double Acceleration(const Eval& e) const override { return e.signal[inputs[0]]; }
  void InitialEquations(std::vector<InitialEquation>& position, std::vector<InitialEquation>& speed) const override {
    position.push_back({{{n, 1.0}, {s, -1.0}}, phi_start});
    speed.push_back({{{n, 1.0}, {s, -1.0}}, w_start});
  }
  double phi_start, w_start;
};

/// Move: angle, speed and acceleration given by the inputs u[1], u[2], u[3] (the user makes
/// them consistent; MSL's position function with its derivative annotations).
class Move : public MotionSource {
 public:
  std::vector<std::string> SignalInputs() const override { return {"u[1]", "u[2]", "u[3]"}; }
  double Acceleration(const Eval& e) const override { return e.signal[inputs[2]]; }
  bool SpeedForced() const override { return true; }
  double ForcedSpeed(const Eval& e) const override { return e.signal[inputs[1]]; }
  void InitialEquationsAt(const Eval& e, std::vector<InitialEquation>& position,
                          std::vector<InitialEquation>& speed) const override {
    position.push_back({{{n, 1.0}, {s, -1.0}}, e.signal[inputs[0]]});
    speed.push_back({{{n, 1.0}, {s, -1.0}}, e.signal[inputs[1]]});
  }
};

/// ConstantSpeed: w = w_fixed, independent of the torque.
class ConstantSpeed : public MotionSource {
 public:
  explicit ConstantSpeed(const NetworkElement& e) : w_fixed(Param(e, "w_fixed")) {}
  double Acceleration(const Eval&) const override { return 0.0; }
  bool SpeedForced() const override { return true; }
  double ForcedSpeed(const Eval&) const override { return w_fixed; }
  void InitialEquations(std::vector<InitialEquation>&, std::vector<InitialEquation>& speed) const override {
    speed.push_back({{{n, 1.0}, {s, -1.0}}, w_fixed});
  }
  double w_fixed;
};

// ------------------------------------------------------------------------------------------
// Rotational-translational gears: (phi_R - phi_supportR) * k = (s_T - s_supportT), with
// k = 1/ratio for IdealGearR2T (ratio in rad/m) and k = radius for IdealRollingWheel, and
// flangeR.tau = -k * flangeT.f. Multiplier = flangeR.tau.

class RotationalToTranslational : public Element {
 public:
  explicit RotationalToTranslational(double k) : k(k) {}
  std::vector<std::string> Flanges() const override { return {"flangeR", "flangeT", "supportR", "supportT"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    r = node_of("flangeR");
    t = node_of("flangeT");
    sr = node_of("supportR");
    st = node_of("supportT");
  }
  std::vector<int> Nodes() const override { return {r, t, sr, st}; }
  std::vector<int> CoupledNodes() const override { return {r, t, sr, st}; }
  std::vector<std::pair<int, double>> Row() const { return {{r, k}, {sr, -k}, {t, -1.0}, {st, 1.0}}; }
  void HolonomicRows(std::vector<InitialEquation>& rows) const override { rows.push_back({Row(), 0.0}); }
  void Constraints(Eval& e) override {
    Constraint& c = e.NewConstraint(index);
    c.row.assign({{r, k}, {sr, -k}, {t, -1.0}, {st, 1.0}});
    // Torque -tau on flangeR, +tau on supportR; force f_T = -tau/k: -f_T on flangeT, +f_T on supportT.
    c.column.assign({{r, -1.0}, {sr, 1.0}, {t, 1.0 / k}, {st, -1.0 / k}});
    constraint = e.n_constraints - 1;
  }
  void AfterSolve(Eval& e) override { tau = e.constraints[constraint].lambda; }
  std::vector<std::string> OutputNames() const override { return {"flangeR.tau", "flangeT.f"}; }
  void Outputs(const Eval&, double* out) const override {
    out[0] = tau;
    out[1] = -tau / k;
  }
  double PeakTorque(const Eval&) const override { return tau; }
  double k;
  int r = -1, t = -1, sr = -1, st = -1, constraint = -1;
  double tau = 0.0;
};

// ------------------------------------------------------------------------------------------
// Translational elements: the rotational laws under translational names.

/// A copy of `e` with its parameter names mapped from the translational to the rotational
/// law's (s_rel0 -> phi_rel0, ...).
using Names = std::vector<std::pair<std::string, std::string>>;
NetworkElement Renamed(const NetworkElement& e, const Names& names) {
  NetworkElement r = e;
  for (const auto& [from, to] : names) {
    if (auto it = r.parameters.scalars.find(from); it != r.parameters.scalars.end()) {
      r.parameters.scalars[to] = it->second;
      r.parameters.scalars.erase(from);
    }
    if (auto it = r.given.find(from); it != r.given.end()) {
      r.given[to] = it->second;
      r.given.erase(from);
    }
  }
  return r;
}

const Names& CompliantNames() {
  static const Names names{{"s_rel0", "phi_rel0"}, {"s_rel_start", "phi_rel_start"}, {"v_rel_start", "w_rel_start"},
                           {"s_nominal", "phi_nominal"}};
  return names;
}

/// The rotational law `Base` with translational output names.
template <class Base>
class Translated : public Base {
 public:
  template <class... Args>
  Translated(std::vector<std::string> outputs, Args&&... args)
      : Base(std::forward<Args>(args)...), outputs_(std::move(outputs)) {}
  std::vector<std::string> OutputNames() const override { return outputs_; }
  std::vector<std::string> outputs_;
};

/// Translational.Force: the input f accelerates the flange (-f on the support).
class Force : public TorqueSource {
 public:
  std::vector<std::string> SignalInputs() const override { return {"f"}; }
  void BindSignals(const std::function<int(const std::string&)>& signal_of) override { u = signal_of("f"); }
  double U(const Eval& e) const override { return e.signal[u]; }
  std::vector<std::string> OutputNames() const override { return {"f", "v"}; }
  int u = -1;
};

/// Torque2: the input tau acts between the flanges (MSL flange_a.tau = tau, flange_b.tau = -tau):
/// +tau on flange_b, -tau on flange_a, i.e. a Torque whose support is flange_a.
class Torque2 : public TorqueInput {
 public:
  std::vector<std::string> Flanges() const override { return {"flange_a", "flange_b"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    n = node_of("flange_b");
    s = node_of("flange_a");
    BindSignals(signal_of);
  }
  std::vector<std::string> OutputNames() const override { return {"tau", "w_rel"}; }
};

class TranslationalSensor : public Element {
 public:
  explicit TranslationalSensor(bool speed) : speed(speed) {}
  std::vector<std::string> Flanges() const override { return {"flange"}; }
  std::vector<std::string> SignalOutputs() const override { return {speed ? "v" : "s"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    n = node_of("flange");
  }
  std::vector<int> Nodes() const override { return {n}; }
  MasslessRole RoleAt(int) const override { return MasslessRole::kNoTorque; }
  void Signals(const Eval& e, double* out) const override { out[0] = speed ? e.w[n] : e.phi[n]; }
  std::vector<std::string> OutputNames() const override { return SignalOutputs(); }
  void Outputs(const Eval& e, double* out) const override { out[0] = e.signal[signal_offset]; }
  bool speed;
  int n = -1;
};

}  // namespace

std::unique_ptr<Element> MakeMoreMslElement(const NetworkElement& e) {
  const std::string& t = e.type;
  if (t == "TorqueSensor") return std::make_unique<RigidSensor>(std::vector<std::string>{"tau"});
  if (t == "PowerSensor") return std::make_unique<RigidSensor>(std::vector<std::string>{"power"});
  if (t == "MultiSensor") return std::make_unique<RigidSensor>(std::vector<std::string>{"power", "w", "tau"});
  if (t == "AccSensor") return std::make_unique<AccelerationSensor>(false);
  if (t == "RelAccSensor") return std::make_unique<AccelerationSensor>(true);
  if (t == "RelativeStates") return std::make_unique<RelativeStates>(e);
  if (t == "Position") return std::make_unique<Position>(e);
  if (t == "Speed") return std::make_unique<Speed>(e);
  if (t == "Accelerate") return std::make_unique<Accelerate>(e);
  if (t == "Move") return std::make_unique<Move>();
  if (t == "Torque2") return std::make_unique<Torque2>();
  if (t == "ConstantSpeed") return std::make_unique<ConstantSpeed>(e);
  if (t == "IdealGearR2T") return std::make_unique<RotationalToTranslational>(1.0 / Param(e, "ratio"));
  if (t == "IdealRollingWheel") return std::make_unique<RotationalToTranslational>(Param(e, "radius"));
  const std::vector<std::string> compliant{"s_rel", "v_rel", "f"};
  if (t == "Mass")
    return std::make_unique<Translated<Inertia>>(
        std::vector<std::string>{"s", "v", "a"},
        Renamed(e, {{"m", "J"}, {"s_start", "phi_start"}, {"v_start", "w_start"}, {"s_nominal", "phi_nominal"}, {"s_fixed", "phi_fixed"}, {"v_fixed", "w_fixed"},
                    {"v_nominal", "w_nominal"}}));
  if (t == "Translational.Fixed") return std::make_unique<Fixed>(Renamed(e, {{"s0", "phi0"}}));
  if (t == "Translational.Spring") return std::make_unique<Translated<Spring>>(compliant, Renamed(e, CompliantNames()));
  if (t == "Translational.Damper") return std::make_unique<Translated<Damper>>(compliant, Renamed(e, CompliantNames()));
  if (t == "Translational.SpringDamper")
    return std::make_unique<Translated<SpringDamper>>(compliant, Renamed(e, CompliantNames()));
  if (t == "Translational.Force") return std::make_unique<Force>();
  if (t == "Translational.PositionSensor") return std::make_unique<TranslationalSensor>(false);
  if (t == "Translational.SpeedSensor") return std::make_unique<TranslationalSensor>(true);
  return nullptr;
}

}  // namespace highlift::sim::detail
