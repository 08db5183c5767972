// `highlift report` under hostile use (issue 27): a signal during its simulations leaves the old
// report as it was and writes nothing (item 2); no output overwrites an input, the campaign
// database of --campaign included, whatever path names it (item 3).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "common/run_cli.h"
#include "highlift/campaign/campaign.h"

namespace highlift {
namespace {

namespace fs = std::filesystem;
using testing::ReadFile;
using testing::RunCli;

fs::path Scratch(const std::string& name) {
  const fs::path dir = fs::path(HIGHLIFT_BINARY_DIR) / "tests" / "report" / ("hostile_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

bool TemporaryIn(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

/// A campaign of the A320-class example (its rupture cases, reduced model, nominal point).
fs::path Campaign(const fs::path& dir) {
  const fs::path out = dir / "a320.campaign";
  const auto run = RunCli({"campaign", "examples/a320_class_flaps.json", "--cases", "rupture_*", "--model", "reduced",
                           "--jobs", "2", "--out", out.string()});
  EXPECT_LE(run.exit_code, 1) << run.err;
  return out;
}

TEST(ReportInputs, TheCampaignDatabaseIsNeverOverwrittenByTheReport) {
  // Was: `report --campaign DIR/campaign.sqlite --out DIR/campaign.sqlite` replaced the campaign
  // database with HTML.
  const fs::path dir = Scratch("campaign_input");
  const fs::path campaign = Campaign(dir);
  const fs::path database = campaign / "campaign.sqlite";
  const std::string before = ReadFile(database);
  ASSERT_FALSE(before.empty());
  fs::create_symlink(database, dir / "link.html");
  struct Case {
    std::string campaign_option, out;
  };
  for (const Case& c : {Case{database.string(), database.string()},        // the file, as the file
                        Case{campaign.string(), database.string()},        // found through its folder
                        Case{campaign.string(), (dir / "link.html").string()},  // through a link
                        Case{database.string(), (campaign / "." / "campaign.sqlite").string()}}) {
    const auto r = RunCli({"report", "examples/a320_class_flaps.json", "--campaign", c.campaign_option, "--no-transient",
                           "--no-scenarios", "--out", c.out, "--json"});
    EXPECT_EQ(r.exit_code, 2) << c.out << ": " << r.err;
    EXPECT_NE(r.err.find("is an input of this command; writing it would destroy the input: choose another file name"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "invalid_input");
    EXPECT_EQ(ReadFile(database), before) << "the campaign database was changed through " << c.out;
    EXPECT_FALSE(TemporaryIn(campaign));
  }
  EXPECT_EQ(campaign::LoadSummary(campaign).cases, campaign::LoadSummary(database).cases);
  // The project and the component database are protected as before.
  const fs::path project = dir / "project.json";
  fs::copy_file(fs::path(HIGHLIFT_SOURCE_DIR) / "examples/a320_class_flaps.json", project);
  const std::string text = ReadFile(project);
  const auto r = RunCli({"report", project.string(), "--no-transient", "--no-scenarios", "--out", project.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(ReadFile(project), text);
}

TEST(ReportSignals, SigintDuringTheSimulationsKeepsTheOldReportAndWritesNothing) {
  // Was: exit 130, and old.html replaced by a report of interrupted runs.
  const fs::path dir = Scratch("sigint");
  const fs::path out = dir / "old.html";
  std::ofstream(out) << "the old report\n";
  const pid_t pid = testing::StartCli(dir, {"report", "examples/a380_class_flaps.json", "--threads", "1", "--json",
                                            "--out", out.string()});
  ASSERT_TRUE(testing::WaitUntilCatching(pid, SIGINT)) << ReadFile(dir / "stderr");
  // The analyses take about a second; the 38 simulations on one thread much longer.
  std::this_thread::sleep_for(std::chrono::milliseconds(4000));
  ::kill(pid, SIGINT);
  const int code = testing::WaitCli(pid);
  ASSERT_NE(code, -1) << "killed by the signal instead of stopping";
  if (code == 0 || code == 1) GTEST_SKIP() << "the report was finished before the signal";
  EXPECT_EQ(code, 130) << ReadFile(dir / "stderr");
  EXPECT_EQ(ReadFile(out), "the old report\n");
  EXPECT_FALSE(TemporaryIn(dir));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  const auto doc = nlohmann::json::parse(ReadFile(dir / "stdout"));
  EXPECT_EQ(doc["status"], "interrupted");
  EXPECT_EQ(doc["ok"], false);
  const std::string err = ReadFile(dir / "stderr");
  EXPECT_NE(err.find("interrupted"), std::string::npos) << err;
  if (err.find("during the analyses and simulations") != std::string::npos) {
    EXPECT_NE(err.find("no report written; '" + out.string() + "' is as it was before"), std::string::npos) << err;
  }
}

}  // namespace
}  // namespace highlift
