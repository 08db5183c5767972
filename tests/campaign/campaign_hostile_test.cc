// Campaigns under hostile use (issue 27): a signal leaves the unfinished runs to do and the
// summary says "interrupted" (items 1, 14 for peak --transient), --elements has simulate's range
// (15), --samples and the number of runs are bounded (17), a second campaign into the same
// result file is refused naming the holder of the lock (18), and a shard or result file edited
// after its runs is refused on merge and flagged by the summary (21).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <streambuf>
#include <thread>

#include "common/run_cli.h"
#include "highlift/campaign/campaign.h"
#include "highlift/componentdb/sqlite.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/sim/drive_network.h"
#include "test_util.h"

namespace highlift::campaign {
namespace {

namespace fs = std::filesystem;
using highlift::testing::RunCli;
using testing::A380;
using testing::MessageOf;
using testing::Scratch;

const std::string kExample = "examples/a380_class_flaps.json";

/// Three reduced-model cases at the nominal point and two corners: 9 runs.
Plan SmallPlan() {
  CampaignOptions o;
  o.case_patterns = {"jam_l3", "jam_r6", "rupture_shaft_l1"};
  o.corners = {"pdu.motor_inertia"};
  o.model = sim::DriveResolution::kReduced;
  return MakePlan(A380(), o);
}

/// A progress stream that requests an interruption (as the CLI's SIGINT handler does) when the
/// first run is reported: the runs then in progress are stopped by the simulator.
class InterruptOnFirstLine : public std::streambuf {
 protected:
  int_type overflow(int_type ch) override {
    if (ch == '\n') RequestInterrupt(SIGINT);
    return traits_type::not_eof(ch);
  }
};

/// Runs `plan` into `dir` on `jobs` threads, interrupted (SIGINT requested) when the first run
/// is reported; the interruption request is cleared again before it returns.
CampaignReport RunInterruptedAtFirstRun(const Plan& plan, const fs::path& dir, int jobs) {
  InterruptOnFirstLine buffer;
  std::ostream progress(&buffer);
  ExecutionOptions e;
  e.directory = dir;
  e.jobs = jobs;
  e.progress = &progress;
  const CampaignReport stopped = RunCampaign(A380(), plan, e);
  ClearInterrupt();
  return stopped;
}

int Count(const fs::path& file, const std::string& sql) {
  componentdb::sqlite::Connection c(file, componentdb::sqlite::Connection::Mode::kReadOnly);
  return static_cast<int>(c.QueryInteger(sql));
}

using highlift::testing::ReadFile;
using highlift::testing::StartCli;
using highlift::testing::WaitCli;

/// Runs the plan as two shards into `dir`.
void RunTwoShards(const Plan& plan, const fs::path& dir) {
  for (int i = 0; i < 2; ++i) {
    ExecutionOptions e;
    e.directory = dir;
    e.jobs = 1;
    e.shard = Shard{i, 2};
    RunCampaign(A380(), plan, e);
  }
}

// --- item 1: interrupted runs stay to do ---------------------------------------------------------

TEST(CampaignInterruption, RunsStoppedByASignalStayToDoAndTheNextSessionDoesThem) {
  // Was: every run in progress or started after the signal was committed as FAILED "interrupted
  // by signal", a resume skipped them and the summary said complete with those failures.
  const Plan plan = SmallPlan();
  ASSERT_EQ(plan.runs(), 9);
  const fs::path dir = Scratch("interrupted");
  const CampaignReport stopped = RunInterruptedAtFirstRun(plan, dir, 2);
  EXPECT_EQ(stopped.interrupted_signal, SIGINT);
  EXPECT_GE(stopped.runs_done_now, 1);
  EXPECT_LT(stopped.runs_done_now, 9) << "no run was stopped";
  EXPECT_EQ(stopped.failures, 0);
  EXPECT_EQ(stopped.runs_left, 9 - stopped.runs_done_now);
  EXPECT_NE(stopped.BriefReport().find("interrupted by signal 2: " + std::to_string(stopped.runs_left) +
                                       " run(s) left to do, run the same command again to resume them"),
            std::string::npos)
      << stopped.BriefReport();
  const fs::path file = dir / "campaign.sqlite";
  EXPECT_EQ(Count(file, "SELECT count(*) FROM runs"), stopped.runs_done_now);
  EXPECT_EQ(Count(file, "SELECT count(*) FROM runs WHERE status != 'ok'"), 0);
  EXPECT_FALSE(fs::exists(file.string() + ".lock")) << "the lock file stays after the session";

  CampaignSummary summary = LoadSummary(dir);
  summary.interrupted_signal = stopped.interrupted_signal;
  EXPECT_FALSE(summary.complete());
  EXPECT_FALSE(summary.ok());
  EXPECT_EQ(summary.ToJson()["interrupted"], true);
  EXPECT_NE(summary.BriefReport().find("(interrupted by signal 2 at "), std::string::npos) << summary.BriefReport();

  ExecutionOptions e;
  e.directory = dir;
  e.jobs = 2;
  const CampaignReport resumed = RunCampaign(A380(), plan, e);
  EXPECT_EQ(resumed.interrupted_signal, 0);
  EXPECT_EQ(resumed.runs_done_before, stopped.runs_done_now);
  EXPECT_EQ(resumed.runs_done_now, 9 - stopped.runs_done_now);
  const CampaignSummary done = LoadSummary(dir);
  EXPECT_TRUE(done.complete());
  EXPECT_EQ(done.failures, 0);
  EXPECT_EQ(done.ToJson()["interrupted"], false);
}

TEST(CampaignInterruption, SigintEndsTheCommandWith130AndASummarySayingInterrupted) {
  const fs::path dir = Scratch("cli-sigint");
  fs::create_directories(dir);
  const fs::path out = dir / "result";
  // 12 jams x (nominal + 3 Sobol points) = 48 reduced-model runs, one thread.
  const std::vector<std::string> args = {"campaign", kExample, "--out", out.string(), "--cases", "jam_*", "--samples",
                                         "3", "--model", "reduced", "--jobs", "1", "--json"};
  const pid_t pid = StartCli(dir, args);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(90);
  const fs::path file = out / "campaign.sqlite";
  const auto committed = [&] {
    try {
      return fs::exists(file) ? Count(file, "SELECT count(*) FROM runs") : 0;
    } catch (const std::exception&) {
      return 0;
    }
  };
  while (committed() < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  const int code = WaitCli(pid);
  ASSERT_NE(code, 0) << "the campaign finished before the signal";
  EXPECT_EQ(code, 130) << ReadFile(dir / "stderr");
  const auto doc = nlohmann::json::parse(ReadFile(dir / "stdout"));
  EXPECT_EQ(doc["status"], "interrupted");
  EXPECT_EQ(doc["interrupted"], true);
  EXPECT_EQ(doc["complete"], false);
  EXPECT_EQ(doc["ok"], false);
  // (Some Sobol points fail on their own: a brake's static capacity below its dynamic torque.)
  const int done = doc["runs_done"];
  EXPECT_LT(done, 48);
  EXPECT_EQ(doc["failures"], Count(file, "SELECT count(*) FROM runs WHERE status != 'ok'"));
  EXPECT_EQ(Count(file, "SELECT count(*) FROM runs WHERE message LIKE '%interrupt%'"), 0);
  EXPECT_NE(ReadFile(dir / "stderr").find("run(s) left to do, run the same command again to resume them"),
            std::string::npos)
      << ReadFile(dir / "stderr");

  const auto resumed = RunCli(args);
  EXPECT_LE(resumed.exit_code, 1) << resumed.err;
  EXPECT_NE(resumed.err.find(std::to_string(done) + " resumed from the file"), std::string::npos) << resumed.err;
  const auto summary = nlohmann::json::parse(resumed.out);
  EXPECT_EQ(summary["runs_done"], 48);
  EXPECT_EQ(summary["complete"], true);
  EXPECT_EQ(summary["interrupted"], false);
  for (const auto& f : summary["failed"])
    EXPECT_EQ(f["message"].get<std::string>().find("interrupt"), std::string::npos) << f.dump();
}

// --- item 14: peak --transient interrupted -------------------------------------------------------

TEST(PeakInterruption, AnInterruptedTransientRunIsNeverOk) {
  // Was: exit 130 with `--json` saying "ok": true over 30 interrupted simulations.
  const fs::path dir = Scratch("peak-sigint");
  fs::create_directories(dir);
  const pid_t pid = StartCli(dir, {"peak", kExample, "--transient", "--no-intervals", "--json"});
  ASSERT_TRUE(highlift::testing::WaitUntilCatching(pid, SIGINT)) << ReadFile(dir / "stderr");
  // The single-DOF analysis takes well under a second; the 36 simulations about 15 s.
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  ::kill(pid, SIGINT);
  const int code = WaitCli(pid);
  if (code == 0 || code == 1) GTEST_SKIP() << "the simulations finished before the signal";
  EXPECT_EQ(code, 130) << ReadFile(dir / "stderr");
  const auto doc = nlohmann::json::parse(ReadFile(dir / "stdout"));
  EXPECT_EQ(doc["ok"], false);
  EXPECT_EQ(doc["status"], "interrupted");
  if (doc.contains("transient")) {  // stopped during the simulations (not in the analysis before)
    ASSERT_TRUE(doc.contains("interrupted")) << doc.dump();
    EXPECT_EQ(doc["interrupted"]["signal"], SIGINT);
    EXPECT_LT(doc["interrupted"]["simulated"].get<int>(), doc["interrupted"]["cases"].get<int>());
    int interrupted = 0;
    for (const auto& c : doc["transient"]) {
      if (c["status"] == "interrupted") {
        ++interrupted;
        EXPECT_EQ(c["ok"], false) << c.dump();
      }
    }
    EXPECT_LE(interrupted, 1) << "a case started after the signal";
  }
}

// --- item 15: --elements has simulate's range ----------------------------------------------------

TEST(CampaignLimits, ElementsBeyondSimulatesRangeAreRefusedBeforeAnyRun) {
  // Was: --elements 100000 accepted, then every run failed (the model refuses it).
  CampaignOptions o;
  o.shaft_elements = sim::DriveNetworkOptions::kMaxShaftElements + 1;
  const std::string m = MessageOf([&] { MakePlan(A380(), o); });
  EXPECT_NE(m.find("--elements 1001 is out of range; give 1 to 1000 spring-dampers per shaft (as for simulate)"),
            std::string::npos)
      << m;
  o.shaft_elements = sim::DriveNetworkOptions::kMaxShaftElements;
  EXPECT_NO_THROW(MakePlan(A380(), o));
  // Every command that takes --elements gives the same range.
  const fs::path out = Scratch("elements");
  for (const std::vector<std::string>& args : {std::vector<std::string>{"campaign", kExample, "--out", out.string()},
                                              {"simulate", kExample, "--scenario", "extension"},
                                              {"peak", kExample, "--transient"},
                                              {"report", kExample, "--out", (out.parent_path() / "e.html").string()}}) {
    std::vector<std::string> a = args;
    a.insert(a.end(), {"--elements", "100000"});
    const auto r = RunCli(a);
    EXPECT_EQ(r.exit_code, 2) << args.front() << ": " << r.err;
    EXPECT_NE(r.err.find("'100000' is out of range"), std::string::npos) << args.front() << ": " << r.err;
    EXPECT_NE(r.err.find("1 to 1000"), std::string::npos) << args.front() << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

// --- item 17: --samples and the runs are bounded ---------------------------------------------------

TEST(CampaignLimits, SamplesAndRunsAreBoundedAndTheMessageNamesTheOption) {
  // Was: --samples 1000000000 accepted, 3.9 GB allocated, an out-of-memory message about components.
  CampaignOptions o;
  o.samples = 1000000000;
  std::string m = MessageOf([&] { MakePlan(A380(), o); });
  EXPECT_NE(m.find("--samples 1000000000 is beyond the limit of 100000 quasi-random points per case: lower --samples"),
            std::string::npos)
      << m;
  o.samples = CampaignOptions::kMaxSamples;  // per case fine, but 38 cases of it are too many runs
  m = MessageOf([&] { MakePlan(A380(), o); });
  EXPECT_NE(m.find("38 case(s) x 100001 sample(s) = 3800038 runs, beyond the limit of 1000000 runs of a campaign: "
                   "lower --samples"),
            std::string::npos)
      << m;
  o.case_patterns = {"jam_l1"};
  const Plan plan = MakePlan(A380(), o);
  EXPECT_EQ(plan.runs(), 100001);

  const fs::path out = Scratch("samples");
  const auto r = RunCli({"campaign", kExample, "--out", out.string(), "--samples", "1000000000", "--json"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("lower --samples"), std::string::npos) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "invalid_input");
  EXPECT_FALSE(fs::exists(out));
}

// --- item 18: one writer per result file -----------------------------------------------------------

TEST(CampaignLock, ASecondCampaignIntoTheSameDirectoryIsRefusedNamingTheHolder) {
  // Was: no lock; the second campaign repeated the first one's runs and died on a raw
  // "UNIQUE constraint failed".
  const fs::path dir = Scratch("cli-lock");
  fs::create_directories(dir);
  const fs::path out = dir / "result";
  const std::vector<std::string> args = {"campaign", kExample, "--out", out.string(), "--cases", "jam_*",
                                         "--samples", "3", "--model", "reduced", "--jobs", "1"};
  const pid_t pid = StartCli(dir, args);
  const fs::path lock = out / "campaign.sqlite.lock";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (ReadFile(lock).find("pid ") == std::string::npos && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const auto second = RunCli(args);
  ::kill(pid, SIGTERM);
  const int first_code = WaitCli(pid);
  ASSERT_EQ(first_code, 130) << "the first campaign was not running all along: " << ReadFile(dir / "stderr");
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_NE(second.err.find("campaign.sqlite' is in use by another process: pid " + std::to_string(pid) + " on host "),
            std::string::npos)
      << second.err;
  EXPECT_NE(second.err.find(" UTC (running a campaign into it) holds its lock"), std::string::npos) << second.err;
  EXPECT_NE(second.err.find("wait until it has finished (or stop it), or give another --out directory"),
            std::string::npos)
      << second.err;
  EXPECT_EQ(second.err.find("UNIQUE"), std::string::npos) << second.err;
  EXPECT_FALSE(fs::exists(lock)) << "the lock file stays after the campaign stopped";
  // Nothing the second one did reached the file: every committed run is the first one's, ok.
  EXPECT_EQ(Count(out / "campaign.sqlite", "SELECT count(*) FROM runs WHERE status != 'ok'"), 0);
}

TEST(CampaignLock, ALockHeldByAnotherOpenFileIsRefusedInProcessToo) {
  const Plan plan = SmallPlan();
  const fs::path dir = Scratch("lock-in-process");
  fs::create_directories(dir);
  const fs::path lock = dir / "campaign.sqlite.lock";
  const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  ExecutionOptions e;
  e.directory = dir;
  e.jobs = 1;
  const std::string m = MessageOf([&] { RunCampaign(A380(), plan, e); });
  ::close(fd);
  EXPECT_NE(m.find("is in use by another process: a process that has not yet written who it is holds its lock"),
            std::string::npos)
      << m;
  EXPECT_FALSE(fs::exists(dir / "campaign.sqlite"));
  EXPECT_EQ(RunCampaign(A380(), plan, e).runs_done_now, 9);  // released: the campaign runs
}

// --- item 21: checksums ------------------------------------------------------------------------------

TEST(CampaignChecksums, AShardWhosePeaksWereEditedIsRefusedOnMergeAndFlaggedBySummary) {
  // Was: a shard whose peak values were edited merged silently.
  const Plan plan = SmallPlan();
  const fs::path shards = Scratch("checksum-shards"), out = Scratch("checksum-merged");
  RunTwoShards(plan, shards);
  const fs::path edited = shards / "campaign-shard-1-of-2.sqlite";
  EXPECT_TRUE(LoadSummary(edited).edited_runs.empty());
  {
    componentdb::sqlite::Connection c(edited, componentdb::sqlite::Connection::Mode::kReadWrite);
    c.Execute("UPDATE component_peaks SET torque = torque / 2 WHERE run = 3");
  }
  const CampaignSummary flagged = LoadSummary(edited);
  EXPECT_EQ(flagged.edited_runs, std::vector<int>{3});
  EXPECT_FALSE(flagged.ok());
  EXPECT_NE(flagged.BriefReport().find("1 run(s) (first: run 3) do not match their checksums"), std::string::npos)
      << flagged.BriefReport();
  const std::string m = MessageOf([&] { MergeShards({shards}, out); });
  EXPECT_NE(m.find("campaign-shard-1-of-2.sqlite': 1 run(s) do not match the checksums recorded when they were "
                   "committed (run 3): the file was edited or damaged after the runs"),
            std::string::npos)
      << m;
  EXPECT_FALSE(fs::exists(out / "campaign.sqlite"));

  // A peak of the runs table, and a deleted run, are found the same way.
  {
    componentdb::sqlite::Connection c(edited, componentdb::sqlite::Connection::Mode::kReadWrite);
    c.Execute("UPDATE component_peaks SET torque = torque * 2 WHERE run = 3");  // back as it was
  }
  EXPECT_TRUE(LoadSummary(edited).edited_runs.empty());
  {
    componentdb::sqlite::Connection c(edited, componentdb::sqlite::Connection::Mode::kReadWrite);
    c.Execute("UPDATE runs SET peak = peak + 1e-9 WHERE run = 5; DELETE FROM runs WHERE run = 7");
  }
  EXPECT_EQ(LoadSummary(edited).edited_runs, (std::vector<int>{5, 7}));
}

TEST(CampaignChecksums, AnUneditedMergeKeepsItsChecksums) {
  const Plan plan = SmallPlan();
  const fs::path shards = Scratch("checksum-clean"), out = Scratch("checksum-clean-merged");
  RunTwoShards(plan, shards);
  const CampaignSummary merged = LoadSummary(MergeShards({shards}, out));
  EXPECT_EQ(merged.runs_done, 9);
  EXPECT_TRUE(merged.edited_runs.empty());
  EXPECT_EQ(Count(out / "campaign.sqlite", "SELECT count(*) FROM checksums"), 9);
  EXPECT_FALSE(fs::exists(out / "campaign.sqlite.lock"));
}

// --- item 19: a count of runs done never exceeds the plan ("incomplete: 43 of 42 runs") ----------

void Edit(const fs::path& file, const std::string& sql) {
  componentdb::sqlite::Connection c(file, componentdb::sqlite::Connection::Mode::kReadWrite);
  c.Execute(sql);
}

TEST(CampaignCounts, ARunOutsideThePlanIsRefusedByNameNotCountedBeyondIt) {
  // Was: the summary counted every row of `runs` (10/9 runs, "complete": false, resume "9 of 9
  // left"), a shard with a run of another shard merged as "incomplete: 6 of 5 runs".
  const Plan plan = SmallPlan();
  const fs::path dir = Scratch("counts");
  ExecutionOptions e;
  e.directory = dir;
  e.jobs = 1;
  RunCampaign(A380(), plan, e);
  const fs::path file = dir / "campaign.sqlite";
  ASSERT_EQ(LoadSummary(dir).runs_done, 9);

  const fs::path beyond = Scratch("counts-beyond");
  fs::create_directories(beyond);
  fs::copy_file(file, beyond / "campaign.sqlite");
  Edit(beyond / "campaign.sqlite",
       "INSERT INTO runs SELECT 9, 3, 0, sample_label, status, message, peak, peak_component, peak_time, single_dof, "
       "steps, simulate_seconds FROM runs WHERE run = 8");
  std::string m = MessageOf([&] { LoadSummary(beyond); });
  EXPECT_NE(m.find("is damaged: it holds run 9, and its plan has runs 0 to 8; its runs would not add up to its plan"),
            std::string::npos)
      << m;
  ExecutionOptions resume = e;
  resume.directory = beyond;
  m = MessageOf([&] { RunCampaign(A380(), plan, resume); });
  EXPECT_NE(m.find("holds run 9, and its plan has runs 0 to 8"), std::string::npos) << m;

  // The same (case, sample) under two run numbers: run 4 (case 1, sample 1) relabelled as sample 0.
  const fs::path twice = Scratch("counts-twice");
  fs::create_directories(twice);
  fs::copy_file(file, twice / "campaign.sqlite");
  Edit(twice / "campaign.sqlite", "UPDATE runs SET sample = 0 WHERE run = 4");
  m = MessageOf([&] { LoadSummary(twice); });
  EXPECT_NE(m.find("holds run 4, and run 4 is case 1, sample 1 of its plan (3 samples per case), not case 1, sample 0"),
            std::string::npos)
      << m;

  // A file without a table this highlift reads: a sentence, not SQLite's raw "no such table"
  // behind "the SQLite library failed: " (item 19, raw SQLite texts).
  const fs::path lacking = Scratch("counts-lacking");
  fs::create_directories(lacking);
  fs::copy_file(file, lacking / "campaign.sqlite");
  Edit(lacking / "campaign.sqlite", "DROP TABLE component_peaks");
  try {
    LoadSummary(lacking);
    m = "(no error)";
  } catch (const std::exception& e) {
    m = e.what();
  }
  EXPECT_NE(m.find("the file lacks a table or column this highlift reads (no such table: component_peaks): it was "
                   "written by another program or version of highlift, or edited"),
            std::string::npos)
      << m;
  EXPECT_EQ(m.find("SQLite library failed"), std::string::npos) << m;

  // A plan whose size no longer matches its cases (runs_total edited).
  Edit(twice / "campaign.sqlite", "UPDATE runs SET sample = 1 WHERE run = 4; UPDATE campaign SET value = '8' WHERE key = 'runs_total'");
  m = MessageOf([&] { LoadSummary(twice); });
  EXPECT_NE(m.find("is damaged: it plans 8 runs, but holds 3 case(s) x 3 sample(s)"), std::string::npos) << m;
}

TEST(CampaignCounts, AShardHoldingARunOfAnotherShardIsRefusedOnMergeNamingIt) {
  const Plan plan = SmallPlan();
  const fs::path shards = Scratch("counts-shards"), out = Scratch("counts-shards-merged");
  RunTwoShards(plan, shards);
  const fs::path first = shards / "campaign-shard-0-of-2.sqlite";
  Edit(first,
       "ATTACH DATABASE '" + (shards / "campaign-shard-1-of-2.sqlite").string() + "' AS other;"
       "INSERT INTO runs SELECT * FROM other.runs WHERE run = 1; DETACH DATABASE other;");
  const std::string m = MessageOf([&] { MergeShards({shards}, out); });
  EXPECT_EQ(m.find("incomplete: 6 of 5"), std::string::npos) << m;
  EXPECT_NE(m.find("campaign-shard-0-of-2.sqlite' is damaged: it holds run 1, and it is shard 0/2, which holds the "
                   "runs I with I mod 2 = 0"),
            std::string::npos)
      << m;
  EXPECT_FALSE(fs::exists(out / "campaign.sqlite"));
  EXPECT_NE(MessageOf([&] { LoadSummary(first); }).find("holds run 1"), std::string::npos);
}

// --- item 4 of the leftovers of 19: the interruption is stored in the file ---------------------------

TEST(CampaignInterruption, TheFileRecordsTheInterruptionSoALaterSummarySaysIt) {
  // Was: a later `campaign summary` said only "incomplete" (the signal lived in the session).
  const Plan plan = SmallPlan();
  const fs::path dir = Scratch("interrupted-stored");
  const CampaignReport stopped = RunInterruptedAtFirstRun(plan, dir, 1);
  ASSERT_EQ(stopped.interrupted_signal, SIGINT);
  ASSERT_GT(stopped.runs_left, 0);

  const CampaignSummary later = LoadSummary(dir);  // a new process: nothing from the session
  EXPECT_EQ(later.interrupted_signal, SIGINT);
  EXPECT_EQ(later.interrupted_time.size(), 20u) << later.interrupted_time;  // 2026-12-03T16:30:54Z
  EXPECT_FALSE(later.ok());
  EXPECT_NE(later.BriefReport().find("(interrupted by signal 2 at " + later.interrupted_time + ": " +
                                     std::to_string(stopped.runs_left) + " run(s) left to do"),
            std::string::npos)
      << later.BriefReport();
  const nlohmann::json j = later.ToJson();
  EXPECT_EQ(j["interrupted"], true);
  EXPECT_EQ(j["interrupted_signal"], SIGINT);
  EXPECT_EQ(j["interrupted_at"], later.interrupted_time);

  // A file begun before the table: read as before ("incomplete"), and a resume adds the table.
  const fs::path old = Scratch("interrupted-old");
  fs::create_directories(old);
  fs::copy_file(dir / "campaign.sqlite", old / "campaign.sqlite");
  Edit(old / "campaign.sqlite", "DROP TABLE interruptions");
  const CampaignSummary before = LoadSummary(old);
  EXPECT_EQ(before.interrupted_signal, 0);
  EXPECT_NE(before.BriefReport().find("(incomplete: run the same command again to resume)"), std::string::npos)
      << before.BriefReport();

  // The resumed campaign completes: no longer interrupted.
  ExecutionOptions e;
  e.directory = dir;
  e.jobs = 1;
  RunCampaign(A380(), plan, e);
  const CampaignSummary done = LoadSummary(dir);
  EXPECT_TRUE(done.complete());
  EXPECT_EQ(done.interrupted_signal, 0);
  EXPECT_EQ(done.ToJson()["interrupted"], false);
  ExecutionOptions old_resume = e;
  old_resume.directory = old;
  RunCampaign(A380(), plan, old_resume);
  EXPECT_TRUE(LoadSummary(old).complete());
}

}  // namespace
}  // namespace highlift::campaign
