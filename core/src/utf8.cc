#include "highlift/core/utf8.h"

#include <cstdint>

namespace highlift {

std::size_t Utf8SequenceLength(std::string_view text, std::size_t pos) {
  if (pos >= text.size()) return 0;
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[pos + i]); };
  const unsigned char b0 = byte(0);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
    cp = b0 & 0x1F;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    cp = b0 & 0x0F;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    cp = b0 & 0x07;
  } else {
    return 0;
  }
  if (text.size() - pos < n) return 0;
  for (std::size_t i = 1; i < n; ++i) {
    if ((byte(i) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i) & 0x3F);
  }
  const bool overlong = (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
  if (overlong || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

std::string ShowByte(char byte) {
  const auto u = static_cast<unsigned char>(byte);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + byte + "'";
  static const char* const kHex = "0123456789ABCDEF";
  return std::string("the byte 0x") + kHex[u >> 4] + kHex[u & 15];
}

std::optional<std::string> FindTextProblem(std::string_view text, std::size_t* offset) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = Utf8SequenceLength(text, i);
    std::optional<std::string> problem;
    if (n == 0) {
      problem = "invalid UTF-8 (" + ShowByte(text[i]) + "); save the file as UTF-8 (it may be Latin-1 or another encoding)";
    } else if (text.substr(i, n) == "\xEF\xBB\xBF") {
      problem = "a byte-order mark (U+FEFF) inside the text; remove it (an editor may have inserted it)";
    } else if (n == 1) {
      const auto u = static_cast<unsigned char>(text[i]);
      if ((u < 0x20 && text[i] != '\t' && text[i] != '\r' && text[i] != '\n') || u == 0x7f)
        problem = "a control character (" + ShowByte(text[i]) + "); remove it";
    }
    if (problem) {
      if (offset) *offset = i;
      return problem;
    }
    i += n;
  }
  return std::nullopt;
}

}  // namespace highlift
