// The result file of a campaign (or of one shard): SQLite in WAL mode, one transaction per run.
//
//   campaign(key, value)       campaign_id, project_name, project_hash, model, shard_index,
//                              shard_count, runs_total, samples_per_case, format,
//                              relative_tolerance (absent in files from before --rtol)
//   cases(case_index, name, kind, component, load_case)
//   parameters(parameter_index, name, nominal, lo, hi)
//   capacities(component, name, capacity)            nominal design, from reduced_models
//   runs(run, case_index, sample, sample_label, status, message, peak, peak_component,
//        peak_time, single_dof, steps, simulate_seconds)
//   run_values(run, parameter_index, value)          the sampled values of each run
//   component_peaks(run, position, component, torque, time)   per run and component (project
//                              order), its largest |torque|
//   passivity(run, violations, report)   per run, the number of elements whose dissipated power
//                              fell below zero (sim::PassivityReport) and its brief report
//   checksums(run, digest)     per run, RunDigest of its rows when it was committed
//   interruptions(session, time, signal, runs_done, runs_left)   one row per session a signal
//                              stopped (UTC time, ISO 8601); files begun before it lack the table
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "highlift/campaign/campaign.h"
#include "highlift/componentdb/sqlite.h"

namespace highlift::campaign::detail {

namespace sqlite = componentdb::sqlite;

/// The metadata of a result file.
struct FileIdentity {
  std::string campaign_id;
  std::string project_name;
  std::string project_hash;
  std::string model;
  double relative_tolerance = 0.0;  ///< of every run; 0: not recorded (a file from before --rtol)
  Shard shard;
  int runs_total = 0;  ///< of the whole campaign
  int samples_per_case = 0;
};

/// Runs of the whole campaign that fall into `shard`.
int RunsInShard(int runs_total, const Shard& shard);

class ResultStore {
 public:
  /// Opens `file` for the plan's shard, creating it (schema, metadata, cases, parameters,
  /// capacities) when absent. Throws InputError when it holds another campaign or shard.
  ResultStore(const std::filesystem::path& file, const Project& project, const Plan& plan, const Shard& shard);
  /// Leaves the file in rollback-journal mode: one self-contained file (no -wal, -shm beside it)
  /// to copy or merge; the next session switches to WAL again.
  ~ResultStore();
  ResultStore(const ResultStore&) = delete;
  ResultStore& operator=(const ResultStore&) = delete;

  const FileIdentity& identity() const { return identity_; }
  std::set<int> DoneRuns();
  int Failures();
  /// Commits one finished run.
  void Write(const RunResult& result);
  /// Records that a signal stopped this session with `runs_left` runs of the shard still to do.
  void RecordInterruption(int signal, int runs_left);
  sqlite::Connection& connection() { return *connection_; }

 private:
  std::unique_ptr<sqlite::Connection> connection_;
  FileIdentity identity_;
};

/// The checksum of a run as stored: 16 hex digits of a hash (FNV-1a) of its row in `runs`, its
/// `run_values` and its `component_peaks`, every number exact; "" when the run is not in the file.
/// ResultStore::Write records it in `checksums` in the run's transaction. It finds edits and
/// damage after the run, not a forger who recomputes it.
std::string RunDigest(sqlite::Connection& connection, int run);
/// The runs whose rows no longer match their recorded checksum (or have none, or whose checksum
/// has no run any more), in run order.
std::vector<int> RunsNotMatchingChecksums(sqlite::Connection& connection);

/// The last interruption recorded in a result file (table `interruptions`).
struct Interruption {
  int signal = 0;    ///< 0: none recorded (or a file begun before the table)
  std::string time;  ///< UTC, ISO 8601
  int runs_left = 0;
};
Interruption LastInterruption(sqlite::Connection& connection);

/// Throws InputError naming the first run of the file that its plan does not have: a run
/// number outside [0, runs_total) or outside the file's shard, or a run whose case and sample
/// are not those its number stands for (run = case * samples_per_case + sample), and a file
/// whose runs_total is not its cases times samples_per_case. Every count of done runs then
/// stays within the plan (issue 27 item 19: "incomplete: 43 of 42 runs").
void CheckRunsBelongToPlan(sqlite::Connection& connection, const FileIdentity& identity);

/// Creates the tables of a result file (empty).
void CreateSchema(sqlite::Connection& connection);
/// Creates the table `passivity` unless the file has it.
void CreatePassivityTable(sqlite::Connection& connection);
/// Creates the table `interruptions` unless the file has it.
void CreateInterruptionsTable(sqlite::Connection& connection);
/// Reads the identity of a result file; throws InputError when it is no campaign result file.
FileIdentity ReadIdentity(sqlite::Connection& connection);

}  // namespace highlift::campaign::detail
