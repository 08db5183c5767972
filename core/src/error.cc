#include "highlift/core/error.h"

#include <algorithm>

#include "highlift/core/utf8.h"

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

// Also escapes bytes that are not UTF-8 (a Latin-1 file name) and cuts a long line only between
// UTF-8 characters, so every message is UTF-8 (issue 27).
std::string CleanText(std::string_view text, std::size_t max_line) {
  std::string out;
  std::size_t line = 0, cut = 0;
  auto end_line = [&] {
    if (cut > 0) out += " [... " + std::to_string(cut) + " more bytes]";
    line = cut = 0;
  };
  static const char* const kHex = "0123456789abcdef";
  for (std::size_t pos = 0; pos < text.size();) {
    const char c = text[pos];
    if (c == '\n') {
      end_line();
      out += c;
      ++pos;
      continue;
    }
    const auto u = static_cast<unsigned char>(c);
    // A whole UTF-8 sequence is kept or cut as one: a line is never cut inside a character.
    const std::size_t length = u < 0x80 ? 1 : Utf8SequenceLength(text, pos);
    if (line >= max_line) {
      cut += std::max<std::size_t>(length, 1);
      pos += std::max<std::size_t>(length, 1);
      continue;
    }
    if ((u < 0x20 && c != '\t' && c != '\r') || u == 0x7f || length == 0) {
      // a control character, or a byte that is not UTF-8 (a cut sequence, a Latin-1 letter)
      out += "\\x";
      out += kHex[u >> 4];
      out += kHex[u & 15];
      line += 4;
      ++pos;
    } else {
      out.append(text.substr(pos, length));
      line += length;
      pos += length;
    }
  }
  end_line();
  return out;
}

namespace {
std::string Compose(const std::string& message, const SourceLocation& where) {
  return where.empty() ? message : where.ToString() + ": " + message;
}
}  // namespace

namespace {
SourceLocation Cleaned(SourceLocation where) {
  where.file = CleanText(where.file);
  where.json_pointer = CleanText(where.json_pointer);
  return where;
}
}  // namespace

InputError::InputError(const std::string& message, SourceLocation where)
    : std::runtime_error(Compose(CleanText(message), Cleaned(where))),
      where_(Cleaned(std::move(where))),
      message_(CleanText(message)) {}

namespace detail {
void CheckFailed(const char* condition, const char* file, int line, const std::string& what) {
  throw InternalError(std::string("internal error (please report): ") + what + " [" + condition +
                      " failed at " + file + ":" + std::to_string(line) + "]");
}
}  // namespace detail

}  // namespace highlift
