// Errors for bad user input. Expected numeric outcomes (an empty domain, a solver that did not
// converge) are report statuses, not exceptions; broken internal invariants are HIGHLIFT_CHECK.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace highlift {

/// Where in an input a problem is. Empty or zero fields are unknown and left out of messages.
struct SourceLocation {
  std::string file;          ///< path of the input file
  std::string json_pointer;  ///< RFC 6901 pointer into the JSON document, e.g. "/components/3/type"
  int line = 0;              ///< 1-based line, 0 when unknown
  int column = 0;            ///< 1-based column, 0 when unknown

  bool empty() const { return file.empty() && json_pointer.empty() && line == 0; }
  /// "file.json:12:5 at /components/3/type" (the parts that are known).
  std::string ToString() const;
};

/// `text` fit for a terminal and a message: control characters other than tab, CR and newline
/// escaped as \xNN (a NUL or an escape sequence in a name), and each line cut after `max_line`
/// bytes with a note of how many were cut (a 1 MB key gives a short message).
std::string CleanText(std::string_view text, std::size_t max_line = 2000);

/// Bad user input: a malformed file, an unknown component type, a unit of the wrong dimension, a
/// database row with a missing value. The message names the thing, the problem and the remedy;
/// `what()` prefixes it with the location. The CLI exits with code 2. The message is stored
/// through CleanText(): no control characters, no line longer than 2000 bytes.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message, SourceLocation where = {});
  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

/// A broken internal invariant: a bug in highlift, never the user's fault.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace detail {
[[noreturn]] void CheckFailed(const char* condition, const char* file, int line, const std::string& what);
}  // namespace detail

}  // namespace highlift

/// Assertion that stays on in release builds; throws highlift::InternalError.
#define HIGHLIFT_CHECK(condition, what)                                               \
  do {                                                                                \
    if (!(condition)) ::highlift::detail::CheckFailed(#condition, __FILE__, __LINE__, (what)); \
  } while (false)
