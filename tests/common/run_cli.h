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

/// The whole content of `file` ("" when it cannot be read).
inline std::string ReadFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A fresh directory `<tmp>/<prefix>_<test name>_<pid>` for the running gtest test.
inline std::filesystem::path TestScratchDirectory(const std::string& prefix) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::temp_directory_path() /
                   (prefix + "_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace highlift::testing
