// `highlift simulate PROJECT.json [--scenario NAME] [--model full|reduced] [--elements N]
// [--output results.csv] [--signals a,b] [--energy] [--json]`: transient simulation (MSL 4.0.0
// semantics, SUNDIALS CVODE) of the project's element network or, for a drive-system project,
// of the model built from its components (sim/include/highlift/sim/drive_network.h) with the
// scenario's load case and failure. The scenario gives the stop time; the settings give the
// relative tolerance and the output interval. Results stream to the CSV file (`time` +
// instance-path columns named after the component ids). Exit 0 on success, 1 when the
// integration failed (the report says when, where and why), 2 on invalid input.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "command.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/core/text_table.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"

namespace highlift::cli {
namespace {

/// Counts rows and forwards them (to a CSV sink, or nowhere).
class CountingSink : public sim::OutputSink {
 public:
  explicit CountingSink(sim::OutputSink* next) : next_(next) {}
  void Begin(const std::vector<std::string>& columns) override {
    columns_ = columns.size();
    if (next_) next_->Begin(columns);
  }
  void Row(double time, const std::vector<double>& values) override {
    ++rows_;
    if (next_) next_->Row(time, values);
  }
  void End() override {
    if (next_) next_->End();
  }
  bool ReadsValues() const override { return next_ != nullptr && next_->ReadsValues(); }
  long rows() const { return rows_; }
  std::size_t columns() const { return columns_; }

 private:
  sim::OutputSink* next_;
  long rows_ = 0;
  std::size_t columns_ = 0;
};

struct Progress {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  bool drawn = false;
};

void DrawProgress(double fraction, void* user) {
  auto* p = static_cast<Progress*>(user);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - p->start).count();
  if (elapsed < 1.0 && !p->drawn) return;  // only runs longer than a second get a bar
  const int width = 40, filled = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r[%s%s] %3d%% %5.1f s", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100), elapsed);
  if (fraction >= 1.0) std::fprintf(stderr, "\n");
  std::fflush(stderr);
  p->drawn = true;
}

std::vector<std::string> SplitSignals(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) {
    while (!item.empty() && item.front() == ' ') item.erase(item.begin());
    while (!item.empty() && item.back() == ' ') item.pop_back();
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

class SimulateCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_option("--scenario", scenario_, "Scenario to run (its stop_time); optional when the project has one");
    app.add_option("--output,--out", out_, "CSV file for the results (time + instance-path columns)");
    app.add_option("--signals", signals_, "Comma-separated columns to write, e.g. clutch.w_rel,inertia3.phi");
    app.add_option("--model", model_,
                   "Drive-system projects: 'full' (every shaft split into elements, default) or 'reduced' "
                   "(inertias lumped at gearboxes and stations)");
    app.add_option("--elements", elements_,
                   "Drive-system projects, full model: spring-dampers per torque shaft (default: the "
                   "project's shaft_elements, at least 4; 1 to " +
                       std::to_string(sim::DriveNetworkOptions::kMaxShaftElements) + ")")
        ->check(NumberIn(1, sim::DriveNetworkOptions::kMaxShaftElements));
    app.add_option("--max-rows", max_rows_, "Refuse runs that would write more output rows than this (default 1e7)")
        ->check(NumberIn(1, 1e12));
    app.add_flag("--energy", energy_, "Energy bookkeeping: energy.* columns and the balance in the report");
    app.add_option("--rtol", rtol_, "Relative tolerance (default: the experiment's Tolerance or settings.relative_tolerance)");
    app.add_option("--start", start_,
                   "given: the start values (with the elements' a_start); steady-state: every inertia starts "
                   "with a = 0 and every spring with a constant twist, the free speeds and angles solved "
                   "(default: given)");
    app.add_option("--atol", atol_,
                   "Absolute tolerance per unit nominal value: a state's absolute tolerance is atol times its "
                   "nominal value (default: settings.absolute_tolerance, else 1e-8); drive-system projects resolve "
                   "a spring's twist to 1e-3 N*m and a speed to at least rtol times the friction speed "
                   "(docs/simulation.md)");
  }

  int Run() override {
    // stdout holds one JSON document with --json (docs/cli.md): the CSV cannot go there as well.
    if (options_.json && out_ == "-")
      throw InputError("--out - writes the CSV to stdout, where --json writes its document; give the CSV a file "
                       "(--out results.csv) or leave out --json");
    const Project project = LoadValidProject(options_.project);
    const bool drive = sim::IsDriveSystemProject(project);
    if (!drive && (!model_.empty() || elements_ >= 0))
      throw InputError("--model and --elements apply to drive-system projects (components and connections); "
                       "this project is an element network: leave them out");
    const Scenario* scenario = nullptr;
    if (!scenario_.empty()) {
      scenario = project.FindScenario(scenario_);
      if (scenario == nullptr) {
        std::string names;
        for (const auto& s : project.scenarios) names += (names.empty() ? "" : ", ") + s.name;
        throw InputError("scenario '" + scenario_ + "' is not in the project; choose one of: " +
                         (names.empty() ? "(none: add a scenario with a stop_time)" : names));
      }
    } else if (project.scenarios.size() == 1) {
      scenario = &project.scenarios.front();
    } else if (!project.scenarios.empty()) {
      std::string names;
      for (const auto& s : project.scenarios) names += (names.empty() ? "" : ", ") + s.name;
      throw InputError("the project has " + std::to_string(project.scenarios.size()) +
                       " scenarios; choose one with --scenario NAME (" + names + ")");
    } else if (!project.experiment || drive) {
      throw InputError(drive ? "the project has no scenario; add one with a stop_time (e.g. "
                               "{\"name\": \"run\", \"kind\": \"extension\", \"stop_time\": \"1 s\"})"
                             : "the element network has no experiment and no scenario; add "
                               "\"experiment\": {\"StopTime\": \"1 s\"} (Modelica's experiment annotation: "
                               "StartTime, StopTime, Interval, Tolerance)");
    }
    sim::DriveModel drive_model;
    sim::Network network;
    if (drive) {
      sim::DriveNetworkOptions build;
      if (!model_.empty()) build.resolution = sim::ParseDriveResolution(model_);
      if (elements_ >= 0) {
        if (elements_ < 1)
          throw InputError("--elements " + std::to_string(elements_) +
                           ": a shaft needs at least 1 spring-damper; give 1 or more (default: the project's "
                           "shaft_elements, at least 4)");
        build.shaft_elements = elements_;
      }
      drive_model = sim::BuildDriveNetwork(project, scenario, build);
      network = drive_model.network;
    } else {
      network = sim::NetworkFromProject(project);
    }
    sim::Simulator simulator(network);
    sim::SimulationOptions options;
    if (drive) options = drive_model.Options(project);
    options.relative_tolerance = project.settings.relative_tolerance;
    if (project.settings.absolute_tolerance) options.absolute_tolerance = *project.settings.absolute_tolerance;
    if (scenario != nullptr) {
      options.stop_time = scenario->stop_time;
      options.output_interval = scenario->output_interval.value_or(project.settings.output_interval);
    } else {  // the element network's experiment
      const Experiment& x = *project.experiment;
      options.start_time = x.start_time;
      options.stop_time = x.stop_time;
      options.output_interval = x.interval.value_or(project.settings.output_interval);
      if (x.tolerance) options.relative_tolerance = *x.tolerance;
    }
    if (!std::isnan(rtol_)) options.relative_tolerance = rtol_;
    if (!std::isnan(atol_)) options.absolute_tolerance = atol_;
    options.start = sim::ParseStartKind(start_.empty() ? project.settings.initial : start_);  // --start over settings
    options.energy = energy_;
    options.Validate();
    // Output rows: a tiny output_interval would write gigabytes (1e-300 s) or never end.
    const double rows = std::floor((options.stop_time - options.start_time) / options.output_interval) + 1;
    if (!(rows <= max_rows_)) {
      const auto count = [](double v) {
        std::ostringstream s;
        s << std::setprecision(3) << v;
        return s.str();
      };
      throw InputError("the run would write " + count(rows) + " output rows (stop_time " +
                       FormatNumber(options.stop_time, 6) + " s / output_interval " +
                       FormatNumber(options.output_interval, 6) + " s), about " + count(rows * 20) +
                       " bytes per CSV column; the limit is " + count(max_rows_) +
                       " rows: raise output_interval (settings or the scenario) to at least " +
                       FormatNumber((options.stop_time - options.start_time) / std::max(max_rows_ - 1, 1.0), 3) +
                       " s, or raise --max-rows");
    }

    std::unique_ptr<sim::CsvSink> csv;
    if (!out_.empty()) csv = std::make_unique<sim::CsvSink>(out_, SplitSignals(signals_));
    else if (!signals_.empty())
      throw InputError("--signals selects CSV columns; give --out FILE as well");
    CountingSink sink(csv.get());
    sim::DerivedColumnSink derived(drive_model.derived, sink);  // component columns (shaft_l1.tau)
    const std::size_t selected = SplitSignals(signals_).size();
    Progress progress;
    const bool terminal = isatty(fileno(stderr)) != 0;
    const sim::SimulationReport report = simulator.Run(options, derived, terminal ? DrawProgress : nullptr, &progress);
    const std::vector<sim::PeakTorque> component_peaks =
        drive ? sim::ComponentPeakTorques(drive_model, project, report) : std::vector<sim::PeakTorque>{};
    if (progress.drawn && !report.ok()) std::fprintf(stderr, "\n");

    if (options_.json) {
      nlohmann::json j;
      j["project"] = options_.project;
      j["scenario"] = scenario != nullptr ? scenario->name : "experiment";
      j["relative_tolerance"] = options.relative_tolerance;
      j["absolute_tolerance"] = options.absolute_tolerance;
      j["start"] = sim::ToString(options.start);
      j["status"] = sim::ToString(report.status);
      j["ok"] = report.ok();
      j["message"] = report.message;
      j["time"] = report.time;
      j["stop_time"] = options.stop_time;
      if (drive) {
        j["model"] = {{"resolution", sim::ToString(drive_model.resolution)},
                      {"shaft_elements", drive_model.shaft_elements},
                      {"elements", drive_model.network.elements().size()},
                      {"load_case", drive_model.load_case}};
        nlohmann::json peaks = nlohmann::json::array();
        for (const auto& p : component_peaks)
          peaks.push_back({{"component", p.element}, {"tau", p.tau}, {"abs_tau", std::abs(p.tau)}, {"time", p.time}});
        j["component_peaks"] = peaks;
      }
      if (report.energy.computed) {
        const auto& e = report.energy;
        j["energy"] = {{"source_work", e.source_work},         {"dissipated", e.dissipated},
                       {"impulsive_loss", e.impulsive_loss},   {"kinetic_start", e.kinetic_start},
                       {"kinetic_end", e.kinetic_end},         {"potential_start", e.potential_start},
                       {"potential_end", e.potential_end},     {"residual", e.Residual()},
                       {"scale", e.Scale()}};
      }
      {
        // The passivity monitor: elements whose dissipated power fell below zero.
        nlohmann::json violations = nlohmann::json::array();
        for (const auto& v : report.passivity.violations)
          violations.push_back({{"element", v.element}, {"time", v.time}, {"duration", v.duration},
                                {"power", v.power}, {"power_time", v.power_time}, {"episodes", v.episodes}});
        j["passivity"] = {{"passive", report.passivity.passive()},
                          {"tolerance", report.passivity.tolerance},
                          {"power_scale", report.passivity.power_scale},
                          {"violations", violations}};
      }
      if (!report.ok()) {
        j["sundials_flag"] = report.sundials_flag;
        j["element"] = report.element;
        nlohmann::json state = nlohmann::json::object();
        for (const auto& [name, value] : report.state) state[name] = value;
        j["state"] = state;
      }
      const std::string partial = PartialOutputFile();
      j["output"] = {{"file", partial.empty() ? out_ : partial},
                     {"partial", !partial.empty()},
                     {"columns", selected > 0 ? selected : sink.columns()},
                     {"rows", sink.rows()}};
      const auto& s = report.statistics;
      j["statistics"] = {{"states", s.states},
                         {"linear_solver", s.linear_solver},
                         {"steps", s.steps},
                         {"rhs_evaluations", s.rhs_evaluations},
                         {"jacobian_evaluations", s.jacobian_evaluations},
                         {"nonlinear_iterations", s.nonlinear_iterations},
                         {"error_test_failures", s.error_test_failures},
                         {"nonlinear_convergence_failures", s.nonlinear_convergence_failures},
                         {"root_evaluations", s.root_evaluations},
                         {"reinitialisations", s.reinitialisations},
                         {"wall_seconds", report.wall_seconds}};
      nlohmann::json events = nlohmann::json::array();
      for (std::size_t i = 0; i < report.events.size() && i < 1000; ++i) {
        const auto& e = report.events[i];
        events.push_back({{"time", e.time}, {"kind", e.kind}, {"element", e.element}, {"what", e.what}});
      }
      j["events"] = events;
      j["events_total"] = report.events.size();
      nlohmann::json peaks = nlohmann::json::array();
      for (const auto& p : report.peak_torques)
        peaks.push_back({{"element", p.element}, {"tau", p.tau}, {"abs_tau", std::abs(p.tau)}, {"time", p.time}});
      j["peak_torques"] = peaks;
      std::cout << JsonText(j) << "\n";
    } else {
      std::cout << report.BriefReport() << "\n";
      if (!out_.empty())
        std::cout << "wrote " << sink.rows() << " rows x "
                  << (selected > 0 ? selected : sink.columns()) + 1 << " columns to "
                  << (PartialOutputFile().empty() ? out_ : PartialOutputFile() + " (partial)") << "\n";
      if (drive)
        std::cout << sim::ToString(drive_model.resolution) << " model of " << project.components.size()
                  << " components: " << drive_model.network.elements().size() << " elements"
                  << (drive_model.resolution == sim::DriveResolution::kFull
                          ? ", " + std::to_string(drive_model.shaft_elements) + " per shaft"
                          : std::string())
                  << "; scenario " << scenario->name
                  << (drive_model.load_case.empty() ? std::string() : ", load case " + drive_model.load_case)
                  << "\n";
      if (report.energy.computed) {
        const auto& e = report.energy;
        std::cout << "energy: source work " << FormatNumber(e.source_work, 6) << " J = stored change "
                  << FormatNumber(e.kinetic_end - e.kinetic_start + e.potential_end - e.potential_start, 6)
                  << " J + dissipated " << FormatNumber(e.dissipated, 6) << " J + impulsive "
                  << FormatNumber(e.impulsive_loss, 6) << " J; residual " << FormatNumber(e.Residual(), 3)
                  << " J\n";
      }
      std::cout << "passivity: " << report.passivity.BriefReport() << "\n";
      TextTable table({drive ? "component" : "element", "peak |tau| [N*m]", "at t [s]"}, {1, 2});
      for (const auto& p : drive ? component_peaks : report.peak_torques)
        table.AddRow({p.element, FormatNumber(std::abs(p.tau), 5), FormatNumber(p.time, 5)});
      std::cout << table.ToString();
    }
    if (!report.ok()) {
      // interrupted: main() says so and names the partial file
      if (report.status != sim::SimulationStatus::kInterrupted)
        std::cerr << "highlift simulate: simulation failed: " << report.message << "\n";
      return kViolated;
    }
    return kSuccess;
  }

 private:
  CommonOptions options_;
  std::string scenario_;
  std::string out_;
  std::string signals_;
  std::string model_;
  int elements_ = -1;
  double max_rows_ = 1e7;
  bool energy_ = false;
  double rtol_ = NAN, atol_ = NAN;  // NaN: not given
  std::string start_;               // empty: given
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(SimulateCommand, "simulate",
                          "Simulate the project's element network or drive system (MSL semantics, SUNDIALS CVODE)")

}  // namespace highlift::cli
