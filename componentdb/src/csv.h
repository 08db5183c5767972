// RFC 4180 CSV: fields separated by commas, optionally quoted with '"' (a quote inside a quoted
// field is doubled); a quoted field may span lines. CRLF and LF line ends.
#pragma once

#include <string>
#include <vector>

namespace highlift::componentdb::csv {

struct Row {
  std::size_t row = 0;  ///< 1-based record number (the header is row 1)
  std::size_t line = 0; ///< 1-based line of the file the record starts on
  std::vector<std::string> fields;
};

/// Splits `text` into rows. Throws InputError for an unterminated quoted field or a quote in
/// the middle of an unquoted field, naming `file_name` and the row.
std::vector<Row> Parse(const std::string& text, const std::string& file_name);

/// One row, quoted where needed, ending with '\n'.
std::string FormatRow(const std::vector<std::string>& fields);

}  // namespace highlift::componentdb::csv
