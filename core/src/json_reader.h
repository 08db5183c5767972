// A small JSON reader that remembers where every value (and every object key) starts, so that
// errors can name line and column. nlohmann's parser does not report positions of values.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "highlift/core/error.h"

namespace highlift::detail {

struct TextPosition {
  int line = 0;    ///< 1-based
  int column = 0;  ///< 1-based, in code points
};

/// A parsed document: the value, and positions by RFC 6901 JSON pointer.
struct LocatedJson {
  nlohmann::json value;
  // Looked up by pointer only (never walked in order): hashed, which makes reading a project of
  // several thousand values cheaper than ordered maps of long, common-prefix keys (issue 30).
  std::unordered_map<std::string, TextPosition> values;  ///< where each value starts
  std::unordered_map<std::string, TextPosition> keys;    ///< where the key of each object member starts

  /// Location of the value at `pointer` (for a missing member: its nearest present ancestor).
  SourceLocation At(const std::string& file, const std::string& pointer) const;
  /// Location of the key of the member at `pointer` (falls back to At()).
  SourceLocation AtKey(const std::string& file, const std::string& pointer) const;
};

/// Parses strict JSON (RFC 8259; duplicate keys are an error). Throws InputError naming the file,
/// line and column of a syntax error.
LocatedJson ParseLocatedJson(std::string_view text, const std::string& file);

/// Escapes a key for a JSON pointer ("~" -> "~0", "/" -> "~1").
std::string EscapePointerToken(std::string_view token);

}  // namespace highlift::detail
