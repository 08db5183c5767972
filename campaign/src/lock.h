// The lock of a campaign result file: one writer at a time.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "highlift/core/output_file.h"

namespace highlift::campaign::detail {

/// An exclusive lock on a result file, held while this process writes it: flock(2) on
/// `file + ".lock"`, which holds the holder's pid, host and start time. The kernel releases the
/// lock when the process ends, however it ends (SIGKILL and a Slurm time limit included), so a
/// lock is never stale; the holder removes the file when it releases it (a signal's exit removes
/// it as a registered temporary file).
class ResultFileLock {
 public:
  /// Takes the lock, or throws InputError naming the file, the holder (pid, host, start time)
  /// and what to do. `action` says what the holder does ("running a campaign into it").
  ResultFileLock(const std::filesystem::path& file, const std::string& action);
  ~ResultFileLock();
  ResultFileLock(const ResultFileLock&) = delete;
  ResultFileLock& operator=(const ResultFileLock&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::unique_ptr<TemporaryFileGuard> removed_on_a_signal_;
};

/// "pid 1234 on host node7 since 2026-12-03 13:05:01 UTC (running a campaign into it)": what a
/// lock file holds for this process now.
std::string LockHolderText(const std::string& action);

}  // namespace highlift::campaign::detail
