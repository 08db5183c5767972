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

bool IsModelicaIdentifier(std::string_view name) {
  if (name.empty() || !IsIdentStart(name.front())) return false;
  if (!std::all_of(name.begin(), name.end(), IsIdentChar)) return false;
  return !IsModelicaKeyword(name);
}

std::string SanitizeModelicaIdentifier(std::string_view name) {
  std::string out;
  out.reserve(name.size() + 2);
  for (char c : name) out += IsIdentChar(c) ? c : '_';
  if (out.empty() || !IsIdentStart(out.front())) out = "x_" + out;
  if (IsModelicaKeyword(out)) out += '_';
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
