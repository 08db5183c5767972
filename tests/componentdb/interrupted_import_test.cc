// An import killed in the middle, and a reader working during an import (WAL).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "highlift/componentdb/database.h"
#include "highlift/componentdb/io.h"
#include "test_util.h"

namespace highlift::componentdb {
namespace {

using highlift::testing::ScratchDirectory;

Records ManyParts(std::size_t n, const std::string& prefix) {
  Records r;
  r.parts.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    Part p;
    p.type = "geared_rotary_actuator";
    p.designation = prefix + std::to_string(i);
    p.program = "bulk test family";
    p.parameters = {highlift::testing::PointQuantity("ratio", 100.0 + static_cast<double>(i % 200), "1"),
                    highlift::testing::PointQuantity("output_torque_rating", 2.0 + static_cast<double>(i % 23), "kN*m"),
                    highlift::testing::IntervalQuantity("input_inertia", 1e-4, 2e-3, "kg*m^2")};
    r.parts.push_back(std::move(p));
  }
  return r;
}

TEST(ComponentDatabaseInterruptedImport, KilledChildLeavesIntactDatabaseWithTheRowsItHadBefore) {
  ScratchDirectory dir;
  const auto file = dir / "db.sqlite";
  Counts before;
  Records exported;
  {
    auto db = ComponentDatabase::Open(file, ComponentDatabase::Mode::kCreate);
    db.Import(SeedRecords());
    before = db.CountRows();
    exported = db.Export();
  }  // no connection is open across fork()
  const Records big = ManyParts(6000, "BULK-");
  constexpr std::size_t kSignalAfter = 4500;
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(pipe_fds[0]);
    try {
      auto db = ComponentDatabase::Open(file, ComponentDatabase::Mode::kReadWrite);
      ImportOptions options;
      options.progress = [&](std::size_t written) {
        if (written == kSignalAfter) {
          const char byte = 'x';
          if (::write(pipe_fds[1], &byte, 1) != 1) ::_exit(3);
          for (;;) ::pause();  // mid-transaction until killed
        }
      };
      db.Import(big, options);
    } catch (...) {
      ::_exit(2);
    }
    ::_exit(1);  // the import finished: the parent was too slow, which it reports
  }
  ::close(pipe_fds[1]);
  char byte = 0;
  ASSERT_EQ(::read(pipe_fds[0], &byte, 1), 1) << "the importing child died before reaching the middle";
  ::close(pipe_fds[0]);
  // Part of the transaction has spilled into the write-ahead log before the kill.
  const auto wal = std::filesystem::path(file.string() + "-wal");
  const auto wal_size = std::filesystem::exists(wal) ? std::filesystem::file_size(wal) : 0;
  EXPECT_GT(wal_size, 0u) << "the import had not written anything to disk when it was killed";
  ASSERT_EQ(::kill(child, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "child status " << status;

  auto db = ComponentDatabase::Open(file, ComponentDatabase::Mode::kReadWrite);
  EXPECT_EQ(db.IntegrityCheck(), "ok");
  EXPECT_EQ(db.CountRows(), before);
  EXPECT_FALSE(db.FindPart("BULK-0").has_value());
  EXPECT_EQ(db.Export(), exported);
  // And the database still takes writes.
  db.Import(ManyParts(10, "AFTER-"));
  EXPECT_EQ(db.CountRows().parts, before.parts + 10);
}

TEST(ComponentDatabaseInterruptedImport, ReaderSeesTheOldContentWhileAnImportRuns) {
  ScratchDirectory dir;
  const auto file = dir / "db.sqlite";
  auto writer = ComponentDatabase::Open(file, ComponentDatabase::Mode::kCreate);
  writer.Import(SeedRecords());
  const Counts before = writer.CountRows();
  ASSERT_EQ(writer.journal_mode(), "wal");
  bool checked = false;
  ImportOptions options;
  options.progress = [&](std::size_t written) {
    if (written != 300) return;
    // A second connection reads while the writer holds its transaction open.
    auto reader = ComponentDatabase::Open(file, ComponentDatabase::Mode::kReadOnly);
    EXPECT_EQ(reader.CountRows(), before);
    EXPECT_FALSE(reader.FindPart("LIVE-0").has_value());
    EXPECT_TRUE(reader.FindPart("GRA-200-A380C").has_value());
    checked = true;
  };
  writer.Import(ManyParts(500, "LIVE-"), options);
  EXPECT_TRUE(checked);
  EXPECT_EQ(writer.CountRows().parts, before.parts + 500);
}

// Issue 27 item 12: `estimate` while `db import --replace` ran saw "0 database parts": a read of
// the parts of a type took the parts in one statement and their parameters in the next, and a
// replace committed between the two gave parts without parameters (new ids). Every read is one
// snapshot now: a reader sees the old or the new parts, each with all its parameters.
TEST(ComponentDatabaseInterruptedImport, ReadersNeverSeeHalfAReplace) {
  ScratchDirectory dir;
  const auto file = dir / "db.sqlite";
  const Records family = ManyParts(200, "REPL-");
  {
    auto db = ComponentDatabase::Open(file, ComponentDatabase::Mode::kCreate);
    db.Import(family);
  }
  std::atomic<bool> stop{false};
  std::atomic<int> replaces{0};
  std::thread writer([&] {
    auto db = ComponentDatabase::Open(file, ComponentDatabase::Mode::kReadWrite);
    ImportOptions replace;
    replace.replace = true;
    while (!stop) {
      db.Import(family, replace);
      ++replaces;
    }
  });
  auto reader = ComponentDatabase::Open(file, ComponentDatabase::Mode::kReadOnly);
  int reads = 0, incomplete = 0;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (std::chrono::steady_clock::now() < until && (reads < 50 || replaces < 20)) {
    const std::vector<Part> parts = reader.Parts("geared_rotary_actuator");
    std::size_t with_parameters = 0;
    for (const Part& part : parts) with_parameters += part.parameters.size() == 3;
    if (parts.size() != family.parts.size() || with_parameters != parts.size()) ++incomplete;
    ++reads;
  }
  stop = true;
  writer.join();
  EXPECT_GT(replaces.load(), 0);
  EXPECT_GT(reads, 0);
  EXPECT_EQ(incomplete, 0) << incomplete << " of " << reads << " reads saw a part count other than "
                           << family.parts.size() << " or parts without their parameters";
}

}  // namespace
}  // namespace highlift::componentdb
