#include "highlift/core/text_table.h"

#include "highlift/core/message_number.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "highlift/core/error.h"

namespace highlift {

TextTable::TextTable(std::vector<std::string> header, std::vector<int> right_aligned)
    : header_(std::move(header)), right_(header_.size(), false) {
  for (int c : right_aligned) {
    HIGHLIFT_CHECK(c >= 0 && static_cast<std::size_t>(c) < right_.size(), "column out of range");
    right_[static_cast<std::size_t>(c)] = true;
  }
}

void TextTable::AddRow(std::vector<std::string> cells) {
  HIGHLIFT_CHECK(cells.size() == header_.size(), "row has a different number of cells than the header");
  rows_.push_back(std::move(cells));
}

namespace {
// Display width in code points (UTF-8 continuation bytes do not count).
std::size_t Width(const std::string& s) {
  return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char ch) {
    return (static_cast<unsigned char>(ch) & 0xC0) != 0x80;
  }));
}
}  // namespace

std::string TextTable::ToString() const {
  std::vector<std::size_t> width(header_.size(), 0);
  for (std::size_t c = 0; c < header_.size(); ++c) width[c] = Width(header_[c]);
  for (const auto& row : rows_)
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], Width(row[c]));
  auto line = [&](const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string pad(width[c] - Width(cells[c]), ' ');
      if (c > 0) out += "  ";
      out += right_[c] ? pad + cells[c] : (c + 1 == cells.size() ? cells[c] : cells[c] + pad);
    }
    return out + "\n";
  };
  std::string out = line(header_);
  std::vector<std::string> rule;
  for (std::size_t c = 0; c < header_.size(); ++c) rule.emplace_back(width[c], '-');
  out += line(rule);
  for (const auto& row : rows_) out += line(row);
  return out;
}

std::string FormatNumber(double value, int significant) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  const double a = std::fabs(value);
  if (a != 0.0 && (a < 1e-4 || a >= 1e7)) {
    std::snprintf(buf, sizeof buf, "%.*e", significant - 1, value);
  } else {
    std::snprintf(buf, sizeof buf, "%.*g", significant, value);
    // %g may still switch to exponent form for values like 12345 with 4 digits: print fixed.
    if (std::string(buf).find('e') != std::string::npos) std::snprintf(buf, sizeof buf, "%.0f", value);
  }
  return buf;
}

std::string FormatMessageNumber(double value, int significant) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0.0) return "0";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", std::clamp(significant, 1, 17), value);
  std::string text = buf;
  // "1e+308" -> "1e308", "1e-06" -> "1e-6"
  const auto e = text.find('e');
  if (e != std::string::npos) {
    std::string exponent = text.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, exponent.find_first_not_of("+-"));
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    text = text.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
  }
  return text;
}

}  // namespace highlift
