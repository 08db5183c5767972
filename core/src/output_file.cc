#include "highlift/core/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <iostream>
#include <mutex>
#include <set>
#include <utility>

#include "highlift/core/error.h"

namespace highlift {
namespace {

namespace fs = std::filesystem;

std::mutex& InputMutex() {
  static std::mutex m;
  return m;
}
std::set<std::pair<dev_t, ino_t>>& Inputs() {
  static std::set<std::pair<dev_t, ino_t>> inputs;
  return inputs;
}

// Temporary files to remove on a signal: fixed storage, so the handler touches no allocator.
constexpr int kSlots = 32;
constexpr std::size_t kPathMax = 4096;
char g_temporary[kSlots][kPathMax];
volatile std::sig_atomic_t g_temporary_used[kSlots];
std::mutex& TemporaryMutex() {
  static std::mutex m;
  return m;
}

volatile std::sig_atomic_t g_signal = 0;
std::atomic<int> g_interruptible{0};
std::string& Partial() {
  static std::string partial;
  return partial;
}

std::string Kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

/// `path` with symbolic links followed to the file they name (which need not exist).
fs::path FollowLinks(const fs::path& path, const std::string& what) {
  fs::path p = path;
  for (int depth = 0; depth < 40; ++depth) {
    struct stat st;
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::error_code ec;
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) throw InputError("cannot read the symbolic link '" + p.string() + "' (" + what + "): " + ec.message());
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  throw InputError("the " + what + " '" + path.string() +
                   "' is a chain of more than 40 symbolic links (a loop?); give the file's real path");
}

/// The checked target of `path`: refuses inputs of this process and non-regular files.
fs::path CheckedTarget(const fs::path& path, const std::string& what) {
  if (path.empty()) throw InputError("the " + what + " has an empty name; give a file path or '-' for stdout");
  const fs::path target = FollowLinks(path, what);
  const std::string shown = "'" + path.string() + "'" + (target == path ? "" : " (-> '" + target.string() + "')");
  struct stat st;
  if (::stat(target.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode))
      throw InputError("the " + what + " " + shown + " is " + Kind(st.st_mode) +
                       "; highlift writes regular files only (give a file path, or '-' for stdout)");
    std::lock_guard<std::mutex> lock(InputMutex());
    if (Inputs().count({st.st_dev, st.st_ino}))
      throw InputError("the " + what + " " + shown +
                       " is an input of this command; writing it would destroy the input: choose another file name");
  }
  return target;
}

std::string Reason(int error) { return std::strerror(error); }

}  // namespace

void RegisterInputFile(const fs::path& file) {
  struct stat st;
  if (::stat(file.c_str(), &st) != 0) return;
  std::lock_guard<std::mutex> lock(InputMutex());
  Inputs().insert({st.st_dev, st.st_ino});
}

int RegisterTemporaryFile(const std::string& path) {
  if (path.size() + 1 > kPathMax) return -1;
  std::lock_guard<std::mutex> lock(TemporaryMutex());
  for (int i = 0; i < kSlots; ++i) {
    if (g_temporary_used[i]) continue;
    std::memcpy(g_temporary[i], path.c_str(), path.size() + 1);
    g_temporary_used[i] = 1;
    return i;
  }
  return -1;
}

void UnregisterTemporaryFile(int slot) {
  if (slot < 0 || slot >= kSlots) return;
  std::lock_guard<std::mutex> lock(TemporaryMutex());
  g_temporary_used[slot] = 0;
}

void RemoveRegisteredTemporaryFiles() noexcept {
  for (int i = 0; i < kSlots; ++i)
    if (g_temporary_used[i]) ::unlink(g_temporary[i]);
}

// ---------------------------------------------------------------------------------------------

OutputFile::OutputFile(const fs::path& path, std::string what) : path_(path), what_(std::move(what)) {
  if (path == "-") {
    target_ = path;
    fd_ = 1;
    return;
  }
  target_ = CheckedTarget(path, what_);
  static std::atomic<unsigned> counter{0};
  const fs::path folder = target_.parent_path();
  temporary_ = folder / ("." + target_.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                         std::to_string(counter++));
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    const int error = errno;
    throw InputError("cannot write the " + what_ + " '" + path_.string() + "': cannot create a file in the folder '" +
                     (folder.empty() ? std::string(".") : folder.string()) + "' (" + Reason(error) +
                     "); check that it exists and is writable");
  }
  temporary_slot_ = RegisterTemporaryFile(temporary_.string());
  struct stat st;
  if (::stat(target_.c_str(), &st) == 0) ::fchmod(fd_, st.st_mode & 07777);  // keep the old permissions
}

OutputFile::~OutputFile() {
  if (!committed_) Discard();
}

void OutputFile::Discard() noexcept {
  if (fd_ > 1) ::close(fd_);
  if (fd_ != 1 && !temporary_.empty()) ::unlink(temporary_.c_str());
  UnregisterTemporaryFile(temporary_slot_);
  temporary_slot_ = -1;
  fd_ = -1;
}

void OutputFile::Fail(const std::string& problem, int error) {
  const bool was_stdout = is_stdout();
  Discard();
  throw InputError("cannot write the " + what_ + " '" + path_.string() + "': " + problem + " (" + Reason(error) + ")" +
                   (was_stdout ? "" : "; the old file, if any, is unchanged") +
                   (error == ENOSPC || error == EDQUOT ? "; free some disk space" : "") +
                   (error == EFBIG ? "; the file exceeds the size limit (ulimit -f)" : ""));
}

void OutputFile::Write(std::string_view data) {
  HIGHLIFT_CHECK(fd_ >= 0 && !committed_, "OutputFile::Write after Commit or a failure");
  buffer_.append(data);
  if (buffer_.size() >= kBufferBytes) Flush();
}

void OutputFile::Flush() {
  if (buffer_.empty()) return;
  if (fd_ == 1) std::cout.flush();  // keep the order of what the command printed before
  const char* p = buffer_.data();
  std::size_t left = buffer_.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      Fail("a write failed", errno);
    }
    p += n;
    left -= static_cast<std::size_t>(n);
    bytes_ += static_cast<std::uint64_t>(n);
  }
  buffer_.clear();
}

void OutputFile::Commit() { CommitAs(path_); }

void OutputFile::CommitAs(const fs::path& other) {
  HIGHLIFT_CHECK(fd_ >= 0 && !committed_, "OutputFile::Commit twice or after a failure");
  Flush();
  if (fd_ == 1) {
    committed_ = true;
    return;
  }
  // Checked again: an input the command read after this file was opened (a campaign database
  // found through a folder, an import file) is protected as well as the ones read before.
  const fs::path target = CheckedTarget(other, what_);
  if (::fsync(fd_) != 0 && errno != EINVAL && errno != EROFS) Fail("the data could not be synced to the disk", errno);
  const int fd = fd_;
  fd_ = -1;  // closed below, whatever close() says
  if (::close(fd) != 0) Fail("closing it failed", errno);
  if (::rename(temporary_.c_str(), target.c_str()) != 0) Fail("replacing '" + target.string() + "' failed", errno);
  UnregisterTemporaryFile(temporary_slot_);
  temporary_slot_ = -1;
  committed_ = true;
}

void WriteOutputFile(const fs::path& path, std::string_view content, const std::string& what) {
  OutputFile out(path, what);
  out.Write(content);
  out.Commit();
}

// ---------------------------------------------------------------------------------------------

bool InterruptRequested() noexcept { return g_signal != 0; }
int InterruptSignal() noexcept { return g_signal; }
void RequestInterrupt(int signal) noexcept { g_signal = signal; }
void ClearInterrupt() noexcept { g_signal = 0; }
bool InInterruptibleScope() noexcept { return g_interruptible.load() > 0; }
InterruptibleScope::InterruptibleScope() noexcept { ++g_interruptible; }
InterruptibleScope::~InterruptibleScope() { --g_interruptible; }
std::string PartialOutputFile() { return Partial(); }
void SetPartialOutputFile(const std::string& file) { Partial() = file; }

}  // namespace highlift
