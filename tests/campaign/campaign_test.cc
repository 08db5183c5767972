// Running campaigns: the same envelope whatever the number of threads or shards, resumption,
// failed runs recorded, merging and what merging refuses, and the simulator in parallel threads.
#include <gtest/gtest.h>

#include <thread>

#include "highlift/campaign/campaign.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/sim/drive_network.h"
#include "test_util.h"

namespace highlift::campaign {
namespace {

namespace fs = std::filesystem;

using testing::A380;
using testing::MessageOf;
using testing::Scratch;

/// A small reduced-model campaign: three cases, nominal + 2 corners + 2 Sobol points.
Plan SmallPlan(std::uint64_t seed = 7) {
  CampaignOptions o;
  o.case_patterns = {"jam_l3", "jam_r6", "rupture_shaft_l1"};
  o.corners = {"pdu.motor_inertia"};
  o.samples = 2;
  o.seed = seed;
  o.vary = {"pdu.speed_ramp_time", "pdu.efficiency"};
  o.model = sim::DriveResolution::kReduced;
  return MakePlan(A380(), o);
}

nlohmann::json Comparable(const CampaignSummary& s) { return testing::WithoutFile(s.ToJson()); }

CampaignReport RunShard(const Plan& plan, const fs::path& dir, int jobs, Shard shard = {}) {
  ExecutionOptions e;
  e.directory = dir;
  e.jobs = jobs;
  e.shard = shard;
  return RunCampaign(A380(), plan, e);
}

TEST(Campaign, SameEnvelopeWithOneOrThreeThreads) {
  const Plan plan = SmallPlan();
  ASSERT_EQ(plan.runs(), 15);
  const fs::path dir1 = Scratch("jobs1"), dir3 = Scratch("jobs3");
  const CampaignReport one = RunShard(plan, dir1, 1);
  const CampaignReport three = RunShard(plan, dir3, 3);
  EXPECT_EQ(one.runs_done_now, 15);
  EXPECT_EQ(three.runs_done_now, 15);
  const CampaignSummary a = LoadSummary(dir1);
  const CampaignSummary b = LoadSummary(dir3);
  EXPECT_TRUE(a.complete());
  EXPECT_EQ(a.failures, 0);
  EXPECT_EQ(Comparable(a), Comparable(b));
  // The envelope holds the shafts, brakes, actuators ... with a capacity and a margin for the
  // shafts; the jams put their largest torque into the jammed station's load path.
  ASSERT_FALSE(a.envelope.empty());
  bool shaft_with_margin = false;
  for (const auto& e : a.envelope) {
    EXPECT_GT(std::abs(e.torque), 0.0) << e.component;
    if (e.component == "shaft_l1") shaft_with_margin = e.margin.has_value() && e.capacity > 0;
  }
  EXPECT_TRUE(shaft_with_margin);
  ASSERT_EQ(a.case_peaks.size(), 3u);
  for (const auto& k : a.case_peaks) {
    EXPECT_EQ(k.runs, 5) << k.case_name;
    EXPECT_GT(k.peak, 0.0) << k.case_name;
    ASSERT_TRUE(k.single_dof.has_value()) << k.case_name;
    EXPECT_GT(*k.single_dof, 0.0);
    EXPECT_GE(*k.single_dof_max, *k.single_dof);
  }
}

TEST(Campaign, ResumesWhereItStoppedAndDoesNotRepeatRuns) {
  const Plan plan = SmallPlan();
  const fs::path dir = Scratch("resume");
  // Shard 0/1 in two sessions: the first session runs everything, the second finds it done.
  const CampaignReport first = RunShard(plan, dir, 2);
  const CampaignReport second = RunShard(plan, dir, 2);
  EXPECT_EQ(first.runs_done_now, 15);
  EXPECT_EQ(second.runs_done_before, 15);
  EXPECT_EQ(second.runs_done_now, 0);
  // Another campaign into the same directory is refused by name, and the file is untouched.
  const std::string m = MessageOf([&] { RunShard(SmallPlan(8), dir, 1); });
  EXPECT_NE(m.find("holds campaign " + plan.campaign_id), std::string::npos) << m;
  EXPECT_NE(m.find("the project or the options differ; give another --out or remove the file"), std::string::npos) << m;
  EXPECT_EQ(LoadSummary(dir).runs_done, 15);
}

TEST(Campaign, ShardsMergeToTheSameEnvelopeAsOneRun) {
  const Plan plan = SmallPlan();
  const fs::path whole = Scratch("whole"), shards = Scratch("shards"), merged = Scratch("merged");
  RunShard(plan, whole, 2);
  for (int i = 0; i < 3; ++i) {
    const CampaignReport r = RunShard(plan, shards, 1, Shard{i, 3});
    EXPECT_EQ(r.runs_in_shard, 5);
    EXPECT_EQ(r.file.filename().string(), "campaign-shard-" + std::to_string(i) + "-of-3.sqlite");
  }
  const std::string m = MessageOf([&] { LoadSummary(shards); });
  EXPECT_NE(m.find("holds shard files but no campaign.sqlite: merge them first"), std::string::npos) << m;
  const fs::path file = MergeShards({shards}, merged);
  EXPECT_EQ(file, merged / "campaign.sqlite");
  EXPECT_EQ(Comparable(LoadSummary(whole)), Comparable(LoadSummary(merged)));
  EXPECT_EQ(LoadSummary(merged).shard, "0/1");
}

TEST(Campaign, MergeRefusesMissingDuplicateAndForeignShardsAndWritesNothing) {
  const Plan plan = SmallPlan();
  const fs::path shards = Scratch("merge-bad"), out = Scratch("merge-bad-out");
  for (int i = 0; i < 3; i += 2) RunShard(plan, shards, 1, Shard{i, 3});  // 0/3 and 2/3, not 1/3
  std::string m = MessageOf([&] { MergeShards({shards}, out); });
  EXPECT_NE(m.find("shards missing from campaign " + plan.campaign_id + ": campaign-shard-1-of-3.sqlite (shard 1/3)"),
            std::string::npos)
      << m;
  EXPECT_FALSE(fs::exists(out));

  const fs::path copy = Scratch("merge-bad-copy");
  fs::create_directories(copy);
  fs::copy_file(shards / "campaign-shard-0-of-3.sqlite", copy / "campaign-shard-0-of-3.sqlite");
  m = MessageOf([&] { MergeShards({shards, copy}, out); });
  EXPECT_NE(m.find("shard 0/3 is given twice"), std::string::npos) << m;
  EXPECT_FALSE(fs::exists(out));

  const fs::path foreign = Scratch("merge-bad-foreign");
  RunShard(SmallPlan(99), foreign, 1, Shard{1, 3});
  m = MessageOf([&] { MergeShards({shards, foreign}, out); });
  EXPECT_NE(m.find("belongs to campaign"), std::string::npos) << m;
  EXPECT_NE(m.find("only shards of one campaign can be merged"), std::string::npos) << m;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Campaign, AFailingRunIsRecordedWithItsMessageAndTheCampaignGoesOn) {
  // A wing-tip brake whose static capacity may fall below its dynamic torque: the corner at the
  // minimum cannot be simulated (the model refuses it), the nominal and maximum corners run.
  Project p = A380();
  Parameter& capacity = p.FindComponent("wtb_left")->parameters.at("static_capacity");
  capacity.domain.lo = 1.0;
  CampaignOptions o;
  o.case_patterns = {"jam_l3", "rupture_shaft_l1"};
  o.corners = {"wtb_left.static_capacity"};
  o.model = sim::DriveResolution::kReduced;
  const Plan plan = MakePlan(p, o);
  ExecutionOptions e;
  e.directory = Scratch("failures");
  e.jobs = 2;
  const CampaignReport r = RunCampaign(p, plan, e);
  EXPECT_EQ(r.runs_done_now, 6);
  EXPECT_EQ(r.failures, 2);
  const CampaignSummary s = LoadSummary(e.directory);
  ASSERT_EQ(s.failed.size(), 2u);
  for (const auto& f : s.failed) {
    EXPECT_EQ(f.sample, 1) << f.message;  // corner 0: the minimum
    EXPECT_NE(f.message.find("static"), std::string::npos) << f.message;
  }
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.FullReport().find("Failed runs:"), std::string::npos);
  EXPECT_EQ(s.ToJson()["failures"], 2);
  // The passivity monitor's count: recorded (not null) and none of the successful runs feeds
  // energy into the transmission.
  EXPECT_EQ(s.not_passive, 0);
  EXPECT_EQ(s.ToJson()["not_passive"], 0);
}

TEST(Campaign, RunsInParallelThreadsGiveTheSameNumbersAsOneAfterAnother) {
  // The simulator keeps no static mutable state and creates one SUNDIALS context per run: the
  // same runs in four threads at once are bit for bit the runs done one after another.
  CampaignOptions o;
  o.case_patterns = {"jam_l3", "rupture_shaft_l2a"};
  o.samples = 1;
  o.vary = {"pdu.motor_inertia"};
  o.model = sim::DriveResolution::kReduced;
  const Plan plan = MakePlan(A380(), o);
  std::vector<RunResult> sequential, parallel(static_cast<std::size_t>(plan.runs()));
  for (int run = 0; run < plan.runs(); ++run) sequential.push_back(ExecuteRun(A380(), plan, run));
  std::vector<std::thread> threads;
  for (int run = 0; run < plan.runs(); ++run)
    threads.emplace_back([&, run] { parallel[static_cast<std::size_t>(run)] = ExecuteRun(A380(), plan, run); });
  for (auto& t : threads) t.join();
  for (int run = 0; run < plan.runs(); ++run) {
    const RunResult &a = sequential[static_cast<std::size_t>(run)], &b = parallel[static_cast<std::size_t>(run)];
    ASSERT_TRUE(a.ok) << a.message;
    EXPECT_EQ(a.peak, b.peak);
    EXPECT_EQ(a.steps, b.steps);
    ASSERT_EQ(a.components.size(), b.components.size());
    for (std::size_t k = 0; k < a.components.size(); ++k) EXPECT_EQ(a.components[k].tau, b.components[k].tau);
  }
}

}  // namespace
}  // namespace highlift::campaign
