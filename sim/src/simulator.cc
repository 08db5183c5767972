// The CVODE driver: BDF with Newton iterations, dense or banded direct linear solver with a
// difference-quotient Jacobian on the band the network structure allows, root finding for
// state events, stop times for time events, re-initialisation after every event.
#include "highlift/sim/simulator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "highlift/core/error.h"
#include "sundials_compat.h"
#include "system.h"

namespace highlift::sim {

using detail::System;

void SimulationOptions::Validate() const {
  auto fail = [](const std::string& what) { throw InputError("simulation option " + what); };
  if (!(stop_time > start_time))
    fail("stop_time = " + std::to_string(stop_time) + " s must be greater than start_time = " +
         std::to_string(start_time) + " s");
  if (!(output_interval > 0)) fail("output_interval must be > 0 s");
  if (!(relative_tolerance > 0 && relative_tolerance < 1))
    fail("relative_tolerance = " + std::to_string(relative_tolerance) + " must lie in (0, 1)");
  if (!(absolute_tolerance > 0)) fail("absolute_tolerance must be > 0");
  if (max_step < 0) fail("max_step must be >= 0 (0: no limit)");
  if (linear_solver != "auto" && linear_solver != "dense" && linear_solver != "band")
    fail("linear_solver = '" + linear_solver + "' must be one of auto, dense, band");
}

std::string ToString(SimulationStatus status) {
  switch (status) {
    case SimulationStatus::kSuccess: return "success";
    case SimulationStatus::kSolverFailure: return "solver_failure";
    case SimulationStatus::kModelError: return "model_error";
    case SimulationStatus::kTooManyEvents: return "too_many_events";
  }
  return "unknown";
}

double EnergyBalance::Scale() const {
  return std::max({std::abs(source_work), std::abs(dissipated), impulsive_loss,
                   std::abs(kinetic_end - kinetic_start), std::abs(potential_end - potential_start),
                   std::abs(kinetic_start) + std::abs(potential_start)});
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

struct CallbackData {
  System* system = nullptr;
  std::string message;
  std::string element;
  std::string cvode_message;  ///< last message of CVODE's error handler
};

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

int RootFunction(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
  auto* data = static_cast<CallbackData*>(user);
  try {
    if (!data->system->Evaluate(t, N_VGetArrayPointer(y), nullptr)) {
      data->message = data->system->error();
      data->element = data->system->error_element();
      return -1;
    }
    data->system->Roots(g);
    return 0;
  } catch (const std::exception& ex) {
    data->message = std::string("root function: ") + ex.what();
    return -1;
  } catch (...) {
    data->message = "root function: unknown exception";
    return -1;
  }
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
  std::vector<double> tau;
  for (const auto& el : elements) report.peak_torques.push_back({el->id, 0.0, options.start_time});
  std::vector<bool> has_torque(elements.size(), false);

  auto fail = [&](SimulationStatus status, std::string message, double t) {
    report.status = status;
    report.message = std::move(message);
    report.time = t;
  };
  auto finish = [&] {
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
  bool first_row = true;
  double last_t = options.start_time, last_loss = 0.0, last_source = 0.0, impulsive_base = 0.0;
  auto write_row = [&](double t) {
    sys.Outputs(out.data());
    if (options.energy) {
      const System::EnergyState s = sys.Energy();
      double* x = out.data() + n_element_outputs;
      x[0] = s.kinetic;
      x[1] = s.potential;
      x[2] = s.loss_power;
      x[3] = s.source_power;
      EnergyBalance& b = report.energy;
      if (first_row) {
        impulsive_base = sys.impulsive_loss();  // the initial projection precedes the balance
        b.kinetic_start = s.kinetic;
        b.potential_start = s.potential;
      } else {
        const double h = t - last_t;
        b.dissipated += 0.5 * h * (s.loss_power + last_loss);
        b.source_work += 0.5 * h * (s.source_power + last_source);
      }
      b.kinetic_end = s.kinetic;
      b.potential_end = s.potential;
      b.impulsive_loss = sys.impulsive_loss() - impulsive_base;
      x[4] = b.impulsive_loss;
      first_row = false;
      last_t = t;
      last_loss = s.loss_power;
      last_source = s.source_power;
    }
    sink.Row(t, out);
    sys.PeakTorques(tau);
    for (std::size_t i = 0; i < tau.size(); ++i) {
      if (std::isnan(tau[i])) continue;
      has_torque[i] = true;
      if (std::abs(tau[i]) > std::abs(report.peak_torques[i].tau))
        report.peak_torques[i] = {elements[i]->id, tau[i], t};
    }
  };

  sink.Begin(columns);
  // Initial event: modes at t0, consistent speeds.
  {
    std::vector<std::string> changes, who;
    if (!sys.HandleEvent(options.start_time, y0.data(), true, &changes, &who)) {
      report.element = sys.error_element();
      fail(SimulationStatus::kModelError, sys.error(), options.start_time);
      return finish();
    }
    for (std::size_t i = 0; i < who.size(); ++i)
      report.events.push_back({options.start_time, "initial", who[i], changes[i]});
    write_row(options.start_time);
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
                      std::to_string(t) + " s";
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
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(cv.y));
  cv.mem = CVodeCreate(CV_BDF, cv.ctx);
  if (!check_ptr(cv.mem, "CVodeCreate")) return finish();
  double t = options.start_time;
  if (!check(CVodeInit(cv.mem, Rhs, t, cv.y), "CVodeInit", t)) return finish();
  if (!check(CVodeSetUserData(cv.mem, &data), "CVodeSetUserData", t)) return finish();
  if (!check(CVodeSetErrHandlerFn(cv.mem, ErrorHandler, &data), "CVodeSetErrHandlerFn", t))
    return finish();
  if (!check(CVodeSStolerances(cv.mem, options.relative_tolerance, options.absolute_tolerance),
             "CVodeSStolerances", t))
    return finish();
  if (!check(CVodeSetMaxNumSteps(cv.mem, options.max_steps_per_output), "CVodeSetMaxNumSteps", t))
    return finish();
  if (options.max_step > 0 && !check(CVodeSetMaxStep(cv.mem, options.max_step), "CVodeSetMaxStep", t))
    return finish();
  const int mu = std::min(sys.upper_bandwidth(), n - 1), ml = std::min(sys.lower_bandwidth(), n - 1);
  const bool band = options.linear_solver == "band" ||
                    (options.linear_solver == "auto" && n > 60 && (mu + ml + 1) * 4 < n);
  if (band) {
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
  const int n_roots = sys.NumRoots();
  std::vector<int> root_info(std::max(n_roots, 1)), directions(std::max(n_roots, 1));
  auto set_directions = [&] {
    if (n_roots == 0) return true;
    sys.RootDirections(directions.data());
    return check(CVodeSetRootDirection(cv.mem, directions.data()), "CVodeSetRootDirection", t);
  };
  if (n_roots > 0 && !check(CVodeRootInit(cv.mem, n_roots, RootFunction), "CVodeRootInit", t))
    return finish();
  if (!set_directions()) return finish();

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
    if (CVodeGetNumGEvals(cv.mem, &v) == CV_SUCCESS) s.root_evaluations += v;
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
  auto handle_event = [&](double te, const char* kind, const std::string& what,
                          const int* fired) {
    sys.Outputs(out.data());  // left limit (state and modes before the event)
    write_row(te);
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
    write_row(te);
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
    return set_directions();
  };

  const double t0 = options.start_time, t_end = options.stop_time, dt = options.output_interval;
  const double eps_t = 1e-12 * std::max(1.0, std::abs(t_end));
  long k = 1;
  double last_progress = -1;
  while (t < t_end - eps_t) {
    double t_out = std::min(t0 + k * dt, t_end);
    if (t_out <= t + eps_t) {
      ++k;
      continue;
    }
    const double t_event = sys.NextTimeEvent(t);
    const bool event_ahead = t_event <= t_end + eps_t;
    double target = t_out;
    if (event_ahead && t_event <= t_out + eps_t) target = t_event;
    const double stop = event_ahead ? std::min(t_event, t_end) : t_end;
    if (!check(CVodeSetStopTime(cv.mem, std::max(stop, target)), "CVodeSetStopTime", t)) break;
    double t_ret = t;
    const int flag = CVode(cv.mem, target, cv.y, &t_ret, CV_NORMAL);
    if (flag < 0) {
      check(flag, "CVode", t_ret);
      record_failure_state();
      break;
    }
    t = t_ret;
    report.time = t;
    if (flag == CV_ROOT_RETURN) {
      if (!sys.Evaluate(t, N_VGetArrayPointer(cv.y), nullptr)) {
        fail(SimulationStatus::kModelError, sys.error(), t);
        break;
      }
      if (!check(CVodeGetRootInfo(cv.mem, root_info.data()), "CVodeGetRootInfo", t)) break;
      std::string what = "root";
      bool switching = false;
      for (const auto& el : elements)
        for (int r = 0; r < el->NumRoots(); ++r)
          if (root_info[el->root_offset + r] != 0) {
            what = el->id + (el->IsSwitching() ? " root " + std::to_string(r) : " contact");
            switching = switching || el->IsSwitching();
          }
      if (!switching) {
        // A kink without a discrete state (backlash contact): the right-hand side stays
        // continuous, so the integrator continues without a restart.
        write_row(t);
        report.events.push_back({t, "state", "", what});
        if (static_cast<int>(report.events.size()) > options.max_events) {
          fail(SimulationStatus::kTooManyEvents,
               "more than " + std::to_string(options.max_events) + " events (chattering?)", t);
          break;
        }
        if (std::abs(t - t_out) <= eps_t) ++k;
        continue;
      }
      if (!handle_event(t, "state", what, root_info.data())) break;
      if (std::abs(t - t_out) <= eps_t) ++k;
      continue;
    }
    if (!sys.Evaluate(t, N_VGetArrayPointer(cv.y), nullptr)) {
      fail(SimulationStatus::kModelError, sys.error(), t);
      break;
    }
    if (event_ahead && std::abs(t - t_event) <= eps_t && t < t_end - eps_t) {
      if (!handle_event(t, "time", "input", nullptr)) break;
      if (std::abs(t - t_out) <= eps_t) ++k;
    } else {
      write_row(t);
      ++k;
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
