// `highlift campaign summary`: the envelope, the per-case peaks and the failures of a result file.
#include <cmath>
#include <map>
#include <sstream>

#include "highlift/campaign/campaign.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "internal.h"
#include "store.h"

namespace highlift::campaign {
namespace {

constexpr double kMarginResolution = 1e-12;  // |margin| below this is 0 (capacity / torque rounding)

nlohmann::json Optional(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

std::string Number(const std::optional<double>& v, int digits = 4) { return v ? FormatNumber(*v, digits) : "-"; }

std::filesystem::path FindResultFile(const std::filesystem::path& path) {
  if (std::filesystem::is_regular_file(path)) return path;
  if (!std::filesystem::is_directory(path))
    throw InputError("'" + path.string() + "' does not exist: give the --out directory of a campaign or its result file");
  const std::filesystem::path file = ResultFile(path, Shard{});
  if (std::filesystem::is_regular_file(file)) return file;
  for (const auto& entry : std::filesystem::directory_iterator(path))
    if (entry.path().filename().string().rfind("campaign-shard-", 0) == 0)
      throw InputError("'" + path.string() + "' holds shard files but no campaign.sqlite: merge them first with "
                       "`highlift campaign merge " + path.string() + "`, or give one shard file");
  throw InputError("'" + path.string() + "' holds no campaign result (campaign.sqlite); run `highlift campaign PROJECT --out " +
                   path.string() + "` first");
}

}  // namespace

CampaignSummary LoadSummary(const std::filesystem::path& file_or_directory) {
  const std::filesystem::path file = FindResultFile(file_or_directory);
  detail::sqlite::Connection c(file, detail::sqlite::Connection::Mode::kReadOnly);
  const detail::FileIdentity id = detail::ReadIdentity(c);
  CampaignSummary s;
  s.file = file;
  s.campaign_id = id.campaign_id;
  s.project_name = id.project_name;
  s.project_hash = id.project_hash;
  s.model = id.model;
  s.relative_tolerance = id.relative_tolerance;
  s.shard = id.shard.ToString();
  s.runs_total = detail::RunsInShard(id.runs_total, id.shard);
  s.samples_per_case = id.samples_per_case;
  s.edited_runs = detail::RunsNotMatchingChecksums(c);
  detail::CheckRunsBelongToPlan(c, id);  // runs_done <= runs_total

  struct CaseInfo {
    std::string name, kind, load_case;
  };
  std::vector<CaseInfo> cases;
  {
    detail::sqlite::Statement q(c, "SELECT name, kind, load_case FROM cases ORDER BY case_index");
    while (q.Step()) cases.push_back({q.Text(0), q.Text(1), q.Text(2)});
  }
  s.cases = static_cast<int>(cases.size());
  {
    detail::sqlite::Statement q(c, "SELECT name FROM parameters ORDER BY parameter_index");
    while (q.Step()) s.parameters.push_back(q.Text(0));
  }

  // Runs, in run order (ties in the envelope go to the first run: independent of scheduling).
  struct RunInfo {
    int case_index = 0, sample = 0;
    std::string label;
  };
  std::map<int, RunInfo> runs;
  std::vector<CasePeakRow> per_case(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    per_case[i].case_name = cases[i].name;
    per_case[i].kind = cases[i].kind;
    per_case[i].load_case = cases[i].load_case;
  }
  {
    detail::sqlite::Statement q(c,
                                "SELECT run, case_index, sample, sample_label, status, message, peak, peak_component, "
                                "peak_time, single_dof FROM runs ORDER BY run");
    while (q.Step()) {
      const int run = static_cast<int>(q.Integer(0));
      const std::int64_t k = q.Integer(1);
      if (k < 0 || k >= static_cast<std::int64_t>(cases.size()))
        throw InputError("'" + file.string() + "' is damaged: run " + std::to_string(run) + " names case " +
                         std::to_string(k) + ", and the file holds " + std::to_string(cases.size()) +
                         " case(s); run the campaign again into a new --out directory");
      runs[run] = {static_cast<int>(k), static_cast<int>(q.Integer(2)), q.Text(3)};
      ++s.runs_done;
      s.rejected_draws += detail::RejectedDraws(runs[run].label);
      CasePeakRow& row = per_case.at(static_cast<std::size_t>(k));
      ++row.runs;
      const std::optional<double> single_dof = q.OptionalReal(9);
      if (single_dof && (!row.single_dof_max || *single_dof > *row.single_dof_max)) row.single_dof_max = single_dof;
      if (runs[run].sample == 0) row.single_dof = single_dof;
      if (q.Text(4) != "ok") {
        ++s.failures;
        ++row.failures;
        s.failed.push_back({run, cases.at(static_cast<std::size_t>(k)).name, runs[run].sample, q.Text(5)});
        continue;
      }
      const double peak = q.Real(6);
      if (row.runs - row.failures == 1 || peak > row.peak) {
        row.peak = peak;
        row.peak_component = q.Text(7);
        row.peak_sample = runs[run].sample;
        row.peak_time = q.Real(8);
      }
    }
  }
  s.case_peaks = std::move(per_case);
  if (!s.complete()) {
    const detail::Interruption last = detail::LastInterruption(c);
    s.interrupted_signal = last.signal;
    s.interrupted_time = last.time;
  }
  s.not_passive =
      c.QueryInteger("SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = 'passivity'") == 0
          ? -1
          : static_cast<int>(c.QueryInteger("SELECT count(*) FROM passivity WHERE violations > 0"));

  std::map<std::string, std::pair<std::string, double>> capacities;
  {
    detail::sqlite::Statement q(c, "SELECT component, name, capacity FROM capacities");
    while (q.Step()) capacities[q.Text(0)] = {q.Text(1), q.Real(2)};
  }
  std::map<std::string, EnvelopeRow> envelope;
  std::vector<std::string> order;  // first appearance: project order
  {
    detail::sqlite::Statement q(c, "SELECT run, component, torque, time FROM component_peaks ORDER BY run, position");
    while (q.Step()) {
      auto found = runs.find(static_cast<int>(q.Integer(0)));
      if (found == runs.end()) continue;  // of a deleted run: edited_runs names it
      const RunInfo& r = found->second;
      const std::string component = q.Text(1);
      const double torque = q.Real(2);
      auto it = envelope.find(component);
      if (it == envelope.end()) {
        order.push_back(component);
        it = envelope.emplace(component, EnvelopeRow()).first;
        it->second.component = component;
        it->second.torque = NAN;
      }
      EnvelopeRow& e = it->second;
      if (std::isnan(e.torque) || std::abs(torque) > std::abs(e.torque)) {
        e.torque = torque;
        e.case_name = cases.at(static_cast<std::size_t>(r.case_index)).name;
        e.sample = r.sample;
        e.sample_label = r.label;
        e.time = q.Real(3);
      }
    }
  }
  for (const std::string& component : order) {
    EnvelopeRow e = envelope.at(component);
    if (auto k = capacities.find(component); k != capacities.end()) {
      e.capacity_name = k->second.first;
      e.capacity = k->second.second;
      if (std::abs(e.torque) > 0) {
        // A torque equal to the capacity is margin 0, not a rounding error's -1e-16.
        const double margin = e.capacity / std::abs(e.torque) - 1.0;
        e.margin = std::abs(margin) < kMarginResolution ? 0.0 : margin;
      }
    }
    s.envelope.push_back(std::move(e));
  }
  return s;
}

bool CampaignSummary::ok() const {
  if (failures > 0 || interrupted_signal != 0 || !edited_runs.empty()) return false;
  for (const auto& e : envelope)
    if (e.margin && *e.margin < 0) return false;
  return true;
}

std::string CampaignSummary::BriefReport() const {
  int negative = 0;
  const EnvelopeRow* worst = nullptr;
  for (const auto& e : envelope) {
    if (e.margin && *e.margin < 0) ++negative;
    if (e.margin && (!worst || *e.margin < *worst->margin)) worst = &e;
  }
  std::ostringstream out;
  out << "campaign " << campaign_id << " of '" << project_name << "': " << runs_done << "/" << runs_total << " runs"
      << (interrupted_signal != 0
              ? " (interrupted by signal " + std::to_string(interrupted_signal) +
                    (interrupted_time.empty() ? std::string() : " at " + interrupted_time) + ": " +
                    std::to_string(runs_total - runs_done) + " run(s) left to do; run the same command again to resume)"
              : complete() ? "" : " (incomplete: run the same command again to resume)")
      << ", " << failures << " failed, "
      << rejected_draws << " sampled draw(s) rejected (a parameter relation or, with --feasible, a requirement broken)";
  if (not_passive != 0)
    out << ", " << (not_passive < 0 ? std::string("negative dissipation not recorded")
                                    : std::to_string(not_passive) + " with negative dissipation");
  if (worst)
    out << "; smallest margin " << FormatNumber(*worst->margin, 3) << " at " << worst->component << " (" << worst->case_name
        << ", " << worst->sample_label << ")";
  out << (negative ? "; " + std::to_string(negative) + " negative margin(s)" : std::string("; all margins >= 0"));
  if (!edited_runs.empty())
    out << "; " << edited_runs.size() << " run(s) (first: run " << edited_runs.front()
        << ") do not match their checksums: the file was edited or damaged after the runs, do not trust it";
  return out.str();
}

std::string CampaignSummary::FullReport() const {
  std::ostringstream out;
  out << "Campaign " << campaign_id << ": project '" << project_name << "' (hash " << project_hash << "), " << model
      << " model, " << cases << " case(s) x " << samples_per_case << " sample(s)";
  if (relative_tolerance > 0) out << ", rtol " << FormatNumber(relative_tolerance, 3);
  if (shard != "0/1") out << ", shard " << shard;
  out << "\nresult file: " << file.string() << "\n";
  if (!parameters.empty()) {
    out << "parameters set per sample (" << parameters.size() << "):";
    for (std::size_t i = 0; i < parameters.size() && i < 8; ++i) out << " " << parameters[i];
    if (parameters.size() > 8) out << " ...";
    out << "\n";
  }
  out << "\nDesign-load envelope: the largest |torque| of every run per component, N*m at the component's own speed,\n"
         "against its capacity (nominal design):\n";
  TextTable envelope_table({"component", "|torque|", "case", "sample", "t [s]", "capacity", "margin"}, {1, 4, 5, 6});
  for (const auto& e : envelope)
    envelope_table.AddRow({e.component, FormatNumber(std::abs(e.torque), 5), e.case_name, e.sample_label,
                           FormatNumber(e.time, 4),
                           e.capacity > 0 ? FormatNumber(e.capacity, 5) + " (" + e.capacity_name + ")" : "-",
                           Number(e.margin, 3)});
  out << envelope_table.ToString() << "\n";
  out << "Peak per case: the largest shaft or brake torque on the case's load path, N*m at the shaft speed, over the\n"
         "samples, beside the single-DOF estimate (nominal and largest over the samples):\n";
  TextTable case_table({"case", "load case", "runs", "failed", "transient", "at", "sample", "single-DOF", "max single-DOF"},
                       {2, 3, 4, 6, 7, 8});
  for (const auto& k : case_peaks)
    case_table.AddRow({k.case_name, k.load_case.empty() ? "-" : k.load_case, std::to_string(k.runs),
                       std::to_string(k.failures), k.runs > k.failures ? FormatNumber(k.peak, 5) : "-",
                       k.peak_component.empty() ? "-" : k.peak_component,
                       k.runs > k.failures ? std::to_string(k.peak_sample) : "-", Number(k.single_dof, 5),
                       Number(k.single_dof_max, 5)});
  out << case_table.ToString() << "\n";
  if (!failed.empty()) {
    out << "Failed runs:\n";
    TextTable failure_table({"run", "case", "sample", "message"}, {0, 2});
    for (const auto& f : failed)
      failure_table.AddRow({std::to_string(f.run), f.case_name, std::to_string(f.sample), f.message});
    out << failure_table.ToString() << "\n";
  }
  out << BriefReport();
  return out.str();
}

nlohmann::json CampaignSummary::ToJson() const {
  nlohmann::json j = {{"campaign_id", campaign_id}, {"project", project_name}, {"project_hash", project_hash},
                      {"model", model},
                      {"relative_tolerance", relative_tolerance > 0 ? nlohmann::json(relative_tolerance) : nlohmann::json(nullptr)},
                      {"shard", shard},          {"file", file.string()},
                      {"runs_total", runs_total},  {"runs_done", runs_done}, {"failures", failures},
                      {"not_passive", not_passive >= 0 ? nlohmann::json(not_passive) : nlohmann::json(nullptr)},
                      {"rejected_draws", rejected_draws},
                      {"cases", cases},            {"samples_per_case", samples_per_case},
                      {"parameters", parameters},  {"complete", complete()}, {"ok", ok()},
                      {"interrupted", interrupted_signal != 0}, {"edited_runs", edited_runs}};
  if (interrupted_signal != 0) {
    j["interrupted_signal"] = interrupted_signal;
    j["interrupted_at"] = interrupted_time.empty() ? nlohmann::json(nullptr) : nlohmann::json(interrupted_time);
  }
  j["envelope"] = nlohmann::json::array();
  for (const auto& e : envelope)
    j["envelope"].push_back({{"component", e.component},   {"torque_N_m", e.torque},   {"case", e.case_name},
                             {"sample", e.sample},         {"sample_label", e.sample_label}, {"time_s", e.time},
                             {"capacity_name", e.capacity_name}, {"capacity_N_m", e.capacity},
                             {"margin", Optional(e.margin)}});
  j["case_peaks"] = nlohmann::json::array();
  for (const auto& k : case_peaks)
    j["case_peaks"].push_back({{"case", k.case_name},          {"kind", k.kind},
                                {"load_case", k.load_case},     {"runs", k.runs},
                                {"failures", k.failures},       {"peak_N_m", k.peak},
                                {"at", k.peak_component},       {"sample", k.peak_sample},
                                {"time_s", k.peak_time},        {"single_dof_N_m", Optional(k.single_dof)},
                                {"single_dof_max_N_m", Optional(k.single_dof_max)}});
  j["failed"] = nlohmann::json::array();
  for (const auto& f : failed)
    j["failed"].push_back({{"run", f.run}, {"case", f.case_name}, {"sample", f.sample}, {"message", f.message}});
  return j;
}

}  // namespace highlift::campaign
