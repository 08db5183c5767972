// Tube sizes from CSV; the shipped table is data/tube_sizes.csv, compiled in (tube_sizes_data.cc is
// generated from it at build time, as the database seed is).
#include "highlift/componentdb/tube_sizes.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "csv.h"
#include "highlift/core/error.h"
#include "highlift/core/units.h"

namespace highlift::componentdb {

namespace detail {
extern const char* const kTubeSizesCsv;  // generated: tube_sizes_data.cc
}

namespace {

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

constexpr const char* kHeader = "designation,outer_diameter [mm],wall_thickness [mm]";

/// "outer_diameter [mm]" -> the scale of mm to m (and `unit_out` = "mm"); throws naming the column.
double ColumnScale(const std::string& field, const std::string& name, const std::string& where, std::string& unit_out) {
  const std::string f = Trim(field);
  const auto open = f.find('['), close = f.rfind(']');
  if (f.rfind(name, 0) != 0 || open == std::string::npos || close != f.size() - 1 || open < name.size() ||
      Trim(f.substr(name.size(), open - name.size())) != "")
    throw InputError(where + ": column '" + f + "' must be '" + name + " [UNIT]' with a length unit, e.g. '" + name +
                     " [mm]'; the header is " + kHeader);
  const std::string unit = Trim(f.substr(open + 1, close - open - 1));
  UnitConversion u;
  try {
    u = ParseUnit(unit);
  } catch (const InputError& e) {
    throw InputError(where + ": column '" + f + "': " + e.message() + "; give a length unit such as mm");
  }
  if (!(u.dimension == dimensions::Length()) || u.offset != 0.0)
    throw InputError(where + ": column '" + f + "': unit '" + unit + "' is " + DescribeDimension(u.dimension) +
                     ", expected a length (e.g. mm)");
  unit_out = unit;
  return u.scale;
}

double Positive(const std::string& field, const std::string& where, const std::string& column) {
  const std::string t = Trim(field);
  double v = 0.0;
  const char* begin = t.data();
  if (!t.empty() && t[0] == '+') ++begin;
  const auto [end, ec] = std::from_chars(begin, t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v) || !(v > 0.0))
    throw InputError(where + ": " + column + " '" + t + "' must be a finite number > 0");
  return v;
}

std::string Short(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

}  // namespace

TubeSizeTable ParseTubeSizes(const std::string& text, const std::string& file_name) {
  const std::vector<csv::Row> rows = csv::Parse(text, file_name);
  TubeSizeTable table;
  table.name = file_name;
  std::size_t r = 0;
  auto blank_or_comment = [](const csv::Row& row) {
    if (row.fields.empty() || (row.fields.size() == 1 && Trim(row.fields[0]).empty())) return true;
    const std::string first = Trim(row.fields[0]);
    return !first.empty() && first[0] == '#';
  };
  while (r < rows.size() && blank_or_comment(rows[r])) ++r;
  if (r == rows.size())
    throw InputError(file_name + ": no header and no size; the first row must be the header " + std::string(kHeader) +
                     ", then one size a row (e.g. 45x1.8,45,1.8)");
  const csv::Row& header = rows[r++];
  const std::string head_where = file_name + " line " + std::to_string(header.line);
  if (header.fields.size() != 3 || Trim(header.fields[0]) != "designation")
    throw InputError(head_where + ": the header must be " + std::string(kHeader) + " (any length unit)");
  std::string d_unit, t_unit;
  const double d_scale = ColumnScale(header.fields[1], "outer_diameter", head_where, d_unit);
  const double t_scale = ColumnScale(header.fields[2], "wall_thickness", head_where, t_unit);
  std::map<std::string, std::size_t> seen;
  for (; r < rows.size(); ++r) {
    const csv::Row& row = rows[r];
    if (blank_or_comment(row)) continue;
    const std::string where = file_name + " line " + std::to_string(row.line);
    if (row.fields.size() != 3)
      throw InputError(where + ": " + std::to_string(row.fields.size()) +
                       " fields; a size is designation,outer_diameter,wall_thickness (e.g. 45x1.8,45,1.8)");
    TubeSize s;
    s.designation = Trim(row.fields[0]);
    if (s.designation.empty()) throw InputError(where + ": the designation is empty; name the size (e.g. 45x1.8)");
    const auto [it, added] = seen.emplace(s.designation, row.line);
    if (!added)
      throw InputError(where + ": designation '" + s.designation + "' is repeated (line " + std::to_string(it->second) +
                       "); a designation names one size");
    const double D = Positive(row.fields[1], where, "outer_diameter");
    const double t = Positive(row.fields[2], where, "wall_thickness");
    s.outer_diameter = D * d_scale;
    s.wall_thickness = t * t_scale;
    if (s.wall_thickness > 0.5 * s.outer_diameter)
      throw InputError(where + ": size '" + s.designation + "' has a wall of " + Short(t) + " " + t_unit +
                       " above half its diameter of " + Short(D) + " " + d_unit + "; a tube's wall is at most D/2 (D/2: a solid bar)");
    s.origin = where;
    table.sizes.push_back(std::move(s));
  }
  if (table.sizes.empty())
    throw InputError(file_name + ": no size after the header; give one size a row (e.g. 45x1.8,45,1.8)");
  return table;
}

TubeSizeTable LoadTubeSizes(const std::string& file_or_standard) {
  if (file_or_standard == "standard") return StandardTubeSizes();
  std::ifstream in(file_or_standard, std::ios::binary);
  if (!in || std::filesystem::is_directory(file_or_standard))
    throw InputError("--tube-sizes '" + file_or_standard + "': cannot read the file; give a CSV file (" + kHeader +
                     ") or 'standard' for the shipped ISO 3 R20 table");
  std::ostringstream text;
  text << in.rdbuf();
  return ParseTubeSizes(text.str(), file_or_standard);
}

const std::string& StandardTubeSizesCsv() {
  static const std::string text(detail::kTubeSizesCsv);
  return text;
}

const TubeSizeTable& StandardTubeSizes() {
  static const TubeSizeTable table = [] {
    TubeSizeTable t = ParseTubeSizes(StandardTubeSizesCsv(), "data/tube_sizes.csv");
    t.name = "standard";
    return t;
  }();
  return table;
}

}  // namespace highlift::componentdb
