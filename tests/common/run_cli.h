// Runs the built `highlift` executable and captures its exit code, stdout and stderr.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/scratch.h"

namespace highlift::testing {

struct CliResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

inline std::string ShellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') q += "'\\''";
    else q += c;
  }
  return q + "'";
}

/// Runs `highlift args...` from the source directory; stdout and stderr go to temporary files.
inline CliResult RunCli(const std::vector<std::string>& args, const std::string& stdin_text = "") {
  static int counter = 0;
  const auto tmp = std::filesystem::temp_directory_path() /
                   ("highlift_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  std::filesystem::create_directories(tmp);
  std::string cmd = "cd " + ShellQuote(HIGHLIFT_SOURCE_DIR) + " && " + ShellQuote(HIGHLIFT_CLI_PATH);
  for (const auto& a : args) cmd += " " + ShellQuote(a);
  if (!stdin_text.empty()) {
    std::ofstream(tmp / "stdin") << stdin_text;
    cmd += " < " + ShellQuote((tmp / "stdin").string());
  } else {
    cmd += " < /dev/null";
  }
  cmd += " > " + ShellQuote((tmp / "out").string()) + " 2> " + ShellQuote((tmp / "err").string());
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::stringstream o, e;
  o << std::ifstream(tmp / "out").rdbuf();
  e << std::ifstream(tmp / "err").rdbuf();
  r.out = o.str();
  r.err = e.str();
  std::filesystem::remove_all(tmp);
  return r;
}

/// Starts `highlift args...` from the source directory without waiting, stdout and stderr going
/// to `dir`/stdout and `dir`/stderr (for tests that send it a signal); returns its pid.
inline pid_t StartCli(const std::filesystem::path& dir, const std::vector<std::string>& args) {
  const std::string out = (dir / "stdout").string(), err = (dir / "stderr").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(HIGHLIFT_SOURCE_DIR) != 0) ::_exit(127);
    if (!std::freopen(out.c_str(), "w", stdout) || !std::freopen(err.c_str(), "w", stderr)) ::_exit(127);
    std::vector<char*> argv{const_cast<char*>(HIGHLIFT_CLI_PATH)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(HIGHLIFT_CLI_PATH, argv.data());
    ::_exit(127);
  }
  return pid;
}

/// The exit code of a process StartCli started (-1 when a signal ended it).
inline int WaitCli(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Waits until the process `pid` catches signal `sig` (its handler is installed: bit sig-1 of
/// SigCgt in /proc/PID/status), at most `timeout_ms`; true when it does. A test that sends a
/// signal waits for this first: under a sanitizer the start of main can take seconds, and a
/// signal that arrives before the handler ends the process by the default action.
inline bool WaitUntilCatching(pid_t pid, int sig, int timeout_ms = 60000) {
  const std::string status_file = "/proc/" + std::to_string(pid) + "/status";
  for (int waited = 0; waited <= timeout_ms; waited += 10) {
    std::ifstream in(status_file);
    std::string line;
    while (std::getline(in, line)) {
      if (line.rfind("SigCgt:", 0) != 0) continue;
      const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
      if ((mask >> (sig - 1)) & 1ULL) return true;
    }
    ::usleep(10000);
  }
  return false;
}

/// The whole content of a file ("" when it cannot be read).
inline std::string ReadFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A fresh directory `<tmp>/<prefix>_<test name>_<pid>` for the running gtest test, removed
/// when the test passed.
inline std::filesystem::path TestScratchDirectory(const std::string& prefix) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::temp_directory_path() /
                   (prefix + "_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return RemoveAfterTheTest(dir);
}

}  // namespace highlift::testing
