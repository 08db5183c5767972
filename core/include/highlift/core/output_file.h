// Output files that never damage data. Every command that writes a file goes through
// OutputFile (or WriteOutputFile), which
//   - refuses to write over a file this process read as input (same st_dev/st_ino, whatever the
//     path or link that names it): RegisterInputFile() is called by the readers (project files,
//     import files, and every SQLite database a command opens); checked when the file is opened
//     and again at Commit(), so an input read meanwhile is protected too;
//   - writes through a symbolic link to its target, and refuses targets that are not regular
//     files (directories, devices, FIFOs), except "-" for stdout;
//   - writes to a temporary file beside the target and renames it over the target only on
//     Commit(), after every write, the flush and the close succeeded: on any failure, or when the
//     process is interrupted, the old file is left as it was and the message says why;
//   - keeps the old file's permission bits.
//
//   OutputFile out(path, "results file");   // checks the target, creates the temporary
//   out.Write(header); out.Write(row);      // throws InputError on the first failed write
//   out.Commit();                           // or CommitAs(path + ".partial")
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace highlift {

/// Records a file the process reads (project, database, import file): OutputFile refuses to
/// write over it. Paths that do not exist are ignored.
void RegisterInputFile(const std::filesystem::path& file);

/// Registers a temporary path for removal when the process is stopped by a signal (see
/// RemoveRegisteredTemporaryFiles). Returns a slot for UnregisterTemporaryFile; -1 when the table
/// is full (the path is then not removed on a signal).
int RegisterTemporaryFile(const std::string& path);
void UnregisterTemporaryFile(int slot);
/// Removes every registered temporary path. Async-signal-safe (unlink only): the CLI calls it
/// from its SIGINT/SIGTERM handler before it exits.
void RemoveRegisteredTemporaryFiles() noexcept;

/// RegisterTemporaryFile for the lifetime of the object (a file made under a temporary name and
/// renamed, or a lock file): removed if a signal ends the process meanwhile.
class TemporaryFileGuard {
 public:
  explicit TemporaryFileGuard(const std::string& path) : slot_(RegisterTemporaryFile(path)) {}
  ~TemporaryFileGuard() { UnregisterTemporaryFile(slot_); }
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;

 private:
  int slot_;
};

class OutputFile {
 public:
  /// Checks `path` ("-": stdout) and opens a temporary file beside its target. `what` names the
  /// file in messages ("results file", "project file"). Throws InputError when the target is an
  /// input of this command, is not a regular file, or its folder is not writable.
  explicit OutputFile(const std::filesystem::path& path, std::string what = "output file");
  /// Without Commit(): removes the temporary file; the old target stays unchanged.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Appends `data` (buffered, 64 KiB); throws InputError naming the file and the system's
  /// reason (disk full, file too large) on the first failed write.
  void Write(std::string_view data);
  /// Flushes, syncs, closes and renames the temporary file over the target; throws InputError
  /// (old target intact) on failure. For stdout: checks that everything was written.
  void Commit();
  /// Like Commit(), but to `other` (e.g. "results.csv.partial") instead of the target; the
  /// same checks apply to `other`.
  void CommitAs(const std::filesystem::path& other);

  const std::filesystem::path& path() const { return path_; }      ///< as given
  const std::filesystem::path& target() const { return target_; }  ///< symbolic links resolved
  bool is_stdout() const { return fd_ == 1; }
  std::uint64_t bytes() const { return bytes_ + buffer_.size(); }
  bool committed() const { return committed_; }

 private:
  static constexpr std::size_t kBufferBytes = 1 << 16;
  void Flush();
  void Discard() noexcept;
  [[noreturn]] void Fail(const std::string& problem, int error);

  std::filesystem::path path_, target_, temporary_;
  std::string what_;
  std::string buffer_;
  int fd_ = -1;
  int temporary_slot_ = -1;
  std::uint64_t bytes_ = 0;
  bool committed_ = false;
};

/// Writes `content` to `path` through an OutputFile (checks, temporary file, rename).
void WriteOutputFile(const std::filesystem::path& path, std::string_view content, const std::string& what);

/// Interruption (SIGINT, SIGTERM) requested by the CLI's signal handler; long loops that can
/// stop cleanly poll InterruptRequested() inside an InterruptibleScope. The handler ends the
/// process at once when no such scope is active.
bool InterruptRequested() noexcept;
int InterruptSignal() noexcept;            ///< the signal number, 0 when none
void RequestInterrupt(int signal) noexcept;  ///< async-signal-safe
void ClearInterrupt() noexcept;
bool InInterruptibleScope() noexcept;
/// Marks a loop that polls InterruptRequested() (e.g. the simulator's step loop).
class InterruptibleScope {
 public:
  InterruptibleScope() noexcept;
  ~InterruptibleScope();
  InterruptibleScope(const InterruptibleScope&) = delete;
  InterruptibleScope& operator=(const InterruptibleScope&) = delete;
};
/// The partial output file written after an interruption ("" when none): the CLI names it.
std::string PartialOutputFile();
void SetPartialOutputFile(const std::string& file);

}  // namespace highlift
