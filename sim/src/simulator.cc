// The CVODE driver: BDF with Newton iterations; a dense, banded or sparse (KLU) direct linear
// solver with a difference-quotient Jacobian on the pattern the network structure allows
// (coloured columns for the sparse one); root finding for state events, stop times for time
// events, re-initialisation after events that change the equations.
#include "highlift/sim/simulator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/core/message_number.h"
#include "sundials_compat.h"
#include "fast_kernels.h"
#include "reduced_klu.h"
#include "system.h"

namespace highlift::sim {

using detail::System;

void SimulationOptions::Validate() const {
  auto fail = [](const std::string& what) { throw InputError("simulation option " + what); };
  if (!(stop_time > start_time))
    fail("stop_time = " + FormatMessageNumber(stop_time) + " s must be greater than start_time = " +
         FormatMessageNumber(start_time) + " s");
  if (!(output_interval > 0)) fail("output_interval must be > 0 s");
  if (!(relative_tolerance > 0 && relative_tolerance < 1))
    fail("relative_tolerance = " + FormatMessageNumber(relative_tolerance) + " must lie in (0, 1)");
  if (!(absolute_tolerance > 0)) fail("absolute_tolerance must be > 0");
  if (!(torque_tolerance >= 0)) fail("torque_tolerance must be >= 0 N*m (0: off)");
  if (!(speed_resolution >= 0 && std::isfinite(speed_resolution)))
    fail("speed_resolution must be >= 0 rad/s and finite (0: off)");
  if (max_step < 0) fail("max_step must be >= 0 (0: no limit)");
  if (!(passivity_tolerance > 0)) fail("passivity_tolerance must be > 0 (relative to the run's power scale)");
  if (linear_solver != "auto" && linear_solver != "dense" && linear_solver != "band" && linear_solver != "sparse" &&
      linear_solver != "sparse_whole")
    fail("linear_solver = '" + linear_solver + "' must be one of auto, dense, band, sparse, sparse_whole");
}

std::string ToString(SimulationStatus status) {
  switch (status) {
    case SimulationStatus::kSuccess: return "success";
    case SimulationStatus::kSolverFailure: return "solver_failure";
    case SimulationStatus::kModelError: return "model_error";
    case SimulationStatus::kTooManyEvents: return "too_many_events";
    case SimulationStatus::kInterrupted: return "interrupted";
  }
  return "unknown";
}

std::string ToString(StartKind start) { return start == StartKind::kSteadyState ? "steady_state" : "given"; }

StartKind ParseStartKind(const std::string& text) {
  if (text == "given") return StartKind::kGiven;
  if (text == "steady_state" || text == "steady-state") return StartKind::kSteadyState;
  throw InputError("unknown start '" + text + "'; choose \"given\" (the start values) or \"steady_state\" "
                   "(every inertia with a = 0, free speeds and twists solved)");
}

double EnergyBalance::Scale() const {
  return std::max({std::abs(source_work), std::abs(dissipated), impulsive_loss,
                   std::abs(kinetic_end - kinetic_start), std::abs(potential_end - potential_start),
                   std::abs(kinetic_start) + std::abs(potential_start)});
}

std::string PassivityReport::BriefReport() const {
  if (violations.empty()) return "passive";
  std::ostringstream s;
  s << violations.size() << (violations.size() == 1 ? " element" : " elements") << " with negative dissipation:";
  for (std::size_t i = 0; i < violations.size(); ++i) {
    const PassivityViolation& v = violations[i];
    s << (i == 0 ? " " : ", ") << v.element << " at " << v.time << " s (" << v.power << " W at " << v.power_time
      << " s, for " << v.duration << " s)";
  }
  return s.str();
}

std::string SimulationReport::BriefReport() const {
  std::ostringstream s;
  s << ToString(status) << ": t = " << time << " s, " << statistics.steps << " steps, "
    << events.size() << " events, " << statistics.rhs_evaluations << " f evaluations, "
    << wall_seconds << " s wall";
  if (!ok()) s << "; " << message;
  return s.str();
}

std::string SimulationReport::FullReport() const {
  std::ostringstream s;
  s << BriefReport() << "\n";
  s << "linear solver " << statistics.linear_solver << ", " << statistics.states << " states, "
    << statistics.jacobian_evaluations << " Jacobians, " << statistics.error_test_failures
    << " error-test failures, " << statistics.nonlinear_convergence_failures
    << " convergence failures, " << statistics.reinitialisations << " re-initialisations\n";
  for (const auto& e : events)
    s << "  event t = " << e.time << " (" << e.kind << ") " << e.element << " " << e.what << "\n";
  for (const auto& p : peak_torques)
    s << "  peak |tau| " << p.element << " = " << std::abs(p.tau) << " N*m at " << p.time << " s\n";
  if (energy.computed)
    s << "energy: source work " << energy.source_work << " J = kinetic "
      << energy.kinetic_end - energy.kinetic_start << " J + potential "
      << energy.potential_end - energy.potential_start << " J + dissipated " << energy.dissipated
      << " J + impulsive " << energy.impulsive_loss << " J; residual " << energy.Residual()
      << " J\n";
  s << "passivity (tolerance " << passivity.tolerance << " of " << passivity.power_scale
    << " W): " << passivity.BriefReport() << "\n";
  if (!ok()) {
    s << "failure: " << message << "\n";
    if (!sundials_flag.empty()) s << "  flag " << sundials_flag << "\n";
    if (!element.empty()) s << "  element " << element << "\n";
  }
  return s.str();
}

int MemorySink::Column(const std::string& name) const {
  for (std::size_t i = 0; i < columns_.size(); ++i)
    if (columns_[i] == name) return static_cast<int>(i);
  return -1;
}

std::vector<double> MemorySink::Series(const std::string& name) const {
  const int c = Column(name);
  if (c < 0) throw std::out_of_range("no output column '" + name + "'");
  std::vector<double> v;
  v.reserve(rows_.size());
  for (const auto& r : rows_) v.push_back(r[c]);
  return v;
}

std::string CheckStructure(const Network& network, double start_time) {
  try {
    System system(network);
    std::vector<double> y = system.InitialState(start_time);
    // The initial equations a = a_start need the initial modes (a failure there is the run's).
    if (system.HasInitialAccelerations() && system.HandleEvent(start_time, y.data(), true, nullptr, nullptr))
      system.SolveInitialAccelerations(start_time, y, false);
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

namespace {
bool StartState(System& sys, const SimulationOptions& options, std::vector<double>& y,
                std::vector<SimulationEvent>& events, std::string& error);
}  // namespace

model::StartValues ComputeStartValues(const Network& network, const SimulationOptions& options) {
  System sys(network);
  std::vector<double> y = sys.InitialState(options.start_time);
  std::vector<SimulationEvent> events;
  std::string error;
  if (!StartState(sys, options, y, events, error))
    throw InputError("the model cannot start at t = " + FormatMessageNumber(options.start_time) + " s: " + error);
  model::StartValues out;
  out.summary = "rest: the springs untwisted, the speeds the initial ones";
  for (const auto& e : events)
    if (e.element.empty()) out.summary = e.what;
  // The flanges of the network by node, an Inertia's (or a Mass's) first: its phi and w are
  // the natural start values in Modelica.
  std::vector<std::vector<PortRef>> at_node(sys.nodes().size());
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& e : network.elements()) {
      const bool body = e.type == "Inertia" || e.type == "Mass";
      if ((pass == 0) != body || e.spec == nullptr) continue;
      for (const auto& port : e.spec->ports) {
        if (port.kind != PortKind::kFlange) continue;
        const int node = sys.NodeOfPort(e.id + "." + port.name);
        if (node >= 0) at_node[node].push_back({e.id, port.name});
      }
    }
  std::vector<int> candidates;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t n = 0; n < at_node.size(); ++n) {
      if (at_node[n].empty()) continue;
      const NetworkElement* owner = network.Find(at_node[n].front().component);
      const bool body = owner != nullptr && (owner->type == "Inertia" || owner->type == "Mass");
      if ((pass == 0) == body) candidates.push_back(static_cast<int>(n));
    }
  for (const auto& s : sys.StartOfFreeNodes(y.data(), candidates, out.inconsistency)) {
    if (!s.fix_phi && !s.fix_w) {
      out.unreached.push_back(sys.nodes()[s.node].name);
      continue;
    }
    model::FlangeStart f;
    f.flange = at_node[s.node].front();
    if (s.fix_phi) f.phi = s.phi;
    if (s.fix_w) f.w = s.w;
    out.flanges.push_back(f);
  }
  return out;
}

struct Simulator::Impl {
  explicit Impl(const Network& network) : system(network) {}
  System system;
};

Simulator::Simulator(const Network& network) : impl_(std::make_unique<Impl>(network)) {}
Simulator::~Simulator() = default;

const std::vector<std::string>& Simulator::OutputNames() const {
  return impl_->system.OutputNames();
}

namespace {

/// The Jacobian by difference quotients on the sparsity pattern of the network: columns that
/// share no row are perturbed together (a greedy colouring), so one right-hand side per colour
/// gives all their columns (Curtis, Powell and Reid).
struct ColoredJacobian {
  std::vector<int> colptr, rows;         ///< the pattern (compressed columns)
  std::vector<std::vector<int>> colors;  ///< the columns of each colour
  std::vector<double> increment;         ///< per column, of the current evaluation
  double relative_tolerance = 1e-6;      ///< the run's (scales the increments of states at rest)
  N_Vector work_y = nullptr, work_f = nullptr, weights = nullptr;
  long rhs_evaluations = 0;
  bool mode_colouring = true;  ///< SimulationOptions::mode_colouring
  /// The KLU solver and its matrix, re-pivoted after a failed refactorisation (SparseJacobian).
  SUNLinearSolver klu = nullptr;
  SUNMatrix matrix = nullptr;
  /// The solver that eliminates the angles and twists (reduced_klu.h), given J and gamma, and
  /// whether CVODE's matrix holds a whole Jacobian for it (not before the first evaluation nor
  /// after one that failed).
  SUNLinearSolver reduced = nullptr;
  bool jacobian_in_matrix = false;

  void Build(const std::vector<int>& pattern_colptr, const std::vector<int>& pattern_rows) {
    colptr = pattern_colptr;
    rows = pattern_rows;
    colors = detail::ColourColumns(colptr, rows);
    increment.assign(colptr.size() - 1, 0.0);
  }
  ~ColoredJacobian() {
    if (work_y != nullptr) N_VDestroy(work_y);
    if (work_f != nullptr) N_VDestroy(work_f);
    if (weights != nullptr) N_VDestroy(weights);
  }
};

struct CallbackData {
  System* system = nullptr;
  void* cvode = nullptr;
  ColoredJacobian* jacobian = nullptr;
  std::string message;
  std::string element;
  std::string cvode_message;  ///< last message of CVODE's error handler
  // The tolerances of CVODE's error weights (ErrorWeightsFn).
  double relative_tolerance = 0.0;
  std::vector<double> absolute_tolerances;
  bool absolute_tolerance_zero = false;  ///< some absolute tolerance is 0
};

// CVODE's error weights 1 / (rtol |y_i| + atol_i), at every step: those of CVodeSVtolerances,
// the same doubles, in one pass over the states instead of three (detail::ErrorWeights).
int ErrorWeightsFn(N_Vector y, N_Vector ewt, void* user) {
  auto* data = static_cast<CallbackData*>(user);
  const double* yd = N_VGetArrayPointer(y);
  const std::size_t n = data->absolute_tolerances.size();
  if (static_cast<std::size_t>(N_VGetLength(y)) != n) return -1;
  if (detail::ErrorWeights(n, data->relative_tolerance, data->absolute_tolerances.data(),
                           data->absolute_tolerance_zero, yd, N_VGetArrayPointer(ewt)))
    return 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!(data->relative_tolerance * std::abs(yd[i]) + data->absolute_tolerances[i] > 0.0)) {
      const auto& names = data->system->StateNames();
      data->message = "the error weight 1 / (rtol |y| + atol) of state '" +
                      (i < names.size() ? names[i] : std::to_string(i)) + "' is undefined: its absolute tolerance is " +
                      FormatMessageNumber(data->absolute_tolerances[i]) + " and its value " + FormatMessageNumber(yd[i]);
      break;
    }
  return -1;
}

// CVODE's messages go into the report instead of stderr.
void ErrorHandler(int error_code, const char* module, const char* function, char* msg, void* user) {
  auto* data = static_cast<CallbackData*>(user);
  if (error_code < 0)
    data->cvode_message = std::string(module ? module : "") + "." + (function ? function : "") + ": " +
                          (msg ? msg : "");
}

int Rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  auto* data = static_cast<CallbackData*>(user);
  try {
    if (!data->system->Evaluate(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot))) {
      data->message = data->system->error();
      data->element = data->system->error_element();
      return -1;
    }
    return 0;
  } catch (const std::exception& ex) {
    data->message = std::string("right-hand side: ") + ex.what();
    return -1;
  } catch (...) {
    data->message = "right-hand side: unknown exception";
    return -1;
  }
}

// The sparse Jacobian by difference quotients, one right-hand side per colour. Increment:
// sqrt(unit roundoff) times the larger of |y_j| and the size below which state j needs no
// relative accuracy, (rtol*|y_j| + atol_j)/rtol = 1/(rtol*ewt_j): a state at rest (a stuck
// brake's shaft, y_j = 0) is then perturbed well above the roundoff of the large torques that
// balance at its node. CVODE's own minimum increment (from the step and the norm of f) is kept.
int SparseJacobian(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector, N_Vector,
                   N_Vector) {
  auto* data = static_cast<CallbackData*>(user);
  ColoredJacobian& jac = *data->jacobian;
  try {
    const int n = static_cast<int>(N_VGetLength(y));
    if (CVodeGetErrWeights(data->cvode, jac.weights) != CV_SUCCESS) return -1;
    sunrealtype h = 0.0;
    CVodeGetCurrentStep(data->cvode, &h);
    const double roundoff = std::numeric_limits<double>::epsilon();
    const double srur = std::sqrt(roundoff);
    const double fnorm = N_VWrmsNorm(fy, jac.weights);
    const double min_inc = fnorm != 0.0 ? 1000.0 * std::abs(h) * roundoff * n * fnorm : 1.0;
    // KLU refactors every new matrix with the pivot order of its first factorisation, and SUNDIALS
    // 6.4 reports a zero pivot on that order as a recoverable setup failure without pivoting
    // afresh; CVODE then retries smaller steps on the same pivots until CV_CONV_FAILURE (the
    // A380-class jam_l2 at Sobol point 13, full model, rtol 1e-5, all its brakes stuck). After such
    // a failure the next factorisation starts from scratch (analysis and pivoting).
    long last_setup = SUNLS_SUCCESS;
    if (jac.klu && CVodeGetLastLinFlag(data->cvode, &last_setup) == CV_SUCCESS && last_setup == SUNLS_PACKAGE_FAIL_REC &&
        SUNLinSol_KLUReInit(jac.klu, jac.matrix, static_cast<sunindextype>(jac.rows.size()), SUNKLU_REINIT_PARTIAL) !=
            SUNLS_SUCCESS)
      return -1;
    const double* yv = N_VGetArrayPointer(y);
    const double* fv = N_VGetArrayPointer(fy);
    const double* wv = N_VGetArrayPointer(jac.weights);
    double* yp = N_VGetArrayPointer(jac.work_y);
    double* fp = N_VGetArrayPointer(jac.work_f);
    sunindextype* colptr = SUNSparseMatrix_IndexPointers(J);
    sunindextype* rowind = SUNSparseMatrix_IndexValues(J);
    double* values = SUNSparseMatrix_Data(J);
    for (int j = 0; j <= n; ++j) colptr[j] = jac.colptr[j];
    for (std::size_t k = 0; k < jac.rows.size(); ++k) rowind[k] = jac.rows[k];
    std::copy(yv, yv + n, yp);
    // The colouring of the mode of the last evaluation, while every perturbed evaluation stays
    // in that mode: the entries outside the mode's pattern are zero (their difference quotients
    // would be exactly zero), the others the same quotients as the superset's colouring gives.
    // Should an evaluation change the mode (a friction branch reassumed), the superset's.
    const System::ModePattern* mode = jac.mode_colouring ? data->system->ModeJacobianPattern() : nullptr;
    for (bool done = false; !done;) {
      done = true;
      for (const auto& group : mode != nullptr ? mode->colours : jac.colors) {
        for (int j : group) {
          const double inc =
              std::max({srur * std::abs(yv[j]), srur / (jac.relative_tolerance * wv[j]), min_inc / wv[j]});
          // The increment that is actually represented in floating point.
          yp[j] = yv[j] + inc;
          jac.increment[j] = yp[j] - yv[j];
        }
        ++jac.rhs_evaluations;
        if (!data->system->Evaluate(t, yp, fp)) {
          data->message = data->system->error();
          data->element = data->system->error_element();
          return 1;  // recoverable: CVODE retries with a smaller step
        }
        if (mode != nullptr && !data->system->InMode(*mode)) {
          for (int j : group) yp[j] = yv[j];
          mode = nullptr;
          done = false;
          break;
        }
        for (int j : group) {
          const double inv = 1.0 / jac.increment[j];
          for (int k = jac.colptr[j]; k < jac.colptr[j + 1]; ++k) {
            const int i = jac.rows[k];
            values[k] = mode == nullptr || mode->entry[k] ? (fp[i] - fv[i]) * inv : 0.0;
          }
          yp[j] = yv[j];
        }
      }
    }
    return 0;
  } catch (const std::exception& ex) {
    data->message = std::string("Jacobian: ") + ex.what();
    return -1;
  } catch (...) {
    data->message = "Jacobian: unknown exception";
    return -1;
  }
}

/// CVODE's linear system for the solver that eliminates the angles and twists: the Jacobian
/// by SparseJacobian when CVODE asks for a new one (jok false), kept in CVODE's matrix A between
/// them (nothing else writes A), and gamma handed to the solver, which forms I - gamma*J as it
/// reads J. CVODE's own version copies its saved J into A and scales A at every setup. A
/// Jacobian that failed half-way is not kept: the next setup evaluates one whatever CVODE says.
int ReducedLinearSystem(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix A, sunbooleantype jok,
                        sunbooleantype* jcur, sunrealtype gamma, void* user, N_Vector tmp1, N_Vector tmp2,
                        N_Vector tmp3) {
  ColoredJacobian& jac = *static_cast<CallbackData*>(user)->jacobian;
  const bool fresh = !jok || !jac.jacobian_in_matrix;
  *jcur = fresh ? SUNTRUE : SUNFALSE;
  if (fresh) {
    jac.jacobian_in_matrix = false;
    const int flag = SparseJacobian(t, y, fy, A, user, tmp1, tmp2, tmp3);
    if (flag != 0) return flag;
    jac.jacobian_in_matrix = true;
  }
  detail::ReducedKluSetGamma(jac.reduced, gamma);
  return 0;
}

/// Whether a root function changed sign from `before` to `after` in the allowed direction
/// (CVodeSetRootDirection: 0 either, 1 rising, -1 falling); marks them in `info` (+1 rising,
/// -1 falling, as CVodeGetRootInfo). A function that is exactly zero before is not a crossing.
/// Only the roots listed in `roots` (those of one kind) are looked at; the others get info 0.
bool SignChanged(const std::vector<double>& before, const std::vector<double>& after, const std::vector<int>& direction,
                 std::vector<int>& info, const std::vector<int>& roots) {
  std::fill(info.begin(), info.end(), 0);
  bool any = false;
  for (const int i : roots) {
    if (before[i] == 0.0) continue;
    const bool rising = before[i] < 0.0 && after[i] >= 0.0;
    const bool falling = before[i] > 0.0 && after[i] <= 0.0;
    if ((rising && direction[i] >= 0) || (falling && direction[i] <= 0)) {
      info[i] = rising ? 1 : -1;
      any = true;
    }
  }
  return any;
}

// The start of a run, shared by Simulator::Run and ComputeStartValues: the initial event (modes
// at t0, consistent speeds), the initial equations on accelerations and, with
// options.initial_equilibrium, the static equilibrium and
// the event iteration at it. `y` holds InitialState on entry and the start on return; false
// with `error` when the model cannot start.
bool StartState(System& sys, const SimulationOptions& options, std::vector<double>& y,
                std::vector<SimulationEvent>& events, std::string& error) {
  std::vector<std::string> changes, who;
  if (!sys.HandleEvent(options.start_time, y.data(), true, &changes, &who)) {
    error = sys.error();
    return false;
  }
  for (std::size_t i = 0; i < who.size(); ++i) events.push_back({options.start_time, "initial", who[i], changes[i]});
  // The initial equations on accelerations (a_start, or every one 0 for a steady-state start),
  // then the modes again at the new start values, without recording those mode changes.
  const std::string accelerations =
      sys.SolveInitialAccelerations(options.start_time, y, options.start == StartKind::kSteadyState);
  if (!accelerations.empty()) {
    changes.clear();
    who.clear();
    if (!sys.HandleEvent(options.start_time, y.data(), true, &changes, &who)) {
      error = sys.error();
      return false;
    }
    events.push_back({options.start_time, "initial", "", accelerations});
  }
  if (!options.initial_equilibrium) return true;
  bool found = false;
  const double imbalance = sys.SolveEquilibrium(options.start_time, y.data(), found);
  std::ostringstream what;
  if (found) {
    what << "static equilibrium: loads balanced to " << imbalance << " N*m";
    changes.clear();
    who.clear();
    if (!sys.HandleEvent(options.start_time, y.data(), true, &changes, &who)) {
      error = sys.error();
      return false;
    }
  } else {
    what << "no static equilibrium (largest torque imbalance " << imbalance << " N*m): the springs start untwisted";
  }
  events.push_back({options.start_time, "initial", "", what.str()});
  return true;
}

// What a sample of the run is: a step end (or an event's limit, or the start), where the
// solution is smooth on both sides; a kink (a root crossed without a restart: an actuator
// reversing, a backlash contact), where the torques are continuous but their slopes are not;
// an output point on the interpolant, which only the energy balance reads.
enum class SampleKind { kStepEnd, kKink, kOutputPoint };

// The two samples before the current one within one smooth stretch of the run (no restart
// between them), for locating the peaks between samples.
struct PeakTrack {
  int samples = 0;             ///< in the stretch so far, counted up to 2
  bool middle_smooth = false;  ///< the last sample is not a kink: it may be a parabola's middle
  double t1 = 0.0, t2 = 0.0;   ///< times of the samples before the last one and of the last one
  std::vector<double> v1, v2;  ///< the elements' torques there
  /// Takes the new sample's torques by swapping buffers, not copying them: `tau` is left with
  /// the oldest sample's buffer, which the next readings overwrite (System::StepEndReadings
  /// writes every element with readings; the others hold NaN in every buffer).
  void Push(double t, std::vector<double>& tau, bool smooth) {
    v1.swap(v2);
    v2.swap(tau);
    t1 = t2;
    t2 = t;
    samples = std::min(samples + 1, 2);
    middle_smooth = smooth;
  }
  void Restart() { samples = 0; }  ///< an event restarts the integration: a new stretch
};

// The peak of |tau| between three consecutive samples (t0, v0), (t1, v1), (t2, v2) of a smooth
// stretch, when |v1| is the largest of the three and all have one sign: the vertex of the
// parabola through them. The vertex replaces `peak` when it is larger and it rises above |v1|
// by no more than the samples' own variation |v1| - min(|v0|, |v2|): a larger rise is the
// parabola's, not the solution's (very unequal spacing, or samples that differ by their
// roundoff on a flat top), and the sampled peak stands then. For a smooth maximum the located
// value's error falls with the cube of the spacing instead of its square.
void LocatePeak(double t0, double v0, double t1, double v1, double t2, double v2, PeakTorque& peak) {
  if (!(v0 * v1 > 0.0 && v2 * v1 > 0.0)) return;  // (NaN or a sign change: no vertex)
  const double a0 = std::abs(v0), a1 = std::abs(v1), a2 = std::abs(v2);
  if (!(a1 >= a0 && a1 >= a2 && t0 < t1 && t1 < t2)) return;
  const double d01 = (a1 - a0) / (t1 - t0), d12 = (a2 - a1) / (t2 - t1);
  const double c = (d12 - d01) / (t2 - t0);  // half the parabola's second derivative
  if (!(c < 0.0)) return;                     // a straight line: the sample is the peak
  const double t_peak = std::clamp(0.5 * (t0 + t1) - 0.5 * d01 / c, t0, t2);
  const double a_peak = a0 + d01 * (t_peak - t0) + c * (t_peak - t0) * (t_peak - t1);
  if (!(a_peak > std::abs(peak.tau)) || a_peak - a1 > a1 - std::min(a0, a2)) return;
  peak.tau = std::copysign(a_peak, v1);
  peak.time = t_peak;
}

class Cvode {
 public:
  Cvode() = default;
  ~Cvode() {
    if (mem != nullptr) CVodeFree(&mem);
    if (ls != nullptr) SUNLinSolFree(ls);
    if (A != nullptr) SUNMatDestroy(A);
    if (y != nullptr) N_VDestroy(y);
  }
  detail::SundialsContext ctx;
  void* mem = nullptr;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver ls = nullptr;
};

}  // namespace

SimulationReport Simulator::Run(const SimulationOptions& options, OutputSink& sink,
                                ProgressCallback progress, void* progress_user) {
  // SIGINT/SIGTERM set InterruptRequested(): the step loop below stops after the current step
  // (an interruption during the set-up stops it before the first step) and the sink gets End().
  const InterruptibleScope interruptible;
  options.Validate();
  const auto wall_start = std::chrono::steady_clock::now();
  System& sys = impl_->system;
  SimulationReport report;
  report.time = options.start_time;
  const int n = sys.NumStates();
  report.statistics.states = n;
  const auto& elements = sys.elements();

  std::vector<double> y0 = sys.InitialState(options.start_time);
  std::vector<double> out(sys.OutputNames().size());
  for (const auto& el : elements) report.peak_torques.push_back({el->id, 0.0, options.start_time});
  std::vector<char> has_torque(elements.size(), 0);  // (not vector<bool>: set at every sample)

  auto fail = [&](SimulationStatus status, std::string message, double t) {
    report.status = status;
    report.message = std::move(message);
    report.time = t;
  };
  // The passivity monitor (PassivityReport): per element the open episode of negative
  // dissipated power and the worst closed episode that lasted longer than one step.
  struct Episode {
    bool open = false;
    int samples = 0;
    double start = 0.0, last = 0.0, min_power = 0.0, min_time = 0.0;
  };
  std::vector<Episode> open_episode(elements.size()), worst_episode(elements.size());
  std::vector<int> episode_count(elements.size(), 0);
  int episodes_open = 0;
  report.passivity.tolerance = options.passivity_tolerance;
  auto close_episode = [&](std::size_t i) {
    Episode& e = open_episode[i];
    if (e.open) --episodes_open;
    if (e.samples >= 2) {
      ++episode_count[i];
      if (worst_episode[i].samples == 0 || e.min_power < worst_episode[i].min_power) worst_episode[i] = e;
    }
    e = Episode{};
  };
  // What a sample reads from an evaluation: the elements' peak torques, dissipated powers (with
  // the passivity monitor's power scale) and the energy state. A step end's are read from
  // CVODE's own evaluation of it before the step's output points are evaluated (below).
  struct Readings {
    std::vector<double> tau, loss;
    double loss_scale = 0.0;
    double loss_min = INFINITY;  ///< the smallest of `loss` (System::StepEndReadings)
    System::EnergyState energy;
  };
  auto read = [&](Readings& r, SampleKind kind) {
    if (kind != SampleKind::kOutputPoint) {
      r.loss_scale = sys.StepEndReadings(r.loss, r.tau, r.loss_min);
    }
    if (options.energy) r.energy = sys.Energy();
  };
  const std::vector<int>& readings_of = sys.ReadingElements();
  auto monitor = [&](double t, const std::vector<double>& loss, double loss_scale, double loss_min) {
    report.passivity.power_scale = std::max(report.passivity.power_scale, loss_scale);
    const double threshold = -options.passivity_tolerance * report.passivity.power_scale;
    // Mostly no episode is open and no power is below the threshold: the smallest power tells
    // (the elements without readings hold 0, not below a threshold of -0 or less), and the loop
    // over the elements is left out.
    if (episodes_open == 0 && !(loss_min < threshold)) return;
    for (const int reading : readings_of) {  // (the others dissipate nothing: System::ReadingElements)
      const auto i = static_cast<std::size_t>(reading);
      Episode& e = open_episode[i];
      if (loss[i] < threshold) {
        if (!e.open) {
          e = {true, 0, t, t, loss[i], t};
          ++episodes_open;
        }
        ++e.samples;
        e.last = t;
        if (loss[i] < e.min_power) e.min_power = loss[i], e.min_time = t;
      } else if (e.open) {
        close_episode(i);
      }
    }
  };
  SUNLinearSolver reduced_solver = nullptr;  // the sparse solver that eliminates states, if used
  auto finish = [&] {
    const long whole = reduced_solver != nullptr ? detail::ReducedKluFullSetups(reduced_solver) : 0;
    if (whole > 0) {
      std::string& name = report.statistics.linear_solver;
      name.insert(name.size() - 1, "; " + std::to_string(whole) + " setups factored whole");
    }
    const double threshold = -options.passivity_tolerance * report.passivity.power_scale;
    for (std::size_t i = 0; i < elements.size(); ++i) {
      if (open_episode[i].open) close_episode(i);
      const Episode& e = worst_episode[i];
      if (e.samples >= 2 && e.min_power < threshold)
        report.passivity.violations.push_back(
            {elements[i]->id, e.start, e.last - e.start, e.min_power, e.min_time, episode_count[i]});
    }
    std::vector<PeakTorque> peaks;
    for (std::size_t i = 0; i < elements.size(); ++i)
      if (has_torque[i]) peaks.push_back(report.peak_torques[i]);
    report.peak_torques = std::move(peaks);
    report.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    sink.End();
    return report;
  };
  const std::size_t n_element_outputs = sys.OutputNames().size();
  std::vector<std::string> columns = sys.OutputNames();
  if (options.energy) {
    for (const char* name : {"energy.kinetic", "energy.potential", "energy.loss_power",
                             "energy.source_power", "energy.impulsive_loss"})
      columns.push_back(name);
    out.resize(columns.size());
    report.energy.computed = true;
  }
  // Peak torques follow the solution at every integrator step end and at both limits of every
  // event, and are located between them (PeakTrack); they do not depend on the output interval
  // nor on whether the rows are written. The energy balance also reads the output points when
  // it is asked for; output rows are interpolated on the output grid.
  bool first_sample = true;
  double last_t = options.start_time, last_loss = 0.0, last_source = 0.0, impulsive_base = 0.0;
  PeakTrack track;
  auto record = [&](double t, Readings& r, SampleKind kind) {
    if (kind != SampleKind::kOutputPoint) {
      monitor(t, r.loss, r.loss_scale, r.loss_min);
      // (Raw pointers: the store into has_torque, a char, could otherwise alias every vector's
      // own pointers, which the loop would then load again for each element.)
      const double* const tau = r.tau.data();
      char* const has = has_torque.data();
      PeakTorque* const peaks = report.peak_torques.data();  // each element named once, at the start
      const bool locate = track.samples >= 2 && track.middle_smooth;
      const double* const before = track.v1.data();
      const double* const middle = track.v2.data();
      for (const int reading : readings_of) {  // (the others carry no torque)
        const auto i = static_cast<std::size_t>(reading);
        const double v = tau[i];
        if (std::isnan(v)) continue;
        has[i] = 1;
        const double a = std::abs(v), a_peak = std::abs(peaks[i].tau);
        if (a > a_peak) {
          peaks[i].tau = v;
          peaks[i].time = t;
        }
        if (!locate) continue;
        // (A located value is at most 2 |middle|: only a middle sample above half the peak and
        // not below the new one can raise it.)
        const double a_middle = std::abs(middle[i]);
        if (a_middle >= a && 2.0 * a_middle > a_peak) LocatePeak(track.t1, before[i], track.t2, middle[i], t, v, peaks[i]);
      }
      track.Push(t, r.tau, kind == SampleKind::kStepEnd);
    }
    if (!options.energy) return;
    const System::EnergyState& energy_now = r.energy;
    EnergyBalance& b = report.energy;
    if (first_sample) {
      impulsive_base = sys.impulsive_loss();  // the initial projection precedes the balance
      b.kinetic_start = energy_now.kinetic;
      b.potential_start = energy_now.potential;
    } else {
      const double h = t - last_t;
      b.dissipated += 0.5 * h * (energy_now.loss_power + last_loss);
      b.source_work += 0.5 * h * (energy_now.source_power + last_source);
    }
    b.kinetic_end = energy_now.kinetic;
    b.potential_end = energy_now.potential;
    b.impulsive_loss = sys.impulsive_loss() - impulsive_base;
    first_sample = false;
    last_t = t;
    last_loss = energy_now.loss_power;
    last_source = energy_now.source_power;
  };
  Readings now;
  auto sample = [&](double t, SampleKind kind = SampleKind::kStepEnd) {
    read(now, kind);
    record(t, now, kind);
  };
  // A row of the evaluated state at t (an output point or an event limit); the values only for
  // a sink that reads them (the CLI without --out and the campaign count or discard the rows).
  const bool reads_values = sink.ReadsValues();
  const bool evaluate_outputs = reads_values || options.energy;
  auto write_row = [&](double t) {
    if (reads_values) sys.Outputs(out.data());
    if (reads_values && options.energy) {
      const System::EnergyState s = sys.Energy();
      double* x = out.data() + n_element_outputs;
      x[0] = s.kinetic;
      x[1] = s.potential;
      x[2] = s.loss_power;
      x[3] = s.source_power;
      x[4] = report.energy.impulsive_loss;
    }
    sink.Row(t, out);
  };
  // Both at once: the solution point itself (initial state, event limits, step ends on the grid).
  auto sample_and_row = [&](double t) {
    sample(t);
    write_row(t);
  };

  sink.Begin(columns);
  // Initial event: modes at t0, consistent speeds; the static equilibrium if asked for.
  {
    std::vector<SimulationEvent> initial;
    std::string error;
    if (!StartState(sys, options, y0, initial, error)) {
      report.events.insert(report.events.end(), initial.begin(), initial.end());
      report.element = sys.error_element();
      fail(SimulationStatus::kModelError, error, options.start_time);
      return finish();
    }
    report.events.insert(report.events.end(), initial.begin(), initial.end());
    sample_and_row(options.start_time);
    HIGHLIFT_CHECK(sys.ReadingsAsDeclared(), "an element without readings (Element::HasReadings) reads a torque or a power");
    sys.AfterEventRow();
  }
  if (n == 0) {
    fail(SimulationStatus::kModelError,
         "the network has no states (no inertia, no compliant element); nothing to integrate",
         options.start_time);
    return finish();
  }

  Cvode cv;
  CallbackData data;
  data.system = &sys;
  auto check = [&](int flag, const char* call, double t) {
    if (flag >= 0) return true;
    report.sundials_flag = detail::CvodeFlagName(flag);
    std::string msg = std::string(call) + " failed with " + report.sundials_flag + " at t = " +
                      FormatMessageNumber(t) + " s";
    if (!data.message.empty()) msg += ": " + data.message;
    else if (!data.cvode_message.empty()) msg += ": " + data.cvode_message;
    if (!data.element.empty()) report.element = data.element;
    fail(SimulationStatus::kSolverFailure, msg, t);
    return false;
  };
  auto check_ptr = [&](const void* p, const char* call) {
    if (p != nullptr) return true;
    report.sundials_flag = "NULL";
    fail(SimulationStatus::kSolverFailure, std::string(call) + " returned NULL (out of memory?)",
         options.start_time);
    return false;
  };

  cv.y = N_VNew_Serial(n, cv.ctx);
  if (!check_ptr(cv.y, "N_VNew_Serial")) return finish();
  detail::InstallFastVectorOps(cv.y);  // CVODE's vectors are clones of it (fast_kernels.h)
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(cv.y));
  cv.mem = CVodeCreate(CV_BDF, cv.ctx);
  if (!check_ptr(cv.mem, "CVodeCreate")) return finish();
  double t = options.start_time;
  if (!check(CVodeInit(cv.mem, Rhs, t, cv.y), "CVodeInit", t)) return finish();
  if (!check(CVodeSetUserData(cv.mem, &data), "CVodeSetUserData", t)) return finish();
  if (!check(CVodeSetErrHandlerFn(cv.mem, ErrorHandler, &data), "CVodeSetErrHandlerFn", t))
    return finish();
  {
    const std::vector<double> atol =
        sys.AbsoluteTolerances(options.absolute_tolerance, options.torque_tolerance,
                               options.relative_tolerance * options.speed_resolution);
    // The weights from our function: CVodeSVtolerances', the same doubles. (Its checks that no
    // tolerance is negative hold by construction: SimulationOptions::Validate makes rtol and
    // atol positive, and AbsoluteTolerances scales atol by magnitudes and stiffnesses.)
    data.relative_tolerance = options.relative_tolerance;
    data.absolute_tolerances = atol;
    data.absolute_tolerance_zero = std::any_of(atol.begin(), atol.end(), [](double a) { return a == 0.0; });
    if (!check(CVodeWFtolerances(cv.mem, ErrorWeightsFn), "CVodeWFtolerances", t)) return finish();
  }
  if (!check(CVodeSetMaxNumSteps(cv.mem, options.max_steps_per_output), "CVodeSetMaxNumSteps", t))
    return finish();
  if (options.stability_limit_detection && !check(CVodeSetStabLimDet(cv.mem, SUNTRUE), "CVodeSetStabLimDet", t))
    return finish();
  if (options.max_step > 0 && !check(CVodeSetMaxStep(cv.mem, options.max_step), "CVodeSetMaxStep", t))
    return finish();
  const int mu = std::min(sys.upper_bandwidth(), n - 1), ml = std::min(sys.lower_bandwidth(), n - 1);
  const bool sparse = options.linear_solver == "sparse" || options.linear_solver == "sparse_whole" ||
                      (options.linear_solver == "auto" && n > 60);
  const bool band = options.linear_solver == "band";
  ColoredJacobian colored;
  data.cvode = cv.mem;
  if (sparse) {
    colored.Build(sys.jacobian_colptr(), sys.jacobian_rows());
    colored.relative_tolerance = options.relative_tolerance;
    colored.mode_colouring = options.mode_colouring;
    colored.work_y = N_VClone(cv.y);
    colored.work_f = N_VClone(cv.y);
    colored.weights = N_VClone(cv.y);
    if (!check_ptr(colored.work_y, "N_VClone") || !check_ptr(colored.work_f, "N_VClone") ||
        !check_ptr(colored.weights, "N_VClone"))
      return finish();
    data.jacobian = &colored;
    cv.A = SUNSparseMatrix(n, n, static_cast<sunindextype>(colored.rows.size()), CSC_MAT, cv.ctx);
    if (!check_ptr(cv.A, "SUNSparseMatrix")) return finish();
    detail::InstallFastSparseOps(cv.A);
    // The angles and twists eliminated before KLU factors the rest (reduced_klu.h), unless
    // the whole matrix is asked for or nothing can be eliminated.
    if (options.linear_solver != "sparse_whole")
      cv.ls = detail::NewReducedKlu(colored.colptr, colored.rows, sys.SpeedRows(), cv.ctx);
    std::string reduced;
    if (cv.ls != nullptr) {
      reduced_solver = cv.ls;
      colored.reduced = cv.ls;
      reduced = ", " + std::to_string(n - detail::ReducedKluSize(cv.ls)) + " of " + std::to_string(n) +
                " states eliminated";
    } else {
      cv.ls = SUNLinSol_KLU(cv.y, cv.A, cv.ctx);
      if (!check_ptr(cv.ls, "SUNLinSol_KLU")) return finish();
      // Fill-reducing ordering AMD (0) rather than KLU's default COLAMD (1): the pattern is
      // structurally symmetric (the node groups' cliques), where AMD gives less fill; the drive
      // models' refactorisations and solves take about 8 % less time (docs/performance.md).
      if (!check(SUNLinSol_KLUSetOrdering(cv.ls, 0), "SUNLinSol_KLUSetOrdering", t)) return finish();
      colored.klu = cv.ls;
      colored.matrix = cv.A;
    }
    report.statistics.linear_solver = "sparse(KLU, " + std::to_string(colored.rows.size()) + " entries, " +
                                      std::to_string(colored.colors.size()) + " colours" + reduced + ")";
  } else if (band) {
    cv.A = SUNBandMatrix(n, mu, ml, cv.ctx);
    if (!check_ptr(cv.A, "SUNBandMatrix")) return finish();
    cv.ls = SUNLinSol_Band(cv.y, cv.A, cv.ctx);
    if (!check_ptr(cv.ls, "SUNLinSol_Band")) return finish();
    report.statistics.linear_solver = "band(" + std::to_string(mu) + "," + std::to_string(ml) + ")";
  } else {
    cv.A = SUNDenseMatrix(n, n, cv.ctx);
    if (!check_ptr(cv.A, "SUNDenseMatrix")) return finish();
    cv.ls = SUNLinSol_Dense(cv.y, cv.A, cv.ctx);
    if (!check_ptr(cv.ls, "SUNLinSol_Dense")) return finish();
    report.statistics.linear_solver = "dense";
  }
  if (!check(CVodeSetLinearSolver(cv.mem, cv.ls, cv.A), "CVodeSetLinearSolver", t)) return finish();
  if (sparse && colored.reduced != nullptr) {
    if (!check(CVodeSetLinSysFn(cv.mem, ReducedLinearSystem), "CVodeSetLinSysFn", t)) return finish();
  } else if (sparse && !check(CVodeSetJacFn(cv.mem, SparseJacobian), "CVodeSetJacFn", t)) {
    return finish();
  }
  // State events are found here, not by CVODE: the root functions are compared at every step's
  // end (and at the output points a long step passes) with their values at the last sample, and
  // a crossing is located on CVODE's interpolant (locate_crossing). The model is evaluated at
  // every step's end anyway, for the peaks, so the comparison costs no evaluation of its own;
  // CVODE's root finding would evaluate the same point and scan every function after every
  // step once more. The kinematic roots (System::KinematicRoot: functions of the node speeds and
  // angles, no restart) are compared and located from the states alone, without evaluating the
  // model (a jammed actuator's input speed reverses hundreds of times).
  const int n_roots = sys.NumRoots();
  std::vector<int> root_info(std::max(n_roots, 1)), directions(std::max(n_roots, 1));
  // The roots of each kind: roots_of[1] the kinematic ones, roots_of[0] those that need the model.
  std::vector<int> roots_of[2];
  for (int k = 0; k < n_roots; ++k) roots_of[sys.KinematicRoot(k) ? 1 : 0].push_back(k);
  const int n_state_roots = static_cast<int>(roots_of[0].size());
  const bool has_kinematic_roots = n_state_roots < n_roots;
  const bool has_state_roots = n_state_roots > 0;
  long root_evaluations = 0;  // the model evaluated for its root functions (step ends, location)
  // The directions follow the discrete state: set at the start and after every event.
  auto set_directions = [&] {
    if (n_roots > 0) sys.RootDirections(directions.data());
  };
  set_directions();

  auto accumulate = [&] {
    long v = 0;
    SolverStatistics& s = report.statistics;
    if (CVodeGetNumSteps(cv.mem, &v) == CV_SUCCESS) s.steps += v;
    if (CVodeGetNumRhsEvals(cv.mem, &v) == CV_SUCCESS) s.rhs_evaluations += v;
    if (CVodeGetNumJacEvals(cv.mem, &v) == CV_SUCCESS) s.jacobian_evaluations += v;
    if (CVodeGetNumLinRhsEvals(cv.mem, &v) == CV_SUCCESS) s.rhs_evaluations += v;
    if (CVodeGetNumNonlinSolvIters(cv.mem, &v) == CV_SUCCESS) s.nonlinear_iterations += v;
    if (CVodeGetNumErrTestFails(cv.mem, &v) == CV_SUCCESS) s.error_test_failures += v;
    if (CVodeGetNumNonlinSolvConvFails(cv.mem, &v) == CV_SUCCESS)
      s.nonlinear_convergence_failures += v;
    s.root_evaluations += root_evaluations;
    root_evaluations = 0;
    s.rhs_evaluations += colored.rhs_evaluations;  // the sparse Jacobian's own
    colored.rhs_evaluations = 0;
  };
  auto record_failure_state = [&] {
    double* yv = N_VGetArrayPointer(cv.y);
    const auto& names = sys.StateNames();
    for (int i = 0; i < n && i < 200; ++i) report.state.push_back({names[i], yv[i]});
    // The state with the largest weighted local error names the element in trouble.
    N_Vector err = N_VClone(cv.y), weights = N_VClone(cv.y);
    if (err != nullptr && weights != nullptr && CVodeGetEstLocalErrors(cv.mem, err) == CV_SUCCESS &&
        CVodeGetErrWeights(cv.mem, weights) == CV_SUCCESS && report.element.empty()) {
      double worst = -1;
      int at = -1;
      for (int i = 0; i < n; ++i) {
        const double v = std::abs(N_VGetArrayPointer(err)[i] * N_VGetArrayPointer(weights)[i]);
        if (v > worst) worst = v, at = i;
      }
      if (at >= 0) {
        const std::string& s = names[at];
        report.element = s.substr(0, s.find('.'));
      }
    }
    if (err != nullptr) N_VDestroy(err);
    if (weights != nullptr) N_VDestroy(weights);
  };
  // A step's return that waits while a kinematic root inside the step is handled first (the
  // step ends at t, the root at t_root < t; CVODE itself stays at the end of its step).
  struct PendingReturn {
    bool active = false;
    double t = 0.0;
    int flag = CV_SUCCESS;
    std::vector<double> y;
  } pending;
  // The stop time last given to CVODE (NAN: none). CVodeReInit forgets it (SUNDIALS 6.4), so
  // every re-initialisation resets this and the next step sets it again: without that a step
  // after an event could pass t_end (seen: a stuck gear from 0.84 s stepped to 1.58 s past a
  // stop time of 0.9 s, and the output loop then wrote rows at t_end without end).
  double stop_set = NAN;
  auto handle_event = [&](double te, const char* kind, const std::string& what,
                          const int* fired) {
    pending.active = false;  // the integrator restarts at te
    write_row(te);  // left limit (state and modes before the event), sampled at the step end
    std::vector<std::string> changes, who;
    double* yv = N_VGetArrayPointer(cv.y);
    if (!sys.HandleEvent(te, yv, false, &changes, &who, fired)) {
      report.element = sys.error_element();
      record_failure_state();
      fail(SimulationStatus::kModelError, sys.error(), te);
      return false;
    }
    if (who.empty()) report.events.push_back({te, kind, "", what});
    for (std::size_t i = 0; i < who.size(); ++i) report.events.push_back({te, kind, who[i], changes[i]});
    track.Restart();  // the integration restarts here: the peaks are not located across it
    sample_and_row(te);  // right limit
    sys.AfterEventRow();
    if (static_cast<int>(report.events.size()) > options.max_events) {
      fail(SimulationStatus::kTooManyEvents,
           "more than " + std::to_string(options.max_events) +
               " events (chattering?); increase max_events or check the friction parameters",
           te);
      return false;
    }
    accumulate();
    ++report.statistics.reinitialisations;
    if (!check(CVodeReInit(cv.mem, te, cv.y), "CVodeReInit", te)) return false;
    stop_set = NAN;
    set_directions();
    return true;
  };

  // One step at a time (CV_ONE_STEP): every step end is sampled; the output points it passed
  // are interpolated (CVodeGetDky); time events are stop times, state events roots.
  const double t0 = options.start_time, t_end = options.stop_time, dt = options.output_interval;
  // Time tolerance: below the output interval, so that distinct output points stay distinct
  // (a tolerance above dt skipped points and later asked CVodeGetDky for a time before the
  // step: CV_BAD_T on long runs with tiny intervals).
  const double eps_t = std::min(1e-12 * std::max(1.0, std::abs(t_end)), 0.25 * dt);
  long k = 1;  // next output point t0 + k*dt
  auto next_output = [&] { return std::min(t0 + static_cast<double>(k) * dt, t_end); };
  N_Vector interpolated = N_VClone(cv.y);
  if (!check_ptr(interpolated, "N_VClone")) return finish();
  struct VectorGuard {
    N_Vector v;
    ~VectorGuard() { N_VDestroy(v); }
  } interpolated_guard{interpolated};
  long steps_since_output = 0;
  double last_progress = -1;
  // Root functions at the last sample point (a step end or an output point).
  std::vector<double> g_prev(std::max(n_roots, 1), 1.0), g_out(std::max(n_roots, 1), 1.0), g_probe(g_out);
  double g_prev_time = t;
  if (n_roots > 0) {
    sys.Evaluate(t, N_VGetArrayPointer(cv.y), nullptr);
    sys.Roots(g_prev.data());
  }
  // The state at tq on the interpolant of the last step, evaluated.
  auto evaluate_interpolated = [&](double tq) {
    if (!sys.Evaluate(tq, N_VGetArrayPointer(interpolated), nullptr)) {
      fail(SimulationStatus::kModelError, sys.error(), tq);
      return false;
    }
    return true;
  };
  // The earliest crossing in (ta, tb] of the roots of one kind (`which`: 1 the kinematic ones,
  // 0 the others), on the interpolant of the last step, by the Illinois variant of regula falsi
  // that CVODE uses for its own roots: the secant point of the root whose secant crosses first,
  // the weight of an end kept twice in a row halved or doubled; to CVODE's time tolerance of
  // 100 units of roundoff. On entry g_prev holds the roots at ta, g_tb those at tb and `info`
  // the roots of that kind that cross in (ta, tb]. On return `interpolated` is the state at
  // t_root (evaluated there for the roots that need the model) and `info` the roots that cross
  // there. The kinematic roots are probed from the states alone (System::KinematicRoots), the
  // others on the evaluated model.
  std::vector<int> kinematic_info(root_info.size(), 0), probe_info(root_info.size(), 0),
      point_info(root_info.size(), 0);
  std::vector<double> g_low, g_high;
  auto locate_crossing = [&](double ta, double tb, int which, std::vector<int>& info,
                             const std::vector<double>& g_tb, double& t_root) {
    const double tol = 100.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(ta), std::abs(tb)) + 1e-15;
    g_low = g_prev;
    g_high = g_tb;
    // The root whose secant point comes first: the largest |g_high / (g_high - g_low)|.
    auto first = [&](const std::vector<int>& flags) {
      int best = -1;
      double most = -1.0;
      for (int i = 0; i < n_roots; ++i)
        if (flags[i] != 0) {
          const double fraction = std::abs(g_high[i] / (g_high[i] - g_low[i]));
          if (fraction > most) most = fraction, best = i;
        }
      return best;
    };
    int lead = first(info);
    double alpha = 1.0;
    int side = 0, side_before = -1;
    // The point before the present end on each side, for the lead root at that time: a root
    // function that is flat at one end (below).
    double t_low_before = NAN, g_low_before = 0.0, t_high_before = NAN, g_high_before = 0.0;
    int low_before_root = -1, high_before_root = -1;
    double flat_step = 1.0;  // the share of the extrapolated step from the informative end
    bool flat_probe = false;  // the last probe was placed by that extrapolation
    // (A root exactly zero at tb is at tb.)
    while (tb - ta > tol && lead >= 0 && g_high[lead] != 0.0) {
      alpha = side_before == side ? (side == 2 ? 2.0 * alpha : 0.5 * alpha) : 1.0;
      double tm;
      const bool zero_low = std::abs(g_low[lead]) <= detail::kRootSentinel;
      const bool zero_high = std::abs(g_high[lead]) <= detail::kRootSentinel;
      const bool flat_low = zero_low && !zero_high, flat_high = zero_high && !zero_low;
      if (flat_low || flat_high) {
        // A function that is exactly zero on one side of its crossing (a brake's normal force
        // before it engages, reported as the sentinel): the secant through the two ends points at
        // the flat end whatever the weights, and regula falsi crept a tenth of the interval per
        // probe (up to 98 probes for one root). The crossing is where the function leaves zero:
        // extrapolated along its other side through that side's last two points (the bracket
        // halved until there are two), the step from that side's end halved after every probe
        // that fell short onto the flat side (as the secant of a concave function does), and kept
        // three quarters of the tolerance inside the bracket, so that an estimate that has
        // converged closes the bracket with one probe.
        const double t1 = flat_low ? tb : ta, g1 = flat_low ? g_high[lead] : g_low[lead];
        const double t2 = flat_low ? t_high_before : t_low_before;
        const double g2 = flat_low ? g_high_before : g_low_before;
        const int root2 = flat_low ? high_before_root : low_before_root;
        const int flat_side = flat_low ? 2 : 1;
        flat_step = side == flat_side && flat_probe ? 0.5 * flat_step : 1.0;
        tm = 0.5 * (ta + tb);
        if (root2 == lead && (g1 > 0.0) == (g2 > 0.0) && std::abs(g2) > std::abs(g1)) {
          const double estimate = t1 - flat_step * g1 * (t1 - t2) / (g1 - g2);
          if (std::isfinite(estimate)) tm = estimate;
        }
        if (tb - ta > 1.5 * tol) {
          tm = std::clamp(tm, ta + 0.75 * tol, tb - 0.75 * tol);
        } else {
          tm = 0.5 * (ta + tb);
        }
        flat_probe = true;
      } else {
        tm = tb - (tb - ta) * g_high[lead] / (g_high[lead] - alpha * g_low[lead]);
        flat_probe = false;
      }
      // Not closer to an end than half the tolerance: then a fraction of the interval inward.
      const double inward = (tb - ta) / tol > 5.0 ? 0.1 : 0.5 * tol / (tb - ta);
      if (!(std::abs(tm - ta) >= 0.5 * tol)) tm = ta + inward * (tb - ta);
      if (!(std::abs(tb - tm) >= 0.5 * tol)) tm = tb - inward * (tb - ta);
      if (!check(CVodeGetDky(cv.mem, tm, 0, interpolated), "CVodeGetDky", tm)) return false;
      if (which == 1) {
        sys.KinematicRoots(tm, N_VGetArrayPointer(interpolated), g_probe.data());
      } else {
        if (!evaluate_interpolated(tm)) return false;
        sys.Roots(g_probe.data());
        ++root_evaluations;
      }
      side_before = side;
      if (SignChanged(g_low, g_probe, directions, probe_info, roots_of[which])) {
        t_high_before = tb, g_high_before = g_high[lead], high_before_root = lead;
        tb = tm;  // a crossing in (ta, tm]
        g_high.swap(g_probe);
        info.swap(probe_info);
        lead = first(info);
        side = 1;
      } else {
        t_low_before = ta, g_low_before = g_low[lead], low_before_root = lead;
        ta = tm;  // none there: the crossing of (ta, tb] lies in (tm, tb]
        g_low.swap(g_probe);
        SignChanged(g_low, g_high, directions, info, roots_of[which]);
        lead = first(info);
        side = 2;
      }
    }
    t_root = tb;
    if (!check(CVodeGetDky(cv.mem, tb, 0, interpolated), "CVodeGetDky", tb)) return false;
    return which == 1 || evaluate_interpolated(tb);
  };
  struct StepEnd {
    bool valid = false;
    Readings readings;
    std::vector<double> g;  ///< the root functions
  } end;
  end.g.assign(g_prev.size(), 1.0);
  // The next time event, asked of the elements again only after an event: between events their
  // discrete state is fixed (Element::NextTimeEvent), and the steps stop at that time.
  double t_event = INFINITY;
  bool t_event_current = false;
  while (t < t_end - eps_t) {
    if (InterruptRequested()) {
      fail(SimulationStatus::kInterrupted,
           "interrupted by signal " + std::to_string(InterruptSignal()) + " at t = " + FormatMessageNumber(t) + " s", t);
      break;
    }
    if (!t_event_current) {
      t_event = sys.NextTimeEvent(t);
      t_event_current = true;
    }
    const bool event_ahead = t_event <= t_end + eps_t;
    const double stop = event_ahead ? std::min(t_event, t_end) : t_end;
    if (stop != stop_set) {
      if (!check(CVodeSetStopTime(cv.mem, stop), "CVodeSetStopTime", t)) break;
      stop_set = stop;
    }
    double t_ret = t;
    int flag = CV_SUCCESS;
    const bool resumed = pending.active;
    if (resumed) {
      // The rest of the last step, after a root inside it handled at t.
      t_ret = pending.t;
      flag = pending.flag;
      std::copy(pending.y.begin(), pending.y.end(), N_VGetArrayPointer(cv.y));
      pending.active = false;
    } else {
      flag = CVode(cv.mem, stop, cv.y, &t_ret, CV_ONE_STEP);
      if (flag < 0) {
        check(flag, "CVode", t_ret);
        record_failure_state();
        break;
      }
    }
    // The root functions at the return: every one where the model is evaluated at the step's
    // end anyway (end.g; the peaks read that evaluation), else the kinematic ones.
    const bool step_moved = n_roots > 0 && t_ret > t;
    // Every root function at (t_ret, cv.y), from the model evaluated there.
    auto evaluate_roots = [&] {
      if (!sys.Evaluate(t_ret, N_VGetArrayPointer(cv.y), nullptr)) {
        fail(SimulationStatus::kModelError, sys.error(), t_ret);
        report.element = sys.error_element();
        record_failure_state();
        return false;
      }
      sys.Roots(end.g.data());
      ++root_evaluations;
      return true;
    };
    if (step_moved) {
      if (has_state_roots) {
        if (!evaluate_roots()) break;
      } else {
        sys.KinematicRoots(t_ret, N_VGetArrayPointer(cv.y), end.g.data());
      }
    }
    // The return moves back to a root inside the step (the state at it is in `interpolated`).
    // The rest of CVODE's step waits while the root is handled first (CVODE itself stays at the
    // step's end); cv.y holds that end until the first root inside is located.
    auto move_to_root = [&](double t_root) {
      if (!pending.active) {
        pending.y.assign(N_VGetArrayPointer(cv.y), N_VGetArrayPointer(cv.y) + n);
        pending.active = true;
        pending.t = t_ret;
        pending.flag = flag;
      }
      std::copy(N_VGetArrayPointer(interpolated), N_VGetArrayPointer(interpolated) + n, N_VGetArrayPointer(cv.y));
      t_ret = t_root;
      flag = CV_SUCCESS;  // this return is the root's; CVODE's own waits
    };
    // A kinematic root in (t, t_ret]: located from the states alone.
    bool kinematic_root = false, state_root = false;
    if (step_moved && has_kinematic_roots && SignChanged(g_prev, end.g, directions, kinematic_info, roots_of[1])) {
      double t_root = t_ret;
      if (!locate_crossing(g_prev_time, t_ret, 1, kinematic_info, end.g, t_root)) {
        record_failure_state();
        break;
      }
      move_to_root(t_root);
      kinematic_root = true;
      // The other roots at the kinematic one, to look for an earlier crossing of theirs.
      if (has_state_roots && !evaluate_roots()) break;
    }
    // A root that needs the model in (g_prev_time, t_ret]: located on the evaluated model. One at
    // the kinematic root's very time is handled with it.
    if (step_moved && has_state_roots && SignChanged(g_prev, end.g, directions, root_info, roots_of[0])) {
      double t_root = t_ret;
      if (!locate_crossing(g_prev_time, t_ret, 0, root_info, end.g, t_root)) {
        record_failure_state();
        break;
      }
      if (t_root < t_ret) {
        move_to_root(t_root);
      } else if (kinematic_root) {
        for (int i = 0; i < n_roots; ++i)
          if (kinematic_info[i] != 0) root_info[i] = kinematic_info[i];
      }
      kinematic_root = false;
      state_root = true;
    }
    // The output points the step passed (those at t_ret itself are written below), evaluated on
    // the interpolant for a sink that reads the rows, for the energy balance, and in a step
    // longer than the output interval: there the root functions are checked at the output
    // points, as CVODE does at output times in its normal mode. A sign change that such a step
    // hides (a friction element that sticks and breaks away within one step) is located on the
    // interpolant and handled as a root of the step. So every pair of crossings more than an
    // output interval apart is seen, and the check does not depend on whether the rows are
    // read. The peaks and the passivity monitor do not read the output points.
    // When the output points are evaluated, the step end's readings are taken first from its
    // evaluation above: the output points' evaluations replace that one, and the step end then
    // needs no second evaluation of the same point unless an event or a row that reads the
    // values needs the elements there.
    const bool check_roots = n_roots > 0 && t_ret - t > dt;
    const bool evaluate_points = evaluate_outputs || check_roots;
    end.valid = flag == CV_SUCCESS && !kinematic_root && !state_root && evaluate_points &&
                next_output() < t_ret - eps_t && sys.IsEvaluatedAt(t_ret, N_VGetArrayPointer(cv.y));
    if (end.valid) read(end.readings, SampleKind::kStepEnd);
    bool failed = false;
    while (next_output() < t_ret - eps_t) {
      const double t_out = next_output();
      HIGHLIFT_CHECK(t_out < t_end + eps_t && (k == 1 || t0 + static_cast<double>(k - 1) * dt < t_end - eps_t),
                     "a CVODE step ended past the stop time");
      // Without a reader of the values only the roots are wanted: evaluated without the
      // solve where the present modes allow it (System::RootsWithoutSolve), the same values.
      bool roots_done = false;
      if (evaluate_points) {
        if (!check(CVodeGetDky(cv.mem, t_out, 0, interpolated), "CVodeGetDky", t_out)) {
          failed = true;
          break;
        }
        roots_done = !evaluate_outputs && check_roots &&
                     sys.RootsWithoutSolve(t_out, N_VGetArrayPointer(interpolated), g_out.data());
        if (!roots_done && !evaluate_interpolated(t_out)) {
          failed = true;
          break;
        }
      }
      if (check_roots) {
        if (!roots_done) sys.Roots(g_out.data());
        if (SignChanged(g_prev, g_out, directions, point_info, roots_of[0])) {
          double t_root = t_out;
          if (!locate_crossing(g_prev_time, t_out, 0, point_info, g_out, t_root)) {
            failed = true;
            break;
          }
          move_to_root(t_root);
          root_info.swap(point_info);
          state_root = true;
          kinematic_root = false;
          break;
        }
        g_prev.swap(g_out);
        g_prev_time = t_out;
      }
      if (options.energy) sample(t_out, SampleKind::kOutputPoint);
      write_row(t_out);
      ++k;
      steps_since_output = 0;
    }
    if (failed) break;
    if (!resumed && ++steps_since_output > options.max_steps_per_output) {  // once per CVODE step
      // What CVODE's mxstep reports in its normal mode, counted here in one-step mode.
      report.sundials_flag = detail::CvodeFlagName(CV_TOO_MUCH_WORK);
      fail(SimulationStatus::kSolverFailure,
           "CVode failed with " + report.sundials_flag + " at t = " + FormatMessageNumber(t_ret) + " s: more than " +
               std::to_string(options.max_steps_per_output) +
               " steps between two output points (the solution is stiff or chatters); raise max_steps_per_output",
           t_ret);
      report.time = t_ret;
      record_failure_state();
      break;
    }
    t = t_ret;
    report.time = t;
    // The step end is sampled from the readings taken above when it has them; the elements are
    // then evaluated there again (the same values) only for an event or a row that reads them.
    const bool from_readings = end.valid;
    const bool on_output = std::abs(t - next_output()) <= eps_t;
    const bool time_event = event_ahead && std::abs(t - t_event) <= eps_t && t < t_end - eps_t;
    const bool root = state_root || kinematic_root;
    const bool event = root || time_event;
    const SampleKind end_kind = event ? SampleKind::kKink : SampleKind::kStepEnd;
    if (event) t_event_current = false;
    if (from_readings) record(t, end.readings, end_kind);
    const bool evaluate = !from_readings || event || (on_output && reads_values);
    if (evaluate && !sys.Evaluate(t, N_VGetArrayPointer(cv.y), nullptr)) {
      fail(SimulationStatus::kModelError, sys.error(), t);
      break;
    }
    if (!from_readings) sample(t, end_kind);
    if (root) {
      if (kinematic_root) root_info = kinematic_info;
      std::string what = "root";
      for (const auto& el : elements)
        for (int r = 0; r < el->NumRoots(); ++r)
          if (root_info[el->root_offset + r] != 0)
            what = el->id + (el->RootRestarts(r) ? " root " + std::to_string(r) : " contact");
      if (!sys.NeedsRestart(root_info.data())) {
        // A kink (backlash contact, spring breakpoint, a regularised gear reversing): the
        // right-hand side stays continuous, so the integrator continues without a restart, and
        // the rest of its step (held above) returns next.
        if (!sys.HandleContinuousRoots(t, N_VGetArrayPointer(cv.y), root_info.data())) {
          fail(SimulationStatus::kModelError, sys.error(), t);
          break;
        }
        ++report.statistics.continuous_roots;
        // The row after the kink reads the evaluation with the new discrete variables.
        if (reads_values && !sys.Evaluate(t, N_VGetArrayPointer(cv.y), nullptr)) {
          fail(SimulationStatus::kModelError, sys.error(), t);
          break;
        }
        write_row(t);
        report.events.push_back({t, "state", "", what});
        if (static_cast<int>(report.events.size()) > options.max_events) {
          fail(SimulationStatus::kTooManyEvents,
               "more than " + std::to_string(options.max_events) + " events (chattering?)", t);
          break;
        }
        // A time event at the kink's very time (the step's stop time) restarts the integrator.
        if (time_event && !handle_event(t, "time", "input", nullptr)) break;
      } else if (!handle_event(t, "state", what, root_info.data())) {
        break;
      }
      if (on_output) ++k;
    } else if (time_event) {
      if (!handle_event(t, "time", "input", nullptr)) break;
      if (on_output) ++k;
    } else if (on_output) {
      write_row(t);
      ++k;
      steps_since_output = 0;
    }
    if (n_roots > 0 && step_moved && !event) {  // the step end's, taken above
      g_prev.swap(end.g);
      g_prev_time = t;
    } else if (n_roots > 0 && kinematic_root && !time_event) {
      // After a kink at a kinematic root the others are those taken at it above (the kink keeps
      // the right-hand side continuous) and the kinematic ones follow the new discrete state.
      if (has_state_roots) g_prev.swap(end.g);
      sys.KinematicRoots(t, N_VGetArrayPointer(cv.y), g_prev.data());
      g_prev_time = t;
    } else if (n_roots > 0) {  // the root functions where the next step starts (cached evaluation)
      if (!sys.Evaluate(t, N_VGetArrayPointer(cv.y), nullptr)) {
        fail(SimulationStatus::kModelError, sys.error(), t);
        break;
      }
      sys.Roots(g_prev.data());
      ++root_evaluations;
      g_prev_time = t;
    }
    if (progress != nullptr) {
      const double fraction = (t - t0) / (t_end - t0);
      if (fraction - last_progress >= 0.01) {
        progress(fraction, progress_user);
        last_progress = fraction;
      }
    }
  }
  accumulate();
  if (report.ok() && progress != nullptr) progress(1.0, progress_user);
  return finish();
}

}  // namespace highlift::sim
