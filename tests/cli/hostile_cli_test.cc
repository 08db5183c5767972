// The guarantees of docs/cli.md under hostile use (issue 19): one JSON document for every outcome
// with --json, outputs that never destroy inputs or devices, checked writes, SIGINT/SIGTERM with
// partial output and exit 130, readable option errors, limits with clear errors.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/run_cli.h"

namespace highlift {
namespace {

namespace fs = std::filesystem;
using testing::RunCli;
using testing::StartCli;
using testing::ShellQuote;

const char* const kProject = "tests/export/small_drive.json";  // simulates in well under a second

fs::path Scratch() { return testing::TestScratchDirectory("highlift_hostile_cli"); }

std::string Read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `text` with the first `from` replaced by `to` (the test fails when `from` is missing).
std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

fs::path CopyProject(const fs::path& dir) {
  const fs::path copy = dir / "project.json";
  fs::copy_file(fs::path(HIGHLIFT_SOURCE_DIR) / kProject, copy);
  return copy;
}

/// One JSON document on stdout, nothing else.
nlohmann::json OneDocument(const testing::CliResult& r) {
  try {
    return nlohmann::json::parse(r.out);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "stdout is not one JSON document (" << e.what() << "):\n" << r.out << "\nstderr:\n" << r.err;
    return {};
  }
}

// --- --json on every outcome --------------------------------------------------------------------

TEST(JsonOnError, EveryCommandPrintsOneDocumentForAMissingProject) {
  const std::vector<std::vector<std::string>> commands = {
      {"estimate"}, {"check"}, {"size"}, {"modes"}, {"peak"}, {"simulate"}, {"info"}, {"validate"},
      {"tradeoff", "--vary", "pdu.max_output_speed=20:30:2", "--show", "pdu.max_output_speed"},
      {"export", "--modelica", "/tmp/highlift-never-written"}};
  for (auto args : commands) {
    const std::string name = args[0];
    args.insert(args.begin() + 1, "no-such-project.json");
    args.push_back("--json");
    const auto r = RunCli(args);
    EXPECT_EQ(r.exit_code, 2) << name << "\n" << r.err;
    const auto doc = OneDocument(r);
    EXPECT_EQ(doc.value("ok", true), false) << name << ": " << r.out;
    EXPECT_FALSE(r.err.empty()) << name;
  }
  const auto show = RunCli({"db", "show", "NO-SUCH-PART", "--json"});
  EXPECT_EQ(show.exit_code, 2);
  const auto doc = OneDocument(show);
  EXPECT_EQ(doc["command"], "db show");
  EXPECT_EQ(doc["status"], "invalid_input");
  EXPECT_NE(doc["error"]["message"].get<std::string>().find("no part or material 'NO-SUCH-PART'"), std::string::npos);
}

TEST(JsonOnError, ErrorDocumentCarriesLocationAndMessages) {
  const fs::path dir = Scratch();
  std::ofstream(dir / "bad.json") << "{\n  \"format\": \"highlift-project/1\",\n  \"name\": 1\n}";
  const auto r = RunCli({"check", (dir / "bad.json").string(), "--json"});
  EXPECT_EQ(r.exit_code, 2);
  const auto doc = OneDocument(r);
  EXPECT_EQ(doc["command"], "check");
  EXPECT_EQ(doc["exit_code"], 2);
  EXPECT_EQ(doc["error"]["location"]["line"], 3);
  ASSERT_FALSE(doc["messages"].empty());
}

TEST(JsonOnError, UsageErrorsPrintADocumentToo) {
  const auto r = RunCli({"info", kProject, "--wide", "nan", "--json"});
  EXPECT_EQ(r.exit_code, 2);
  const auto doc = OneDocument(r);
  EXPECT_EQ(doc["status"], "invalid_input");
  EXPECT_NE(r.err.find("'nan' is not a finite number"), std::string::npos) << r.err;
}

// --- option values ---------------------------------------------------------------------------------

TEST(OptionValues, NonFiniteAndOutOfRangeValuesAreRejectedReadably) {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"tradeoff", kProject, "--vary", "pdu.max_output_speed=-inf:inf:3", "--show", "pdu.max_output_speed"},
       "LO and HI must be finite numbers"},
      {{"info", kProject, "--wide", "nan"}, "'nan' is not a finite number; give a number >= 0"},
      {{"info", kProject, "--wide", "-1"}, "'-1' is out of range; give a number >= 0"},
      {{"estimate", kProject, "--min-fit-parts", "-1"}, "'-1' is out of range; give a number from 3 to 1e6"},
      {{"simulate", kProject, "--elements", "-7"}, "'-7' is out of range; give a number from 1 to 1000"},
      {{"modes", kProject, "--elements", "1000"}, "give a number from 0 to 100"},
      {{"check", kProject, "--max-revisions", "-1"}, "give a number > 0"},
  };
  for (const auto& c : cases) {
    const auto r = RunCli(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args[0] << " " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args[0] << ": " << r.err;
    EXPECT_EQ(r.err.find("179769"), std::string::npos) << "DBL_MAX printed: " << r.err;
  }
}

TEST(OptionValues, ModesRefusesAProjectSettingBeyondTheLimit) {
  const fs::path dir = Scratch();
  std::string text = Read(fs::path(HIGHLIFT_SOURCE_DIR) / kProject);
  text = Replaced(text, "\"shaft_elements\": 2", "\"shaft_elements\": 1000");
  std::ofstream(dir / "p.json") << text;
  const auto r = RunCli({"modes", (dir / "p.json").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("1000 sub-elements per shaft segment (settings 'shaft_elements') are more than the mode "
                       "analysis handles (100"),
            std::string::npos)
      << r.err;
}

// --- output files ------------------------------------------------------------------------------------

TEST(OutputFiles, SimulateRefusesToWriteOverItsProject) {
  const fs::path dir = Scratch();
  const fs::path project = CopyProject(dir);
  const std::string before = Read(project);
  const auto r = RunCli({"simulate", project.string(), "--scenario", "jam_gra_1", "--out", project.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is an input of this command; writing it would destroy the input"), std::string::npos) << r.err;
  EXPECT_EQ(Read(project), before);
}

TEST(OutputFiles, EstimateRefusesToRewriteItsInputEvenThroughALink) {
  const fs::path dir = Scratch();
  const fs::path project = CopyProject(dir);
  fs::create_symlink(project, dir / "link.json");
  const std::string before = Read(project);
  for (const fs::path& out : {project, dir / "link.json"}) {
    const auto r = RunCli({"estimate", project.string(), "--no-db", "--write", out.string()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("is an input of this command"), std::string::npos) << r.err;
  }
  EXPECT_EQ(Read(project), before);
}

TEST(OutputFiles, WriteThroughASymlinkKeepsTheLink) {
  const fs::path dir = Scratch();
  const fs::path project = CopyProject(dir);
  std::ofstream(dir / "target.json") << "old";
  fs::create_symlink(dir / "target.json", dir / "link.json");
  const auto r = RunCli({"estimate", project.string(), "--no-db", "--write", (dir / "link.json").string()});
  EXPECT_NE(r.exit_code, 2) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  EXPECT_NE(Read(dir / "target.json").find("highlift-project/1"), std::string::npos);
}

TEST(OutputFiles, DevicesAreRefusedAndStayDevices) {
  const auto r = RunCli({"simulate", kProject, "--scenario", "jam_gra_1", "--out", "/dev/null", "--json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'/dev/null' is a character device"), std::string::npos) << r.err;
  EXPECT_EQ(OneDocument(r)["ok"], false);
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(OutputFiles, AFailedWriteLeavesTheOldFileAndSaysWhy) {
  // ulimit -f makes write() fail with EFBIG, as a full disk fails with ENOSPC.
  const fs::path dir = Scratch();
  const fs::path out = dir / "results.csv";
  std::ofstream(out) << "old results\n";
  const std::string cmd = "cd " + ShellQuote(HIGHLIFT_SOURCE_DIR) + " && trap '' XFSZ && ulimit -f 8 && " +
                          ShellQuote(HIGHLIFT_CLI_PATH) + " simulate " + kProject +
                          " --scenario rupture_wtb --json --out " + ShellQuote(out.string()) + " > " +
                          ShellQuote((dir / "stdout").string()) + " 2> " + ShellQuote((dir / "stderr").string());
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = Read(dir / "stderr");
  EXPECT_NE(err.find("cannot write the results file"), std::string::npos) << err;
  EXPECT_NE(err.find("the old file, if any, is unchanged"), std::string::npos) << err;
  EXPECT_EQ(Read(out), "old results\n");
  EXPECT_EQ(nlohmann::json::parse(Read(dir / "stdout"))["ok"], false);
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

// --- signals ------------------------------------------------------------------------------------------

bool TemporaryExists(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

TEST(Signals, SigintDuringSimulateKeepsAPartialFileAndTheOldOne) {
  const fs::path dir = Scratch();
  const fs::path out = dir / "results.csv";
  std::ofstream(out) << "old results\n";
  // 300 spring-dampers per shaft: a run of several seconds, each step short.
  const pid_t pid = StartCli(dir, {"simulate", kProject, "--scenario", "rupture_wtb", "--elements", "300", "--json",
                                "--out", out.string()});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!TemporaryExists(dir) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(TemporaryExists(dir)) << Read(dir / "stderr");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal instead of stopping cleanly";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const auto doc = nlohmann::json::parse(Read(dir / "stdout"));
  EXPECT_EQ(doc["status"], "interrupted");
  EXPECT_EQ(doc["output"]["partial"], true);
  EXPECT_EQ(doc["output"]["file"], out.string() + ".partial");
  EXPECT_EQ(Read(out), "old results\n");
  const std::string partial = Read(out.string() + ".partial");
  EXPECT_EQ(partial.rfind("\"time\"", 0), 0u);
  EXPECT_NE(partial.find("\n# partial output: interrupted by signal 2 after "), std::string::npos);
  EXPECT_EQ(partial.back(), '\n');
  EXPECT_NE(Read(dir / "stderr").find("partial output in '" + out.string() + ".partial'"), std::string::npos);
  EXPECT_FALSE(TemporaryExists(dir));
}

TEST(Signals, SigtermOutsideAnInterruptibleLoopExits130WithADocument) {
  const fs::path dir = Scratch();
  // modes at 100 elements per segment takes long enough to be stopped inside the analysis.
  const pid_t pid = StartCli(dir, {"modes", "examples/a380_class_flaps.json", "--elements", "100", "--json"});
  ASSERT_TRUE(highlift::testing::WaitUntilCatching(pid, SIGTERM)) << Read(dir / "stderr");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 0) GTEST_SKIP() << "the analysis finished before the signal";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const auto doc = nlohmann::json::parse(Read(dir / "stdout"));
  EXPECT_EQ(doc["status"], "interrupted");
  EXPECT_NE(Read(dir / "stderr").find("interrupted"), std::string::npos);
}

// --- limits and messages -----------------------------------------------------------------------

TEST(Limits, TinyOutputIntervalIsRefusedBeforeTheRun) {
  // Was: CVodeGetDky CV_BAD_T (stop 1e7 s, output 1 us) or gigabytes of CSV (1e-300 s).
  const fs::path dir = Scratch();
  std::string text = Read(fs::path(HIGHLIFT_SOURCE_DIR) / kProject);
  text = Replaced(text, "\"output_interval\": \"1 ms\"", "\"output_interval\": \"1 us\"");
  text = Replaced(text, "\"stop_time\": \"2 s\"", "\"stop_time\": \"1e7 s\"");
  std::ofstream(dir / "p.json") << text;
  const auto r = RunCli({"simulate", (dir / "p.json").string(), "--scenario", "jam_gra_1", "--json"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("the run would write 1e+13 output rows"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the limit is 1e+07 rows"), std::string::npos) << r.err;
  EXPECT_EQ(OneDocument(r)["ok"], false);
}

TEST(Messages, DirectoryAsProject) {
  const auto r = RunCli({"validate", "examples"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("the project path is a directory"), std::string::npos) << r.err;
}

TEST(Messages, EscapeSequencesInANameNeverReachTheTerminal) {
  const fs::path dir = Scratch();
  std::string text = Read(fs::path(HIGHLIFT_SOURCE_DIR) / kProject);
  text = Replaced(text, "\"one-station rig\"", "\"rig \\u001b[2J\\u001b]0;owned\\u0007\"");
  std::ofstream(dir / "p.json") << text;
  const auto r = RunCli({"validate", (dir / "p.json").string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rig \\x1b[2J\\x1b]0;owned\\x07"), std::string::npos) << r.out;
}

TEST(Messages, ShaftWallThickerThanTheRadiusStopsInfo) {
  // Was: validated, and `info` computed a mass from it.
  const fs::path dir = Scratch();
  std::string text = Read(fs::path(HIGHLIFT_SOURCE_DIR) / kProject);
  text = Replaced(text, "\"wall_thickness\": \"2.0 mm\"", "\"wall_thickness\": \"30 mm\"");
  std::ofstream(dir / "p.json") << text;
  for (const std::string command : {"validate", "info"}) {
    const auto r = RunCli({command, (dir / "p.json").string()});
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_NE(r.err.find("wall_thickness 30 mm is more than the radius (outer_diameter 50 mm / 2)"), std::string::npos)
        << command << ": " << r.err;
  }
}

TEST(Messages, ClosedLoopIsNamedByEveryCommand) {
  const fs::path dir = Scratch();
  std::string text = Read(fs::path(HIGHLIFT_SOURCE_DIR) / kProject);
  text = Replaced(text, "[\"appu.b\", \"wtb.a\"]", "[\"appu.b\", \"wtb.a\"], [\"wtb.b\", \"pdu.right\"]");
  std::ofstream(dir / "p.json") << text;
  for (const std::string command : {"validate", "check", "simulate", "size", "modes", "peak"}) {
    const auto r = RunCli({command, (dir / "p.json").string()});
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_NE(r.err.find("connection shaft_2.b - gbx_1.input closes a loop in the transmission ('pdu' -> 'stl'"), std::string::npos)
        << command << ": " << r.err;
  }
}

}  // namespace
}  // namespace highlift
