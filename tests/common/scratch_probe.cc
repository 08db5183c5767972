// The test program that scratch_test.cc runs: its tests register scratch folders under
// $HIGHLIFT_SCRATCH_PROBE_DIR and pass or fail on purpose, so that what the cleaner removes and
// keeps can be seen from outside the process.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/scratch.h"

namespace highlift {
namespace {

namespace fs = std::filesystem;
using testing::RemoveAfterTheTest;
using testing::RemoveAtTheEnd;

fs::path ProbeDir() {
  const char* dir = std::getenv("HIGHLIFT_SCRATCH_PROBE_DIR");
  return dir ? fs::path(dir) : fs::path();
}

/// Registers the folder `name` under the probe folder with `remove`, then makes it, with a file.
void Make(const std::string& name, fs::path (*remove)(const fs::path&)) {
  ASSERT_FALSE(ProbeDir().empty()) << "HIGHLIFT_SCRATCH_PROBE_DIR is not set";
  const fs::path dir = remove(ProbeDir() / name);
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "scratch\n";
}

TEST(Probe, Passes) {
  Make("passes_test", RemoveAfterTheTest);
  Make("passes_program", RemoveAtTheEnd);
}

TEST(Probe, Fails) {
  Make("fails_test", RemoveAfterTheTest);
  Make("fails_program", RemoveAtTheEnd);
  ADD_FAILURE() << "fails on purpose";
}

// Fails in the first round of --gtest_repeat only: the program's last round passes.
TEST(Probe, FailsTheFirstTimeOnly) {
  static int runs = 0;
  Make("flaky_program", RemoveAtTheEnd);
  EXPECT_GT(runs++, 0) << "fails on purpose, the first time";
}

// Scratch registered for a test outside any test: it stays for the whole program.
class ProbeSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { Make("suite", RemoveAfterTheTest); }
};

TEST_F(ProbeSuite, First) { EXPECT_TRUE(fs::exists(ProbeDir() / "suite" / "file")); }

TEST_F(ProbeSuite, SecondStillSeesIt) { EXPECT_TRUE(fs::exists(ProbeDir() / "suite" / "file")); }

}  // namespace
}  // namespace highlift
