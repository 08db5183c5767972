// Running a campaign (threads, progress, resume) and merging the shards of a Slurm job array.
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <iomanip>
#include <map>
#include <mutex>
#include <ostream>
#include <sstream>
#include <thread>
#include <unistd.h>

#include "highlift/campaign/campaign.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/core/text_table.h"
#include "lock.h"
#include "store.h"

namespace highlift::campaign {
namespace {

int AvailableCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

std::string Duration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  std::ostringstream out;
  if (s >= 3600) out << s / 3600 << "h" << std::setw(2) << std::setfill('0') << (s % 3600) / 60 << "m";
  else if (s >= 60) out << s / 60 << "m" << std::setw(2) << std::setfill('0') << s % 60 << "s";
  else out << s << "s";
  return out.str();
}

/// A bar redrawn in place on a terminal, one line per run in a log.
class Progress {
 public:
  Progress(std::ostream* out, bool terminal, int total, int done_before, int failures_before)
      : out_(out), terminal_(terminal), total_(total), done_(done_before), failures_(failures_before),
        done_before_(done_before), start_(std::chrono::steady_clock::now()) {}

  void Finished(const RunResult& r, const Plan& plan) {
    ++done_;
    failures_ += r.ok ? 0 : 1;
    if (!out_) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const int now = done_ - done_before_;
    const double eta = now > 0 ? elapsed / now * (total_ - done_) : 0.0;
    std::ostringstream line;
    if (terminal_) {
      constexpr int kWidth = 30;
      const int filled = total_ > 0 ? kWidth * done_ / total_ : kWidth;
      line << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
           << std::string(static_cast<std::size_t>(kWidth - filled), '.') << "] " << done_ << "/" << total_
           << " runs, " << failures_ << " failed, " << std::fixed << std::setprecision(1)
           << (elapsed > 0 ? now / elapsed : 0.0) << " runs/s, ETA " << Duration(eta) << "   ";
      if (done_ == total_) line << "\n";
    } else {
      line << "campaign: " << done_ << "/" << total_ << " runs done, " << failures_ << " failed, ETA " << Duration(eta)
           << " | run " << r.run << " " << plan.cases[static_cast<std::size_t>(r.case_index)].name << " "
           << r.sample_label << ": "
           << (r.ok ? "ok, peak " + FormatNumber(r.peak, 5) + " N*m at " + (r.peak_component.empty() ? "-" : r.peak_component)
                    : "FAILED: " + r.message)
           << "\n";
    }
    *out_ << line.str() << std::flush;
  }

  /// A signal stopped the campaign: ends the bar's line on a terminal.
  void Stopped() {
    if (out_ && terminal_ && done_ < total_) *out_ << "\n" << std::flush;
  }

 private:
  std::ostream* out_;
  bool terminal_;
  int total_, done_, failures_, done_before_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

std::string CampaignReport::BriefReport() const {
  std::ostringstream out;
  out << "campaign '" << file.string() << "': " << runs_done_before + runs_done_now << "/" << runs_in_shard << " runs ("
      << runs_done_now << " now";
  if (runs_done_before > 0) out << ", " << runs_done_before << " resumed from the file";
  out << "), " << failures << " failed, " << std::fixed << std::setprecision(1) << wall_seconds << " s wall";
  if (interrupted_signal != 0)
    out << "; interrupted by signal " << interrupted_signal << ": " << runs_left
        << " run(s) left to do, run the same command again to resume them";
  return out.str();
}

std::filesystem::path ResultFile(const std::filesystem::path& directory, const Shard& shard) {
  if (shard.whole()) return directory / "campaign.sqlite";
  return directory / ("campaign-shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".sqlite");
}

CampaignReport RunCampaign(const Project& project, const Plan& plan, const ExecutionOptions& options) {
  if (options.jobs < 0) throw InputError("--jobs " + std::to_string(options.jobs) + ": give 1 or more threads (0: every core)");
  if (options.shard.count < 1 || options.shard.index < 0 || options.shard.index >= options.shard.count)
    throw InputError("shard " + options.shard.ToString() + " is invalid: give I/N with 0 <= I < N");
  const auto start = std::chrono::steady_clock::now();
  // From here on SIGINT/SIGTERM only set InterruptRequested(): the runs stop cleanly and the
  // finished ones are committed (a second signal ends the process at once; the committed runs
  // stay all the same).
  const InterruptibleScope interruptible;
  CampaignReport report;
  report.file = ResultFile(options.directory, options.shard);
  std::filesystem::create_directories(options.directory);
  const detail::ResultFileLock lock(report.file, "running a campaign into it");
  detail::ResultStore store(report.file, project, plan, options.shard);

  const std::set<int> done = store.DoneRuns();
  std::vector<int> pending;
  for (int run = options.shard.index; run < plan.runs(); run += options.shard.count)
    if (!done.count(run)) pending.push_back(run);
  report.runs_in_shard = detail::RunsInShard(plan.runs(), options.shard);
  report.runs_done_before = static_cast<int>(done.size());
  Progress progress(options.progress, options.progress_is_terminal, report.runs_in_shard, report.runs_done_before,
                    store.Failures());

  const int jobs = std::max(1, std::min<int>(options.jobs > 0 ? options.jobs : AvailableCores(),
                                             static_cast<int>(pending.size())));
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::condition_variable ready;
  std::deque<RunResult> finished;
  int working = 0;  // workers not yet done (under mutex)
  std::vector<std::thread> workers;
  for (int w = 0; w < jobs && !pending.empty(); ++w) {
    ++working;
    workers.emplace_back([&] {
      // After a signal no run starts; a run the signal stopped comes back marked interrupted.
      for (std::size_t i; !InterruptRequested() && (i = next.fetch_add(1)) < pending.size();) {
        RunResult r = ExecuteRun(project, plan, pending[i]);
        std::lock_guard<std::mutex> lock(mutex);
        finished.push_back(std::move(r));
        ready.notify_one();
      }
      std::lock_guard<std::mutex> lock(mutex);
      --working;
      ready.notify_one();
    });
  }
  // This thread is the only writer: each run is committed as it arrives.
  std::string error;
  for (;;) {
    RunResult r;
    {
      std::unique_lock<std::mutex> lock(mutex);
      ready.wait(lock, [&] { return !finished.empty() || working == 0; });
      if (finished.empty()) break;
      r = std::move(finished.front());
      finished.pop_front();
    }
    if (r.interrupted) continue;  // not a result: the run stays to do
    try {
      store.Write(r);
    } catch (const std::exception& e) {
      error = e.what();
      next.store(pending.size());  // hand out no more runs; the committed ones stay
      break;
    }
    ++report.runs_done_now;
    report.run_seconds += r.build_seconds + r.single_dof_seconds + r.simulate_seconds;
    report.simulate_seconds += r.simulate_seconds;
    progress.Finished(r, plan);
  }
  for (auto& w : workers) w.join();
  if (!error.empty()) throw std::runtime_error("writing the campaign results failed: " + error);
  report.failures = store.Failures();
  report.runs_left = report.runs_in_shard - report.runs_done_before - report.runs_done_now;
  if (InterruptRequested()) {
    report.interrupted_signal = InterruptSignal();
    progress.Stopped();
    // In the file too, so that a later `campaign summary` says "interrupted", not only "incomplete".
    if (report.runs_left > 0) store.RecordInterruption(report.interrupted_signal, report.runs_left);
  }
  report.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

// ---------------------------------------------------------------------------------------------
// Merging shards

std::filesystem::path MergeShards(const std::vector<std::filesystem::path>& inputs, const std::filesystem::path& out) {
  if (inputs.empty()) throw InputError("give the directories (or files) of the shards to merge");
  std::vector<std::filesystem::path> files;
  for (const auto& in : inputs) {
    if (std::filesystem::is_directory(in)) {
      std::vector<std::filesystem::path> here;
      for (const auto& entry : std::filesystem::directory_iterator(in)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("campaign-shard-", 0) == 0 && entry.path().extension() == ".sqlite") here.push_back(entry.path());
      }
      if (here.empty())
        throw InputError("directory '" + in.string() + "' holds no shard files (campaign-shard-I-of-N.sqlite)");
      std::sort(here.begin(), here.end());
      files.insert(files.end(), here.begin(), here.end());
    } else if (std::filesystem::is_regular_file(in)) {
      files.push_back(in);
    } else {
      throw InputError("'" + in.string() + "' does not exist: give shard directories or files");
    }
  }
  struct Input {
    std::filesystem::path file;
    detail::FileIdentity identity;
    int done = 0;
  };
  std::vector<Input> shards;
  for (const auto& f : files) {
    detail::sqlite::Connection c(f, detail::sqlite::Connection::Mode::kReadOnly);
    Input in{f, detail::ReadIdentity(c), 0};
    detail::CheckRunsBelongToPlan(c, in.identity);  // then done <= the shard's runs
    in.done = static_cast<int>(c.QueryInteger("SELECT count(*) FROM runs"));
    const std::vector<int> edited = detail::RunsNotMatchingChecksums(c);
    if (!edited.empty()) {
      std::string list;
      for (std::size_t k = 0; k < edited.size() && k < 10; ++k) list += (k ? ", " : "") + std::to_string(edited[k]);
      if (edited.size() > 10) list += ", ...";
      throw InputError("'" + f.string() + "': " + std::to_string(edited.size()) +
                       " run(s) do not match the checksums recorded when they were committed (run " + list +
                       "): the file was edited or damaged after the runs; run that shard again into a new --out "
                       "directory and merge that file");
    }
    shards.push_back(in);
  }
  const Input& first = shards.front();
  std::map<int, const Input*> by_index;
  for (const Input& s : shards) {
    if (s.identity.campaign_id != first.identity.campaign_id)
      throw InputError("'" + s.file.string() + "' belongs to campaign " + s.identity.campaign_id + " (project '" +
                       s.identity.project_name + "', hash " + s.identity.project_hash + "), '" + first.file.string() +
                       "' to campaign " + first.identity.campaign_id + " (project '" + first.identity.project_name +
                       "', hash " + first.identity.project_hash + "): only shards of one campaign can be merged");
    if (s.identity.shard.count != first.identity.shard.count)
      throw InputError("'" + s.file.string() + "' is shard " + s.identity.shard.ToString() + ", '" + first.file.string() +
                       "' shard " + first.identity.shard.ToString() + ": the shards were cut differently");
    auto [it, inserted] = by_index.emplace(s.identity.shard.index, &s);
    if (!inserted)
      throw InputError("shard " + s.identity.shard.ToString() + " is given twice: '" + it->second->file.string() +
                       "' and '" + s.file.string() + "'");
    const int expected = detail::RunsInShard(s.identity.runs_total, s.identity.shard);
    if (s.done != expected)
      throw InputError("shard " + s.identity.shard.ToString() + " ('" + s.file.string() + "') is incomplete: " +
                       std::to_string(s.done) + " of " + std::to_string(expected) +
                       " runs; run its command again (it resumes) before merging");
  }
  std::vector<std::string> missing;
  for (int i = 0; i < first.identity.shard.count; ++i)
    if (!by_index.count(i))
      missing.push_back(ResultFile("", Shard{i, first.identity.shard.count}).string() + " (shard " +
                        Shard{i, first.identity.shard.count}.ToString() + ")");
  if (!missing.empty()) {
    std::string list;
    for (const auto& m : missing) list += (list.empty() ? "" : ", ") + m;
    throw InputError("shards missing from campaign " + first.identity.campaign_id + ": " + list);
  }
  const std::filesystem::path target = ResultFile(out, Shard{});
  if (std::filesystem::exists(target))
    throw InputError("'" + target.string() + "' exists already; remove it or merge into another --out directory");

  std::filesystem::create_directories(out);
  const detail::ResultFileLock lock(target, "merging shards into it");
  if (std::filesystem::exists(target))  // merged by another process meanwhile
    throw InputError("'" + target.string() + "' exists already; remove it or merge into another --out directory");
  const std::filesystem::path partial = target.string() + ".merging";
  std::filesystem::remove(partial);
  const TemporaryFileGuard removed_on_a_signal(partial.string());
  try {
    // A new file under a temporary name, renamed when complete: no transaction needed (ATTACH
    // is not allowed inside one), and a failure leaves nothing under the result name.
    detail::sqlite::Connection c(partial, detail::sqlite::Connection::Mode::kReadWriteCreate);
    c.Execute("PRAGMA journal_mode = OFF; PRAGMA synchronous = OFF");
    detail::CreateSchema(c);
    bool metadata = false;
    for (const auto& [index, s] : by_index) {
      detail::sqlite::Statement attach(c, "ATTACH DATABASE ? AS shard");
      attach.Bind(1, s->file.string()).Run();
      if (!metadata) {
        c.Execute(
            "INSERT INTO campaign SELECT * FROM shard.campaign;"
            "UPDATE campaign SET value = '0' WHERE key = 'shard_index';"
            "UPDATE campaign SET value = '1' WHERE key = 'shard_count';"
            "INSERT INTO cases SELECT * FROM shard.cases;"
            "INSERT INTO parameters SELECT * FROM shard.parameters;"
            "INSERT INTO capacities SELECT * FROM shard.capacities;");
        metadata = true;
      }
      const std::int64_t duplicates =
          c.QueryInteger("SELECT count(*) FROM shard.runs WHERE run IN (SELECT run FROM main.runs)");
      if (duplicates > 0)
        throw InputError("'" + s->file.string() + "' holds " + std::to_string(duplicates) +
                         " run(s) that another shard holds too: the shard files were copied or renamed");
      c.Execute(
          "INSERT INTO runs SELECT * FROM shard.runs;"
          "INSERT INTO run_values SELECT * FROM shard.run_values;"
          "INSERT INTO component_peaks SELECT * FROM shard.component_peaks;"
          "INSERT INTO checksums SELECT * FROM shard.checksums;");
      if (c.QueryInteger("SELECT count(*) FROM shard.sqlite_master WHERE type = 'table' AND name = 'passivity'") > 0) {
        detail::CreatePassivityTable(c);
        c.Execute("INSERT INTO passivity SELECT * FROM shard.passivity;");
      }
      c.Execute("DETACH DATABASE shard;");
    }
  } catch (...) {
    std::filesystem::remove(partial);
    throw;
  }
  std::filesystem::rename(partial, target);
  return target;
}

}  // namespace highlift::campaign
