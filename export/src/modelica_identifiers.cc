// Modelica identifiers, string literals and number literals.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string>

#include "highlift/core/error.h"
#include "highlift/export/modelica.h"

namespace highlift {
namespace {

// Modelica 3.6 keywords (Modelica Language Specification, section 2.3.3), sorted.
constexpr std::string_view kKeywords[] = {
    "algorithm", "and",        "annotation", "block",      "break",     "class",     "connect",
    "connector", "constant",   "constrainedby", "der",     "discrete",  "each",      "else",
    "elseif",    "elsewhen",   "encapsulated", "end",      "enumeration", "equation", "expandable",
    "extends",   "external",   "false",      "final",      "flow",      "for",       "function",
    "if",        "import",     "impure",     "in",         "initial",   "inner",     "input",
    "loop",      "model",      "not",        "operator",   "or",        "outer",     "output",
    "package",   "parameter",  "partial",    "protected",  "public",    "pure",      "record",
    "redeclare", "replaceable", "return",    "stream",     "then",      "true",      "type",
    "when",      "while",      "within",     "optimization", "subtype"};

// The names of the predefined types and the built-in enumeration and operator packages of the
// Modelica language (specification 3.6, sections 4.9 and 16.2): not keywords, but an instance
// named so makes the model illegal or hides the type.
constexpr std::string_view kPredefinedNames[] = {"AssertionLevel", "Boolean", "Clock",       "Connections",
                                                  "ExternalObject", "Integer", "Real",        "StateSelect",
                                                  "String"};

// Latin letters with diacritics and ligatures (Unicode Latin-1 Supplement U+00C0..U+00FF and
// Latin Extended-A U+0100..U+017F) as their ASCII base letters; '?' marks the entries of
// kLatinSpecial (two letters) and the two signs that are no letters (U+00D7, U+00F7).
constexpr std::string_view kLatin1 = "AAAAAA?CEEEEIIIIDNOOOOO?OUUUUY??aaaaaa?ceeeeiiiidnooooo?ouuuuy?y";
constexpr std::string_view kLatinA =
    "AaAaAaCcCcCcCcDdDdEeEeEeEeEeGgGgGgGgHhHhIiIiIiIiIi??JjKkkLlLlLlLlLlNnNnNnnNnOoOoOo??RrRrRrSsSsSsSsTtTtTtUuUuUuUu"
    "UuUuWwYyYZzZzZzs";
static_assert(kLatin1.size() == 0x40 && kLatinA.size() == 0x80);
struct LatinSpecial {
  char32_t code;
  const char* ascii;
};
constexpr LatinSpecial kLatinSpecial[] = {{0xC6, "AE"}, {0xDE, "TH"},  {0xDF, "ss"}, {0xE6, "ae"}, {0xFE, "th"},
                                          {0x132, "IJ"}, {0x133, "ij"}, {0x152, "OE"}, {0x153, "oe"}};

constexpr char32_t kReplacement = 0xFFFD;  // an invalid byte: never a letter of the tables

// The next code point of UTF-8 text at `i` (advanced past it); an invalid byte is skipped alone
// and returned as kReplacement.
char32_t NextCodePoint(std::string_view text, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
  if (length == 0 || i + length > text.size()) {
    ++i;
    return kReplacement;
  }
  char32_t code = length == 1 ? lead : lead & (0x7F >> length);
  for (int k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) {
      ++i;
      return kReplacement;
    }
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  i += length;
  return code;
}

bool IsIdentStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool IsIdentChar(char c) { return IsIdentStart(c) || (c >= '0' && c <= '9'); }

}  // namespace

std::string ToString(ModelResolution resolution) {
  return resolution == ModelResolution::kFull ? "full" : "reduced";
}

ModelResolution ModelResolutionFromString(std::string_view name) {
  if (name == "full") return ModelResolution::kFull;
  if (name == "reduced") return ModelResolution::kReduced;
  throw InputError("unknown model resolution '" + std::string(name) +
                   "': use 'full' (each shaft split into settings.shaft_elements elements) or "
                   "'reduced' (inertias lumped at gearboxes and stations)");
}

bool IsModelicaKeyword(std::string_view name) {
  return std::find(std::begin(kKeywords), std::end(kKeywords), name) != std::end(kKeywords);
}

bool IsModelicaReservedName(std::string_view name) {
  return IsModelicaKeyword(name) ||
         std::find(std::begin(kPredefinedNames), std::end(kPredefinedNames), name) != std::end(kPredefinedNames);
}

bool IsModelicaIdentifier(std::string_view name) {
  if (name.empty() || !IsIdentStart(name.front())) return false;
  if (!std::all_of(name.begin(), name.end(), IsIdentChar)) return false;
  return !IsModelicaReservedName(name);
}

std::string TransliterateToAscii(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const char32_t code = NextCodePoint(text, i);
    if (code < 0x80) {
      out += static_cast<char>(code);
      continue;
    }
    const auto special = std::find_if(std::begin(kLatinSpecial), std::end(kLatinSpecial),
                                      [&](const LatinSpecial& s) { return s.code == code; });
    if (special != std::end(kLatinSpecial)) {
      out += special->ascii;
    } else if (code >= 0xC0 && code < 0x100 && kLatin1[code - 0xC0] != '?') {
      out += kLatin1[code - 0xC0];
    } else if (code >= 0x100 && code < 0x180) {
      out += kLatinA[code - 0x100];
    } else {
      out += '_';
    }
  }
  return out;
}

std::string SanitizeModelicaIdentifier(std::string_view name) {
  std::string out;
  for (char c : TransliterateToAscii(name)) out += IsIdentChar(c) ? c : '_';
  if (out.empty() || !IsIdentStart(out.front())) out = "x_" + out;
  if (IsModelicaReservedName(out)) out += '_';
  return out;
}

IdentifierMap::IdentifierMap(std::vector<std::string> reserved) {
  for (auto& r : reserved) taken_.emplace(std::move(r), std::string());
}

const std::string& IdentifierMap::Add(const std::string& name) {
  if (auto it = by_name_.find(name); it != by_name_.end()) return it->second;
  const std::string base = SanitizeModelicaIdentifier(name);
  std::string candidate = base;
  for (int n = 2; taken_.count(candidate) != 0; ++n) candidate = base + "_" + std::to_string(n);
  taken_.emplace(candidate, name);
  return by_name_.emplace(name, candidate).first->second;
}

const std::string& IdentifierMap::Get(const std::string& name) const {
  auto it = by_name_.find(name);
  HIGHLIFT_CHECK(it != by_name_.end(), "IdentifierMap: no identifier for '" + name + "'");
  return it->second;
}

bool IdentifierMap::Contains(const std::string& name) const { return by_name_.count(name) != 0; }

std::map<std::string, std::string> IdentifierMap::Renamed() const {
  std::map<std::string, std::string> renamed;
  for (const auto& [name, id] : by_name_)
    if (name != id) renamed.emplace(name, id);
  return renamed;
}

std::string EscapeModelicaString(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '\\': out += "\\\\"; break;
      case '"': out += "\\\""; break;
      case '\a': out += "\\a"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\v': out += "\\v"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) break;  // dropped
        out += c;
    }
  }
  return out;
}

std::string FormatModelicaReal(double value, std::string_view what) {
  if (!std::isfinite(value))
    throw InputError(std::string(what) + " = " + (std::isnan(value) ? "nan" : "inf") +
                     " cannot be written to Modelica: give a finite value");
  if (value == 0.0) return "0";  // also -0
  std::array<char, 64> buffer{};
  auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  HIGHLIFT_CHECK(ec == std::errc(), "to_chars failed");
  std::string shortest(buffer.data(), end);
  // A value computed from decimal data (a share of a friction torque, a unit conversion) is
  // often one or two units in the last place off its decimal: 0.15 * 0.5 * ... gives
  // 0.034999999999999996. The 15-digit text is taken when it reads back within 2 ulp.
  auto [end15, ec15] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                     std::chars_format::general, 15);
  HIGHLIFT_CHECK(ec15 == std::errc(), "to_chars failed");
  std::string rounded(buffer.data(), end15);
  if (rounded.size() >= shortest.size()) return shortest;
  double back = 0.0;
  std::from_chars(rounded.data(), rounded.data() + rounded.size(), back);
  const double ulp = std::nextafter(std::abs(value), HUGE_VAL) - std::abs(value);
  return std::abs(back - value) <= 2 * ulp ? rounded : shortest;
}

}  // namespace highlift
