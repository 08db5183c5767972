// Aligned plain-text tables for human-readable reports (FullReport(), CLI output).
#pragma once

#include <string>
#include <vector>

namespace highlift {

/// A table with a header row; columns are padded to their widest cell. Columns listed in
/// `right_aligned` (0-based) are right-aligned, which suits numbers.
class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header, std::vector<int> right_aligned = {});
  void AddRow(std::vector<std::string> cells);
  std::size_t rows() const { return rows_.size(); }
  /// The table as text: header, a rule of dashes, the rows; every line ends with '\n'.
  std::string ToString() const;

 private:
  std::vector<std::string> header_;
  std::vector<bool> right_;
  std::vector<std::vector<std::string>> rows_;
};

/// Formats a value with `significant` significant digits (like %g, but never "1e+03" for values
/// between 1e-4 and 1e7).
std::string FormatNumber(double value, int significant = 4);

}  // namespace highlift
