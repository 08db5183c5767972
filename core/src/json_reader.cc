#include "json_reader.h"

#include "highlift/core/utf8.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace highlift::detail {

std::string EscapePointerToken(std::string_view token) {
  std::string out;
  for (char ch : token) {
    if (ch == '~') {
      out += "~0";
    } else if (ch == '/') {
      out += "~1";
    } else {
      out += ch;
    }
  }
  return out;
}

SourceLocation LocatedJson::At(const std::string& file, const std::string& pointer) const {
  SourceLocation where;
  where.file = file;
  where.json_pointer = pointer;
  std::string p = pointer;
  while (true) {
    if (auto it = values.find(p); it != values.end()) {
      where.line = it->second.line;
      where.column = it->second.column;
      return where;
    }
    if (p.empty()) return where;
    p.erase(p.rfind('/'));
  }
}

SourceLocation LocatedJson::AtKey(const std::string& file, const std::string& pointer) const {
  if (auto it = keys.find(pointer); it != keys.end()) {
    SourceLocation where;
    where.file = file;
    where.json_pointer = pointer;
    where.line = it->second.line;
    where.column = it->second.column;
    return where;
  }
  return At(file, pointer);
}

namespace {

constexpr int kMaxDepth = 256;

class Parser {
 public:
  Parser(std::string_view text, const std::string& file, LocatedJson& out) : text_(text), file_(file), out_(out) {}

  void ParseDocument() {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF")
      Fail("the file starts with a UTF-8 byte-order mark (bytes EF BB BF); save it as UTF-8 without BOM "
           "(most editors call this \"UTF-8\", not \"UTF-8 with BOM\")");
    SkipSpace();
    if (AtEnd()) Fail("the file is empty; a project file is one JSON object");
    out_.value = ParseValue("", 0);
    SkipSpace();
    if (!AtEnd()) Fail("unexpected text after the end of the JSON document");
  }

 private:
  bool AtEnd() const { return pos_ >= text_.size(); }
  char Peek() const { return AtEnd() ? '\0' : text_[pos_]; }

  TextPosition Here() const { return {line_, column_}; }

  // Advances one byte, keeping line and column (columns count code points).
  void Advance() {
    const char ch = text_[pos_++];
    if (ch == '\n') {
      ++line_;
      column_ = 1;
    } else if ((static_cast<unsigned char>(ch) & 0xC0) != 0x80) {
      // the column counts the first byte of every code point
      if (pos_ < text_.size() && (static_cast<unsigned char>(text_[pos_]) & 0xC0) == 0x80) {
        ++column_;
        while (pos_ < text_.size() && (static_cast<unsigned char>(text_[pos_]) & 0xC0) == 0x80) ++pos_;
      } else {
        ++column_;
      }
    }
  }

  [[noreturn]] void Fail(const std::string& message) const { FailAt(Here(), message); }

  static std::string Shown(char ch) { return ShowByte(ch); }
  std::size_t Utf8Length() const { return Utf8SequenceLength(text_, pos_); }

  [[noreturn]] void FailAt(TextPosition at, const std::string& message) const {
    SourceLocation where;
    where.file = file_;
    where.line = at.line;
    where.column = at.column;
    throw InputError("invalid JSON: " + message, where);
  }

  void SkipSpace() {
    while (!AtEnd()) {
      const char ch = Peek();
      if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r') {
        Advance();
      } else {
        break;
      }
    }
  }

  void Expect(char ch, const char* context) {
    if (Peek() != ch) {
      if (AtEnd()) Fail(std::string("unexpected end of file; expected '") + ch + "' " + context);
      Fail(std::string("expected '") + ch + "' " + context + ", found " + Shown(Peek()));
    }
    Advance();
  }

  nlohmann::json ParseValue(const std::string& pointer, int depth) {
    if (depth > kMaxDepth) Fail("nesting deeper than " + std::to_string(kMaxDepth) + " levels");
    out_.values[pointer] = Here();
    const char ch = Peek();
    if (ch == '{') return ParseObject(pointer, depth);
    if (ch == '[') return ParseArray(pointer, depth);
    if (ch == '"') return ParseString();
    if (ch == '-' || (ch >= '0' && ch <= '9')) return ParseNumber();
    if (Literal("true")) return true;
    if (Literal("false")) return false;
    if (Literal("null")) return nullptr;
    if (AtEnd()) Fail("unexpected end of file; expected a value");
    if (ch == '\'') Fail("strings are written in double quotes (\"...\"), not single quotes");
    Fail("found " + Shown(ch) + " where a value must start; expected a value (object, array, string, number, true, false or null)");
  }

  bool Literal(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return false;
    for (std::size_t i = 0; i < word.size(); ++i) Advance();
    return true;
  }

  nlohmann::json ParseObject(const std::string& pointer, int depth) {
    nlohmann::json object = nlohmann::json::object();
    Advance();  // '{'
    SkipSpace();
    if (Peek() == '}') {
      Advance();
      return object;
    }
    while (true) {
      SkipSpace();
      if (Peek() != '"') {
        if (Peek() == '}') Fail("trailing comma before '}' is not allowed in JSON");
        Fail("expected a member name in double quotes, found " + (AtEnd() ? std::string("the end of the file") : Shown(Peek())));
      }
      const TextPosition key_position = Here();
      std::string key = ParseString();
      for (const char c : key)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
          FailAt(key_position, "a member name contains a control character (written as a \\u escape); remove it");
      const std::string member = pointer + "/" + EscapePointerToken(key);
      if (object.contains(key)) FailAt(key_position, "duplicate key '" + key + "' in the same object; give each key once");
      out_.keys[member] = key_position;
      SkipSpace();
      Expect(':', "after a member name");
      SkipSpace();
      object.emplace(std::move(key), ParseValue(member, depth + 1));
      SkipSpace();
      if (Peek() == ',') {
        Advance();
        continue;
      }
      if (Peek() == '}') {
        Advance();
        return object;
      }
      if (AtEnd()) Fail("unexpected end of file; expected ',' or '}' after an object member");
      Fail("expected ',' or '}' after an object member, found " + Shown(Peek()));
    }
  }

  nlohmann::json ParseArray(const std::string& pointer, int depth) {
    nlohmann::json array = nlohmann::json::array();
    Advance();  // '['
    SkipSpace();
    if (Peek() == ']') {
      Advance();
      return array;
    }
    while (true) {
      SkipSpace();
      if (Peek() == ']') Fail("trailing comma before ']' is not allowed in JSON");
      array.push_back(ParseValue(pointer + "/" + std::to_string(array.size()), depth + 1));
      SkipSpace();
      if (Peek() == ',') {
        Advance();
        continue;
      }
      if (Peek() == ']') {
        Advance();
        return array;
      }
      if (AtEnd()) Fail("unexpected end of file; expected ',' or ']' after an array element");
      Fail("expected ',' or ']' after an array element, found " + Shown(Peek()));
    }
  }

  unsigned ParseHex4() {
    unsigned v = 0;
    for (int i = 0; i < 4; ++i) {
      const char ch = Peek();
      unsigned d;
      if (ch >= '0' && ch <= '9') {
        d = static_cast<unsigned>(ch - '0');
      } else if (ch >= 'a' && ch <= 'f') {
        d = static_cast<unsigned>(ch - 'a' + 10);
      } else if (ch >= 'A' && ch <= 'F') {
        d = static_cast<unsigned>(ch - 'A' + 10);
      } else {
        Fail("invalid \\u escape: expected 4 hexadecimal digits");
      }
      v = v * 16 + d;
      Advance();
    }
    return v;
  }

  static void AppendUtf8(std::string& s, std::uint32_t cp) {
    if (cp < 0x80) {
      s += static_cast<char>(cp);
    } else if (cp < 0x800) {
      s += static_cast<char>(0xC0 | (cp >> 6));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      s += static_cast<char>(0xE0 | (cp >> 12));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      s += static_cast<char>(0xF0 | (cp >> 18));
      s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  std::string ParseString() {
    Advance();  // opening quote
    std::string s;
    while (true) {
      if (AtEnd()) Fail("unterminated string; add the closing '\"'");
      const char ch = Peek();
      if (ch == '"') {
        Advance();
        return s;
      }
      if (static_cast<unsigned char>(ch) < 0x20) Fail("control character in a string; write \\n or \\t");
      if (ch != '\\' && static_cast<unsigned char>(ch) < 0x80) {
        // A run of printable ASCII: one byte and one column each, what Advance() does for them.
        // A byte followed by a stray continuation byte is left to the code-point path below,
        // which reports it as before.
        const std::size_t start = pos_;
        while (pos_ < text_.size()) {
          const auto c = static_cast<unsigned char>(text_[pos_]);
          if (c < 0x20 || c >= 0x80 || c == '"' || c == '\\') break;
          if (pos_ + 1 < text_.size() && (static_cast<unsigned char>(text_[pos_ + 1]) & 0xC0) == 0x80) break;
          ++pos_;
        }
        if (pos_ > start) {
          column_ += static_cast<int>(pos_ - start);
          s.append(text_.substr(start, pos_ - start));
          continue;
        }
      }
      if (ch != '\\') {
        // copy a whole code point, which must be UTF-8 (JSON output of it would fail later)
        const std::size_t n = Utf8Length();
        if (n == 0)
          Fail("invalid UTF-8 in a string (" + Shown(ch) +
               "); save the file as UTF-8 (it may be Latin-1 or another encoding)");
        if (text_.substr(pos_, n) == "\xEF\xBB\xBF")
          Fail("a byte-order mark (U+FEFF) inside a string; remove it (an editor may have inserted it)");
        const std::size_t start = pos_;
        Advance();
        if (pos_ - start != n) Fail("invalid UTF-8 in a string; save the file as UTF-8");
        s.append(text_.substr(start, pos_ - start));
        continue;
      }
      Advance();
      const char e = Peek();
      if (AtEnd()) Fail("unterminated string; add the closing '\"'");
      Advance();
      switch (e) {
        case '"': s += '"'; break;
        case '\\': s += '\\'; break;
        case '/': s += '/'; break;
        case 'b': s += '\b'; break;
        case 'f': s += '\f'; break;
        case 'n': s += '\n'; break;
        case 'r': s += '\r'; break;
        case 't': s += '\t'; break;
        case 'u': {
          std::uint32_t cp = ParseHex4();
          if (cp >= 0xD800 && cp <= 0xDBFF) {
            if (Peek() != '\\') Fail("invalid \\u escape: high surrogate without its low surrogate");
            Advance();
            if (Peek() != 'u') Fail("invalid \\u escape: high surrogate without its low surrogate");
            Advance();
            const std::uint32_t low = ParseHex4();
            if (low < 0xDC00 || low > 0xDFFF) Fail("invalid \\u escape: bad low surrogate");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
          } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
            Fail("invalid \\u escape: low surrogate without a high surrogate");
          } else if (cp == 0xFEFF) {
            Fail("a byte-order mark (\\uFEFF) inside a string; remove it");
          }
          AppendUtf8(s, cp);
          break;
        }
        default:
          Fail(std::string("invalid escape '\\") + e + "' in a string");
      }
    }
  }

  nlohmann::json ParseNumber() {
    const std::size_t start = pos_;
    bool is_integer = true;
    if (Peek() == '-') Advance();
    if (Peek() == '0') {
      Advance();
    } else if (Peek() >= '1' && Peek() <= '9') {
      while (Peek() >= '0' && Peek() <= '9') Advance();
    } else {
      Fail("invalid number: expected a digit");
    }
    if (Peek() == '.') {
      is_integer = false;
      Advance();
      if (!(Peek() >= '0' && Peek() <= '9')) Fail("invalid number: expected a digit after '.'");
      while (Peek() >= '0' && Peek() <= '9') Advance();
    }
    if (Peek() == 'e' || Peek() == 'E') {
      is_integer = false;
      Advance();
      if (Peek() == '+' || Peek() == '-') Advance();
      if (!(Peek() >= '0' && Peek() <= '9')) Fail("invalid number: expected a digit in the exponent");
      while (Peek() >= '0' && Peek() <= '9') Advance();
    }
    const std::string_view digits = text_.substr(start, pos_ - start);
    if (is_integer) {
      if (digits[0] == '-') {
        std::int64_t v = 0;
        auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
        if (r.ec == std::errc()) return v;
      } else {
        std::uint64_t v = 0;
        auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
        if (r.ec == std::errc()) return v;
      }
    }
    double v = 0;
    auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (r.ec != std::errc() || !std::isfinite(v)) Fail("number out of range: " + std::string(digits));
    return v;
  }

  std::string_view text_;
  const std::string& file_;
  LocatedJson& out_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

}  // namespace

LocatedJson ParseLocatedJson(std::string_view text, const std::string& file) {
  LocatedJson out;
  Parser parser(text, file, out);
  parser.ParseDocument();
  return out;
}

}  // namespace highlift::detail
