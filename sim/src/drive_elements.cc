// The power drive unit and the failure monitoring of the HighLift library (PDU, Monitoring) and
// the MSL sensors, tables and math blocks of drive models (AngleSensor, SpeedSensor,
// RelAngleSensor, RelSpeedSensor, CombiTimeTable, CombiTable1Ds, Gain, Add, Integrator).
// Specification: export/modelica/HighLift/Drives/PDU.mo, Control/Monitoring.mo and the MSL 4.0.0
// classes; docs/highlift_elements.md ("Power drive unit, monitoring and signals").
//
// Discrete variables of the Modelica classes (the PDU's brakeApplied, the monitor's relations
// and latch) change only at events: each relation is held between events and has a root
// function that locates its crossing; a root that fired toggles its relation, otherwise the
// relation is re-evaluated from the state at the event.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "composites.h"
#include "highlift/core/error.h"
#include "highlift/core/message_number.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {
namespace {

using namespace msl;  // Param, Given, TableOr, Friction, SignalBlock

double Clamp(double x, double lo, double hi) { return std::max(lo, std::min(hi, x)); }

/// Time tolerance for comparing an event time with the time it was scheduled for.
double TimeTolerance(double t) { return 1e-12 * std::max(1.0, std::abs(t)); }

std::string Where(const NetworkElement& e) { return "element '" + e.id + "' (" + e.type + ")"; }

int WholeNumber(const NetworkElement& e, const std::string& name) {
  const double v = Param(e, name);
  if (v != std::floor(v))
    throw InputError(Where(e) + ": parameter '" + name + "' = " + FormatMessageNumber(v) +
                     " must be a whole number");
  return static_cast<int>(v);
}

/// A relation held between events: at an event it toggles when its root fired (the crossing
/// was located, even if the margin at the event time is within roundoff), else it is
/// re-evaluated from the value of its root function (true for g > 0).
bool UpdateRelation(bool held, bool fired, double g) { return fired ? !held : g > 0; }

// ------------------------------------------------------------------------------------------
// HighLift.Drives.PDU: the speed loop acts on the output inertia J = n_m*J_m*ratio^2 + J_g;
// the pressure-off brakes are the MSL friction state machine between the output node and the
// housing (the ShaftBrake law with tauB_max = tauB_lim = tauPOB: peak = 1), their normalized
// torque built up linearly over t_POB from the instant the brakes are applied (BrakeActuation
// with t_rise = t_POB). The housing is an internal, never connected support flange.

class Pdu : public Friction {
 public:
  explicit Pdu(const NetworkElement& e)
      : n_m(WholeNumber(e, "n_m")),
        J_m(Param(e, "J_m")),
        ratio(Param(e, "ratio")),
        J_g(Param(e, "J_g")),
        w_max(Param(e, "w_max")),
        tau_stall(Param(e, "tau_stall")),
        P_max(Param(e, "P_max")),
        t_ramp(Param(e, "t_ramp")),
        T_w(Param(e, "T_w")),
        T_i(Param(e, "T_i")),
        tauPOB(Param(e, "tauPOB")),
        t_POB(Param(e, "t_POB")),
        w_hold(Param(e, "w_hold")),
        t_motor_lost(Given(e, "t_motor_lost") ? Param(e, "t_motor_lost") : INFINITY) {
    if (n_m < 1)
      throw InputError(Where(e) + ": parameter 'n_m' = " + FormatMessageNumber(n_m) +
                       " must be at least 1 (the number of motors)");
    J = n_m * J_m * ratio * ratio + J_g;
    if (!(J > 0))
      throw InputError(Where(e) + ": the output inertia n_m*J_m*ratio^2 + J_g is 0, so the speed "
                       "loop gain J/T_w is 0; give the motor inertia J_m or the gear inertia J_g");
    k_w = J / T_w;
    n_active = n_m;
    peak = 1.0;
    can_be_free = true;
  }

  std::vector<std::vector<std::string>> RigidFlanges() const override {
    return {{"flange_left", "flange_right"}};
  }
  std::vector<std::string> Flanges() const override {
    return {"flange_left", "flange_right", "support"};
  }
  std::vector<std::string> SignalInputs() const override { return {"w_ref", "stop"}; }
  /// The outputs phi and w are the output node's: no feedthrough from w_ref or stop.
  bool DirectFeedthrough() const override { return false; }
  std::vector<std::string> SignalOutputs() const override { return {"phi", "w"}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    p = node_of("flange_left");
    m = node_of("support");
    u = signal_of("w_ref");
    try {
      stop_signal = signal_of("stop");
    } catch (const InputError&) {
      stop_signal = -1;  // optional: no shutdown command
    }
  }
  /// The shutdown command (latched): a monitor has commanded the wing-tip brakes.
  bool StopCommanded(const Eval& e) const { return stop_signal >= 0 && e.signal[stop_signal] > 0.5; }
  void AddInertia(std::vector<Node>& nodes) const override { nodes[p].J += J; }
  // States: the ramped set point w_set and the integral z of the speed error (rad).
  int NumStates() const override { return 2; }
  std::vector<std::string> StateNames() const override { return {id + ".w_set", id + ".z"}; }
  void InitStates(const Eval&, double* y) const override {
    y[state_offset] = 0.0;
    y[state_offset + 1] = 0.0;
  }
  void Signals(const Eval& e, double* out) const override {
    out[0] = e.phi[p];
    out[1] = e.w[p];
  }

  // --- the law ---
  int NActive(const Eval& e) const {
    return e.t_segment >= t_motor_lost - TimeTolerance(t_motor_lost) ? n_m - 1 : n_m;
  }
  double WTarget(const Eval& e) const {
    if (stopped) return 0.0;
    const double w_avail = w_max * NActive(e) / n_m;
    return Clamp(e.signal[u], -w_avail, w_avail);
  }
  double WSet(const Eval& e) const { return e.y[state_offset]; }
  double Z(const Eval& e) const { return e.y[state_offset + 1]; }
  /// Torque limit at the output speed: stall torque, and the power limit P_max/|w|.
  double TauLimit(const Eval& e) const {
    return std::min(tau_stall, P_max / std::max(std::abs(e.w[p]), 1e-60));
  }
  /// The PI law before the limit: k_w*(e + z/T_i), e = w_set - w (T_i = 0: proportional).
  double TauRaw(const Eval& e) const {
    const double error = WSet(e) - e.w[p];
    return k_w * (T_i > 0 ? error + Z(e) / T_i : error);
  }
  /// The motors hold the output until the pressure-off brakes have built up their torque
  /// (t_POB after the application); only then is the drive torque removed.
  bool Driving(const Eval& e) const {
    if (stopped) return false;  // depressurised: nothing holds but the brakes
    if (!applied) return true;
    const double full = t_on + t_POB;  // a time event: switch with the right limit
    return e.t_segment < full - TimeTolerance(full);
  }
  double TauDrive(const Eval& e) const {
    if (!Driving(e)) return 0.0;
    const double lim = TauLimit(e);
    return Clamp(TauRaw(e), -lim, lim);
  }
  /// Normalized brake torque (BrakeActuation y with t_rise = t_POB).
  double Actuation(const Eval& e) const {
    if (!applied) return 0.0;
    if (t_POB <= 0) return 1.0;
    return Clamp((e.t - t_on) / t_POB, 0.0, 1.0);
  }
  // Engaged from the instant of application (a vanishing capacity that then rises), so that the
  // friction modes are set at that event rather than at a second event an instant later.
  double Fn(const Eval& e) const override {
    if (!applied || tauPOB <= 0) return 0.0;
    return std::max(Actuation(e), 1e-12);
  }
  double TauSlide(const Eval& e, double) const override { return tauPOB * Fn(e); }

  void Forces(Eval& e) override {
    tau_drive = TauDrive(e);
    e.AddForce(p, tau_drive);
    e.AddForce(m, -tau_drive);
    Friction::Forces(e);
  }
  void Derivatives(Eval& e) override {
    const double rate = w_max / t_ramp;
    e.ydot[state_offset] = Clamp((WTarget(e) - WSet(e)) / T_w, -rate, rate);
    // Integral with back-calculation anti-windup (continuous): in the limit z relaxes to the
    // value that gives the limited torque; held while the brakes are applied.
    if (T_i > 0 && Driving(e))
      e.ydot[state_offset + 1] = WSet(e) - e.w[p] + (tau_drive - TauRaw(e)) / k_w;
    else
      e.ydot[state_offset + 1] = 0.0;
  }
  // Bumpless release: when the brakes open, the integral takes over the torque they held, so
  // the loads do not back-drive the transmission while the loop builds up its integral.
  void EventStates(const Eval&, double* y) override {
    if (T_i > 0 && was_applied && !applied) y[state_offset + 1] = T_i * hold_torque / k_w;
    was_applied = applied;
  }

  // --- events: the friction roots 0..2, then |w_target| <= w_hold and |w_set| <= w_hold ---
  int NumRoots() const override { return 5; }
  void Roots(const Eval& e, double* g) const override {
    Friction::Roots(e, g);
    g[3] = w_hold - std::abs(WTarget(e));
    g[4] = w_hold - std::abs(WSet(e));
  }
  void RootDirections(int* d) const override {
    Friction::RootDirections(d);
    d[3] = d[4] = 0;
  }
  double NextTimeEvent(double t) const override {
    double next = INFINITY;
    if (t < t_motor_lost - TimeTolerance(t_motor_lost)) next = t_motor_lost;
    const double full = t_on + t_POB;
    if (applied && t_POB > 0 && t < full - TimeTolerance(full)) next = std::min(next, full);
    return next;
  }
  void PrepareEvent(const Eval& e) override {
    // At rest means |.| <= w_hold: a root function of exactly 0 counts as at rest.
    const double g_command = w_hold - std::abs(WTarget(e)), g_set = w_hold - std::abs(WSet(e));
    command_at_rest = Fired(3) ? !command_at_rest : g_command >= 0;
    set_point_at_rest = Fired(4) ? !set_point_at_rest : g_set >= 0;
    if (!stopped && StopCommanded(e)) stopped = true;  // latched until the end of the run
    const bool now = (command_at_rest && set_point_at_rest) || stopped;
    // Applied at the start: the brakes have held the parked drive, their torque is built up.
    if (now && !applied) t_on = e.initial ? e.t - t_POB : e.t;
    if (applied && !now) hold_torque = mode == kStuck ? -tau : 0.0;  // torque the brakes held
    applied = now;
    n_active = NActive(e);
    Friction::PrepareEvent(e);
  }
  // The shutdown command may change at the same event (the monitor switches in its own
  // PrepareEvent): checked in the event iteration too.
  double Violation(const Eval& e) const override {
    if (!stopped && StopCommanded(e)) return 1.0;
    return Friction::Violation(e);
  }
  void Fix(const Eval& e) override {
    if (!stopped && StopCommanded(e)) {
      stopped = true;
      if (!applied) t_on = e.t;
      applied = true;
      Friction::PrepareEvent(e);  // the brake's friction mode for the new normal force
      return;
    }
    Friction::Fix(e);
  }
  std::string ModeText() const override {
    std::string s = ModeName(mode) + (applied ? (stopped ? ", shut down, brakes applied" : ", brakes applied") : ", driving");
    if (n_active < n_m) s += ", " + std::to_string(n_active) + " of " + std::to_string(n_m) + " motors";
    return s;
  }

  // --- outputs and energy ---
  /// Torque the PDU delivers into the transmission: drive torque less brake torque less the
  /// torque that accelerates its own inertia.
  double OutputTorque(const Eval& e) const { return tau_drive - tau - J * e.acc[p]; }
  std::vector<std::string> OutputNames() const override {
    return {"phi", "w", "w_set", "tau", "tau_drive", "tau_brake", "brake", "f_brake", "mode",
            "n_active"};
  }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = e.phi[p];
    out[1] = e.w[p];
    out[2] = WSet(e);
    out[3] = OutputTorque(e);
    out[4] = tau_drive;
    out[5] = tau;
    out[6] = applied ? 1.0 : 0.0;
    out[7] = Actuation(e);
    out[8] = OutputMode();
    out[9] = NActive(e);
  }
  double PeakTorque(const Eval& e) const override { return OutputTorque(e); }
  double SourcePower(const Eval& e) const override { return tau_drive * (e.w[p] - e.w[m]); }

  int n_m;
  double J_m, ratio, J_g, w_max, tau_stall, P_max, t_ramp, T_w, T_i, tauPOB, t_POB, w_hold, t_motor_lost;
  double J = 0.0, k_w = 0.0;
  int u = -1;
  // Discrete state.
  bool command_at_rest = false, set_point_at_rest = false, applied = false, was_applied = false;
  bool stopped = false;  ///< shut down by the stop input (latched)
  int stop_signal = -1;
  double hold_torque = 0.0;  ///< N*m, the torque on the shaft the brakes held at their release
  double t_on = 0.0;
  int n_active = 0;
  mutable double tau_drive = 0.0;
};

// ------------------------------------------------------------------------------------------
// HighLift.Control.Monitoring: six held relations (three asymmetries, two overspeeds, the
// uncommanded movement), the latched fault with its time, and the brake command wtb from
// t_fault + t_detect on (a time event).

class Monitoring : public Element {
 public:
  explicit Monitoring(const NetworkElement& e)
      : phi_asym(Param(e, "phi_asym")),
        w_over(Param(e, "w_over")),
        phi_unc(Param(e, "phi_unc")),
        t_detect(Param(e, "t_detect")),
        enable_asymmetry(Param(e, "enableAsymmetry") != 0),
        enable_overspeed(Param(e, "enableOverspeed") != 0),
        enable_uncommanded(Param(e, "enableUncommanded") != 0) {}

  enum Input { kPhiLeft, kPhiRight, kPhiPdu, kPhiCmd, kWLeft, kWRight, kInputs };
  std::vector<std::string> SignalInputs() const override {
    return {"phi_left", "phi_right", "phi_pdu", "phi_cmd", "w_left", "w_right"};
  }
  std::vector<std::string> SignalOutputs() const override {
    return {"asymmetry", "overspeed", "uncommanded", "wtb"};
  }
  void Bind(const std::function<int(const std::string&)>&,
            const std::function<int(const std::string&)>& signal_of) override {
    const auto names = SignalInputs();
    for (int i = 0; i < kInputs; ++i) in[i] = signal_of(names[i]);
  }

  static constexpr int kRelations = 6;
  bool Enabled(int k) const {
    return k < 3 ? enable_asymmetry : (k < 5 ? enable_overspeed : enable_uncommanded);
  }
  /// Root function of relation k: |x_k| - threshold_k (> 0: detected).
  double G(const Eval& e, int k) const {
    auto s = [&](Input i) { return e.signal[in[i]]; };
    switch (k) {
      case 0: return std::abs(s(kPhiLeft) - s(kPhiRight)) - phi_asym;
      case 1: return std::abs(s(kPhiLeft) - s(kPhiPdu)) - phi_asym;
      case 2: return std::abs(s(kPhiRight) - s(kPhiPdu)) - phi_asym;
      case 3: return std::abs(s(kWLeft)) - w_over;
      case 4: return std::abs(s(kWRight)) - w_over;
      default: return std::abs(s(kPhiPdu) - s(kPhiCmd)) - phi_unc;
    }
  }
  /// The detections and the command are held between events.
  bool SignalsFollowState() const override { return false; }
  bool DirectFeedthrough() const override { return false; }
  bool Asymmetry() const { return enable_asymmetry && (held[0] || held[1] || held[2]); }
  bool Overspeed() const { return enable_overspeed && (held[3] || held[4]); }
  bool Uncommanded() const { return enable_uncommanded && held[5]; }
  double CommandTime() const { return t_fault + t_detect; }
  bool Command(double t_segment) const {
    return fault && t_segment >= CommandTime() - TimeTolerance(CommandTime());
  }

  void Signals(const Eval& e, double* out) const override {
    out[0] = Asymmetry();
    out[1] = Overspeed();
    out[2] = Uncommanded();
    out[3] = Command(e.t_segment);
  }
  int NumRoots() const override { return kRelations; }
  void Roots(const Eval& e, double* g) const override {
    for (int k = 0; k < kRelations; ++k) g[k] = Enabled(k) ? G(e, k) : 1.0;
  }
  bool RootsNeedSolve() const override { return false; }  // the sensor inputs
  bool IsSwitching() const override { return true; }
  void PrepareEvent(const Eval& e) override {
    for (int k = 0; k < kRelations; ++k)
      held[k] = Enabled(k) && UpdateRelation(held[k], Fired(k), G(e, k));
    if (!fault && (Asymmetry() || Overspeed() || Uncommanded())) {
      fault = true;
      t_fault = e.t;
      detected = Asymmetry() ? "asymmetry" : (Overspeed() ? "overspeed" : "uncommanded movement");
    }
    command = Command(e.t);
  }
  double NextTimeEvent(double t) const override {
    if (fault && t < CommandTime() - TimeTolerance(CommandTime())) return CommandTime();
    return INFINITY;
  }
  std::string ModeText() const override {
    if (!fault) return "monitoring";
    return (command ? "brake command (" : "detected (") + detected + ")";
  }
  std::vector<std::string> OutputNames() const override {
    return {"asymmetry", "overspeed", "uncommanded", "wtb", "fault"};
  }
  void Outputs(const Eval& e, double* out) const override {
    for (int i = 0; i < 4; ++i) out[i] = e.signal[signal_offset + i];
    out[4] = fault;
  }

  double phi_asym, w_over, phi_unc, t_detect;
  bool enable_asymmetry, enable_overspeed, enable_uncommanded;
  int in[kInputs] = {-1, -1, -1, -1, -1, -1};
  bool held[kRelations] = {};
  bool fault = false, command = false;
  double t_fault = 0.0;
  std::string detected;
};

// ------------------------------------------------------------------------------------------
// Modelica.Mechanics.Rotational.Sensors: ideal sensors, no torque, no energy.

class Sensor : public Element {
 public:
  Sensor(std::vector<std::string> flanges, std::string output)
      : flanges_(std::move(flanges)), output_(std::move(output)) {}
  std::vector<std::string> Flanges() const override { return flanges_; }
  std::vector<std::string> SignalOutputs() const override { return {output_}; }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>&) override {
    a = node_of(flanges_[0]);
    b = flanges_.size() > 1 ? node_of(flanges_[1]) : -1;
  }
  std::vector<int> Nodes() const override { return b < 0 ? std::vector<int>{a} : std::vector<int>{a, b}; }
  MasslessRole RoleAt(int) const override { return MasslessRole::kNoTorque; }
  bool HasReadings() const override { return false; }  // measures: no torque, no power
  std::vector<std::string> OutputNames() const override { return {output_}; }
  void Outputs(const Eval& e, double* out) const override { out[0] = e.signal[signal_offset]; }
  std::vector<std::string> flanges_;
  std::string output_;
  int a = -1, b = -1;
};

class AngleSensor : public Sensor {
 public:
  AngleSensor() : Sensor({"flange"}, "phi") {}
  void Signals(const Eval& e, double* out) const override { out[0] = e.phi[a]; }
};
class SpeedSensor : public Sensor {
 public:
  SpeedSensor() : Sensor({"flange"}, "w") {}
  void Signals(const Eval& e, double* out) const override { out[0] = e.w[a]; }
};
class RelAngleSensor : public Sensor {
 public:
  RelAngleSensor() : Sensor({"flange_a", "flange_b"}, "phi_rel") {}
  void Signals(const Eval& e, double* out) const override { out[0] = e.phi[b] - e.phi[a]; }
};
class RelSpeedSensor : public Sensor {
 public:
  RelSpeedSensor() : Sensor({"flange_a", "flange_b"}, "w_rel") {}
  void Signals(const Eval& e, double* out) const override { out[0] = e.w[b] - e.w[a]; }
};

// ------------------------------------------------------------------------------------------
// Tables (MSL 4.0.0 Modelica.Blocks.Sources.CombiTimeTable, Modelica.Blocks.Tables.CombiTable1Ds)
// with one output: table column 2.

enum Extrapolation { kHoldLastPoint = 1, kLastTwoPoints = 2, kPeriodic = 3 };
enum TimeEvents { kAlways = 1, kAtDiscontinuities = 2, kNoTimeEvents = 3 };

/// Value of the straight line through rows i and j of `table` at x.
double Line(const Table& table, std::size_t i, std::size_t j, double x) {
  const double x0 = table[i][0], x1 = table[j][0];
  if (x1 == x0) return table[j][1];
  return table[i][1] + (table[j][1] - table[i][1]) * (x - x0) / (x1 - x0);
}

class CombiTimeTable : public SignalBlock {
 public:
  explicit CombiTimeTable(const NetworkElement& e)
      : table(TableOr(e, "table", {}, 2)),
        constant_segments(WholeNumber(e, "smoothness") == 3),
        extrapolation(WholeNumber(e, "extrapolation")),
        time_scale(Param(e, "timeScale")),
        offset(Param(e, "offset")),
        start_time(Param(e, "startTime")),
        shift_time(Given(e, "shiftTime") ? Param(e, "shiftTime") : start_time),
        time_events(WholeNumber(e, "timeEvents")) {
    const int smoothness = WholeNumber(e, "smoothness");
    if (smoothness != 1 && smoothness != 3)
      throw InputError(Where(e) + ": parameter 'smoothness' = " + FormatMessageNumber(smoothness) +
                       " is not supported; use 1 (LinearSegments) or 3 (ConstantSegments)");
    if (constant_segments) time_events = kAlways;  // MSL: always for constant segments
    for (std::size_t r = 2; r < table.size(); ++r)
      if (table[r][0] == table[r - 2][0])
        throw InputError(Where(e) + ": table 'table' has the time " + FormatMessageNumber(table[r][0]) +
                         " more than twice (row " + std::to_string(r + 1) +
                         "); a jump needs exactly two rows with the same time");
    period = table.back()[0] - table.front()[0];
    if (extrapolation == kPeriodic && table.size() > 1 && !(period > 0))
      throw InputError(Where(e) + ": extrapolation = 3 (Periodic) needs a table that spans a "
                       "positive time; give rows with different times or another extrapolation");
  }

  bool Jump(std::size_t k) const {
    return (k + 1 < table.size() && table[k + 1][0] == table[k][0]) ||
           (k > 0 && table[k - 1][0] == table[k][0]);
  }
  bool PeriodJump() const {
    return extrapolation == kPeriodic && table.back()[1] != table.front()[1];
  }
  /// Whether row k's time is an event of the table (always at a jump unless NoTimeEvents).
  bool EventAt(std::size_t k) const {
    if (time_events == kAlways) return true;
    if (time_events == kNoTimeEvents) return false;
    return Jump(k) || (PeriodJump() && (k == 0 || k + 1 == table.size()));
  }

  // Table value at scaled time x, with xs the scaled time of the last event: a row time that
  // is an event belongs to the interval on its right only once its event has been handled.
  double TableValue(double x, double xs) const {
    const std::size_t n = table.size();
    if (n == 1) return table[0][1];
    const double t0 = table.front()[0], t1 = table.back()[0];
    if (extrapolation == kPeriodic) {
      const bool events = time_events == kAlways || PeriodJump();
      const double q = std::floor(((events ? xs : x) - t0) / period + 1e-9);
      x -= q * period;
      xs -= q * period;
    }
    const double tol = 1e-12 * std::max(1.0, std::abs(x));
    auto handled = [&](std::size_t k) { return !EventAt(k) || xs >= table[k][0] - tol; };
    if (extrapolation != kPeriodic) {
      const bool right = x > t1 + tol || (std::abs(x - t1) <= tol && handled(n - 1));
      if (x < t0 || right) {
        const bool left = x < t0;
        if (extrapolation == kHoldLastPoint) return left ? table[0][1] : table[n - 1][1];
        // LastTwoPoints: the line through the first (last) two points of distinct time.
        if (left) {
          std::size_t j = 1;
          while (j + 1 < n && table[j][0] == t0) ++j;
          return Line(table, j - 1, j, x);
        }
        std::size_t i = n - 2;
        while (i > 0 && table[i][0] == t1) --i;
        return Line(table, i, i + 1, x);
      }
    }
    // The interval [t_k, t_k+1] (t_k < t_k+1) with the largest k that x has entered.
    std::size_t k = n;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      if (!(table[i][0] < table[i + 1][0])) continue;
      if (k == n || table[i][0] < x - tol || (table[i][0] <= x + tol && handled(i))) k = i;
      if (table[i][0] > x + tol) break;
    }
    if (constant_segments) return table[k][1];
    return Line(table, k, k + 1, x);
  }
  double Signal(const Eval& e) const override {
    if (e.t_segment < start_time - TimeTolerance(start_time)) return offset;
    return offset + TableValue((e.t - shift_time) / time_scale, (e.t_segment - shift_time) / time_scale);
  }
  double NextTimeEvent(double t) const override {
    double next = INFINITY;
    auto consider = [&](double te) {
      if (te > t + TimeTolerance(te) && te >= start_time) next = std::min(next, te);
    };
    if (t < start_time - TimeTolerance(start_time)) next = start_time;
    if (table.size() < 2 || time_events == kNoTimeEvents) return next;
    double base = 0.0;  // table time shift of the period that holds t
    if (extrapolation == kPeriodic)
      base = std::floor(((t - shift_time) / time_scale - table.front()[0]) / period + 1e-9) * period;
    for (int repeat = 0; repeat < (extrapolation == kPeriodic ? 2 : 1); ++repeat)
      for (std::size_t k = 0; k < table.size(); ++k)
        if (EventAt(k)) consider(shift_time + (table[k][0] + base + repeat * period) * time_scale);
    return next;
  }

  Table table;
  bool constant_segments;
  int extrapolation;
  double time_scale, offset, start_time, shift_time;
  int time_events;
  double period = 0.0;
};

class CombiTable1Ds : public SignalBlock {
 public:
  explicit CombiTable1Ds(const NetworkElement& e) : extrapolation(WholeNumber(e, "extrapolation")) {
    if (WholeNumber(e, "smoothness") != 1)
      throw InputError(Where(e) + ": parameter 'smoothness' must be 1 (LinearSegments), the "
                       "only interpolation supported");
    const Table table = TableOr(e, "table", {}, 2);
    for (std::size_t r = 1; r < table.size(); ++r)
      if (!(table[r][0] > table[r - 1][0]))
        throw InputError(Where(e) + ": table 'table' first column must be strictly increasing "
                         "(row " + std::to_string(r + 1) + "); remove the repeated abscissa");
    for (const auto& row : table) {
      xs.push_back(row[0]);
      ys.push_back(row[1]);
    }
  }
  std::vector<std::string> SignalInputs() const override { return {"u"}; }
  void Bind(const std::function<int(const std::string&)>&,
            const std::function<int(const std::string&)>& signal_of) override {
    u = signal_of("u");
  }
  double Value(double x) const {
    const std::size_t n = xs.size();  // >= 1 (TableOr)
    if (n == 1) return ys[0];
    const double x0 = xs.front(), x1 = xs.back();
    if (extrapolation == kPeriodic) {
      const double span = x1 - x0;
      x -= std::floor((x - x0) / span) * span;
    } else if (extrapolation == kHoldLastPoint) {
      if (x <= x0) return ys.front();
      if (x >= x1) return ys.back();
    }
    // Linear, extrapolated through the outer two points.
    return InterpolatePointsNear(
        n, [this](std::size_t i) { return xs[i]; }, [this](std::size_t i) { return ys[i]; }, x, interval_);
  }
  double Signal(const Eval& e) const override { return Value(e.signal[u]); }
  /// The table's two columns, contiguous: a table is read at every evaluation, one per actuator.
  std::vector<double> xs, ys;
  mutable std::size_t interval_ = 0;  ///< the interval of the last read (InterpolatePointsNear)
  int extrapolation;
  int u = -1;
};

// ------------------------------------------------------------------------------------------
// Modelica.Blocks.Math.Gain and Add, Modelica.Blocks.Continuous.Integrator.

class Gain : public SignalBlock {
 public:
  explicit Gain(const NetworkElement& e) : k(Param(e, "k")) {}
  std::vector<std::string> SignalInputs() const override { return {"u"}; }
  void Bind(const std::function<int(const std::string&)>&,
            const std::function<int(const std::string&)>& signal_of) override {
    u = signal_of("u");
  }
  double Signal(const Eval& e) const override { return k * e.signal[u]; }
  void SignalDerivatives(const Eval& e, double* d1, double* d2) const override {
    *d1 = k * e.signal_d1[u];
    *d2 = k * e.signal_d2[u];
  }
  double k;
  int u = -1;
};

class Add : public SignalBlock {
 public:
  explicit Add(const NetworkElement& e) : k1(Param(e, "k1")), k2(Param(e, "k2")) {}
  std::vector<std::string> SignalInputs() const override { return {"u1", "u2"}; }
  void Bind(const std::function<int(const std::string&)>&,
            const std::function<int(const std::string&)>& signal_of) override {
    u1 = signal_of("u1");
    u2 = signal_of("u2");
  }
  double Signal(const Eval& e) const override { return k1 * e.signal[u1] + k2 * e.signal[u2]; }
  void SignalDerivatives(const Eval& e, double* d1, double* d2) const override {
    *d1 = k1 * e.signal_d1[u1] + k2 * e.signal_d1[u2];
    *d2 = k1 * e.signal_d2[u1] + k2 * e.signal_d2[u2];
  }
  double k1, k2;
  int u1 = -1, u2 = -1;
};

class Integrator : public SignalBlock {
 public:
  explicit Integrator(const NetworkElement& e) : k(Param(e, "k")), y_start(Param(e, "y_start")) {}
  std::vector<std::string> SignalInputs() const override { return {"u"}; }
  void Bind(const std::function<int(const std::string&)>&,
            const std::function<int(const std::string&)>& signal_of) override {
    u = signal_of("u");
  }
  int NumStates() const override { return 1; }
  std::vector<std::string> StateNames() const override { return {id + ".y"}; }
  void InitStates(const Eval&, double* y) const override { y[state_offset] = y_start; }
  // Before the state vector exists (initial signal evaluation) the output is y_start.
  double Signal(const Eval& e) const override {
    return e.y == nullptr ? y_start : e.y[state_offset];
  }
  void Derivatives(Eval& e) override { e.ydot[state_offset] = k * e.signal[u]; }
  double k, y_start;
  int u = -1;
};

}  // namespace

std::unique_ptr<Element> MakeDriveElement(const NetworkElement& e) {
  const std::string& t = e.type;
  if (t == "PDU") return std::make_unique<Pdu>(e);
  if (t == "Monitoring") return std::make_unique<Monitoring>(e);
  if (t == "AngleSensor") return std::make_unique<AngleSensor>();
  if (t == "SpeedSensor") return std::make_unique<SpeedSensor>();
  if (t == "RelAngleSensor") return std::make_unique<RelAngleSensor>();
  if (t == "RelSpeedSensor") return std::make_unique<RelSpeedSensor>();
  if (t == "CombiTimeTable") return std::make_unique<CombiTimeTable>(e);
  if (t == "CombiTable1Ds") return std::make_unique<CombiTable1Ds>(e);
  if (t == "Gain") return std::make_unique<Gain>(e);
  if (t == "Add") return std::make_unique<Add>(e);
  if (t == "Integrator") return std::make_unique<Integrator>(e);
  return nullptr;
}

std::optional<Composite> ExpandDriveComposite(const NetworkElement& element) {
  (void)element;  // the PDU is one element (its brakes are its own friction state machine)
  return std::nullopt;
}

}  // namespace highlift::sim::detail
