#include "csv.h"

#include <algorithm>

#include "highlift/core/error.h"
#include "highlift/core/utf8.h"

namespace highlift::componentdb::csv {

std::vector<Row> Parse(const std::string& text, const std::string& file_name) {
  std::vector<Row> rows;
  Row row;
  row.row = 1;
  row.line = 1;
  std::size_t line = 1;  // of the character at i
  std::string field;
  bool quoted = false;        // inside a quoted field
  bool was_quoted = false;    // the current field was quoted (closing quote seen)
  bool any = false;           // the current row has content
  std::size_t i = 0;
  const std::size_t n = text.size();
  if (n >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3;  // UTF-8 byte order mark
  // Names, designations and notes must be UTF-8 without control characters: every JSON output
  // of them (db show --json, db export) needs it.
  std::size_t bad = 0;
  if (const auto problem = FindTextProblem(std::string_view(text).substr(i), &bad)) {
    const auto before = text.begin() + static_cast<std::ptrdiff_t>(i + bad);
    const auto line = std::count(text.begin(), before, '\n') + 1;
    const auto line_start = std::string_view(text).substr(0, i + bad).rfind('\n');
    const std::size_t column = i + bad - (line_start == std::string_view::npos ? 0 : line_start + 1) + 1;
    throw InputError(file_name + " line " + std::to_string(line) + ", byte " + std::to_string(column) + ": " + *problem);
  }
  const auto end_field = [&] {
    row.fields.push_back(std::move(field));
    field.clear();
    was_quoted = false;
  };
  const auto end_row = [&] {
    end_field();
    rows.push_back(std::move(row));
    row = Row{};
    row.row = rows.size() + 1;
    row.line = line + 1;  // the next record starts after this '\n'
    any = false;
  };
  for (; i < n; ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '\n') ++line;
      if (c == '"') {
        if (i + 1 < n && text[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          quoted = false;
          was_quoted = true;
        }
      } else {
        field += c;
      }
      continue;
    }
    if (c == '"') {
      if (!field.empty() || was_quoted)
        throw InputError(file_name + " row " + std::to_string(row.row) +
                         ": a quote inside an unquoted field; quote the whole field and double inner quotes");
      quoted = true;
      any = true;
    } else if (c == ',') {
      end_field();
      any = true;
    } else if (c == '\r' && i + 1 < n && text[i + 1] == '\n') {
      // handled at '\n'
    } else if (c == '\n') {
      end_row();
      ++line;
    } else {
      if (was_quoted && c != ' ' && c != '\t')
        throw InputError(file_name + " row " + std::to_string(row.row) +
                         ": text after the closing quote of a field; put a comma after the quote");
      if (!was_quoted) field += c;
      any = true;
    }
  }
  if (quoted)
    throw InputError(file_name + " row " + std::to_string(row.row) +
                     ": a quoted field is not closed before the end of the file; add the closing quote");
  if (any || !field.empty()) end_row();
  return rows;
}

std::string FormatRow(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) out += ',';
    const std::string& f = fields[i];
    const bool quote = f.find_first_of(",\"\r\n") != std::string::npos ||
                       (!f.empty() && (f.front() == ' ' || f.back() == ' ' || f.front() == '#'));
    if (!quote) {
      out += f;
      continue;
    }
    out += '"';
    for (char c : f) {
      if (c == '"') out += '"';
      out += c;
    }
    out += '"';
  }
  return out + '\n';
}

}  // namespace highlift::componentdb::csv
