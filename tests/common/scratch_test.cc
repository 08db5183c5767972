// The scratch cleaner of common/scratch.h, seen from outside scratch_probe, a test program that
// passes and fails on purpose: a passing test's scratch is gone after it; a failed test's is
// kept and named; the program's scratch goes only when every test passed.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "common/run_cli.h"
#include "common/scratch.h"

namespace highlift {
namespace {

namespace fs = std::filesystem;
using testing::ShellQuote;

struct ProbeRun {
  int exit_code = -1;
  std::string out;  // stdout and stderr
};

/// Runs the probe with gtest's options `args`, its scratch under `dir`.
ProbeRun RunProbe(const fs::path& dir, const std::vector<std::string>& args) {
  std::string command = "HIGHLIFT_SCRATCH_PROBE_DIR=" + ShellQuote(dir.string()) + " " +
                        ShellQuote(HIGHLIFT_SCRATCH_PROBE_PATH);
  for (const auto& arg : args) command += " " + ShellQuote(arg);
  command += " 2>&1";
  ProbeRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) run.out.append(buffer, n);
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

bool Has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The line of the cleaner that names a kept `path`, `kept` saying whose it is.
std::string Kept(const std::string& kept, const fs::path& path) { return kept + ": " + path.string(); }

TEST(ScratchCleaner, APassingTestLeavesNothing) {
  const fs::path dir = testing::TestScratchDirectory("highlift_scratch_test");
  const auto run = RunProbe(dir, {"--gtest_filter=Probe.Passes"});
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_FALSE(fs::exists(dir / "passes_test")) << run.out;
  EXPECT_FALSE(fs::exists(dir / "passes_program")) << run.out;
  EXPECT_FALSE(Has(run.out, "kept")) << run.out;
}

TEST(ScratchCleaner, AFailedTestKeepsItsScratchAndSaysWhere) {
  const fs::path dir = testing::TestScratchDirectory("highlift_scratch_test");
  const auto run = RunProbe(dir, {"--gtest_filter=Probe.Fails"});
  ASSERT_EQ(run.exit_code, 1) << run.out;
  EXPECT_TRUE(fs::exists(dir / "fails_test" / "file")) << run.out;
  EXPECT_TRUE(fs::exists(dir / "fails_program" / "file")) << run.out;
  EXPECT_TRUE(Has(run.out, Kept("Probe.Fails failed; its scratch is kept for a look", dir / "fails_test"))) << run.out;
  EXPECT_TRUE(Has(run.out, Kept("a test failed; the program's scratch is kept for a look", dir / "fails_program")))
      << run.out;
}

// One failed test keeps the program's scratch, not the scratch of the tests that passed.
TEST(ScratchCleaner, AFailedTestKeepsTheProgramsScratchOnly) {
  const fs::path dir = testing::TestScratchDirectory("highlift_scratch_test");
  const auto run = RunProbe(dir, {"--gtest_filter=Probe.Passes:Probe.Fails:ProbeSuite.*"});
  ASSERT_EQ(run.exit_code, 1) << run.out;
  EXPECT_FALSE(fs::exists(dir / "passes_test")) << run.out;
  EXPECT_TRUE(fs::exists(dir / "passes_program" / "file")) << run.out;
  EXPECT_TRUE(fs::exists(dir / "fails_test" / "file")) << run.out;
  EXPECT_TRUE(fs::exists(dir / "fails_program" / "file")) << run.out;
  EXPECT_TRUE(fs::exists(dir / "suite" / "file")) << run.out;
}

// gtest's verdict at the end of --gtest_repeat is the last round's; a failure in an earlier round
// keeps the program's scratch all the same.
TEST(ScratchCleaner, AFailureInAnEarlierRoundKeepsTheProgramsScratch) {
  const fs::path dir = testing::TestScratchDirectory("highlift_scratch_test");
  const auto run = RunProbe(dir, {"--gtest_filter=Probe.FailsTheFirstTimeOnly", "--gtest_repeat=2"});
  ASSERT_EQ(run.exit_code, 1) << run.out;
  EXPECT_TRUE(fs::exists(dir / "flaky_program" / "file")) << run.out;
}

// Registered for a test in SetUpTestSuite, outside any test: it outlives the suite's first test
// (the second sees it) and goes at the end of the program.
TEST(ScratchCleaner, ScratchRegisteredOutsideATestGoesAtTheEnd) {
  const fs::path dir = testing::TestScratchDirectory("highlift_scratch_test");
  const auto run = RunProbe(dir, {"--gtest_filter=ProbeSuite.*"});
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_TRUE(Has(run.out, "[  PASSED  ] 2 tests.")) << run.out;
  EXPECT_FALSE(fs::exists(dir / "suite")) << run.out;
}

}  // namespace
}  // namespace highlift
