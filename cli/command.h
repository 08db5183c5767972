// The `highlift` command registry. Each command lives in its own file under cli/commands/ and
// registers itself with HIGHLIFT_REGISTER_COMMAND, so commands are added without touching main.
//
// Exit codes for every command: 0 success; 1 the analysis found violated requirements or
// infeasibility; 2 invalid input or usage; 3 internal error; 130 interrupted (SIGINT/SIGTERM).
// Messages go to stderr; with --json, stdout holds exactly one JSON document for every outcome
// (main() prints an {"ok": false, "status": ...} document when a command fails before printing
// its own). See cli/main.cc and docs/cli.md.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "highlift/core/error.h"
#include "highlift/core/message_number.h"

namespace highlift::cli {

enum ExitCode : int { kSuccess = 0, kViolated = 1, kInvalidInput = 2, kInternalError = 3, kInterruptedExit = 130 };

using highlift::CleanText;  // core/error.h: control characters escaped, long lines cut

/// A numeric option value within [lo, hi] (either may be infinite: no bound), finite, with a
/// readable message ("--wide: 'nan' is not a finite number; give a number > 0"). Unlike
/// CLI::PositiveNumber it never prints DBL_MAX.
inline CLI::Validator NumberIn(double lo, double hi, bool lo_open = false) {
  auto show = [](double v) { return FormatMessageNumber(v); };
  std::string range;
  if (std::isfinite(lo) && std::isfinite(hi)) range = "a number from " + show(lo) + " to " + show(hi);
  else if (std::isfinite(lo)) range = std::string("a number ") + (lo_open ? "> " : ">= ") + show(lo);
  else if (std::isfinite(hi)) range = "a number <= " + show(hi);
  else range = "a finite number";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0;
        if (!CLI::detail::lexical_cast(text, v)) return "'" + text + "' is not a number; give " + range;
        if (!std::isfinite(v)) return "'" + text + "' is not a finite number; give " + range;
        if (v < lo || (lo_open && v == lo) || v > hi) return "'" + text + "' is out of range; give " + range;
        return {};
      },
      "", "");
}
inline CLI::Validator Positive() { return NumberIn(0.0, std::numeric_limits<double>::infinity(), true); }
inline CLI::Validator NonNegative() { return NumberIn(0.0, std::numeric_limits<double>::infinity()); }

/// The text of a JSON document for stdout: indented by 2, with every byte that is not UTF-8 (a
/// Latin-1 file name, a database text) replaced by U+FFFD instead of nlohmann's exception
/// (which would end the command as an internal error). Every command prints its documents so.
inline std::string JsonText(const nlohmann::json& document) {
  return document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// {"file", "json_pointer", "line", "column"}: the known parts of a location, for --json documents.
inline nlohmann::json LocationJson(const SourceLocation& where) {
  nlohmann::json j = nlohmann::json::object();
  if (!where.file.empty()) j["file"] = where.file;
  if (!where.json_pointer.empty()) j["json_pointer"] = where.json_pointer;
  if (where.line > 0) j["line"] = where.line;
  if (where.column > 0) j["column"] = where.column;
  return j;
}

/// Adds a finiteness check to every floating-point option of `app` and its subcommands, so
/// nan and inf never reach a command (main() calls it for every command).
inline void RejectNonFiniteNumbers(CLI::App& app) {
  for (CLI::Option* opt : app.get_options())
    if (opt->get_type_name() == "FLOAT") opt->check(NumberIn(-std::numeric_limits<double>::infinity(),
                                                             std::numeric_limits<double>::infinity()));
  for (CLI::App* sub : app.get_subcommands(std::function<bool(CLI::App*)>())) RejectNonFiniteNumbers(*sub);
}

/// Points of the domains `size --json` and `peak --json` sample to report the tightness of
/// their enclosures (--tightness overrides).
constexpr int kDefaultTightnessSamples = 32;

/// A command: Setup() declares its options on the subcommand; Run() does the work after
/// parsing and returns an exit code. Exceptions of type highlift::InputError are reported by
/// main() with exit code 2 (and, with --json, an error document when Run() printed none).
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
