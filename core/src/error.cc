#include "highlift/core/error.h"

namespace highlift {

std::string SourceLocation::ToString() const {
  std::string s = file;
  if (line > 0) {
    s.append(s.empty() ? "line " : ":");
    s.append(std::to_string(line));
    if (column > 0) {
      s.push_back(':');
      s.append(std::to_string(column));
    }
  }
  if (!json_pointer.empty()) {
    s.append(s.empty() ? "at " : " at ");
    s.append(json_pointer);
  }
  return s;
}

namespace {
std::string Compose(const std::string& message, const SourceLocation& where) {
  return where.empty() ? message : where.ToString() + ": " + message;
}
}  // namespace

InputError::InputError(const std::string& message, SourceLocation where)
    : std::runtime_error(Compose(message, where)), where_(std::move(where)), message_(message) {}

namespace detail {
void CheckFailed(const char* condition, const char* file, int line, const std::string& what) {
  throw InternalError(std::string("internal error (please report): ") + what + " [" + condition +
                      " failed at " + file + ":" + std::to_string(line) + "]");
}
}  // namespace detail

}  // namespace highlift
