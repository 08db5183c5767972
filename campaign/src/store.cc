// The campaign result file (schema in store.h).
#include "store.h"

#include <cstdio>
#include <ctime>
#include <limits>

#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "internal.h"
#include "highlift/reduced_models/analyses.h"

namespace highlift::campaign::detail {
namespace {

// 2: the checksums table.
constexpr int kFormat = 2;

/// Exact text of a stored double (hexadecimal floating point), "N" for NULL.
void AddReal(std::string& text, const sqlite::Statement& s, int column) {
  if (s.IsNull(column)) {
    text += "N|";
    return;
  }
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a|", s.Real(column));
  text += buffer;
}
void AddInteger(std::string& text, const sqlite::Statement& s, int column) {
  text += s.IsNull(column) ? std::string("N") : std::to_string(s.Integer(column));
  text += '|';
}
void AddText(std::string& text, const sqlite::Statement& s, int column) {
  if (s.IsNull(column)) {
    text += "N|";
    return;
  }
  const std::string value = s.Text(column);
  text += std::to_string(value.size()) + ":" + value + "|";
}

std::string Get(sqlite::Connection& connection, const std::string& key) {
  sqlite::Statement s(connection, "SELECT value FROM campaign WHERE key = ?");
  s.Bind(1, key);
  if (!s.Step()) throw InputError("'" + connection.file() + "' is not a complete campaign result file: no '" + key + "'");
  return s.Text(0);
}

int GetInteger(sqlite::Connection& connection, const std::string& key) {
  const std::string text = Get(connection, key);
  std::size_t end = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &end);
  } catch (const std::exception&) {
    end = 0;
  }
  if (end == 0 || end != text.size() || value < 0 || value > std::numeric_limits<int>::max())
    throw InputError("'" + connection.file() + "' is damaged: its '" + key + "' is '" + CleanText(text, 80) +
                     "', not a whole number >= 0; run the campaign again into a new --out directory");
  return static_cast<int>(value);
}

void Put(sqlite::Statement& s, const std::string& key, const std::string& value) {
  s.Reset();
  s.Bind(1, key).Bind(2, value).Run();
}

}  // namespace

std::string RunDigest(sqlite::Connection& connection, int run) {
  std::string text = "run\n";
  {
    sqlite::Statement s(connection,
                        "SELECT run, case_index, sample, sample_label, status, message, peak, peak_component, peak_time, "
                        "single_dof, steps, simulate_seconds FROM runs WHERE run = ?");
    s.Bind(1, static_cast<std::int64_t>(run));
    if (!s.Step()) return "";
    for (int k : {0, 1, 2}) AddInteger(text, s, k);
    for (int k : {3, 4, 5}) AddText(text, s, k);
    AddReal(text, s, 6);
    AddText(text, s, 7);
    for (int k : {8, 9}) AddReal(text, s, k);
    AddInteger(text, s, 10);
    AddReal(text, s, 11);
  }
  {
    sqlite::Statement s(connection, "SELECT parameter_index, value FROM run_values WHERE run = ? ORDER BY parameter_index");
    s.Bind(1, static_cast<std::int64_t>(run));
    for (text += "\nvalues\n"; s.Step();) {
      AddInteger(text, s, 0);
      AddReal(text, s, 1);
    }
  }
  {
    sqlite::Statement s(connection,
                        "SELECT position, component, torque, time FROM component_peaks WHERE run = ? ORDER BY position");
    s.Bind(1, static_cast<std::int64_t>(run));
    for (text += "\npeaks\n"; s.Step();) {
      AddInteger(text, s, 0);
      AddText(text, s, 1);
      AddReal(text, s, 2);
      AddReal(text, s, 3);
    }
  }
  return Hex(Hash64(text));
}

std::vector<int> RunsNotMatchingChecksums(sqlite::Connection& connection) {
  std::map<int, std::string> recorded;
  {
    sqlite::Statement s(connection, "SELECT run, digest FROM checksums");
    while (s.Step()) recorded[static_cast<int>(s.Integer(0))] = s.Text(1);
  }
  std::set<int> bad;
  {
    sqlite::Statement s(connection, "SELECT run FROM runs ORDER BY run");
    while (s.Step()) {
      const int run = static_cast<int>(s.Integer(0));
      auto it = recorded.find(run);
      if (it == recorded.end() || it->second != RunDigest(connection, run)) bad.insert(run);
      if (it != recorded.end()) recorded.erase(it);
    }
  }
  for (const auto& [run, digest] : recorded) bad.insert(run);  // a checksum without its run: the run was deleted
  return {bad.begin(), bad.end()};
}

int RunsInShard(int runs_total, const Shard& shard) {
  return runs_total <= shard.index ? 0 : (runs_total - shard.index + shard.count - 1) / shard.count;
}

void CreateSchema(sqlite::Connection& connection) {
  connection.Execute(R"sql(
    CREATE TABLE campaign(key TEXT PRIMARY KEY, value TEXT NOT NULL);
    CREATE TABLE cases(case_index INTEGER PRIMARY KEY, name TEXT NOT NULL, kind TEXT NOT NULL,
                       component TEXT NOT NULL, load_case TEXT NOT NULL);
    CREATE TABLE parameters(parameter_index INTEGER PRIMARY KEY, name TEXT NOT NULL, nominal REAL NOT NULL,
                            lo REAL NOT NULL, hi REAL NOT NULL);
    CREATE TABLE capacities(component TEXT PRIMARY KEY, name TEXT NOT NULL, capacity REAL NOT NULL);
    CREATE TABLE runs(run INTEGER PRIMARY KEY, case_index INTEGER NOT NULL, sample INTEGER NOT NULL,
                      sample_label TEXT NOT NULL, status TEXT NOT NULL, message TEXT NOT NULL,
                      peak REAL, peak_component TEXT, peak_time REAL, single_dof REAL,
                      steps INTEGER NOT NULL, simulate_seconds REAL NOT NULL);
    CREATE TABLE run_values(run INTEGER NOT NULL, parameter_index INTEGER NOT NULL, value REAL NOT NULL,
                            PRIMARY KEY(run, parameter_index)) WITHOUT ROWID;
    CREATE TABLE component_peaks(run INTEGER NOT NULL, position INTEGER NOT NULL, component TEXT NOT NULL,
                                 torque REAL NOT NULL, time REAL NOT NULL, PRIMARY KEY(run, position)) WITHOUT ROWID;
    CREATE TABLE checksums(run INTEGER PRIMARY KEY, digest TEXT NOT NULL);
  )sql");
  CreatePassivityTable(connection);
  CreateInterruptionsTable(connection);
}

void CreateInterruptionsTable(sqlite::Connection& connection) {
  connection.Execute(
      "CREATE TABLE IF NOT EXISTS interruptions(session INTEGER PRIMARY KEY, time TEXT NOT NULL, "
      "signal INTEGER NOT NULL, runs_done INTEGER NOT NULL, runs_left INTEGER NOT NULL)");
}

Interruption LastInterruption(sqlite::Connection& connection) {
  Interruption last;
  if (connection.QueryInteger("SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = 'interruptions'") == 0)
    return last;
  sqlite::Statement s(connection, "SELECT signal, time, runs_left FROM interruptions ORDER BY session DESC LIMIT 1");
  if (s.Step()) {
    last.signal = static_cast<int>(s.Integer(0));
    last.time = s.Text(1);
    last.runs_left = static_cast<int>(s.Integer(2));
  }
  return last;
}

void CheckRunsBelongToPlan(sqlite::Connection& connection, const FileIdentity& id) {
  const std::string remedy = "; run the campaign again into a new --out directory";
  const std::int64_t cases = connection.QueryInteger("SELECT count(*) FROM cases");
  if (id.samples_per_case < 1 || cases * id.samples_per_case != id.runs_total)
    throw InputError("'" + connection.file() + "' is damaged: it plans " + std::to_string(id.runs_total) +
                     " runs, but holds " + std::to_string(cases) + " case(s) x " + std::to_string(id.samples_per_case) +
                     " sample(s)" + remedy);
  sqlite::Statement s(connection,
                      "SELECT run, case_index, sample FROM runs WHERE run < 0 OR run >= ?1 OR run % ?2 != ?3 "
                      "OR case_index != run / ?4 OR sample != run % ?4 ORDER BY run");
  s.Bind(1, static_cast<std::int64_t>(id.runs_total)).Bind(2, static_cast<std::int64_t>(id.shard.count))
      .Bind(3, static_cast<std::int64_t>(id.shard.index)).Bind(4, static_cast<std::int64_t>(id.samples_per_case));
  if (!s.Step()) return;
  const std::int64_t run = s.Integer(0), k = s.Integer(1), sample = s.Integer(2);
  std::int64_t others = 0;
  while (s.Step()) ++others;
  std::string why;
  if (run < 0 || run >= id.runs_total)
    why = "its plan has runs 0 to " + std::to_string(id.runs_total - 1);
  else if (run % id.shard.count != id.shard.index)
    why = "it is shard " + id.shard.ToString() + ", which holds the runs I with I mod " + std::to_string(id.shard.count) +
          " = " + std::to_string(id.shard.index);
  else
    why = "run " + std::to_string(run) + " is case " + std::to_string(run / id.samples_per_case) + ", sample " +
          std::to_string(run % id.samples_per_case) + " of its plan (" + std::to_string(id.samples_per_case) +
          " samples per case), not case " + std::to_string(k) + ", sample " + std::to_string(sample);
  throw InputError("'" + connection.file() + "' is damaged: it holds run " + std::to_string(run) + ", and " + why +
                   (others > 0 ? " (and " + std::to_string(others) + " more such run(s))" : std::string()) +
                   "; its runs would not add up to its plan" + remedy);
}

void CreatePassivityTable(sqlite::Connection& connection) {
  connection.Execute(
      "CREATE TABLE IF NOT EXISTS passivity(run INTEGER PRIMARY KEY, violations INTEGER NOT NULL, report TEXT NOT NULL)");
}

FileIdentity ReadIdentity(sqlite::Connection& connection) {
  if (connection.QueryInteger("SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = 'campaign'") == 0)
    throw InputError("'" + connection.file() + "' is not a campaign result file (no table 'campaign')");
  FileIdentity id;
  id.campaign_id = Get(connection, "campaign_id");
  id.project_name = Get(connection, "project_name");
  id.project_hash = Get(connection, "project_hash");
  id.model = Get(connection, "model");
  {
    sqlite::Statement s(connection, "SELECT value FROM campaign WHERE key = 'relative_tolerance'");
    if (s.Step()) {
      const std::string text = s.Text(0);
      char* end = nullptr;
      id.relative_tolerance = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(id.relative_tolerance > 0 && id.relative_tolerance < 1))
        throw InputError("'" + connection.file() + "' is damaged: its 'relative_tolerance' is '" + CleanText(text, 80) +
                         "', not a number in (0, 1); run the campaign again into a new --out directory");
    }
  }
  const int format = GetInteger(connection, "format");
  if (format != kFormat)
    throw InputError("'" + connection.file() + "' has result format " + std::to_string(format) + "; this highlift reads format " +
                     std::to_string(kFormat) + " (format 2 added the checksum of every run): run the campaign again");
  id.shard = {GetInteger(connection, "shard_index"), GetInteger(connection, "shard_count")};
  if (id.shard.count < 1 || id.shard.index >= id.shard.count)
    throw InputError("'" + connection.file() + "' is damaged: it calls itself shard " + id.shard.ToString() +
                     "; run the campaign again into a new --out directory");
  id.runs_total = GetInteger(connection, "runs_total");
  id.samples_per_case = GetInteger(connection, "samples_per_case");
  return id;
}

ResultStore::ResultStore(const std::filesystem::path& file, const Project& project, const Plan& plan, const Shard& shard) {
  if (std::filesystem::exists(file)) {
    connection_ = std::make_unique<sqlite::Connection>(file, sqlite::Connection::Mode::kReadWrite);
    identity_ = detail::ReadIdentity(*connection_);
    if (identity_.campaign_id != plan.campaign_id)
      throw InputError("'" + file.string() + "' holds campaign " + identity_.campaign_id + " (project '" +
                       identity_.project_name + "', hash " + identity_.project_hash + "), not this campaign " +
                       plan.campaign_id + " (project hash " + plan.project_hash +
                       "): the project or the options differ; give another --out or remove the file");
    if (identity_.shard.index != shard.index || identity_.shard.count != shard.count)
      throw InputError("'" + file.string() + "' holds shard " + identity_.shard.ToString() + ", not " + shard.ToString());
    connection_->Execute("PRAGMA journal_mode = WAL; PRAGMA synchronous = NORMAL");
    CreatePassivityTable(*connection_);  // a file begun before the passivity monitor
    CreateInterruptionsTable(*connection_);  // or before interruptions were recorded
    detail::CheckRunsBelongToPlan(*connection_, identity_);
    return;
  }
  // Everything the summary needs besides the runs, in one transaction: a file either has all of
  // it or does not exist in a usable form (a crash here leaves a file without 'campaign' rows,
  // which the next start rejects by name; creating into a temporary name avoids even that).
  const std::filesystem::path partial = file.string() + ".creating";
  std::filesystem::remove(partial);
  const TemporaryFileGuard removed_on_a_signal(partial.string());
  {
    sqlite::Connection c(partial, sqlite::Connection::Mode::kReadWriteCreate);
    sqlite::Transaction t(c);
    CreateSchema(c);
    sqlite::Statement put(c, "INSERT INTO campaign(key, value) VALUES(?, ?)");
    Put(put, "format", std::to_string(kFormat));
    Put(put, "campaign_id", plan.campaign_id);
    Put(put, "project_name", plan.project_name);
    Put(put, "project_hash", plan.project_hash);
    Put(put, "model", sim::ToString(plan.options.model));
    Put(put, "shard_index", std::to_string(shard.index));
    Put(put, "shard_count", std::to_string(shard.count));
    Put(put, "runs_total", std::to_string(plan.runs()));
    Put(put, "samples_per_case", std::to_string(plan.samples_per_case));
    Put(put, "seed", std::to_string(plan.options.seed));
    Put(put, "sampling", ToString(plan.options.sampling));
    Put(put, "relative_tolerance",  // shortest text that reads back exactly
        nlohmann::json(plan.options.relative_tolerance > 0 ? plan.options.relative_tolerance
                                                           : project.settings.relative_tolerance)
            .dump());
    sqlite::Statement add_case(c, "INSERT INTO cases VALUES(?, ?, ?, ?, ?)");
    for (std::size_t i = 0; i < plan.cases.size(); ++i) {
      const CampaignCase& k = plan.cases[i];
      add_case.Reset();
      add_case.Bind(1, static_cast<std::int64_t>(i)).Bind(2, k.name).Bind(3, k.kind).Bind(4, k.component)
          .Bind(5, k.scenario.load_case).Run();
    }
    sqlite::Statement add_parameter(c, "INSERT INTO parameters VALUES(?, ?, ?, ?, ?)");
    for (std::size_t i = 0; i < plan.parameters.size(); ++i) {
      const SampledParameter& p = plan.parameters[i];
      add_parameter.Reset();
      add_parameter.Bind(1, static_cast<std::int64_t>(i)).Bind(2, p.Name()).Bind(3, p.nominal).Bind(4, p.domain.lo)
          .Bind(5, p.domain.hi).Run();
    }
    reduced_models::PeakOptions nominal;
    nominal.intervals = false;
    nominal.rank = false;
    sqlite::Statement add_capacity(c, "INSERT INTO capacities VALUES(?, ?, ?)");
    for (const auto& w : reduced_models::AnalysePeaks(project, nominal).worst) {
      if (w.allowable <= 0) continue;
      add_capacity.Reset();
      add_capacity.Bind(1, w.component).Bind(2, w.allowable_name).Bind(3, w.allowable).Run();
    }
    t.Commit();
  }
  std::filesystem::rename(partial, file);
  connection_ = std::make_unique<sqlite::Connection>(file, sqlite::Connection::Mode::kReadWrite);
  connection_->Execute("PRAGMA journal_mode = WAL; PRAGMA synchronous = NORMAL");
  identity_ = detail::ReadIdentity(*connection_);
}

ResultStore::~ResultStore() {
  if (!connection_) return;
  try {
    connection_->Execute("PRAGMA journal_mode = DELETE");
  } catch (const std::exception&) {
    // Another reader holds the file open: it stays in WAL mode, which loses nothing.
  }
}

std::set<int> ResultStore::DoneRuns() {
  std::set<int> done;
  sqlite::Statement s(*connection_, "SELECT run FROM runs");
  while (s.Step()) done.insert(static_cast<int>(s.Integer(0)));
  return done;
}

void ResultStore::RecordInterruption(int signal, int runs_left) {
  char time[32] = "";
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  if (gmtime_r(&now, &utc) != nullptr) std::strftime(time, sizeof time, "%Y-%m-%dT%H:%M:%SZ", &utc);
  sqlite::Statement s(*connection_, "INSERT INTO interruptions(time, signal, runs_done, runs_left) VALUES(?, ?, ?, ?)");
  s.Bind(1, std::string(time)).Bind(2, static_cast<std::int64_t>(signal))
      .Bind(3, connection_->QueryInteger("SELECT count(*) FROM runs")).Bind(4, static_cast<std::int64_t>(runs_left)).Run();
}

int ResultStore::Failures() {
  return static_cast<int>(connection_->QueryInteger("SELECT count(*) FROM runs WHERE status != 'ok'"));
}

void ResultStore::Write(const RunResult& r) {
  sqlite::Transaction t(*connection_);
  {
    sqlite::Statement s(*connection_, "INSERT INTO runs VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    s.Bind(1, static_cast<std::int64_t>(r.run)).Bind(2, static_cast<std::int64_t>(r.case_index))
        .Bind(3, static_cast<std::int64_t>(r.sample)).Bind(4, r.sample_label).Bind(5, r.ok ? "ok" : "failed")
        .Bind(6, r.message);
    if (r.ok) {
      s.Bind(7, r.peak).Bind(8, r.peak_component).Bind(9, r.peak_time);
    } else {
      s.BindNull(7).BindNull(8).BindNull(9);
    }
    s.Bind(10, r.single_dof).Bind(11, static_cast<std::int64_t>(r.steps)).Bind(12, r.simulate_seconds).Run();
  }
  {
    sqlite::Statement s(*connection_, "INSERT INTO passivity VALUES(?, ?, ?)");
    s.Bind(1, static_cast<std::int64_t>(r.run)).Bind(2, static_cast<std::int64_t>(r.passivity.violations.size()))
        .Bind(3, r.passivity.BriefReport()).Run();
  }
  {
    sqlite::Statement s(*connection_, "INSERT INTO run_values VALUES(?, ?, ?)");
    for (std::size_t i = 0; i < r.values.size(); ++i) {
      s.Reset();
      s.Bind(1, static_cast<std::int64_t>(r.run)).Bind(2, static_cast<std::int64_t>(i)).Bind(3, r.values[i]).Run();
    }
  }
  {
    sqlite::Statement s(*connection_, "INSERT INTO component_peaks VALUES(?, ?, ?, ?, ?)");
    for (std::size_t i = 0; i < r.components.size(); ++i) {
      const sim::PeakTorque& p = r.components[i];
      s.Reset();
      s.Bind(1, static_cast<std::int64_t>(r.run)).Bind(2, static_cast<std::int64_t>(i)).Bind(3, p.element)
          .Bind(4, p.tau).Bind(5, p.time).Run();
    }
  }
  {
    // Of the rows as stored, so that the check reads exactly what it hashes.
    sqlite::Statement s(*connection_, "INSERT OR REPLACE INTO checksums VALUES(?, ?)");
    s.Bind(1, static_cast<std::int64_t>(r.run)).Bind(2, RunDigest(*connection_, r.run)).Run();
  }
  t.Commit();
}

}  // namespace highlift::campaign::detail
