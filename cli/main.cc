// highlift: the command-line front end. Commands register themselves (cli/command.h).
//
// The guarantees of docs/cli.md are kept here, once for every command:
//   - exit codes: 0 ok, 1 violated/failed, 2 invalid input or usage, 3 internal error,
//     130 interrupted (SIGINT/SIGTERM);
//   - with --json, stdout holds exactly one JSON document for every outcome: when a command
//     ends with an error before printing its own document, main prints one with "ok": false,
//     the status, the error and the messages written to stderr;
//   - messages reach the terminal without control characters and without bytes that are not
//     UTF-8 (escaped as \xNN; U+FFFD on stdout under --json), with lines cut at kMaxLine bytes
//     (a 1 MB key gives a short message); JSON documents are written with invalid UTF-8
//     replaced (JsonText), never refused;
//   - library exceptions (std::bad_alloc, std::filesystem errors, nlohmann::json errors) become
//     sentences, never raw library texts;
//   - SIGINT/SIGTERM: a loop that polls highlift::InterruptRequested() (the simulator) stops
//     cleanly and the command finishes its output (marked partial); otherwise the handler
//     removes temporary files, says so and exits 130 at once.
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <limits>
#include <new>

#include <nlohmann/json.hpp>

#include "command.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/core/utf8.h"

namespace highlift::cli {

std::vector<CommandEntry>& Commands() {
  static std::vector<CommandEntry> commands;
  return commands;
}

void CommonOptions::AddTo(CLI::App& app, bool project_required) {
  auto* opt = app.add_option("project", project, "JSON project file");
  if (project_required) opt->required();
  app.add_flag("--json", json, "Print one JSON document on stdout instead of tables");
  app.add_option("--db", db, "Component database (default: the shipped database in the user's data directory)");
}

namespace {

constexpr std::size_t kMaxLine = 2000;  // bytes per message line on stderr
constexpr int kInterrupted = 130;       // 128 + SIGINT, the shell convention

/// Forwards a stream to the real stdout/stderr, counting the bytes, escaping control characters
/// and bytes that are not UTF-8, and (for stderr) cutting long lines and keeping the lines for
/// the JSON error document. Every byte a command writes passes here: whatever a message carries
/// (a Latin-1 file name, a database text, a component id), stdout and stderr are UTF-8.
class GuardedBuffer : public std::streambuf {
 public:
  GuardedBuffer(std::streambuf* next, bool keep_lines, std::size_t max_line)
      : next_(next), keep_lines_(keep_lines), max_line_(max_line) {}
  std::size_t count() const { return count_; }
  const std::vector<std::string>& lines() const { return lines_; }
  /// A byte that is not UTF-8 becomes U+FFFD instead of the text \xNN: inside a JSON document
  /// "\x" is no escape (stdout under --json).
  void ReplaceInvalidBytesByFffd(bool on) { fffd_ = on; }
  /// Writes an unfinished UTF-8 sequence at the end of the output as escaped bytes.
  void Finish() { FlushPending(); }

 protected:
  int_type overflow(int_type ch) override {
    if (ch != traits_type::eof()) Put(static_cast<char>(ch));
    return traits_type::not_eof(ch);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i) Put(s[i]);
    return n;
  }
  int sync() override { return next_->pubsync(); }

 private:
  void Put(char c) {
    ++count_;
    const auto u = static_cast<unsigned char>(c);
    if (!pending_.empty()) {
      if ((u & 0xC0) == 0x80) {
        pending_ += c;
        if (pending_.size() < pending_length_) return;
        // The whole sequence is there: written as one character (never cut inside), or escaped
        // byte by byte when it is no UTF-8 (an overlong form, a surrogate, beyond U+10FFFF).
        if (Utf8SequenceLength(pending_, 0) == pending_.size()) Character(pending_);
        else Invalid(pending_);
        pending_.clear();
        return;
      }
      FlushPending();  // a sequence cut short: its bytes are escaped, then c is a byte of its own
    }
    if (c == '\n') {
      if (cut_ > 0) Emit(" [... " + std::to_string(cut_) + " more bytes]");
      Emit("\n");
      line_ = cut_ = 0;
      return;
    }
    if (u >= 0xC2 && u <= 0xF4) {  // the lead byte of a 2- to 4-byte sequence
      pending_.assign(1, c);
      pending_length_ = u >= 0xF0 ? 4 : u >= 0xE0 ? 3 : 2;
      return;
    }
    if (u >= 0x80) {  // a continuation byte without its lead, or a byte UTF-8 never uses
      Invalid(std::string(1, c));
      return;
    }
    if ((u < 0x20 && c != '\t' && c != '\r') || u == 0x7f) {
      Escaped(c);
    } else {
      Character(std::string(1, c));
    }
  }
  void FlushPending() {
    if (pending_.empty()) return;
    Invalid(pending_);
    pending_.clear();
  }
  void Character(const std::string& bytes) {
    if (line_ >= max_line_) {
      cut_ += bytes.size();
      return;
    }
    next_->sputn(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (keep_lines_) current_ += bytes;
    line_ += bytes.size();
  }
  void Invalid(const std::string& bytes) {
    for (const char b : bytes) {
      if (fffd_) {
        if (line_ >= max_line_) ++cut_;
        else Character("\xEF\xBF\xBD");
      } else {
        Escaped(b);
      }
    }
  }
  void Escaped(char c) {  // "\x1b", "\xe9"
    if (line_ >= max_line_) {
      ++cut_;
      return;
    }
    Emit(CleanText(std::string_view(&c, 1)));
    line_ += 4;
  }
  void Emit(const std::string& text) {
    next_->sputn(text.data(), static_cast<std::streamsize>(text.size()));
    if (!keep_lines_) return;
    for (const char c : text) {
      if (c != '\n') {
        current_ += c;
      } else {
        if (lines_.size() < 200) lines_.push_back(current_);
        current_.clear();
      }
    }
  }

  std::streambuf* next_;
  bool keep_lines_;
  std::size_t max_line_;
  bool fffd_ = false;
  std::size_t count_ = 0, line_ = 0, cut_ = 0;
  std::string pending_;             // the bytes so far of a UTF-8 sequence being written
  std::size_t pending_length_ = 0;  // its length announced by its lead byte
  std::string current_;
  std::vector<std::string> lines_;
};

// What the signal handler writes when it ends the process at once (prepared before Run()).
std::string g_signal_stderr;
std::string g_signal_json;
bool g_json = false;
const GuardedBuffer* g_stdout = nullptr;

void WriteAll(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n <= 0) return;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

extern "C" void OnSignal(int signal) {
  if (highlift::InInterruptibleScope() && !highlift::InterruptRequested()) {
    highlift::RequestInterrupt(signal);  // the polling loop stops and the command finishes
    return;
  }
  highlift::RemoveRegisteredTemporaryFiles();
  WriteAll(2, g_signal_stderr);
  if (g_json && g_stdout != nullptr && g_stdout->count() == 0) WriteAll(1, g_signal_json);
  ::_exit(kInterrupted);
}

void InstallSignalHandlers() {
  // A file-size limit (ulimit -f) is a failed write like a full disk: write() then fails with
  // EFBIG, OutputFile names the file and removes its temporary, and the command exits 2. The
  // default action of SIGXFSZ would kill the process with a core dump and leave the temporary.
  ::signal(SIGXFSZ, SIG_IGN);
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = OnSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool JsonRequested(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) {
    const CLI::Option* opt = sub->get_option_no_throw("--json");
    if ((opt != nullptr && opt->count() > 0) || JsonRequested(*sub)) return true;
  }
  return false;
}

std::string CommandPath(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) {
    const std::string rest = CommandPath(*sub);
    return sub->get_name() + (rest.empty() ? "" : " " + rest);
  }
  return "";
}


std::string StatusOf(int code) {
  switch (code) {
    case kSuccess: return "ok";
    case kViolated: return "failed";
    case kInvalidInput: return "invalid_input";
    case kInterrupted: return "interrupted";
    default: return "internal_error";
  }
}

/// The document printed for an outcome the command did not describe itself.
std::string OutcomeDocument(const std::string& command, int code, const std::string& message,
                            const SourceLocation& where, const std::vector<std::string>& messages) {
  nlohmann::json doc = {{"command", command}, {"ok", code == kSuccess}, {"status", StatusOf(code)}, {"exit_code", code}};
  if (!message.empty())
    doc["error"] = {{"message", CleanText(message, kMaxLine)}, {"location", LocationJson(where)}};
  doc["messages"] = messages;
  return doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

struct Failure {
  int code = kSuccess;
  std::string message;
  SourceLocation where;
};

/// Runs the command, turning every exception into an exit code and a sentence.
Failure RunGuarded(Command& command) {
  try {
    return {command.Run(), "", {}};
  } catch (const highlift::InputError& e) {
    return {kInvalidInput, e.message(), e.where()};  // message(): whole, even with a NUL inside
  } catch (const highlift::InternalError& e) {
    return {3, e.what(), {}};
  } catch (const std::bad_alloc&) {
    return {kInvalidInput,
            "out of memory: the problem is too large for this machine; make the model smaller (fewer components, "
            "fewer --elements) or use a machine with more memory",
            {}};
  } catch (const std::filesystem::filesystem_error& e) {
    SourceLocation where;
    where.file = e.path1().string();
    return {kInvalidInput, "cannot access the file: " + e.code().message() +
                               (e.path2().empty() ? "" : " (and '" + e.path2().string() + "')"),
            where};
  } catch (const nlohmann::json::exception& e) {
    return {3, std::string("internal error (please report): a JSON document could not be built (nlohmann::json error ") +
                   std::to_string(e.id) + ")",
            {}};
  } catch (const std::exception& e) {
    return {kInvalidInput, e.what(), {}};
  }
}

}  // namespace
}  // namespace highlift::cli

int main(int argc, char** argv) {
  using namespace highlift::cli;
  GuardedBuffer out(std::cout.rdbuf(), false, std::numeric_limits<std::size_t>::max());
  GuardedBuffer err(std::cerr.rdbuf(), true, kMaxLine);
  std::streambuf* const real_out = std::cout.rdbuf(&out);
  std::streambuf* const real_err = std::cerr.rdbuf(&err);
  g_stdout = &out;
  const auto restore = [&](int code) {
    out.Finish();
    err.Finish();
    std::cout.flush();
    std::cerr.flush();
    std::cout.rdbuf(real_out);
    std::cerr.rdbuf(real_err);
    return code;
  };

  CLI::App app{"highlift: design-tool backend for aircraft high-lift drive systems"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("highlift ") + HIGHLIFT_VERSION);

  std::map<CLI::App*, std::unique_ptr<Command>> commands;
  for (const auto& entry : Commands()) {
    CLI::App* sub = app.add_subcommand(entry.name, entry.description);
    auto command = entry.make();
    command->Setup(*sub);
    RejectNonFiniteNumbers(*sub);
    commands.emplace(sub, std::move(command));
  }

  // An unknown command: CLI11 would say only "A subcommand is required" (it takes the word for the
  // project of no command). Name the word and the closest command.
  if (argc >= 2 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const auto& entry : Commands()) names.push_back(entry.name);
    const std::string word = argv[1];
    if (std::find(names.begin(), names.end(), word) == names.end()) {
      const std::string message = "unknown command '" + word + "'" + highlift::SuggestionHint(word, names, "the commands are") +
                                  "; run `highlift --help` for what each does";
      std::cerr << "highlift: error: " << CleanText(message) << "\n";
      bool json = false;
      for (int i = 1; i < argc; ++i) json = json || std::string(argv[i]) == "--json";
      if (json) std::cout << OutcomeDocument("", kInvalidInput, message, {}, err.lines());
      return restore(kInvalidInput);
    }
  }

  // An unknown subcommand ("db lst", "campaign sumary DIR"): CLI11 would say "A subcommand is
  // required" or "The following argument was not expected: DIR". Name the word and the closest
  // subcommand when the command requires one, or when the word is close to one (a command whose
  // subcommands are optional takes other words as its positional, a project file).
  if (argc >= 3 && argv[2][0] != '-') {
    for (CLI::App* sub : app.get_subcommands({})) {
      if (sub->get_name() != argv[1]) continue;
      std::vector<std::string> names;
      for (const CLI::App* s : sub->get_subcommands({})) names.push_back(s->get_name());
      const std::string word = argv[2];
      if (names.empty() || std::find(names.begin(), names.end(), word) != names.end()) break;
      const bool required = sub->get_require_subcommand_min() > 0;
      const std::string close = highlift::DidYouMean(word, names);
      if (!required && close.empty()) break;
      const std::string message = "unknown subcommand '" + word + "' of '" + sub->get_name() + "'" +
                                  highlift::SuggestionHint(word, names, "its subcommands are") +
                                  "; run `highlift " + sub->get_name() + " --help` for what each does";
      std::cerr << "highlift " << sub->get_name() << ": error: " << CleanText(message) << "\n";
      bool json = false;
      for (int i = 1; i < argc; ++i) json = json || std::string(argv[i]) == "--json";
      if (json) std::cout << OutcomeDocument(sub->get_name(), kInvalidInput, message, {}, err.lines());
      return restore(kInvalidInput);
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return restore(app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    return restore(app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return restore(app.exit(e));
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    if (what == "A subcommand is required" && argc >= 2) {  // "highlift db": say which there are
      for (CLI::App* sub : app.get_subcommands({})) {
        if (sub->get_name() != argv[1]) continue;
        std::string names;
        for (const CLI::App* s : sub->get_subcommands({})) names += (names.empty() ? "" : ", ") + s->get_name();
        what = "'" + sub->get_name() + "' needs a subcommand: " + names + "; run `highlift " + sub->get_name() +
               " --help` for what each does";
        std::cerr << "highlift " << sub->get_name() << ": error: " << what << "\n";
        bool json = false;
        for (int i = 1; i < argc; ++i) json = json || std::string(argv[i]) == "--json";
        if (json) std::cout << OutcomeDocument(sub->get_name(), kInvalidInput, what, {}, err.lines());
        return restore(kInvalidInput);
      }
    }
    app.exit(e, std::cout, std::cerr);  // prints the usage problem to stderr
    bool json = false;
    for (int i = 1; i < argc; ++i) json = json || std::string(argv[i]) == "--json";
    if (json) std::cout << OutcomeDocument(CommandPath(app), kInvalidInput, e.what(), {}, err.lines());
    return restore(kInvalidInput);
  }

  g_json = JsonRequested(app);
  out.ReplaceInvalidBytesByFffd(g_json);
  const std::string name = CommandPath(app);
  for (auto& [sub, command] : commands) {
    if (!sub->parsed()) continue;
    g_signal_stderr = "highlift " + name + ": interrupted; stopped without finishing, no output file written\n";
    g_signal_json = OutcomeDocument(name, kInterrupted, "interrupted by a signal before the command finished", {}, {});
    InstallSignalHandlers();
    Failure result = RunGuarded(*command);
    if (highlift::InterruptRequested()) {
      const std::string partial = highlift::PartialOutputFile();
      std::cerr << "highlift " << name << ": interrupted by signal " << highlift::InterruptSignal()
                << (partial.empty() ? std::string("") : "; partial output in '" + partial + "'") << "\n";
      if (result.code == kSuccess || result.code == kViolated) result.code = kInterrupted;
    }
    if (!result.message.empty()) {
      const std::string location = result.where.empty() ? "" : result.where.ToString() + ": ";
      std::cerr << "highlift " << name << ": " << (result.code == 3 ? "" : "error: ") << location << result.message
                << "\n";
    }
    std::cerr.flush();
    if (g_json && out.count() == 0)
      std::cout << OutcomeDocument(name, result.code, result.message, result.where, err.lines());
    return restore(result.code);
  }
  return restore(kInvalidInput);
}
