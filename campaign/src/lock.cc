// The lock of a campaign result file (lock.h).
#include "lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "highlift/core/error.h"

namespace highlift::campaign::detail {
namespace {

std::string ReadHolder(int fd) {
  std::string text;
  char buffer[512];
  for (off_t at = 0;;) {
    const ssize_t n = ::pread(fd, buffer, sizeof buffer, at);
    if (n <= 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    at += n;
    if (text.size() > 2000) break;
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return CleanText(text, 500);
}

}  // namespace

std::string LockHolderText(const std::string& action) {
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0) std::strcpy(host, "?");
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char when[64];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", &utc);
  return "pid " + std::to_string(::getpid()) + " on host " + host + " since " + when + " (" + action + ")";
}

ResultFileLock::ResultFileLock(const std::filesystem::path& file, const std::string& action)
    : path_(file.string() + ".lock") {
  // The holder removes the lock file when it is done: a file opened just before that removal
  // is locked in vain, so the lock counts only when the path still names the locked file.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
      const int error = errno;
      throw InputError("cannot create the lock file '" + path_.string() + "' of the campaign result file '" +
                       file.string() + "' (" + std::strerror(error) + "); check that the folder is writable");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string holder = ReadHolder(fd);
      ::close(fd);
      if (error != EWOULDBLOCK)
        throw InputError("cannot lock '" + path_.string() + "' (" + std::strerror(error) +
                         "); the file system of the --out directory may not support locks: use a local or "
                         "cluster file system that does");
      throw InputError("'" + file.string() + "' is in use by another process: " +
                       (holder.empty() ? std::string("a process that has not yet written who it is") : holder) +
                       " holds its lock '" + path_.string() +
                       "'; wait until it has finished (or stop it), or give another --out directory");
    }
    struct stat locked, named;
    if (::fstat(fd, &locked) == 0 && ::stat(path_.c_str(), &named) == 0 && locked.st_dev == named.st_dev &&
        locked.st_ino == named.st_ino) {
      fd_ = fd;
      break;
    }
    ::close(fd);  // removed by its holder meanwhile: lock the new file
  }
  if (fd_ < 0) throw InputError("cannot take the lock '" + path_.string() + "': it is removed and created again all the time");
  removed_on_a_signal_ = std::make_unique<TemporaryFileGuard>(path_.string());
  const std::string holder = LockHolderText(action) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, holder.data(), holder.size(), 0) != static_cast<ssize_t>(holder.size())) {
    // The lock holds all the same; another process only cannot say who holds it.
  }
}

ResultFileLock::~ResultFileLock() {
  removed_on_a_signal_.reset();
  ::unlink(path_.c_str());  // before the close: nobody locks the removed file and counts it
  ::close(fd_);
}

}  // namespace highlift::campaign::detail
