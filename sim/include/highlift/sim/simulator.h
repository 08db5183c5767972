// Transient simulation of an element network with MSL 4.0.0 semantics on SUNDIALS CVODE.
//
// Formulation. Connected flanges form nodes; a Fixed flange (or an unconnected support) is the
// ground. Every node carries its angle and speed as states; every compliant or clutch element
// carries its relative angle phi_rel as a state (relative-twist states: the spring torque never
// suffers from the cancellation of two large absolute angles). Kinematic couplings (gears,
// planetary gears, speed sources and the friction elements that are stuck) are linear
// constraints on the node accelerations; at each right-hand-side evaluation the accelerations
// and the constraint torques follow from one small KKT system per group of coupled nodes.
// Linear multistep methods keep linear invariants, so the constraints stay satisfied.
//
// Events. Friction stick/slip (the MSL state machine of PartialFriction, Brake, Clutch,
// BearingFriction, OneWayClutch and LossyGear), backlash contact and the engagement of brakes
// and clutches are state events: their root functions are compared at every step end (the model
// is evaluated there for the peaks anyway) and a crossing is located on CVODE's interpolant by
// the Illinois method CVODE uses for its own roots; steps, ramp corners and pulse edges of the
// sources are time events hit exactly with CVodeSetStopTime. After every event
// the modes are iterated to a consistent set (the worst violator of a stuck set is released
// first), the speeds are projected onto the active constraints, and CVODE is re-initialised.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "highlift/model/start_values.h"
#include "highlift/sim/network.h"

namespace highlift::sim {

/// How the run starts. kGiven: the start values of the elements (and their a_start initial
/// equations). kSteadyState: besides, every inertia starts with a = 0 and every spring with a
/// constant twist; the free speeds and angles are solved for it (an inertia with a damper under
/// a constant torque starts at w = tau / d, a spring under a constant torque at its deflection).
enum class StartKind { kGiven, kSteadyState };
std::string ToString(StartKind start);  ///< "given", "steady_state"
/// Reads "given", "steady_state" (or "steady-state"); InputError listing them otherwise.
StartKind ParseStartKind(const std::string& text);

struct SimulationOptions {
  double start_time = 0.0;           // s
  double stop_time = 1.0;            // s
  double output_interval = 1e-3;     // s, equidistant output grid (plus event rows)
  double relative_tolerance = 1e-6;  // CVODE relative tolerance
  double absolute_tolerance = 1e-8;  // CVODE absolute tolerance (rad, rad/s)
  /// N*m; > 0: the absolute tolerance of a spring's twist is torque_tolerance / its stiffness
  /// (a stiff jam or end stop is resolved in torque, not to a fixed angle); 0: every state
  /// uses absolute_tolerance.
  double torque_tolerance = 0.0;
  /// rad/s; > 0: the absolute tolerance of a node's speed is at least relative_tolerance *
  /// speed_resolution, so a speed below it is resolved relative to this speed (drive models:
  /// the regularised friction speed w_small, below which the friction laws change sign, to the
  /// relative tolerance of the laws) rather than to absolute_tolerance rad/s. 0: off.
  double speed_resolution = 0.0;
  double max_step = 0.0;             // s, 0: no limit
  /// CVODE's BDF stability limit detection: lowers the order when lightly damped oscillatory
  /// modes make the order-3 to order-5 formulas unstable (a transmission's torsional modes);
  /// without it such runs take many small steps.
  bool stability_limit_detection = true;
  long max_steps_per_output = 100000;  // CVODE mxstep between two output points
  int max_events = 1000000;          // guard against chattering
  /// "auto": dense for small networks, sparse (KLU, difference-quotient Jacobian on the
  /// network's sparsity pattern with column colouring) from 60 states on; "dense", "band"
  /// (difference quotients on the band of the state ordering) or "sparse" to force one.
  /// "sparse" eliminates the node angles and the spring twists (whose derivatives are speeds)
  /// from each Newton system before KLU factors the rest, where that adds no entry;
  /// "sparse_whole" factors the whole system (the same solutions up to roundoff; slower).
  std::string linear_solver = "auto";
  /// Sparse Jacobians: the columns that share a difference quotient are coloured on the pattern
  /// of the current mode (the active constraints; no column for a node angle that no law
  /// reads), not on the superset of every mode (the A380-class model: 10 colours instead of
  /// 21). The same Jacobian to the last bit from fewer evaluations; networks with hydraulic
  /// nodes keep the superset's. false: the superset's colouring (for comparison).
  bool mode_colouring = true;
  /// Start from the static equilibrium at rest: the spring twists that balance the loads
  /// acting at the start time (for instance airloads held by a brake), found after the
  /// initial modes; off: the springs start untwisted (or at their given start values).
  bool initial_equilibrium = false;
  /// The start values as given (with the elements' a_start) or a steady-state start (StartKind).
  StartKind start = StartKind::kGiven;
  /// Adds the energy columns energy.kinetic, energy.potential (J), energy.loss_power,
  /// energy.source_power (W) and energy.impulsive_loss (J) and fills SimulationReport::energy.
  bool energy = false;
  /// Passivity monitor (PassivityReport): a dissipative element whose dissipated power stays
  /// below -passivity_tolerance * (the run's power scale) over more than one integrator step is
  /// a violation. Relative, > 0.
  double passivity_tolerance = 1e-6;

  /// Throws InputError naming the option when a value is invalid.
  void Validate() const;
};

/// Where results go, one row at a time (results stream: memory does not grow with the run).
class OutputSink {
 public:
  virtual ~OutputSink() = default;
  virtual void Begin(const std::vector<std::string>& columns) = 0;  // without "time"
  virtual void Row(double time, const std::vector<double>& values) = 0;
  virtual void End() {}
  /// False for a sink whose Row() does not read the values (one that counts or discards the
  /// rows): the simulator then does not compute the outputs, and Row() gets the time and a
  /// vector of the right size with unspecified values.
  virtual bool ReadsValues() const { return true; }
};

/// Discards the rows and reads no values (a run whose results are in its report: the peaks, the
/// events, the energy balance; the campaigns, `peak --transient`).
class DiscardSink : public OutputSink {
 public:
  void Begin(const std::vector<std::string>&) override {}
  void Row(double, const std::vector<double>&) override {}
  bool ReadsValues() const override { return false; }
};

/// Keeps every row in memory (tests, small runs).
class MemorySink : public OutputSink {
 public:
  void Begin(const std::vector<std::string>& columns) override { columns_ = columns; }
  void Row(double time, const std::vector<double>& values) override {
    times_.push_back(time);
    rows_.push_back(values);
  }
  const std::vector<std::string>& columns() const { return columns_; }
  const std::vector<double>& times() const { return times_; }
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  /// Index of column `name`, or -1.
  int Column(const std::string& name) const;
  /// Values of one column; throws std::out_of_range for an unknown column.
  std::vector<double> Series(const std::string& name) const;

 private:
  std::vector<std::string> columns_;
  std::vector<double> times_;
  std::vector<std::vector<double>> rows_;
};

/// Writes CSV ("time" + instance-path columns, each number the shortest text that reads back as
/// the same double) to a file, row by row.
/// `signals` selects columns (empty: all); an unknown signal is an InputError listing the
/// closest names. The file is written through highlift::OutputFile: inputs, devices and
/// directories are refused, every write is checked (InputError on failure) and the old file is
/// replaced only by End(). After an interruption (InterruptRequested()) End() writes the rows so
/// far with a "# partial output" trailer line to FILE.partial and leaves FILE unchanged.
class CsvSink : public OutputSink {
 public:
  CsvSink(const std::filesystem::path& file, std::vector<std::string> signals = {});
  ~CsvSink() override;
  void Begin(const std::vector<std::string>& columns) override;
  void Row(double time, const std::vector<double>& values) override;
  void End() override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One discrete event of a run.
struct SimulationEvent {
  double time = 0.0;
  std::string kind;     ///< "time", "state", "initial"
  std::string element;  ///< element whose mode changed ("" if none)
  std::string what;     ///< e.g. "mode -1 -> 0", "contact", "step"
};

struct SolverStatistics {
  long steps = 0;
  long rhs_evaluations = 0;
  long jacobian_evaluations = 0;
  long nonlinear_iterations = 0;
  long error_test_failures = 0;
  long nonlinear_convergence_failures = 0;
  long root_evaluations = 0;
  long reinitialisations = 0;
  long continuous_roots = 0;  ///< roots crossed without a restart (kinks)
  int states = 0;
  /// "dense", "band(mu,ml)" or "sparse(KLU, ...)" with the states eliminated and the setups
  /// that had to factor the whole matrix (ReducedKlu).
  std::string linear_solver;
};

/// The energy balance of a run (SimulationOptions::energy), integrated by the trapezoidal rule
/// over the step ends, event limits and output points: source work = change of kinetic and potential energy + dissipated work
/// + kinetic energy removed by speed projections at events.
struct EnergyBalance {
  bool computed = false;
  double source_work = 0.0;     ///< integral of the power of sources and loads, J
  double dissipated = 0.0;      ///< integral of the loss power, J
  double impulsive_loss = 0.0;  ///< removed by speed projections at events, J
  double kinetic_start = 0.0, kinetic_end = 0.0;      ///< J
  double potential_start = 0.0, potential_end = 0.0;  ///< J
  /// source_work - (stored change + dissipated + impulsive_loss), J.
  double Residual() const {
    return source_work - (kinetic_end - kinetic_start + potential_end - potential_start +
                          dissipated + impulsive_loss);
  }
  /// The largest of the terms, for a relative tolerance.
  double Scale() const;
};

/// One element whose dissipated power (Element::LossPower: friction, brakes, dampers, gear
/// losses) fell below zero beyond the tolerance for longer than one integrator step: it fed
/// energy into the network (for instance a friction element sliding against its slip).
struct PassivityViolation {
  std::string element;
  double time = 0.0;      ///< s, start of the (worst) episode of negative dissipation
  double duration = 0.0;  ///< s, from its first to its last negative sample
  double power = 0.0;     ///< W, the most negative dissipated power of that episode (< 0)
  double power_time = 0.0;  ///< s, when that power was reached
  int episodes = 0;       ///< episodes of this element beyond the tolerance in the run
};

/// The passivity monitor of a run: every dissipative element's power is followed at every
/// integrator step end and event limit. The power scale is the largest sum over the elements
/// of |dissipated power| + |source power| seen in the run; an episode is a run of consecutive
/// samples with power below -tolerance * (the scale so far), and it is a violation when it
/// lasts longer than one step (two or more samples) and its most negative power is below
/// -tolerance * (the run's final scale).
struct PassivityReport {
  double tolerance = 0.0;    ///< relative (SimulationOptions::passivity_tolerance)
  double power_scale = 0.0;  ///< W
  std::vector<PassivityViolation> violations;  ///< one per element, its worst episode
  bool passive() const { return violations.empty(); }
  /// "passive" or "N elements with negative dissipation: wtb_left at 0.61 s, -2.4e3 W, ...".
  std::string BriefReport() const;
};

/// Largest absolute torque of one element over a run, and when: over the integrator's step
/// ends and event limits, located between them where three samples of a smooth stretch have
/// their largest |tau| in the middle (the vertex of the parabola through them); the output
/// points are not read, so the peak does not depend on the output interval
/// (docs/simulation.md).
struct PeakTorque {
  std::string element;
  double tau = 0.0;   ///< signed value at the peak, N*m
  double time = 0.0;  ///< s
};

/// kInterrupted: SIGINT/SIGTERM (highlift::InterruptRequested()) stopped the run after the last
/// complete output row.
enum class SimulationStatus { kSuccess, kSolverFailure, kModelError, kTooManyEvents, kInterrupted };
std::string ToString(SimulationStatus status);

struct SimulationReport {
  SimulationStatus status = SimulationStatus::kSuccess;
  std::string message;            ///< what went wrong, naming the call, flag, element
  double time = 0.0;              ///< time reached
  std::string sundials_flag;      ///< e.g. "CV_CONV_FAILURE" when the solver failed
  std::string element;            ///< element blamed by the failure, if any
  std::vector<std::pair<std::string, double>> state;  ///< state at failure (name, value)
  std::vector<SimulationEvent> events;
  SolverStatistics statistics;
  std::vector<PeakTorque> peak_torques;  ///< one per element that carries a torque
  EnergyBalance energy;                  ///< when SimulationOptions::energy
  PassivityReport passivity;             ///< always
  double wall_seconds = 0.0;

  bool ok() const { return status == SimulationStatus::kSuccess; }
  std::string BriefReport() const;
  std::string FullReport() const;
};

/// The structural check of an element network: everything the simulator checks when it
/// assembles the model (ports and signal connections, flanges whose motion nothing determines,
/// massless nodes, algebraic loops) and the consistency of the initial values at `start_time`.
/// Returns "" when the network can be simulated, else the message naming the element and the
/// remedy. `highlift validate` and `highlift simulate` use this one check, so they agree.
std::string CheckStructure(const Network& network, double start_time = 0.0);

/// The start of a run with `options` (start_time, initial_equilibrium) as start values of the
/// network's flanges (highlift/model/start_values.h): the state Simulator::Run starts from,
/// computed by the same start sequence, for the Modelica export. Throws InputError when the
/// network cannot be assembled or started.
model::StartValues ComputeStartValues(const Network& network, const SimulationOptions& options);

/// Progress callback: fraction of the time span done in [0, 1].
using ProgressCallback = void (*)(double fraction, void* user);

/// An assembled, runnable model of a network. Construction checks the structure and throws
/// InputError (naming the element and the remedy) for unsupported or singular networks.
class Simulator {
 public:
  explicit Simulator(const Network& network);
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  /// Names of all output columns (instance paths such as "clutch.w_rel"), without "time".
  const std::vector<std::string>& OutputNames() const;

  /// Runs from options.start_time to options.stop_time, writing rows to `sink`: the
  /// equidistant grid and, at each event, the left- and right-limit rows. Never throws for a
  /// numerical failure: the report says what happened.
  SimulationReport Run(const SimulationOptions& options, OutputSink& sink,
                       ProgressCallback progress = nullptr, void* progress_user = nullptr);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace highlift::sim
