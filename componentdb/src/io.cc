#include "highlift/componentdb/io.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unistd.h>

#include "csv.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/core/text_table.h"
#include "highlift/core/units.h"
#include "highlift/core/message_number.h"
#include "highlift/core/utf8.h"

namespace highlift::componentdb {
namespace {

constexpr const char* kJsonFormat = "highlift-componentdb/1";

std::string Join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

/// Parses a number (or "inf", "-inf"); nullopt for an empty field; throws for anything else.
std::optional<double> ParseNumber(const std::string& field, const std::string& origin,
                                  const std::string& column) {
  const std::string t = Trim(field);
  if (t.empty()) return std::nullopt;
  double v = 0.0;
  const char* begin = t.data();
  if (!t.empty() && t[0] == '+') ++begin;
  const auto [end, ec] = std::from_chars(begin, t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size() || std::isnan(v))
    throw InputError(origin + ": column '" + column + "' must be a number (or inf, -inf), got '" + t + "'");
  return v;
}

std::string FormatShortest(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, end);
}

std::string DidYouMean(const std::string& name, const std::vector<std::string>& candidates) {
  const auto s = Suggest(name, candidates);
  if (s.empty()) return "";
  std::string out = "; did you mean ";
  for (std::size_t i = 0; i < s.size(); ++i) out += (i ? " or '" : "'") + s[i] + "'";
  return out + "?";
}

std::vector<std::string> TypeNames() {
  std::vector<std::string> names;
  for (const auto& t : ComponentTypes()) names.push_back(t.name);
  return names;
}

std::vector<std::string> ValueParameterNames(const ComponentTypeSpec& type) {
  std::vector<std::string> names;
  for (const auto& p : type.parameters)
    if (p.kind == ParameterKind::kScalar || p.kind == ParameterKind::kInteger) names.push_back(p.name);
  return names;
}

Dimension MaterialPropertyDimension(const std::string& name) {
  if (name == "density") return dimensions::Density();
  return dimensions::Pressure();
}

/// Checks one quantity against its expected dimension and valid range and fills in SI values.
void ValidateQuantity(Quantity& q, const Dimension& dimension, const std::string& example_unit,
                      const Domain& valid_range, bool integer, const std::string& what,
                      std::map<std::string, UnitConversion>& units) {
  const std::string prefix = q.origin + ": " + what + " parameter '" + q.name + "'";
  if (!q.value && !q.lo && !q.hi)
    throw InputError(prefix + ": no value; give a value, or min and max (or both)");
  if (q.lo.has_value() != q.hi.has_value())
    throw InputError(prefix + ": an interval needs both min and max; use inf or -inf for an open side");
  if (q.lo && *q.lo > *q.hi)
    throw InputError(prefix + ": min " + FormatShortest(*q.lo) + " exceeds max " + FormatShortest(*q.hi));
  if (q.value && q.lo && !(*q.lo <= *q.value && *q.value <= *q.hi))
    throw InputError(prefix + ": value " + FormatShortest(*q.value) + " lies outside its interval [" +
                     FormatShortest(*q.lo) + ", " + FormatShortest(*q.hi) + "]");
  if (q.unit.empty()) q.unit = "1";
  auto it = units.find(q.unit);
  if (it == units.end()) {
    try {
      it = units.emplace(q.unit, ParseUnit(q.unit)).first;
    } catch (const InputError& e) {
      throw InputError(prefix + ": " + e.message());
    }
  }
  const UnitConversion& u = it->second;
  if (!(u.dimension == dimension))
    throw InputError(prefix + ": unit '" + q.unit + "' is " + DescribeDimension(u.dimension) +
                     ", expected " + DescribeDimension(dimension) + " (e.g. '" +
                     (example_unit.empty() ? std::string("1") : example_unit) + "')");
  const auto si = [&](double v) { return u.scale * v + u.offset; };
  q.value_si.reset();
  if (q.value) q.value_si = si(*q.value);
  q.domain_si = q.lo ? Domain{si(*q.lo), si(*q.hi)} : Domain::Point(*q.value_si);
  if (integer && q.value && std::floor(*q.value_si) != *q.value_si)
    throw InputError(prefix + ": must be a whole number, got " + FormatShortest(*q.value));
  const auto outside = [&](double v) { return !valid_range.contains(v); };
  if ((q.value_si && outside(*q.value_si)) ||
      (!std::isinf(q.domain_si.lo) && outside(q.domain_si.lo)) ||
      (!std::isinf(q.domain_si.hi) && outside(q.domain_si.hi)))
    throw InputError(prefix + ": " + (q.value ? FormatShortest(*q.value) : "[" + FormatShortest(*q.lo) + ", " + FormatShortest(*q.hi) + "]") +
                     " " + q.unit + " is outside its valid range [" + FormatMessageNumber(valid_range.lo) + ", " +
                     FormatMessageNumber(valid_range.hi) + "] (SI)");
  if (q.source.empty())
    throw InputError(prefix + ": no source; say where the number comes from or how it was derived");
}

}  // namespace

const std::vector<std::string>& CsvColumns() {
  static const std::vector<std::string> columns{"type", "designation", "program", "supplier",
                                                "note", "parameter",   "value",   "min",
                                                "max",  "unit",        "tag",     "source"};
  return columns;
}

Records ParseCsv(const std::string& text, const std::string& file_name) {
  const auto rows = csv::Parse(text, file_name);
  Records records;
  if (rows.empty()) throw InputError(file_name + ": empty file; the first row must be the header " + Join(CsvColumns()));
  std::vector<std::string> header;
  for (const auto& f : rows[0].fields) header.push_back(Trim(f));
  if (header != CsvColumns())
    throw InputError(file_name + " row 1: the header must be exactly " + Join(CsvColumns()) +
                     "; found " + Join(header));
  std::map<std::string, std::size_t> part_index, material_index;
  std::map<std::string, std::size_t> first_row;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto& fields = rows[r].fields;
    const std::string origin = file_name + " row " + std::to_string(rows[r].row);
    if (fields.size() == 1 && Trim(fields[0]).empty()) continue;  // blank line
    if (!fields.empty() && !fields[0].empty() && fields[0][0] == '#') continue;  // comment
    if (fields.size() != CsvColumns().size())
      throw InputError(origin + ": expected " + std::to_string(CsvColumns().size()) + " columns (" +
                       Join(CsvColumns()) + "), found " + std::to_string(fields.size()));
    const auto f = [&](int i) { return Trim(fields[static_cast<std::size_t>(i)]); };
    const std::string type = f(0), designation = f(1);
    if (type.empty()) throw InputError(origin + ": column 'type' is empty; give a component type or 'material'");
    if (designation.empty()) throw InputError(origin + ": column 'designation' is empty; every part needs a unique designation");
    Quantity q;
    q.name = f(5);
    if (q.name.empty()) throw InputError(origin + ": column 'parameter' is empty");
    q.value = ParseNumber(fields[6], origin, "value");
    q.lo = ParseNumber(fields[7], origin, "min");
    q.hi = ParseNumber(fields[8], origin, "max");
    q.unit = f(9);
    const std::string tag = f(10);
    const auto parsed_tag = TagFromString(tag);
    if (!parsed_tag) throw InputError(origin + ": column 'tag' must be P, P-low or E, got '" + tag + "'");
    q.tag = *parsed_tag;
    q.source = f(11);
    q.origin = origin;
    const auto check_same = [&](std::string& have, const std::string& given, const char* column) {
      if (given.empty()) return;
      if (have.empty()) { have = given; return; }
      if (have != given)
        throw InputError(origin + ": column '" + column + "' of '" + designation + "' is '" + given +
                         "' but was '" + have + "' at row " + std::to_string(first_row[designation]) +
                         "; leave it empty or repeat the same text");
    };
    if (type == "material") {
      auto [it, added] = material_index.emplace(designation, records.materials.size());
      if (added) {
        records.materials.push_back({});
        records.materials.back().name = designation;
        records.materials.back().origin = origin;
        first_row[designation] = rows[r].row;
      }
      Material& m = records.materials[it->second];
      check_same(m.note, f(4), "note");
      m.properties.push_back(std::move(q));
    } else {
      auto [it, added] = part_index.emplace(designation, records.parts.size());
      if (added) {
        records.parts.push_back({});
        Part& p = records.parts.back();
        p.type = type;
        p.designation = designation;
        p.origin = origin;
        first_row[designation] = rows[r].row;
      }
      Part& p = records.parts[it->second];
      if (p.type != type)
        throw InputError(origin + ": part '" + designation + "' has type '" + type + "' but type '" + p.type +
                         "' at row " + std::to_string(first_row[designation]) + "; a designation names one part");
      check_same(p.program, f(2), "program");
      check_same(p.supplier, f(3), "supplier");
      check_same(p.note, f(4), "note");
      p.parameters.push_back(std::move(q));
    }
  }
  return records;
}

namespace {

using Json = nlohmann::ordered_json;

void RejectUnknownKeys(const Json& object, const std::vector<std::string>& allowed, const std::string& origin) {
  for (auto it = object.begin(); it != object.end(); ++it)
    if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end())
      throw InputError(origin + ": unknown key '" + it.key() + "'" + DidYouMean(it.key(), allowed) +
                       " Allowed keys: " + Join(allowed));
}

std::string JsonString(const Json& object, const std::string& key, const std::string& origin, bool required) {
  if (!object.contains(key)) {
    if (required) throw InputError(origin + ": missing key '" + key + "'");
    return "";
  }
  if (!object[key].is_string()) throw InputError(origin + ": key '" + key + "' must be a string");
  return object[key].get<std::string>();
}

std::optional<double> JsonNumber(const Json& object, const std::string& key, const std::string& origin) {
  if (!object.contains(key) || object[key].is_null()) return std::nullopt;
  const Json& v = object[key];
  if (v.is_number()) return v.get<double>();
  if (v.is_string() && (v == "inf" || v == "-inf")) return v == "inf" ? HUGE_VAL : -HUGE_VAL;
  throw InputError(origin + ": key '" + key + "' must be a number (or \"inf\", \"-inf\")");
}

std::vector<Quantity> JsonQuantities(const Json& object, const std::string& origin) {
  if (!object.is_object()) throw InputError(origin + ": must be an object of name -> {value, min, max, unit, tag, source}");
  std::vector<Quantity> out;
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string where = origin + "/" + it.key();
    if (!it.value().is_object()) throw InputError(where + ": must be an object with keys value, min, max, unit, tag, source");
    RejectUnknownKeys(it.value(), {"value", "min", "max", "unit", "tag", "source"}, where);
    Quantity q;
    q.name = it.key();
    q.value = JsonNumber(it.value(), "value", where);
    q.lo = JsonNumber(it.value(), "min", where);
    q.hi = JsonNumber(it.value(), "max", where);
    q.unit = JsonString(it.value(), "unit", where, false);
    const std::string tag = JsonString(it.value(), "tag", where, true);
    const auto parsed = TagFromString(tag);
    if (!parsed) throw InputError(where + ": 'tag' must be P, P-low or E, got '" + tag + "'");
    q.tag = *parsed;
    q.source = JsonString(it.value(), "source", where, false);
    q.origin = where;
    out.push_back(std::move(q));
  }
  return out;
}

}  // namespace

Records ParseJson(const std::string& text, const std::string& file_name) {
  // UTF-8 without control characters; a BOM at the very start is allowed (nlohmann::json skips it)
  const std::size_t skip = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  std::size_t bad = 0;
  if (const auto problem = FindTextProblem(std::string_view(text).substr(skip), &bad)) {
    const auto line = std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(skip + bad), '\n') + 1;
    throw InputError(file_name + " line " + std::to_string(line) + ": " + *problem);
  }
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const Json::parse_error& e) {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..." -> the part
    // after the library's tag
    std::string what = e.what();
    if (const auto at = what.find("] "); what.rfind("[json.exception", 0) == 0 && at != std::string::npos)
      what = what.substr(at + 2);
    throw InputError(file_name + ": not valid JSON: " + what);
  }
  if (!doc.is_object()) throw InputError(file_name + ": the document must be an object with keys format, materials, parts");
  RejectUnknownKeys(doc, {"format", "materials", "parts"}, file_name);
  if (JsonString(doc, "format", file_name, true) != kJsonFormat)
    throw InputError(file_name + ": 'format' must be \"" + std::string(kJsonFormat) + "\"");
  Records records;
  if (doc.contains("materials")) {
    if (!doc["materials"].is_array()) throw InputError(file_name + ": 'materials' must be an array");
    for (std::size_t i = 0; i < doc["materials"].size(); ++i) {
      const Json& m = doc["materials"][i];
      const std::string origin = file_name + " material " + std::to_string(i + 1) + " (/materials/" + std::to_string(i) + ")";
      if (!m.is_object()) throw InputError(origin + ": must be an object");
      RejectUnknownKeys(m, {"name", "note", "properties"}, origin);
      Material material;
      material.name = JsonString(m, "name", origin, true);
      material.note = JsonString(m, "note", origin, false);
      material.origin = origin;
      if (m.contains("properties"))
        material.properties = JsonQuantities(m["properties"], file_name + " /materials/" + std::to_string(i) + "/properties");
      records.materials.push_back(std::move(material));
    }
  }
  if (doc.contains("parts")) {
    if (!doc["parts"].is_array()) throw InputError(file_name + ": 'parts' must be an array");
    for (std::size_t i = 0; i < doc["parts"].size(); ++i) {
      const Json& p = doc["parts"][i];
      const std::string origin = file_name + " part " + std::to_string(i + 1) + " (/parts/" + std::to_string(i) + ")";
      if (!p.is_object()) throw InputError(origin + ": must be an object");
      RejectUnknownKeys(p, {"type", "designation", "program", "supplier", "note", "parameters"}, origin);
      Part part;
      part.type = JsonString(p, "type", origin, true);
      part.designation = JsonString(p, "designation", origin, true);
      part.program = JsonString(p, "program", origin, false);
      part.supplier = JsonString(p, "supplier", origin, false);
      part.note = JsonString(p, "note", origin, false);
      part.origin = origin;
      if (p.contains("parameters"))
        part.parameters = JsonQuantities(p["parameters"], file_name + " /parts/" + std::to_string(i) + "/parameters");
      records.parts.push_back(std::move(part));
    }
  }
  return records;
}

Records ReadRecords(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError("cannot read '" + file.string() + "': no such file or not readable");
  RegisterInputFile(file);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string ext = file.extension().string();
  Records records;
  if (ext == ".csv") records = ParseCsv(buffer.str(), file.string());
  else if (ext == ".json") records = ParseJson(buffer.str(), file.string());
  else throw InputError("'" + file.string() + "': unknown file kind '" + ext + "'; import takes .csv or .json");
  ValidateRecords(records);
  return records;
}

void ValidateRecords(Records& records) {
  std::map<std::string, UnitConversion> units;
  std::map<std::string, std::string> seen;  // designation -> origin
  for (auto& part : records.parts) {
    const std::string origin = part.origin.empty() ? "part '" + part.designation + "'" : part.origin;
    const ComponentTypeSpec* type = FindComponentType(part.type);
    if (!type)
      throw InputError(origin + ": unknown component type '" + part.type + "'" + DidYouMean(part.type, TypeNames()) +
                       " Valid types: " + Join(TypeNames()) + " (or 'material' in CSV)");
    if (part.designation.empty()) throw InputError(origin + ": empty designation; every part needs a unique designation");
    if (auto [it, added] = seen.emplace(part.designation, origin); !added)
      throw InputError(origin + ": designation '" + part.designation + "' is used twice (also at " + it->second +
                       "); designations must be unique");
    if (part.parameters.empty())
      throw InputError(origin + ": part '" + part.designation + "' has no parameters; give at least one value");
    std::set<std::string> names;
    for (auto& q : part.parameters) {
      if (q.origin.empty()) q.origin = origin;
      const std::string what = "part '" + part.designation + "' (" + part.type + ")";
      const ParameterSpec* spec = type->FindParameter(q.name);
      if (!spec || !(spec->kind == ParameterKind::kScalar || spec->kind == ParameterKind::kInteger))
        throw InputError(q.origin + ": " + what + " has no parameter '" + q.name + "'" +
                         DidYouMean(q.name, ValueParameterNames(*type)) +
                         " Valid parameters: " + Join(ValueParameterNames(*type)));
      if (!names.insert(q.name).second)
        throw InputError(q.origin + ": " + what + " parameter '" + q.name + "' is given twice");
      ValidateQuantity(q, spec->dimension, spec->unit, spec->valid_range, spec->kind == ParameterKind::kInteger, what,
                       units);
    }
  }
  std::set<std::string> seen_materials;
  for (auto& material : records.materials) {
    const std::string origin = material.origin.empty() ? "material '" + material.name + "'" : material.origin;
    if (material.name.empty()) throw InputError(origin + ": empty material name");
    if (!seen_materials.insert(material.name).second)
      throw InputError(origin + ": material '" + material.name + "' is given twice; names must be unique");
    std::set<std::string> names;
    for (auto& q : material.properties) {
      if (q.origin.empty()) q.origin = origin;
      const auto& valid = MaterialPropertyNames();
      if (std::find(valid.begin(), valid.end(), q.name) == valid.end())
        throw InputError(q.origin + ": material '" + material.name + "' has no property '" + q.name + "'" +
                         DidYouMean(q.name, valid) + " Valid properties: " + Join(valid));
      if (!names.insert(q.name).second)
        throw InputError(q.origin + ": material '" + material.name + "' property '" + q.name + "' is given twice");
      ValidateQuantity(q, MaterialPropertyDimension(q.name), q.name == "density" ? "kg/m^3" : "GPa",
                       Domain{0.0, HUGE_VAL}, false,
                       "material '" + material.name + "'", units);
    }
    for (const auto& name : MaterialPropertyNames())
      if (!names.count(name))
        throw InputError(origin + ": material '" + material.name + "' lacks property '" + name +
                         "'; every material needs " + Join(MaterialPropertyNames()));
  }
}

std::string ToCsv(const Records& records) {
  std::string out = csv::FormatRow(CsvColumns());
  const auto number = [](const std::optional<double>& v) { return v ? FormatShortest(*v) : std::string(); };
  for (const auto& m : records.materials) {
    bool first = true;
    for (const auto& q : m.properties) {
      out += csv::FormatRow({"material", m.name, "", "", first ? m.note : "", q.name, number(q.value),
                             number(q.lo), number(q.hi), q.unit, ToString(q.tag), q.source});
      first = false;
    }
  }
  for (const auto& p : records.parts) {
    bool first = true;
    for (const auto& q : p.parameters) {
      out += csv::FormatRow({p.type, p.designation, first ? p.program : "", first ? p.supplier : "",
                             first ? p.note : "", q.name, number(q.value), number(q.lo), number(q.hi),
                             q.unit, ToString(q.tag), q.source});
      first = false;
    }
    if (p.parameters.empty())
      throw InputError("part '" + p.designation + "' has no parameters and cannot be written as CSV (one row per parameter); export JSON instead");
  }
  return out;
}

namespace {
Json QuantitiesToJson(const std::vector<Quantity>& quantities) {
  Json out = Json::object();
  const auto number = [](double v) -> Json {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
  };
  for (const auto& q : quantities) {
    Json j = Json::object();
    if (q.value) j["value"] = number(*q.value);
    if (q.lo) j["min"] = number(*q.lo);
    if (q.hi) j["max"] = number(*q.hi);
    j["unit"] = q.unit;
    j["tag"] = ToString(q.tag);
    j["source"] = q.source;
    out[q.name] = std::move(j);
  }
  return out;
}
}  // namespace

nlohmann::ordered_json ToJson(const Records& records) {
  Json doc = Json::object();
  doc["format"] = kJsonFormat;
  doc["materials"] = Json::array();
  for (const auto& m : records.materials)
    doc["materials"].push_back(Json{{"name", m.name}, {"note", m.note}, {"properties", QuantitiesToJson(m.properties)}});
  doc["parts"] = Json::array();
  for (const auto& p : records.parts)
    doc["parts"].push_back(Json{{"type", p.type},         {"designation", p.designation},
                                {"program", p.program},   {"supplier", p.supplier},
                                {"note", p.note},         {"parameters", QuantitiesToJson(p.parameters)}});
  return doc;
}

void WriteRecords(const Records& records, const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  std::string text;
  if (ext == ".csv") text = ToCsv(records);
  else if (ext == ".json") text = ToJson(records).dump(2) + "\n";
  else throw InputError("'" + file.string() + "': unknown file kind '" + ext + "'; export writes .csv or .json");
  WriteOutputFile(file, text, "export file");
}

}  // namespace highlift::componentdb
