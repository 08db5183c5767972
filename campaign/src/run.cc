// One run of a campaign: the project with the sample's values, its drive model under the case's
// scenario, the transient simulation and the single-DOF estimate of the same failure. Nothing
// here touches shared mutable state: runs execute in parallel threads (the simulator creates its
// own SUNDIALS context per run).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>

#include "highlift/campaign/campaign.h"
#include "highlift/core/error.h"
#include "highlift/core/message_number.h"
#include "highlift/model/component_model.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/sim/simulator.h"

namespace highlift::campaign {
namespace {

constexpr double kPeakOutputInterval = 1e-3;  // s: as `peak --transient` (the peaks follow every step)

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

CaseSimulation SimulateCase(const Project& project, const Scenario& scenario, const std::vector<std::string>& load_path,
                            const sim::DriveNetworkOptions& options, const CampaignOptions* limits) {
  const auto start = std::chrono::steady_clock::now();
  const sim::DriveModel model = sim::BuildDriveNetwork(project, &scenario, options);
  sim::Simulator simulator(model.network);
  sim::SimulationOptions run = model.Options(project);
  run.output_interval = std::min(run.output_interval, kPeakOutputInterval);
  if (limits) {
    run.output_interval = (run.stop_time - run.start_time) / CampaignOptions::kRowsPerRun;
    run.max_steps_per_output = limits->max_steps_per_output;
    run.max_events = limits->max_events;
    if (limits->relative_tolerance > 0) run.relative_tolerance = limits->relative_tolerance;
  }
  CaseSimulation out;
  out.build_seconds = Seconds(start);
  sim::DiscardSink sink;  // the peaks are in the report
  out.report = simulator.Run(run, sink);
  out.components = sim::ComponentPeakTorques(model, project, out.report);
  // The reduced model lumps a chain of shafts into one spring: each shaft of the chain carries
  // the spring's torque (its derived column <shaft>.tau).
  std::map<std::string, const sim::PeakTorque*> by_element;
  for (const sim::PeakTorque& p : out.report.peak_torques) by_element[p.element] = &p;
  std::set<std::string> present;
  for (const sim::PeakTorque& p : out.components) present.insert(p.element);
  const auto stem = [](const std::string& column) {
    return column.size() > 4 && column.compare(column.size() - 4, 4, ".tau") == 0 ? column.substr(0, column.size() - 4)
                                                                                  : std::string();
  };
  for (const sim::DerivedColumn& d : model.derived) {
    const std::string component = stem(d.name), element = stem(d.source);
    auto it = by_element.find(element);
    if (component.empty() || present.count(component) || it == by_element.end() || !project.FindComponent(component))
      continue;
    out.components.push_back({component, d.factor * it->second->tau, it->second->time});
    present.insert(component);
  }
  std::map<std::string, std::size_t> position;
  for (const Component& c : project.components) position.emplace(c.id, position.size());
  std::stable_sort(out.components.begin(), out.components.end(), [&](const sim::PeakTorque& a, const sim::PeakTorque& b) {
    return position.at(a.element) < position.at(b.element);
  });
  out.load_path_peak = {"", 0.0, 0.0};
  for (const sim::PeakTorque& p : out.components) {
    const Component* c = project.FindComponent(p.element);
    const model::ComponentModel* m = c ? model::FindComponentModel(c->type) : nullptr;
    if (!m || !(m->roles().segment || m->roles().tip_brake)) continue;
    if (!load_path.empty() && std::find(load_path.begin(), load_path.end(), p.element) == load_path.end()) continue;
    auto k = model.speed_factor.find(p.element);
    const double at_shaft_speed = std::abs(p.tau) * (k == model.speed_factor.end() ? 1.0 : k->second);
    if (at_shaft_speed > out.load_path_peak.tau) out.load_path_peak = {p.element, at_shaft_speed, p.time};
  }
  return out;
}

RunResult ExecuteRun(const Project& project, const Plan& plan, int run) {
  RunResult r;
  r.run = run;
  r.case_index = plan.CaseOf(run);
  const CampaignCase& c = plan.cases.at(static_cast<std::size_t>(r.case_index));
  const Sample sample = plan.SampleOf(run);
  r.sample = sample.index;
  r.sample_label = sample.label;
  r.values = sample.values;
  try {
    // The copy of the project with the sample's values is campaign-layer work: not timed.
    const Project sampled = plan.parameters.empty() ? Project() : plan.Apply(project, sample);
    const Project& p = plan.parameters.empty() ? project : sampled;
    const auto start = std::chrono::steady_clock::now();

    if (!c.peak_case.empty()) {
      try {
        reduced_models::PeakOptions peak;
        peak.intervals = false;
        peak.rank = false;
        peak.only_case = c.peak_case;
        const reduced_models::PeakReport estimate = reduced_models::AnalysePeaks(p, peak);
        if (!estimate.cases.empty()) r.single_dof = estimate.cases.front().tau_total.nominal;
      } catch (const std::exception& e) {
        r.message = std::string("no single-DOF estimate: ") + e.what();
      }
      r.single_dof_seconds = Seconds(start);
    }

    sim::DriveNetworkOptions network;
    network.resolution = plan.options.model;
    network.shaft_elements = plan.options.shaft_elements;
    CaseSimulation simulation = SimulateCase(p, c.scenario, c.load_path, network, &plan.options);
    r.build_seconds = simulation.build_seconds;
    r.simulate_seconds = simulation.report.wall_seconds;
    r.steps = simulation.report.statistics.steps;
    r.passivity = simulation.report.passivity;
    if (!simulation.report.ok()) {
      const sim::SimulationReport& report = simulation.report;
      r.ok = false;
      r.interrupted = report.status == sim::SimulationStatus::kInterrupted;
      r.message = ToString(report.status) + " at t = " + FormatMessageNumber(report.time) + " s: " + report.message;
      if (report.sundials_flag == "CV_TOO_MUCH_WORK")
        r.message += " (campaign --max-steps, " + std::to_string(plan.options.max_steps_per_output) + " in this campaign)";
      return r;
    }
    r.components = std::move(simulation.components);
    r.peak = simulation.load_path_peak.tau;
    r.peak_component = simulation.load_path_peak.element;
    r.peak_time = simulation.load_path_peak.time;
  } catch (const std::exception& e) {
    // A sample the model cannot be built for (a value outside a valid range, a brake whose
    // static capacity falls below its dynamic torque, ...) is a failed run, not a failed campaign.
    r.ok = false;
    r.message = e.what();
  }
  return r;
}

}  // namespace highlift::campaign
