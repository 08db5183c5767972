// Scratch files of the tests: removed once the test (or the test program) that made them has
// passed, so that runs do not fill the temporary directory of a CI machine; kept, and named on
// stdout, when it failed, for a look.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace highlift::testing {

/// The gtest listener that removes registered scratch paths after the outcome is known: a
/// test's paths at its end (after TearDown and the fixture's destructor, so nothing holds them
/// open), the program's at its end (after every TearDownTestSuite).
class ScratchCleaner : public ::testing::EmptyTestEventListener {
 public:
  /// The one cleaner of this program, appended to gtest's listeners at the first call (gtest
  /// owns it from then on).
  static ScratchCleaner& Instance() {
    static ScratchCleaner* const cleaner = [] {
      auto* c = new ScratchCleaner;
      ::testing::UnitTest::GetInstance()->listeners().Append(c);
      return c;
    }();
    return *cleaner;
  }

  void AfterTheTest(const std::filesystem::path& path) { Add(test_paths_, path); }
  void AtTheEnd(const std::filesystem::path& path) { Add(program_paths_, path); }

  void OnTestEnd(const ::testing::TestInfo& info) override {
    a_test_failed_ = a_test_failed_ || info.result()->Failed();
    Settle(test_paths_, !info.result()->Failed(),
           std::string(info.test_suite_name()) + "." + info.name() + " failed; its scratch is kept for a look");
  }
  // unit_test.Passed() sees only the last round of --gtest_repeat: a_test_failed_ sees them all.
  void OnTestProgramEnd(const ::testing::UnitTest& unit_test) override {
    Settle(program_paths_, unit_test.Passed() && !a_test_failed_,
           "a test failed; the program's scratch is kept for a look");
  }

 private:
  static void Add(std::vector<std::filesystem::path>& paths, const std::filesystem::path& path) {
    if (std::find(paths.begin(), paths.end(), path) == paths.end()) paths.push_back(path);
  }

  /// Removes `paths` when `passed`, else prints `kept` and the path of those that exist; forgets
  /// them either way.
  static void Settle(std::vector<std::filesystem::path>& paths, bool passed, const std::string& kept) {
    for (const auto& path : paths) {
      std::error_code error;
      if (passed) {
        std::filesystem::remove_all(path, error);
        if (error) std::printf("could not remove the scratch %s: %s\n", path.c_str(), error.message().c_str());
      } else if (std::filesystem::exists(path, error)) {
        std::printf("%s: %s\n", kept.c_str(), path.c_str());
      }
    }
    std::fflush(stdout);
    paths.clear();
  }

  std::vector<std::filesystem::path> test_paths_;     // removed when the running test passes
  std::vector<std::filesystem::path> program_paths_;  // removed when every test passed
  bool a_test_failed_ = false;                         // in any round of --gtest_repeat
};

// Installed before main, so that it sees every test's outcome, also those before the first
// registration.
inline const bool kScratchCleanerInstalled = [] {
  ScratchCleaner::Instance();
  return true;
}();

/// Registers `path` (file or folder, made or not yet) for removal when the running test passed;
/// outside a test (a static initializer, SetUpTestSuite), when the whole program passed.
/// Returns `path`.
inline std::filesystem::path RemoveAfterTheTest(const std::filesystem::path& path) {
  if (::testing::UnitTest::GetInstance()->current_test_info())
    ScratchCleaner::Instance().AfterTheTest(path);
  else
    ScratchCleaner::Instance().AtTheEnd(path);
  return path;
}

/// Registers `path` for removal at the end of the program when every test passed: for scratch
/// the tests of one program share (a database built once, a HIGHLIFT_DATA_DIR). Returns `path`.
inline std::filesystem::path RemoveAtTheEnd(const std::filesystem::path& path) {
  ScratchCleaner::Instance().AtTheEnd(path);
  return path;
}

}  // namespace highlift::testing
