// The `highlift` command registry. Each command lives in its own file under cli/commands/ and
// registers itself with HIGHLIFT_REGISTER_COMMAND, so commands are added without touching main.
//
// Exit codes for every command: 0 success; 1 the analysis found violated requirements or
// infeasibility; 2 invalid input or usage. Messages go to stderr; with --json, stdout holds
// exactly one JSON document.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace highlift::cli {

enum ExitCode : int { kSuccess = 0, kViolated = 1, kInvalidInput = 2 };

/// Points of the domains `size --json` and `peak --json` sample to report the tightness of
/// their enclosures (--tightness overrides).
constexpr int kDefaultTightnessSamples = 32;

/// A command: Setup() declares its options on the subcommand; Run() does the work after
/// parsing and returns an exit code. Exceptions of type highlift::InputError are reported by
/// main() with exit code 2.
class Command {
 public:
  virtual ~Command() = default;
  virtual void Setup(CLI::App& app) = 0;
  virtual int Run() = 0;
};

struct CommandEntry {
  std::string name;
  std::string description;
  std::function<std::unique_ptr<Command>()> make;
};

/// All registered commands, in registration order.
std::vector<CommandEntry>& Commands();

inline bool RegisterCommand(std::string name, std::string description,
                            std::function<std::unique_ptr<Command>()> make) {
  Commands().push_back({std::move(name), std::move(description), std::move(make)});
  return true;
}

/// Options every project command shares: the project file, --json and --db.
struct CommonOptions {
  std::string project;  ///< path of the JSON project file
  bool json = false;    ///< print one JSON document on stdout instead of tables
  std::string db;       ///< component database (empty: the default in the user's data directory)

  void AddTo(CLI::App& app, bool project_required = true);
};

}  // namespace highlift::cli

#define HIGHLIFT_REGISTER_COMMAND(Class, name, description)                       \
  namespace {                                                                      \
  [[maybe_unused]] const bool registered_##Class = ::highlift::cli::RegisterCommand( \
      name, description, [] { return std::unique_ptr<::highlift::cli::Command>(new Class()); }); \
  }
