// `highlift campaign` from the command line: bad input (exit 2, nothing written), the summary,
// agreement with `peak --transient`, and a campaign killed with SIGKILL and resumed.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <thread>

#include "common/run_cli.h"
#include "highlift/componentdb/sqlite.h"
#include "test_util.h"

namespace highlift::campaign {
namespace {

namespace fs = std::filesystem;
using highlift::testing::RunCli;

const std::string kExample = "examples/a380_class_flaps.json";

fs::path Scratch(const std::string& name) { return testing::Scratch("cli-" + name); }

/// The summary JSON without the file name.
nlohmann::json Comparable(const std::string& out) { return testing::WithoutFile(nlohmann::json::parse(out)); }

TEST(CampaignCli, BadInputIsExit2WithAMessageAndWritesNothing) {
  const fs::path out = Scratch("bad");
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"--cases", "jam_z*"}, "--cases 'jam_z*' matches no case; the cases are: jam_l1,"},
      {{"--corners", "pdu.ratio"}, "--corners 'pdu.ratio': the parameter has no domain to sample"},
      {{"--samples", "2", "--vary", "wtb_left.inertia"}, "--vary 'wtb_left.inertia': the parameter has no domain to sample"},
      {{"--shard", "4/4"}, "--shard '4/4' is invalid: give I/N with 0 <= I < N"},
      {{"--shard", "x"}, "--shard 'x' is invalid"},
      {{"--model", "coarse"}, "coarse"},
      {{"--sampling", "random"}, "--sampling 'random' is unknown; choose 'sobol' or 'lhs'"},
      {{"--jobs", "-2"}, "--jobs -2: give 1 or more threads"},
      {{"--max-steps", "-5"}, "--max-steps -5: give 1 or more solver steps"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"campaign", kExample, "--out", out.string()};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = RunCli(args);
    EXPECT_EQ(r.exit_code, 2) << c.args.front() << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args.front() << " wrote " << out;
  }
  const auto none = RunCli({"campaign", "summary", out.string()});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("does not exist: give the --out directory of a campaign"), std::string::npos) << none.err;
}

TEST(CampaignCli, MergingShardsOfDifferentCampaignsIsExit2) {
  const fs::path a = Scratch("merge-a"), b = Scratch("merge-b"), out = Scratch("merge-out");
  const std::vector<std::string> common = {"--cases", "jam_l1", "--model", "reduced"};
  auto run = [&](const fs::path& dir, const std::string& shard, const std::string& seed) {
    std::vector<std::string> args = {"campaign", kExample, "--out", dir.string(), "--shard", shard,
                                     "--samples", "1", "--seed", seed};
    args.insert(args.end(), common.begin(), common.end());
    const auto r = RunCli(args);
    ASSERT_LE(r.exit_code, 1) << r.err;
  };
  run(a, "0/2", "1");
  run(b, "1/2", "2");
  const auto r = RunCli({"campaign", "merge", a.string(), b.string(), "--out", out.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("only shards of one campaign can be merged"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "campaign.sqlite"));
}

TEST(CampaignCli, NominalTransientPeakIsTheOneOfPeakTransient) {
  // The campaign's nominal run of a case is the simulation `peak --transient` makes of it.
  const fs::path out = Scratch("peak");
  const auto c = RunCli({"campaign", kExample, "--out", out.string(), "--cases", "jam_l3", "--json", "--jobs", "1"});
  ASSERT_LE(c.exit_code, 1) << c.err;
  const auto p = RunCli({"peak", kExample, "--transient", "--case", "jam_l3", "--json", "--no-intervals"});
  ASSERT_LE(p.exit_code, 1) << p.err;
  const nlohmann::json campaign = nlohmann::json::parse(c.out), peak = nlohmann::json::parse(p.out);
  ASSERT_EQ(campaign["case_peaks"].size(), 1u);
  ASSERT_EQ(peak["transient"].size(), 1u);
  // The same model and scenario; the campaign writes 20 rows per run where peak --transient
  // writes one per kPeakOutputInterval, and the output times (CVODE's stop times, its time
  // tolerance) move the step sequence at round-off: the peaks agree to 1e-6, not to the bit.
  const double campaign_peak = campaign["case_peaks"][0]["peak_N_m"].get<double>();
  EXPECT_NEAR(campaign_peak, peak["transient"][0]["transient"].get<double>(), 1e-6 * campaign_peak);
  EXPECT_EQ(campaign["case_peaks"][0]["at"], peak["transient"][0]["at"]);
  EXPECT_EQ(campaign["case_peaks"][0]["single_dof_N_m"].get<double>(), peak["transient"][0]["single_dof"].get<double>());
  // One allowable of the actuators in both (issue 26 item 3: peak and campaign agree on the
  // actuators): the campaign's capacity is peak's allowable, and an actuator the campaign finds
  // overloaded has a negative peak margin (peak's single-DOF value bounds the simulated torque).
  const auto all = RunCli({"peak", kExample, "--json", "--no-intervals"});
  ASSERT_LE(all.exit_code, 1) << all.err;
  std::map<std::string, nlohmann::json> worst;
  const nlohmann::json peak_all = nlohmann::json::parse(all.out);
  for (const auto& w : peak_all["worst"]) worst[w["component"].get<std::string>()] = w;
  int actuators = 0;
  for (const auto& e : campaign["envelope"]) {
    const std::string id = e["component"].get<std::string>();
    if (id.rfind("gra_", 0) != 0) continue;
    ++actuators;
    ASSERT_TRUE(worst.count(id)) << id;
    const double allowable = worst[id]["allowable_N_m"].get<double>();
    EXPECT_NEAR(e["capacity_N_m"].get<double>(), allowable, 1e-9 * allowable) << id;
    if (e["margin"].get<double>() < 0) {
      EXPECT_LT(worst[id]["margin"].get<double>(), 0.0) << id;
    }
  }
  EXPECT_EQ(actuators, 12);
  // summary prints the same JSON again.
  const auto s = RunCli({"campaign", "summary", out.string(), "--json"});
  EXPECT_EQ(s.exit_code, c.exit_code);
  EXPECT_EQ(Comparable(s.out), Comparable(c.out));
  const auto text = RunCli({"campaign", "summary", out.string()});
  EXPECT_NE(text.out.find("Design-load envelope"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("1/1 runs"), std::string::npos) << text.out;
}

int CommittedRuns(const fs::path& file) {
  try {
    if (!fs::exists(file)) return 0;
    componentdb::sqlite::Connection c(file, componentdb::sqlite::Connection::Mode::kReadOnly);
    return static_cast<int>(c.QueryInteger("SELECT count(*) FROM runs"));
  } catch (const std::exception&) {
    return 0;  // being created
  }
}

TEST(CampaignCli, AKilledCampaignResumesToTheSameEnvelope) {
  const fs::path killed = Scratch("killed"), whole = Scratch("uninterrupted");
  // 12 jams x (nominal + 3 Sobol points) = 48 reduced-model runs, one thread.
  const std::vector<std::string> options = {"--cases", "jam_*", "--samples", "3", "--model", "reduced", "--jobs", "1"};
  std::vector<std::string> args = {"campaign", std::string(HIGHLIFT_SOURCE_DIR) + "/" + kExample, "--out", killed.string()};
  args.insert(args.end(), options.begin(), options.end());

  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::vector<char*> argv = {const_cast<char*>(HIGHLIFT_CLI_PATH)};
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    execv(HIGHLIFT_CLI_PATH, argv.data());
    _exit(127);
  }
  // Kill it (SIGKILL: no handler runs) once a few runs are committed.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int committed = 0;
  while ((committed = CommittedRuns(killed / "campaign.sqlite")) < 5 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the campaign ended before it was killed";
  committed = CommittedRuns(killed / "campaign.sqlite");
  ASSERT_GE(committed, 5);
  ASSERT_LT(committed, 48) << "the campaign finished before it was killed";

  std::vector<std::string> again = {"campaign", kExample, "--out", killed.string(), "--json"};
  again.insert(again.end(), options.begin(), options.end());
  const auto resumed = RunCli(again);
  ASSERT_LE(resumed.exit_code, 1) << resumed.err;
  EXPECT_NE(resumed.err.find(std::to_string(committed) + " resumed from the file"), std::string::npos) << resumed.err;

  std::vector<std::string> straight = {"campaign", kExample, "--out", whole.string(), "--json"};
  straight.insert(straight.end(), options.begin(), options.end());
  const auto uninterrupted = RunCli(straight);
  ASSERT_LE(uninterrupted.exit_code, 1) << uninterrupted.err;
  const nlohmann::json a = Comparable(resumed.out), b = Comparable(uninterrupted.out);
  EXPECT_EQ(a["runs_done"], 48);
  EXPECT_EQ(a["envelope"], b["envelope"]);
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace highlift::campaign
