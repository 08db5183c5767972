// BuildDesignReport: runs the interval check, sizing, modes, single-DOF peaks and the
// simulations (sizing cases and the project's scenarios, side by side on threads) and collects
// what the page shows as one JSON document.
#include "highlift/report/report.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <deque>
#include <map>
#include <set>
#include <thread>

#include "highlift/campaign/bounds.h"
#include "highlift/campaign/campaign.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "highlift/core/units.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sizing.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"
#include "span_layout.h"

namespace highlift::report {
namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// Six significant digits: the page shows four, and the file stays small.
double Round(double v) {
  if (!std::isfinite(v) || v == 0.0) return v;
  const double scale = std::pow(10.0, 5 - static_cast<int>(std::floor(std::log10(std::abs(v)))));
  return std::round(v * scale) / scale;
}
nlohmann::json Number(double v) { return std::isfinite(v) ? nlohmann::json(Round(v)) : nlohmann::json(nullptr); }

/// The components whose torque a sizing case's transient peak and capacity are read at: the
/// shaft segments and the wing-tip brakes on its load path (as `highlift peak --transient`).
bool CarriesCaseTorque(const Component& c) {
  const ComponentRoles r = RolesOf(c.type);
  return r.segment || r.tip_brake;
}

// ---------------------------------------------------------------------------------------------
// Simulations

/// A signal of a time history: its column and what it shows.
struct SignalChoice {
  std::string column;
  std::string group;  ///< "speed" (rad/s), "torque" (N*m) or "state"
};

/// The columns a time history keeps: PDU and sensor speeds, the torques of the system torque
/// limiters, wing-tip brakes and shafts, the monitor's brake command. The shaft columns are cut
/// down to the one with the largest peak after the run.
std::vector<SignalChoice> ChooseSignals(const Project& project) {
  std::vector<SignalChoice> out;
  for (const Component& c : project.components)
    if (RolesOf(c.type).drive_unit) out.push_back({c.id + ".w", "speed"});
  for (const Component& c : project.components)
    if (RolesOf(c.type).tip_sensor) out.push_back({c.id + ".w", "speed"});
  for (const Component& c : project.components) {
    const ComponentRoles r = RolesOf(c.type);
    if (r.wing_limiter || r.tip_brake || r.segment) out.push_back({c.id + ".tau", "torque"});
  }
  out.push_back({"monitor.wtb", "state"});
  return out;
}

/// Keeps the rows of the chosen columns (the others are dropped as they arrive).
class SelectingSink : public sim::OutputSink {
 public:
  explicit SelectingSink(std::vector<SignalChoice> wanted) : wanted_(std::move(wanted)) {}
  void Begin(const std::vector<std::string>& columns) override {
    for (const SignalChoice& w : wanted_) {
      auto it = std::find(columns.begin(), columns.end(), w.column);
      if (it == columns.end()) continue;
      index_.push_back(static_cast<int>(it - columns.begin()));
      kept_.push_back(w);
    }
    values_.assign(kept_.size(), {});
  }
  void Row(double time, const std::vector<double>& values) override {
    times_.push_back(time);
    for (std::size_t k = 0; k < index_.size(); ++k) values_[k].push_back(values[index_[k]]);
  }
  const std::vector<SignalChoice>& kept() const { return kept_; }
  const std::vector<double>& times() const { return times_; }
  const std::vector<std::vector<double>>& values() const { return values_; }

 private:
  std::vector<SignalChoice> wanted_;
  std::vector<SignalChoice> kept_;
  std::vector<int> index_;
  std::vector<double> times_;
  std::vector<std::vector<double>> values_;
};

struct SimulationJob {
  Scenario scenario;
  const reduced_models::PeakCase* peak_case = nullptr;  ///< the sizing case it answers, if any
  bool keep_history = false;                            ///< a project scenario: the page plots it
  // Results
  sim::DriveModel model;
  sim::SimulationReport report;
  std::vector<sim::PeakTorque> component_peaks;
  std::unique_ptr<SelectingSink> history;
  std::string error;  ///< the model could not be built
};

void RunJob(const Project& project, const ReportOptions& options, const std::vector<SignalChoice>& signals,
            SimulationJob& job) {
  try {
    sim::DriveNetworkOptions build;
    build.shaft_elements = options.shaft_elements;
    job.model = sim::BuildDriveNetwork(project, &job.scenario, build);
    sim::Simulator simulator(job.model.network);
    sim::SimulationOptions run = job.model.Options(project);
    // The peaks follow every step; the time history needs no finer grid than the scenario's own.
    if (job.peak_case) run.output_interval = std::min(run.output_interval, 1e-3);
    job.history = std::make_unique<SelectingSink>(job.keep_history ? signals : std::vector<SignalChoice>{});
    sim::DerivedColumnSink sink(job.model.derived, *job.history);
    job.report = simulator.Run(run, sink);
    job.component_peaks = sim::ComponentPeakTorques(job.model, project, job.report);
  } catch (const std::exception& e) {
    job.error = e.what();
    job.report.status = sim::SimulationStatus::kModelError;
    job.report.message = e.what();
  }
}

/// Runs the jobs on `threads` threads (each simulation owns its model and solver).
void RunJobs(const Project& project, const ReportOptions& options, const std::vector<SignalChoice>& signals,
             std::deque<SimulationJob>& jobs) {
  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, std::max(1, static_cast<int>(jobs.size())));
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < jobs.size(); i = next++) RunJob(project, options, signals, jobs[i]);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

/// Rows kept of a long history: per bucket of rows the first row and, per signal, the rows of
/// its smallest and largest value, so every peak and every switch survives.
std::vector<std::size_t> ThinRows(const std::vector<std::vector<double>>& values, std::size_t rows, int max_points) {
  std::vector<std::size_t> keep;
  if (rows <= static_cast<std::size_t>(max_points)) {
    for (std::size_t i = 0; i < rows; ++i) keep.push_back(i);
    return keep;
  }
  const std::size_t per_signal = std::max<std::size_t>(1, values.size());
  const std::size_t buckets = std::max<std::size_t>(50, max_points / (1 + 2 * std::min<std::size_t>(per_signal, 4)));
  std::set<std::size_t> chosen = {0, rows - 1};
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t lo = rows * b / buckets, hi = std::max(lo + 1, rows * (b + 1) / buckets);
    chosen.insert(lo);
    for (const auto& v : values) {
      const auto [mn, mx] = std::minmax_element(v.begin() + lo, v.begin() + hi);
      chosen.insert(mn - v.begin());
      chosen.insert(mx - v.begin());
    }
  }
  return {chosen.begin(), chosen.end()};
}

nlohmann::json HistoryJson(const Project& project, const SimulationJob& job, int max_points) {
  const SelectingSink& h = *job.history;
  const Scenario& s = job.scenario;
  nlohmann::json j = {{"name", s.name},          {"kind", s.kind},
                      {"description", s.description}, {"load_case", s.load_case},
                      {"stop_time", s.stop_time}, {"ok", job.report.ok()},
                      {"message", job.report.message}, {"wall_seconds", Round(job.report.wall_seconds)},
                      {"states", job.report.statistics.states}, {"events", job.report.events.size()},
                      {"passivity", job.report.passivity.BriefReport()}};
  // Of the shafts keep the one with the largest peak: the torque the failure puts into the line.
  std::string peak_shaft;
  double peak = -1;
  for (const sim::PeakTorque& p : job.component_peaks) {
    const Component* c = project.FindComponent(p.element);
    if (c && RolesOf(c->type).segment && std::abs(p.tau) > peak) {
      peak = std::abs(p.tau);
      peak_shaft = p.element;
    }
  }
  std::vector<std::size_t> columns;
  std::vector<std::vector<double>> kept_values;
  for (std::size_t k = 0; k < h.kept().size(); ++k) {
    const std::string& column = h.kept()[k].column;
    const Component* c = project.FindComponent(column.substr(0, column.find('.')));
    if (c && RolesOf(c->type).segment && column != peak_shaft + ".tau") continue;
    columns.push_back(k);
    kept_values.push_back(h.values()[k]);
  }
  const std::vector<std::size_t> rows = ThinRows(kept_values, h.times().size(), max_points);
  nlohmann::json time = nlohmann::json::array();
  for (std::size_t r : rows) time.push_back(Round(h.times()[r]));
  j["time"] = time;
  j["rows_simulated"] = h.times().size();
  nlohmann::json signals = nlohmann::json::array();
  for (std::size_t k : columns) {
    nlohmann::json values = nlohmann::json::array();
    for (std::size_t r : rows) values.push_back(Number(h.values()[k][r]));
    const std::string& group = h.kept()[k].group;
    signals.push_back({{"name", h.kept()[k].column},
                       {"group", group},
                       {"unit", group == "speed" ? "rad/s" : group == "torque" ? "N*m" : ""},
                       {"values", values}});
  }
  j["signals"] = signals;
  return j;
}

// ---------------------------------------------------------------------------------------------
// Sections

nlohmann::json ComponentsJson(const Project& estimated, const SpanLayout& layout) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < estimated.components.size(); ++i) {
    const Component& c = estimated.components[i];
    const ComponentTypeSpec* type = FindComponentType(c.type);
    nlohmann::json parameters = nlohmann::json::array();
    for (const auto& [name, p] : c.parameters) {
      const ParameterSpec* spec = type ? type->FindParameter(name) : nullptr;
      std::string unit = spec ? spec->unit : "";
      auto show = [&](double si) -> nlohmann::json {
        if (!std::isfinite(si)) return nullptr;
        if (!spec || unit.empty()) return Round(si);
        try {
          return Round(FromSI(si, unit, spec->dimension));
        } catch (const InputError&) {
          return Round(si);
        }
      };
      parameters.push_back({{"name", name},
                            {"unit", unit},
                            {"value", p.nominal ? show(*p.nominal) : nlohmann::json(nullptr)},
                            {"min", show(p.domain.lo)},
                            {"max", show(p.domain.hi)},
                            {"provenance", ToString(p.provenance)},
                            {"note", p.note}});
    }
    for (const auto& [name, text] : c.texts) parameters.push_back({{"name", name}, {"text", text}});
    out.push_back({{"id", c.id},
                   {"type", c.type},
                   {"type_name", type ? type->display_name : c.type},
                   {"description", c.description},
                   {"x", Number(layout.x[i])},
                   {"lane", layout.lane[i]},
                   {"side", c.labels.count("side") ? c.labels.at("side") : ""},
                   {"parameters", parameters}});
  }
  return out;
}

nlohmann::json ModesJson(const reduced_models::ModesReport& modes, const Project& project, const SpanLayout& layout) {
  nlohmann::json j = modes.ToJson();
  for (auto& m : j["models"]) {
    nlohmann::json x = nlohmann::json::array();
    for (const auto& name : m["nodes"]) {
      const std::optional<double> at = layout.NodePosition(project, name.get<std::string>(), modes.elements_per_segment);
      x.push_back(at ? nlohmann::json(Round(*at)) : nlohmann::json(nullptr));
    }
    m["node_x"] = x;
    for (auto& shape : m["clamped_shapes"])
      for (auto& v : shape) v = Round(v.get<double>());
    for (auto& f : m["free_hz"]) f = Round(f.get<double>());
    for (auto& f : m["clamped_hz"]) f = Round(f.get<double>());
  }
  return j;
}

/// Capacity of a sizing case at the shaft (reference) speed: the smallest allowable among the
/// torque shafts and wing-tip brakes on its load path (the components whose torque the transient
/// peak is taken over), referred to the shaft speed.
struct Capacity {
  double value = 0.0;
  std::string component;
  std::string name;
};
Capacity CaseCapacity(const Project& project, const reduced_models::PeakCase& pc, const reduced_models::PeakReport& peaks) {
  Capacity best;
  for (const auto& w : peaks.worst) {
    if (w.allowable <= 0 || w.local_torque <= 0 || w.torque.bounds.hi <= 0) continue;
    const Component* c = project.FindComponent(w.component);
    if (!c || !CarriesCaseTorque(*c)) continue;
    if (std::find(pc.load_path.begin(), pc.load_path.end(), w.component) == pc.load_path.end()) continue;
    // local_torque is the upper bound of the torque at the component's own speed, torque the same
    // at the shaft speed: their ratio is the speed ratio.
    const double at_shaft = w.allowable * w.torque.bounds.hi / w.local_torque;
    if (best.component.empty() || at_shaft < best.value) best = {at_shaft, w.component, w.allowable_name};
  }
  return best;
}

}  // namespace

/// The campaign's results as the page shows them: its identity and state, the envelope per
/// component (torque at the component's own speed against its capacity) and the peak per case
/// (at the shaft speed, as the peak cases). Throws InputError when the campaign belongs to
/// another project or to this one before it changed.
nlohmann::json CampaignJson(const Project& project, const campaign::CampaignSummary& summary) {
  const std::string hash = campaign::ProjectHash(project);
  if (summary.project_hash != hash)
    throw InputError("--campaign " + summary.file.string() + ": the campaign was run on project '" +
                     summary.project_name + "' (content hash " + summary.project_hash + "), and " + project.file + " holds '" +
                     project.name + "' (hash " + hash +
                     "): another project, or this one changed since; the envelope would not describe this design: run `highlift campaign` on this project again "
                     "(a new --out folder) or give the campaign of this project");
  nlohmann::json j = summary.ToJson();
  j["brief"] = summary.BriefReport();
  return j;
}

void ReportOptions::Validate() const {
  if (shaft_elements < 0)
    throw InputError("report option shaft_elements = " + std::to_string(shaft_elements) +
                     ": give 0 (the project's setting) or 1 or more spring-dampers per shaft");
  if (max_points < 100)
    throw InputError("report option max_points = " + std::to_string(max_points) +
                     ": give at least 100 points per time history");
  if (threads < 0) throw InputError("report option threads = " + std::to_string(threads) + ": give 0 (all) or more");
}

DesignReport BuildDesignReport(const Project& project, const Project& estimated, const std::string& estimation_brief,
                               const ReportOptions& options) {
  options.Validate();
  if (!sim::IsDriveSystemProject(project))
    throw InputError(project.file + ": the report describes a drive system, and this project has no components "
                     "(an element network): use `highlift simulate` for it");
  const Clock::time_point start = Clock::now();
  DesignReport out;
  nlohmann::json& data = out.data;
  data["project"] = {{"name", project.name}, {"description", project.description}, {"file", project.file},
                     {"sources", project.sources}};
  // The optimize result first: a file of another project is refused before the analyses run.
  data["synthesis"] = nullptr;
  if (!options.optimize.empty()) {
    data["synthesis"] = ReadSynthesis(project, options.optimize);
    out.synthesis_ok = data["synthesis"]["found"].get<bool>();
  }

  // Summary: the interval check, as `highlift check`.
  Clock::time_point t = Clock::now();
  const icsp::DriveSystemNetwork net = icsp::BuildDriveSystemNetwork(estimated);
  const icsp::CheckResult check = icsp::CheckDriveSystem(net, options.propagation);
  data["check"] = CheckDocument(estimated, net, check, estimation_brief);
  const Verdict verdict = DescribeVerdict(data["check"]);
  data["verdict"] = {{"status", verdict.status}, {"headline", verdict.headline}, {"domains", verdict.domains},
                     {"nominal", verdict.nominal}};
  out.feasible = check.feasible;
  out.nominal_feasible = !check.nominal_checked || check.nominal_feasible;
  out.timings.check = Since(t);
  data["requirements"] = nlohmann::json::array();
  for (const Requirement& r : project.requirements)
    data["requirements"].push_back({{"id", r.id}, {"expression", r.expression}, {"description", r.description}});

  // Architecture
  const SpanLayout layout = LayOutAlongSpan(estimated);
  data["components"] = ComponentsJson(estimated, layout);
  data["span_from_lengths"] = layout.from_lengths;
  nlohmann::json edges = nlohmann::json::array();
  for (const auto& [a, b] : layout.edges) edges.push_back({a, b});
  data["edges"] = edges;

  // Sizing
  t = Clock::now();
  const reduced_models::SizingReport sizing = reduced_models::Size(project, {});
  data["sizing"] = sizing.ToJson();
  out.timings.sizing = Since(t);

  // Modes
  t = Clock::now();
  const reduced_models::ModesReport modes = reduced_models::AnalyseModes(project, {});
  data["modes"] = ModesJson(modes, project, layout);
  out.timings.modes = Since(t);

  // Peaks, single-DOF
  t = Clock::now();
  const reduced_models::PeakReport peaks = reduced_models::AnalysePeaks(project, {});
  out.timings.peaks = Since(t);

  // Simulations: every sizing case (transient peaks) and every project scenario (time
  // histories); a scenario that is a sizing case runs once.
  const std::vector<SignalChoice> signals = ChooseSignals(project);
  std::deque<SimulationJob> jobs;
  if (options.transient) {
    for (const auto& pc : peaks.cases) {
      SimulationJob& job = jobs.emplace_back();
      job.scenario = sim::SizingScenario(project, pc.kind, pc.component);
      job.peak_case = &pc;
    }
  }
  if (options.scenarios) {
    for (const Scenario& s : project.scenarios) {
      auto same = std::find_if(jobs.begin(), jobs.end(), [&](const SimulationJob& j) { return j.scenario.name == s.name; });
      if (same != jobs.end()) {
        same->keep_history = true;
        continue;
      }
      SimulationJob& job = jobs.emplace_back();
      job.scenario = s;
      job.keep_history = true;
    }
  }
  t = Clock::now();
  RunJobs(project, options, signals, jobs);
  out.timings.simulations = Since(t);
  out.timings.simulation_count = static_cast<int>(jobs.size());
  for (const auto& job : jobs) {
    out.timings.simulated += job.report.wall_seconds;
    out.simulations_ok = out.simulations_ok && job.report.ok();
  }

  // Peak loads: single-DOF beside transient beside capacity, per case.
  nlohmann::json cases = nlohmann::json::array();
  nlohmann::json margins = nlohmann::json::array();
  for (const auto& pc : peaks.cases) {
    nlohmann::json c = {{"name", pc.name}, {"kind", pc.kind}, {"component", pc.component}, {"acts_at", pc.acts_at},
                        {"single_dof", {{"nominal", Number(pc.tau_total.nominal)},
                                        {"min", Number(pc.tau_total.bounds.lo)},
                                        {"max", Number(pc.tau_total.bounds.hi)}}}};
    nlohmann::json ranking = nlohmann::json::array();  // the parameters that widen the enclosure most
    for (std::size_t k = 0; k < pc.ranking.size() && k < 3; ++k)
      ranking.push_back({{"parameter", pc.ranking[k].parameter}, {"share", Round(pc.ranking[k].share)}});
    c["ranking"] = ranking;
    const Capacity capacity = CaseCapacity(project, pc, peaks);
    if (!capacity.component.empty())
      c["capacity"] = {{"value", Number(capacity.value)}, {"component", capacity.component}, {"name", capacity.name}};
    c["transient"] = nullptr;
    for (const auto& job : jobs) {
      if (job.peak_case != &pc) continue;
      // The largest shaft (or brake) torque on the load path, referred to the shaft speed, as
      // `highlift peak --transient` reports it.
      nlohmann::json tr = {{"scenario", job.scenario.name}, {"ok", job.report.ok()}, {"message", job.report.message},
                           {"passivity", job.report.passivity.BriefReport()}};
      double best = 0;
      for (const sim::PeakTorque& p : job.component_peaks) {
        const Component* comp = project.FindComponent(p.element);
        if (!comp || !CarriesCaseTorque(*comp)) continue;
        if (std::find(pc.load_path.begin(), pc.load_path.end(), p.element) == pc.load_path.end()) continue;
        auto k = job.model.speed_factor.find(p.element);
        const double at_shaft = std::abs(p.tau) * (k == job.model.speed_factor.end() ? 1.0 : k->second);
        if (at_shaft > best) {
          best = at_shaft;
          tr["at"] = p.element;
          tr["time"] = Round(p.time);
        }
      }
      tr["value"] = Number(best);
      c["transient"] = tr;
      if (!capacity.component.empty() && best > 0)
        margins.push_back({{"what", "transient peak, " + pc.name}, {"component", tr.value("at", "")},
                           {"load", Number(best)}, {"allowable", Number(capacity.value)},
                           {"allowable_name", capacity.name + " of " + capacity.component},
                           {"margin", Number(capacity.value / best - 1)}});
    }
    cases.push_back(c);
  }
  data["peak_cases"] = cases;

  // Per component: its single-DOF value beside the largest simulated torque of any sizing case,
  // with the flag of `highlift peak --transient` (campaign::CompareWithTransient, one law).
  nlohmann::json components = nlohmann::json::array();
  if (options.transient) {
    std::vector<campaign::SimulatedCase> simulated;
    for (const auto& job : jobs)
      if (job.peak_case)
        simulated.push_back({job.peak_case->name, job.report.ok() && job.error.empty(),
                             campaign::ComponentTorquesAtInput(project, job.component_peaks)});
    for (const auto& c : campaign::CompareWithTransient(peaks, simulated))
      components.push_back({{"component", c.component}, {"single_dof", Number(c.single_dof)},
                            {"single_dof_case", c.single_dof_case}, {"transient", Number(c.transient)},
                            {"transient_case", c.transient_case}, {"bound", c.bound()}, {"flag", c.Flag()}});
  }
  data["peak_components"] = components;

  // The campaign: envelope over the samples, per case the largest peak over the samples.
  data["campaign"] = nullptr;
  if (!options.campaign.empty()) {
    const Clock::time_point t_campaign = Clock::now();
    const campaign::CampaignSummary summary = campaign::LoadSummary(options.campaign);
    nlohmann::json cj = CampaignJson(project, summary);
    out.campaign_ok = summary.complete() && summary.ok();
    std::map<std::string, const campaign::CasePeakRow*> by_case;
    for (const auto& k : summary.case_peaks) by_case.emplace(k.case_name, &k);
    for (auto& c : data["peak_cases"]) {
      const auto it = by_case.find(c["name"].get<std::string>());
      if (it == by_case.end()) continue;
      const campaign::CasePeakRow& k = *it->second;
      c["campaign"] = {{"value", Number(k.peak)}, {"at", k.peak_component}, {"sample", k.peak_sample},
                       {"time", Round(k.peak_time)}, {"runs", k.runs}, {"failures", k.failures}};
    }
    for (const auto& e : summary.envelope)
      if (e.margin)
        margins.push_back({{"what", "campaign envelope, " + e.case_name + " sample " + std::to_string(e.sample)},
                           {"component", e.component}, {"load", Number(std::abs(e.torque))},
                           {"allowable", Number(e.capacity)}, {"allowable_name", e.capacity_name + " of " + e.component},
                           {"margin", Number(*e.margin)}});
    data["campaign"] = std::move(cj);
    out.timings.campaign = Since(t_campaign);
  }

  // Worst margins: steady state (sizing), single-DOF peaks, transient peaks; smallest first.
  for (const auto& m : sizing.margins)
    margins.push_back({{"what", "steady state"}, {"component", m.component}, {"load", Number(m.load)},
                       {"allowable", Number(m.allowable)}, {"allowable_name", m.allowable_name},
                       {"margin", Number(m.margin)}});
  for (const auto& w : peaks.worst)
    if (w.allowable > 0)
      margins.push_back({{"what", "single-DOF peak, " + w.worst_case}, {"component", w.component},
                         {"load", Number(w.local_torque)}, {"allowable", Number(w.allowable)},
                         {"allowable_name", w.allowable_name}, {"margin", Number(w.margin)}});
  std::stable_sort(margins.begin(), margins.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    const double ma = a["margin"].is_null() ? INFINITY : a["margin"].get<double>();
    const double mb = b["margin"].is_null() ? INFINITY : b["margin"].get<double>();
    return ma < mb;
  });
  data["margins"] = margins;

  // Time histories of the project's scenarios, in project order.
  nlohmann::json histories = nlohmann::json::array();
  for (const Scenario& s : project.scenarios)
    for (const auto& job : jobs)
      if (job.keep_history && job.scenario.name == s.name) histories.push_back(HistoryJson(project, job, options.max_points));
  data["scenarios"] = histories;

  out.timings.total = Since(start);
  data["timings"] = {{"check", Round(out.timings.check)},         {"sizing", Round(out.timings.sizing)},
                     {"modes", Round(out.timings.modes)},         {"peaks", Round(out.timings.peaks)},
                     {"campaign", Round(out.timings.campaign)},
                     {"simulations", Round(out.timings.simulations)},
                     {"simulated", Round(out.timings.simulated)}, {"simulation_count", out.timings.simulation_count},
                     {"total", Round(out.timings.total)}};
  return out;
}

std::string DesignReport::BriefReport() const {
  const std::string name = data["project"].value("name", "");
  std::string s = "report of " + name + ": " + data["verdict"].value("headline", "");
  s += "; " + std::to_string(timings.simulation_count) + " simulations in " + FormatNumber(timings.simulations, 3) +
       " s" + (simulations_ok ? "" : " (some failed: see the peak loads and scenarios sections)") + ", analyses " +
       FormatNumber(timings.Tool(), 3) + " s";
  if (data.contains("campaign") && !data["campaign"].is_null())
    s += "; campaign: " + data["campaign"].value("brief", std::string());
  if (data.contains("synthesis") && !data["synthesis"].is_null())
    s += "; synthesis: " + data["synthesis"].value("status", std::string());
  return s;
}

}  // namespace highlift::report
