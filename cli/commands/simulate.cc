// `highlift simulate PROJECT.json [--scenario NAME] [--out results.csv] [--signals a,b] [--json]`:
// transient simulation of the project's element network (MSL 4.0.0 semantics, SUNDIALS CVODE).
// The scenario gives the stop time; the settings give the relative tolerance and the output
// interval. Results stream to the CSV file (`time` + instance-path columns). Exit 0 on success,
// 1 when the integration failed (the report says when, where and why), 2 on invalid input.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "command.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/core/text_table.h"
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
    app.add_option("--out", out_, "CSV file for the results (time + instance-path columns)");
    app.add_option("--signals", signals_, "Comma-separated columns to write, e.g. clutch.w_rel,inertia3.phi");
  }

  int Run() override {
    const Project project = LoadProject(options_.project);
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
      throw InputError("the project has " + std::to_string(project.scenarios.size()) +
                       " scenarios; choose one with --scenario NAME");
    } else {
      throw InputError("the project has no scenario; add one with a stop_time (e.g. "
                       "{\"name\": \"run\", \"kind\": \"extension\", \"stop_time\": \"1 s\"})");
    }
    const sim::Network network = sim::NetworkFromProject(project);
    sim::Simulator simulator(network);
    sim::SimulationOptions options;
    options.stop_time = scenario->stop_time;
    options.relative_tolerance = project.settings.relative_tolerance;
    options.output_interval = project.settings.output_interval;
    options.Validate();

    std::unique_ptr<sim::CsvSink> csv;
    if (!out_.empty()) csv = std::make_unique<sim::CsvSink>(out_, SplitSignals(signals_));
    else if (!signals_.empty())
      throw InputError("--signals selects CSV columns; give --out FILE as well");
    CountingSink sink(csv.get());
    const std::size_t selected = SplitSignals(signals_).size();
    Progress progress;
    const bool terminal = isatty(fileno(stderr)) != 0;
    const sim::SimulationReport report =
        simulator.Run(options, sink, terminal ? DrawProgress : nullptr, &progress);
    if (progress.drawn && !report.ok()) std::fprintf(stderr, "\n");

    if (options_.json) {
      nlohmann::json j;
      j["project"] = options_.project;
      j["scenario"] = scenario->name;
      j["status"] = sim::ToString(report.status);
      j["ok"] = report.ok();
      j["message"] = report.message;
      j["time"] = report.time;
      j["stop_time"] = options.stop_time;
      if (!report.ok()) {
        j["sundials_flag"] = report.sundials_flag;
        j["element"] = report.element;
        nlohmann::json state = nlohmann::json::object();
        for (const auto& [name, value] : report.state) state[name] = value;
        j["state"] = state;
      }
      j["output"] = {{"file", out_},
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
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << report.BriefReport() << "\n";
      if (!out_.empty())
        std::cout << "wrote " << sink.rows() << " rows x "
                  << (selected > 0 ? selected : sink.columns()) + 1 << " columns to "
                  << out_ << "\n";
      TextTable table({"element", "peak |tau| [N*m]", "at t [s]"}, {1, 2});
      for (const auto& p : report.peak_torques)
        table.AddRow({p.element, FormatNumber(std::abs(p.tau), 5), FormatNumber(p.time, 5)});
      std::cout << table.ToString();
    }
    if (!report.ok()) {
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
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(SimulateCommand, "simulate",
                          "Simulate the project's element network (MSL semantics, SUNDIALS CVODE)")

}  // namespace highlift::cli
