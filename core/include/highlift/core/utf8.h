// UTF-8 checks for text read from files: names, keys and notes must be UTF-8 so that every JSON
// output of them works (nlohmann::json refuses to write invalid UTF-8).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace highlift {

/// Length (1 to 4) of the well-formed UTF-8 sequence starting at text[pos], or 0 when the bytes
/// there are not UTF-8: a stray continuation byte, an overlong form, a surrogate, a code point
/// beyond U+10FFFF or a sequence cut by the end of the text.
std::size_t Utf8SequenceLength(std::string_view text, std::size_t pos);

/// The first problem of `text` as a sentence ("invalid UTF-8 (the byte 0xE9) at byte 12"), or
/// nullopt when it is UTF-8 without byte-order marks (U+FEFF) and without control characters
/// other than tab, CR and newline.
std::optional<std::string> FindTextProblem(std::string_view text, std::size_t* offset = nullptr);

/// "the byte 0xE9" for a message (or 'x' for printable ASCII).
std::string ShowByte(char byte);

}  // namespace highlift
