// Strict reading and writing of project files (docs/project-format.md).
#include "highlift/core/project_io.h"
#include "highlift/core/output_file.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "highlift/core/graph.h"
#include "highlift/core/text_table.h"
#include "highlift/core/message_number.h"
#include "json_reader.h"

namespace highlift {

namespace {

using nlohmann::json;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr const char* kFormat = "highlift-project/1";

// ---------------------------------------------------------------------------------------------
// Small helpers

std::string TypeName(const json& v) {
  switch (v.type()) {
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::null: return "null";
    default: return "a number";
  }
}

std::string Trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

std::string Quote(const std::string& s) { return "\"" + s + "\""; }

// A problem inside a quantity: `sub` is the pointer below the quantity's own pointer.
struct QuantityError {
  std::string sub;
  std::string message;
  bool at_key = false;
};

// The smallest magnitude of a parameter value in SI units other than 0 (see ReadParameter).
constexpr double kSmallestMagnitude = 1e-300;

// Reads a leading number (with optional sign; "inf" only when allowed) from `s`, advancing it.
std::optional<double> TakeNumber(std::string_view& s, bool allow_infinite) {
  std::size_t i = 0;
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
  s.remove_prefix(i);
  std::string_view t = s;
  bool negative = false;
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) {
    negative = t[0] == '-';
    t.remove_prefix(1);
  }
  if (allow_infinite && t.substr(0, 3) == "inf") {
    std::size_t n = t.substr(0, 8) == "infinity" ? 8 : 3;
    s = t.substr(n);
    return negative ? -kInf : kInf;
  }
  if (t.empty() || !(std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '.')) return std::nullopt;
  double v = 0;
  auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (r.ec != std::errc() || !std::isfinite(v)) return std::nullopt;
  // "5e" or "5m": from_chars stops before a letter that is not an exponent, which is what we want
  s = t.substr(static_cast<std::size_t>(r.ptr - t.data()));
  return negative ? -v : v;
}

// The parts of a quantity string "44 [43, 51] GPa".
struct QuantityText {
  std::optional<double> nominal;
  std::optional<double> lo, hi;
  std::string unit;
};

QuantityText SplitQuantity(const std::string& text) {
  QuantityText q;
  std::string_view s = text;
  const std::string usage =
      "; write a number and a unit (\"50 mm\"), an interval (\"[43, 51] GPa\") or both (\"44 [43, 51] GPa\")";
  if (Trim(s).empty()) throw QuantityError{"", "empty quantity string" + usage};
  if (Trim(s)[0] != '[') {
    q.nominal = TakeNumber(s, false);
    if (!q.nominal) throw QuantityError{"", "cannot read a number at the start of " + Quote(text) + usage};
  }
  std::string rest = Trim(s);
  if (!rest.empty() && rest[0] == '[') {
    const auto close = rest.find(']');
    if (close == std::string::npos) throw QuantityError{"", "missing ']' in " + Quote(text) + usage};
    std::string_view inner = std::string_view(rest).substr(1, close - 1);
    const auto lo = TakeNumber(inner, true);
    std::string_view after = inner;
    const std::string sep = Trim(after);
    if (!lo || sep.empty() || sep[0] != ',')
      throw QuantityError{"", "cannot read the interval in " + Quote(text) + "; write [min, max]"};
    std::string_view second = std::string_view(sep).substr(1);
    const auto hi = TakeNumber(second, true);
    if (!hi || !Trim(second).empty())
      throw QuantityError{"", "cannot read the interval in " + Quote(text) + "; write [min, max]"};
    q.lo = lo;
    q.hi = hi;
    rest = Trim(std::string_view(rest).substr(close + 1));
  }
  q.unit = rest;
  return q;
}

// Converts `value` in `unit` to SI; `expected` == nullptr accepts any dimension.
double ConvertToSI(double value, const std::string& unit, const Dimension* expected, const std::string& text) {
  if (std::isinf(value) && unit.empty()) return value;
  try {
    if (expected) return ToSI(value, unit, *expected);
    const UnitConversion c = ParseUnit(unit);
    return c.scale * value + c.offset;
  } catch (const InputError& e) {
    std::string message = e.message() + " in " + Quote(text);
    if (message.rfind("unknown unit", 0) == 0)
      message += " (units are UDUNITS-2 expressions such as mm, N*m, rpm, kg*m^2, GPa)";
    throw QuantityError{"", message};
  }
}

std::string FormatValue(double si, const std::string& unit, const Dimension& dimension) {
  if (std::isinf(si)) return si > 0 ? "inf" : "-inf";
  const std::string u = unit.empty() ? "1" : unit;
  double v = si;
  try {
    v = FromSI(si, u, dimension);
  } catch (const InputError&) {
    return FormatMessageNumber(si);
  }
  return FormatMessageNumber(v);
}

std::string UnitSuffix(const std::string& unit) { return (unit.empty() || unit == "1") ? "" : " " + unit; }

std::string FormatDomain(const Domain& d, const std::string& unit, const Dimension& dimension) {
  return "[" + FormatValue(d.lo, unit, dimension) + ", " + FormatValue(d.hi, unit, dimension) + "]" +
         UnitSuffix(unit);
}

// One value inside the object form: a number (in `unit`, else SI) or a string with a unit.
double ObjectValue(const json& v, const std::string& key, const std::string& unit, const Dimension* expected,
                   bool allow_infinite) {
  if (v.is_number()) {
    if (unit.empty()) return v.get<double>();  // SI
    return ConvertToSI(v.get<double>(), unit, expected, v.dump() + " " + unit);
  }
  if (v.is_string()) {
    const std::string text = v.get<std::string>();
    std::string_view s = text;
    const auto number = TakeNumber(s, allow_infinite);
    if (!number)
      throw QuantityError{"/" + key, "cannot read a number at the start of " + Quote(text) + "; write e.g. \"44 GPa\""};
    std::string u = Trim(s);
    if (u.find('[') != std::string::npos)
      throw QuantityError{"/" + key, "'" + key + "' takes one value, not an interval; use \"min\" and \"max\""};
    if (u.empty()) u = unit;
    if (u.empty()) return *number;  // SI
    try {
      return ConvertToSI(*number, u, expected, text);
    } catch (QuantityError& e) {
      e.sub = "/" + key;
      throw;
    }
  }
  throw QuantityError{"/" + key, "'" + key + "' must be a number or a string with a unit, got " + TypeName(v)};
}

void ReadNoteAndProvenance(const json& v, Parameter& p) {
  if (v.contains("note")) {
    if (!v["note"].is_string()) throw QuantityError{"/note", "'note' must be a string, got " + TypeName(v["note"])};
    p.note = v["note"].get<std::string>();
  }
  if (v.contains("provenance")) {
    const json& pv = v["provenance"];
    if (!pv.is_string()) throw QuantityError{"/provenance", "'provenance' must be a string, got " + TypeName(pv)};
    const auto prov = ProvenanceFromString(pv.get<std::string>());
    const std::vector<std::string> names = {"user", "database", "fit", "estimated", "default", "propagated", "optimized"};
    if (!prov)
      throw QuantityError{"/provenance", "unknown provenance '" + pv.get<std::string>() + "'" +
                                             SuggestionHint(pv.get<std::string>(), names, "valid provenances")};
    p.provenance = *prov;
  }
  if (v.contains("design")) {
    if (!v["design"].is_boolean())
      throw QuantityError{"/design", "'design' must be true or false, got " + TypeName(v["design"])};
    p.design = v["design"].get<bool>();
  }
}

void CheckObjectKeys(const json& v, const std::vector<std::string>& allowed, const std::string& what) {
  for (const auto& [key, value] : v.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      throw QuantityError{"/" + detail::EscapePointerToken(key),
                          "unknown key '" + key + "' in " + what + SuggestionHint(key, allowed, "allowed keys"),
                          true};
  }
}

// A scalar quantity in any of the documented forms. Missing bounds of the object form take the
// bounds of `fill` (the valid range of the parameter).
Parameter QuantityFromJson(const json& v, const Dimension& expected, const Domain& fill) {
  Parameter p;
  p.provenance = Provenance::kUser;
  if (v.is_number()) {
    p.nominal = v.get<double>();
    p.domain = Domain::Point(*p.nominal);
    return p;
  }
  if (v.is_string()) {
    const std::string text = v.get<std::string>();
    const QuantityText q = SplitQuantity(text);
    if (q.nominal) p.nominal = ConvertToSI(*q.nominal, q.unit, &expected, text);
    if (q.lo) {
      p.domain = {ConvertToSI(*q.lo, q.unit, &expected, text), ConvertToSI(*q.hi, q.unit, &expected, text)};
    } else {
      p.domain = Domain::Point(*p.nominal);
    }
  } else if (v.is_object()) {
    CheckObjectKeys(v, {"value", "min", "max", "unit", "note", "provenance", "part", "design"}, "a quantity");
    std::string unit;
    if (v.contains("unit")) {
      if (!v["unit"].is_string()) throw QuantityError{"/unit", "'unit' must be a string, got " + TypeName(v["unit"])};
      unit = Trim(v["unit"].get<std::string>());
      try {
        ConvertToSI(1.0, unit, &expected, unit);
      } catch (QuantityError& e) {
        e.sub = "/unit";
        throw;
      }
    }
    if (v.contains("part")) {
      if (!v["part"].is_string() || v["part"].get<std::string>().empty())
        throw QuantityError{"/part", "'part' must be the designation of a database part, e.g. \"GRA-200-A380C\""};
      p.database_part = v["part"].get<std::string>();
      p.provenance = Provenance::kDatabase;
    }
    if (!v.contains("value") && !v.contains("min") && !v.contains("max") && !v.contains("part"))
      throw QuantityError{"", "a quantity object needs \"value\", \"min\"/\"max\" or \"part\""};
    if (v.contains("value")) p.nominal = ObjectValue(v["value"], "value", unit, &expected, false);
    if (v.contains("min") || v.contains("max")) {
      p.domain.lo = v.contains("min") ? ObjectValue(v["min"], "min", unit, &expected, true) : fill.lo;
      p.domain.hi = v.contains("max") ? ObjectValue(v["max"], "max", unit, &expected, true) : fill.hi;
    } else if (p.nominal) {
      p.domain = Domain::Point(*p.nominal);
    } else {
      p.domain = fill;  // a database part: unknown until resolved
    }
    ReadNoteAndProvenance(v, p);
  } else {
    throw QuantityError{"", "a quantity must be a number (SI), a string with a unit (\"50 mm\"), an interval "
                            "(\"[43, 51] GPa\") or an object, got " + TypeName(v)};
  }
  if (p.domain.empty())
    throw QuantityError{"", "the interval is empty (min > max); write [min, max]"};
  if (p.nominal && !p.domain.contains(*p.nominal))
    throw QuantityError{"", "the nominal value lies outside its interval"};
  return p;
}

// ---------------------------------------------------------------------------------------------
// The reader

struct Node {
  const json& value;
  std::string pointer;

  Node operator[](const std::string& key) const { return {value.at(key), pointer + "/" + detail::EscapePointerToken(key)}; }
  Node operator[](std::size_t i) const { return {value.at(i), pointer + "/" + std::to_string(i)}; }
  bool has(const std::string& key) const { return value.is_object() && value.contains(key); }
};

class Reader {
 public:
  Reader(const detail::LocatedJson& doc, std::string file) : doc_(doc), file_(std::move(file)) {}

  Project Read() {
    const Node root{doc_.value, ""};
    RequireObject(root, "a project file");
    CheckKeys(root, {"format", "name", "description", "sources", "settings", "components", "connections",
                     "elements", "element_connections", "requirements", "load_cases", "scenarios",
                     "experiment"},
              "the project");
    Project p;
    p.file = file_;
    if (!root.has("format"))
      Fail(root, "missing key 'format'; start the file with \"format\": \"" + std::string(kFormat) + "\"");
    const std::string format = String(root["format"], "'format'");
    if (format != kFormat)
      Fail(root["format"], "unsupported format '" + format + "'; this version of highlift reads \"" + kFormat + "\"");
    if (!root.has("name")) Fail(root, "missing key 'name' in the project; add \"name\": \"...\"");
    p.name = String(root["name"], "'name'");
    if (root.has("description")) p.description = String(root["description"], "'description'");
    if (root.has("sources")) {
      const Node sources = root["sources"];
      RequireArray(sources, "'sources'");
      for (std::size_t i = 0; i < sources.value.size(); ++i) p.sources.push_back(String(sources[i], "a source"));
    }
    if (root.has("settings")) p.settings = ReadSettings(root["settings"]);
    if (root.has("components")) ReadComponents(root["components"], false, p.components);
    if (root.has("elements")) ReadComponents(root["elements"], true, p.elements);
    if (root.has("connections")) p.connections = ReadConnections(root["connections"], "connection");
    if (root.has("element_connections"))
      p.element_connections = ReadConnections(root["element_connections"], "element connection");
    if (root.has("requirements")) ReadRequirements(root["requirements"], p);
    if (root.has("load_cases")) ReadLoadCases(root["load_cases"], p);
    if (root.has("scenarios")) ReadScenarios(root["scenarios"], p);
    if (root.has("experiment")) p.experiment = ReadExperiment(root["experiment"]);
    return p;
  }

  // Public for ParseQuantity: converts a QuantityError at `node` into an InputError.
  [[noreturn]] void FailQuantity(const Node& node, const QuantityError& e, const std::string& context) const {
    const std::string pointer = node.pointer + e.sub;
    SourceLocation where = e.at_key ? doc_.AtKey(file_, pointer) : doc_.At(file_, pointer);
    throw InputError(context + e.message, where);
  }

 private:
  SourceLocation Where(const Node& n) const { return doc_.At(file_, n.pointer); }

  [[noreturn]] void Fail(const Node& n, const std::string& message) const { throw InputError(message, Where(n)); }

  void RequireObject(const Node& n, const std::string& what) const {
    if (!n.value.is_object()) Fail(n, what + " must be a JSON object {...}, got " + TypeName(n.value));
  }
  void RequireArray(const Node& n, const std::string& what) const {
    if (!n.value.is_array()) Fail(n, what + " must be a JSON array [...], got " + TypeName(n.value));
  }

  void CheckKeys(const Node& n, const std::vector<std::string>& allowed, const std::string& what) const {
    for (const auto& [key, value] : n.value.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      const std::string pointer = n.pointer + "/" + detail::EscapePointerToken(key);
      throw InputError("unknown key '" + key + "' in " + what + SuggestionHint(key, allowed, "allowed keys"),
                       doc_.AtKey(file_, pointer));
    }
  }

  void Require(const Node& n, const std::string& key, const std::string& what) const {
    if (!n.has(key)) Fail(n, "missing key '" + key + "' in " + what + "; add \"" + key + "\": ...");
  }

  std::string String(const Node& n, const std::string& what) const {
    if (!n.value.is_string()) Fail(n, what + " must be a string, got " + TypeName(n.value));
    return n.value.get<std::string>();
  }

  double Number(const Node& n, const std::string& what) const {
    if (!n.value.is_number()) Fail(n, what + " must be a number, got " + TypeName(n.value));
    return n.value.get<double>();
  }

  // A single quantity (no interval) of the given dimension: a number (SI) or "1.5 s".
  double Scalar(const Node& n, const Dimension& dimension, const std::string& what) const {
    try {
      if (n.value.is_number()) return n.value.get<double>();
      if (!n.value.is_string())
        Fail(n, what + " must be a number (SI) or a string with a unit, got " + TypeName(n.value));
      const std::string text = n.value.get<std::string>();
      const QuantityText q = SplitQuantity(text);
      if (!q.nominal || q.lo) Fail(n, what + " takes one value, not an interval: " + Quote(text));
      return ConvertToSI(*q.nominal, q.unit, &dimension, text);
    } catch (const QuantityError& e) {
      FailQuantity(n, e, what + ": ");
    }
  }

  // Named scalars: number (SI) or "value unit" of any dimension.
  std::map<std::string, double> Values(const Node& n, const std::string& what) const {
    RequireObject(n, what);
    std::map<std::string, double> values;
    for (const auto& [key, value] : n.value.items()) {
      const Node item = n[key];
      try {
        if (value.is_number()) {
          values[key] = value.get<double>();
          continue;
        }
        if (!value.is_string())
          Fail(item, what + " '" + key + "' must be a number (SI) or a string with a unit, got " + TypeName(value));
        const std::string text = value.get<std::string>();
        const QuantityText q = SplitQuantity(text);
        if (!q.nominal || q.lo) Fail(item, what + " '" + key + "' takes one value, not an interval");
        values[key] = ConvertToSI(*q.nominal, q.unit, nullptr, text);
      } catch (const QuantityError& e) {
        FailQuantity(item, e, what + " '" + key + "': ");
      }
    }
    return values;
  }

  // The Modelica experiment annotation's names: StartTime, StopTime, Interval, Tolerance.
  Experiment ReadExperiment(const Node& n) const {
    RequireObject(n, "'experiment'");
    CheckKeys(n, {"StartTime", "StopTime", "Interval", "Tolerance"}, "the experiment");
    Experiment x;
    x.where = Where(n);
    if (n.has("StartTime")) x.start_time = Scalar(n["StartTime"], dimensions::Time(), "experiment 'StartTime'");
    if (!n.has("StopTime")) Fail(n, "the experiment needs 'StopTime' (e.g. \"StopTime\": \"1 s\")");
    x.stop_time = Scalar(n["StopTime"], dimensions::Time(), "experiment 'StopTime'");
    if (!(x.stop_time > x.start_time))
      Fail(n["StopTime"], "experiment 'StopTime' must be greater than 'StartTime'");
    if (n.has("Interval")) {
      x.interval = Scalar(n["Interval"], dimensions::Time(), "experiment 'Interval'");
      if (!(*x.interval > 0)) Fail(n["Interval"], "experiment 'Interval' must be > 0 (e.g. \"1 ms\")");
    }
    if (n.has("Tolerance")) {
      x.tolerance = Number(n["Tolerance"], "experiment 'Tolerance'");
      if (!(*x.tolerance > 0 && *x.tolerance < 1))
        Fail(n["Tolerance"], "experiment 'Tolerance' must lie between 0 and 1 (e.g. 1e-6)");
    }
    return x;
  }

  Settings ReadSettings(const Node& n) const {
    RequireObject(n, "'settings'");
    CheckKeys(n, {"shaft_elements", "relative_tolerance", "absolute_tolerance", "output_interval",
                  "structural_damping", "initial", "values"},
              "the settings");
    Settings s;
    if (n.has("shaft_elements")) {
      const Node e = n["shaft_elements"];
      if (!e.value.is_number_integer() || e.value.get<long long>() < 1 || e.value.get<long long>() > 1000)
        Fail(e, "settings 'shaft_elements' must be an integer from 1 to 1000, got " + e.value.dump());
      s.shaft_elements = e.value.get<int>();
    }
    if (n.has("relative_tolerance")) {
      s.relative_tolerance = Number(n["relative_tolerance"], "settings 'relative_tolerance'");
      if (!(s.relative_tolerance > 0 && s.relative_tolerance < 1))
        Fail(n["relative_tolerance"], "settings 'relative_tolerance' must lie between 0 and 1 (e.g. 1e-6), got " +
                                          n["relative_tolerance"].value.dump());
    }
    if (n.has("absolute_tolerance")) {
      s.absolute_tolerance = Number(n["absolute_tolerance"], "settings 'absolute_tolerance'");
      if (!(*s.absolute_tolerance > 0))
        Fail(n["absolute_tolerance"], "settings 'absolute_tolerance' must be > 0 (e.g. 1e-8), got " +
                                          n["absolute_tolerance"].value.dump());
    }
    if (n.has("output_interval")) {
      s.output_interval = Scalar(n["output_interval"], dimensions::Time(), "settings 'output_interval'");
      if (!(s.output_interval > 0)) Fail(n["output_interval"], "settings 'output_interval' must be > 0 (e.g. \"1 ms\")");
    }
    if (n.has("structural_damping")) {
      s.structural_damping = Scalar(n["structural_damping"], dimensions::Time(), "settings 'structural_damping'");
      if (!(s.structural_damping >= 0 && s.structural_damping < 1))
        Fail(n["structural_damping"], "settings 'structural_damping' (d = beta*c) must lie in [0, 1) s "
                                      "(e.g. \"0.4 ms\"; 0: no damping beyond the components' own)");
    }
    if (n.has("initial")) {
      s.initial = String(n["initial"], "settings 'initial'");
      if (s.initial != "given" && s.initial != "steady_state")
        Fail(n["initial"], "settings 'initial' must be \"given\" (the start values) or \"steady_state\" (every "
                           "inertia starts with a = 0), got \"" + s.initial + "\"");
    }
    if (n.has("values")) s.values = Values(n["values"], "settings value");
    return s;
  }

  // Components and elements -------------------------------------------------------------------

  void ReadComponents(const Node& n, bool elements, std::vector<Component>& out) {
    const std::string key = elements ? "'elements'" : "'components'";
    RequireArray(n, key);
    for (std::size_t i = 0; i < n.value.size(); ++i) out.push_back(ReadComponent(n[i], elements, i));
  }

  Component ReadComponent(const Node& n, bool element, std::size_t index) {
    const std::string kind = element ? "element" : "component";
    const std::string anonymous = kind + " " + std::to_string(index);
    RequireObject(n, anonymous);
    Require(n, "id", anonymous);
    Component c;
    c.id = String(n["id"], anonymous + ": 'id'");
    c.where = Where(n);
    CheckId(n["id"], c.id, kind);
    const std::string named = kind + " '" + c.id + "'";
    CheckKeys(n, {"id", "type", "description", "labels", "parameters"}, named);
    Require(n, "type", named);
    c.type = String(n["type"], named + ": 'type'");
    const ComponentTypeSpec* spec = element ? FindElementType(c.type) : FindComponentType(c.type);
    if (spec == nullptr) {
      std::vector<std::string> names;
      for (const auto& t : element ? ElementTypes() : ComponentTypes()) names.push_back(t.name);
      Fail(n["type"], named + ": unknown " + kind + " type '" + c.type + "'" + SuggestionHint(c.type, names, "valid types"));
    }
    const std::string context = named + " (" + c.type + "): ";
    if (n.has("description")) c.description = String(n["description"], context + "'description'");
    if (n.has("labels")) {
      const Node labels = n["labels"];
      RequireObject(labels, context + "'labels'");
      for (const auto& [key, value] : labels.value.items())
        c.labels[key] = String(labels[key], context + "label '" + key + "'");
    }
    std::set<std::string> given;
    if (n.has("parameters")) {
      const Node parameters = n["parameters"];
      RequireObject(parameters, context + "'parameters'");
      std::vector<std::string> names;
      for (const auto& ps : spec->parameters) names.push_back(ps.name);
      for (const auto& [key, value] : parameters.value.items()) {
        const ParameterSpec* ps = spec->FindParameter(key);
        const Node item = parameters[key];
        if (ps == nullptr)
          throw InputError(context + "unknown parameter '" + key + "'" + SuggestionHint(key, names, "parameters of " + c.type),
                           doc_.AtKey(file_, item.pointer));
        ReadParameter(item, *ps, context, c);
        given.insert(key);
      }
    }
    // Parameters not given take the catalogue default; optional ones without a default stay absent.
    for (const auto& ps : spec->parameters) {
      if (given.count(ps.name) || ps.kind == ParameterKind::kTable || ps.kind == ParameterKind::kText) continue;
      if (ps.optional && !ps.nominal) continue;
      Parameter p;
      p.nominal = ps.nominal;
      p.domain = ps.default_domain;
      p.provenance = Provenance::kDefault;
      p.note = ps.source;
      c.parameters[ps.name] = p;
    }
    return c;
  }

  // Ids and the names of load cases and scenarios are names of the constraint language: `check`,
  // `tradeoff`, the report and requirements name quantities after them (shaft_1.polar_moment,
  // torque.<load case>.<component>, peak.<case>.inertia), so a '-', a space, a bracket or a
  // non-ASCII letter would be read as an operator or refused there (docs/project.schema.json:
  // "identifier").
  static bool IsIdentifier(const std::string& name) {
    const auto letter = [](char ch) { return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || ch == '_'; };
    return !name.empty() && letter(name[0]) &&
           std::all_of(name.begin(), name.end(), [&](char ch) { return letter(ch) || (ch >= '0' && ch <= '9'); });
  }
  void CheckName(const Node& n, const std::string& name, const std::string& what) const {
    if (IsIdentifier(name)) return;
    Fail(n, what + " '" + name + "' is not valid: use ASCII letters, digits and '_', starting with a letter or '_' "
                  "(requirements, `check` and `tradeoff` name quantities after it, as in torque.<load case>.<component>, "
                  "where '-', spaces, brackets and '.' are operators or separators)");
  }

  void CheckId(const Node& n, const std::string& id, const std::string& kind) {
    CheckName(n, id, kind + " id");
    const SourceLocation here = Where(n);
    auto [it, inserted] = ids_.emplace(id, std::make_pair(here, kind));
    if (!inserted)
      Fail(n, "duplicate id '" + id + "': already used by the " + it->second.second + " at line " +
                  std::to_string(it->second.first.line) + ", column " + std::to_string(it->second.first.column) +
                  "; give every component and element a unique id");
  }

  void ReadParameter(const Node& item, const ParameterSpec& ps, const std::string& context, Component& c) const {
    const std::string what = context + "parameter '" + ps.name + "'";
    switch (ps.kind) {
      case ParameterKind::kText:
        c.texts[ps.name] = String(item, what);
        return;
      case ParameterKind::kTable:
        c.tables[ps.name] = ReadMatrix(item, what);
        return;
      case ParameterKind::kInteger:
      case ParameterKind::kBoolean: {
        Parameter p;
        p.provenance = Provenance::kUser;
        const bool object_form = item.value.is_object();
        if (object_form) {
          try {
            CheckObjectKeys(item.value, {"value", "note", "provenance"}, "an integer or boolean parameter");
            ReadNoteAndProvenance(item.value, p);
          } catch (const QuantityError& e) {
            FailQuantity(item, e, what + ": ");
          }
          Require(item, "value", what);
        }
        const Node value_node = object_form ? item["value"] : item;
        const json* v = &value_node.value;
        if (ps.kind == ParameterKind::kBoolean) {
          if (!v->is_boolean()) Fail(value_node, what + " must be true or false, got " + TypeName(*v));
          p.nominal = v->get<bool>() ? 1.0 : 0.0;
        } else {
          if (!v->is_number_integer()) Fail(value_node, what + " must be an integer, got " + v->dump());
          p.nominal = static_cast<double>(v->get<long long>());
        }
        p.domain = Domain::Point(*p.nominal);
        p.where = Where(item);
        if (ps.kind == ParameterKind::kInteger && !ps.valid_range.contains(*p.nominal))
          Fail(value_node, what + " = " + FormatNumber(*p.nominal, 10) + " is outside its valid range " +
                               FormatDomain(ps.valid_range, "1", ps.dimension));
        c.parameters[ps.name] = p;
        return;
      }
      case ParameterKind::kScalar:
        break;
    }
    Parameter p;
    try {
      p = QuantityFromJson(item.value, ps.dimension, ps.valid_range);
    } catch (const QuantityError& e) {
      FailQuantity(item, e, what + ": ");
    }
    p.where = Where(item);
    // Values this close to zero are subnormal floating-point numbers (below 2.2e-308) or next to
    // them: they carry no physical meaning in a drive system (5e-324 kg*m^2, 1e-320 N*m) and lose
    // their precision in the analyses (the interval bounds of `check` and `size` round them to 0,
    // a mode analysis divides by their square root). 0 itself stays valid where the range has it.
    for (const double si : {p.nominal.value_or(0.0), p.domain.lo, p.domain.hi})
      if (si != 0.0 && std::abs(si) < kSmallestMagnitude)
        Fail(item, what + " = " + FormatValue(si, ps.unit, ps.dimension) + UnitSuffix(ps.unit) +
                       " is closer to zero than any physical value (" + FormatMessageNumber(kSmallestMagnitude) +
                       " in SI units); give 0 or a value of at least " +
                       FormatValue(kSmallestMagnitude, ps.unit, ps.dimension) + UnitSuffix(ps.unit));
    if (p.nominal && !ps.valid_range.contains(*p.nominal))
      Fail(item, what + " = " + FormatValue(*p.nominal, ps.unit, ps.dimension) + UnitSuffix(ps.unit) +
                     " is outside its valid range " + FormatDomain(ps.valid_range, ps.unit, ps.dimension) +
                     "; check the value and its unit");
    if (!(ps.valid_range.lo <= p.domain.lo && p.domain.hi <= ps.valid_range.hi))
      Fail(item, what + ": interval " + FormatDomain(p.domain, ps.unit, ps.dimension) +
                     " is not inside its valid range " + FormatDomain(ps.valid_range, ps.unit, ps.dimension) +
                     "; check the bounds and their unit");
    c.parameters[ps.name] = p;
  }

  // A table parameter: {"unit": [...], "points": [[...], ...]} or a plain matrix in SI.
  std::vector<std::vector<double>> ReadMatrix(const Node& n, const std::string& what) const {
    std::vector<std::string> units;
    if (n.value.is_object()) {
      CheckKeys(n, {"unit", "points"}, what);
      Require(n, "points", what);
      if (n.has("unit")) {
        const Node u = n["unit"];
        RequireArray(u, what + ": 'unit'");
        for (std::size_t i = 0; i < u.value.size(); ++i) units.push_back(String(u[i], what + ": a unit"));
      }
    }
    const Node points = n.value.is_object() ? n["points"] : n;
    RequireArray(points, what);
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < points.value.size(); ++i) {
      const Node row = points[i];
      RequireArray(row, what + ": row " + std::to_string(i));
      if (!rows.empty() && row.value.size() != rows.front().size())
        Fail(row, what + ": row " + std::to_string(i) + " has " + std::to_string(row.value.size()) +
                      " columns, the first row " + std::to_string(rows.front().size()));
      if (!units.empty() && units.size() != row.value.size())
        Fail(row, what + ": " + std::to_string(units.size()) + " units for " + std::to_string(row.value.size()) +
                      " columns; give one unit per column");
      std::vector<double> r;
      for (std::size_t j = 0; j < row.value.size(); ++j) {
        double v = Number(row[j], what + ": an entry");
        if (!units.empty()) {
          try {
            v = ConvertToSI(v, units[j], nullptr, units[j]);
          } catch (const QuantityError& e) {
            FailQuantity(n["unit"][j], e, what + ": ");
          }
        }
        r.push_back(v);
      }
      rows.push_back(std::move(r));
    }
    return rows;
  }

  // Connections --------------------------------------------------------------------------------

  PortRef ReadPortRef(const Node& n, const std::string& what) const {
    const std::string text = String(n, what);
    const auto dot = text.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == text.size() || text.find('.', dot + 1) != std::string::npos)
      Fail(n, what + ": '" + text + "' is not a port reference; " +
                  (what.find("element") != std::string::npos ? "write \"element.port\", e.g. \"spring.flange_a\""
                                                              : "write \"component.port\", e.g. \"pdu.left\""));
    return {text.substr(0, dot), text.substr(dot + 1)};
  }

  std::vector<Connection> ReadConnections(const Node& n, const std::string& kind) const {
    RequireArray(n, "'" + kind + "s'");
    std::vector<Connection> out;
    for (std::size_t i = 0; i < n.value.size(); ++i) {
      const Node item = n[i];
      const std::string what = kind + " " + std::to_string(i);
      if (!item.value.is_array() || item.value.size() != 2)
        Fail(item, what + " must be a pair of ports [\"a.port\", \"b.port\"], got " + item.value.dump());
      Connection c;
      c.a = ReadPortRef(item[0], what);
      c.b = ReadPortRef(item[1], what);
      c.where = Where(item);
      if (c.a == c.b) Fail(item, what + " connects '" + c.a.ToString() + "' to itself");
      out.push_back(std::move(c));
    }
    return out;
  }

  // Requirements, load cases, scenarios -----------------------------------------------------------

  void ReadRequirements(const Node& n, Project& p) const {
    RequireArray(n, "'requirements'");
    for (std::size_t i = 0; i < n.value.size(); ++i) {
      const Node item = n[i];
      const std::string anonymous = "requirement " + std::to_string(i);
      RequireObject(item, anonymous);
      Require(item, "id", anonymous);
      Requirement r;
      r.id = String(item["id"], anonymous + ": 'id'");
      const std::string what = "requirement '" + r.id + "'";
      CheckKeys(item, {"id", "expression", "description"}, what);
      Require(item, "expression", what);
      r.expression = String(item["expression"], what + ": 'expression'");
      if (Trim(r.expression).empty()) Fail(item["expression"], what + ": the expression is empty");
      if (item.has("description")) r.description = String(item["description"], what + ": 'description'");
      r.where = Where(item);
      for (const auto& other : p.requirements)
        if (other.id == r.id)
          Fail(item["id"], "duplicate requirement id '" + r.id + "' (also at line " + std::to_string(other.where.line) +
                               "); give every requirement a unique id");
      p.requirements.push_back(std::move(r));
    }
  }

  Table ReadTable(const Node& n, const Dimension& y_dimension, const std::string& what, bool time_only) const {
    RequireObject(n, what);
    CheckKeys(n, {"against", "unit", "points"}, what);
    Table t;
    if (n.has("against")) {
      t.abscissa = String(n["against"], what + ": 'against'");
      if (t.abscissa != "time" && t.abscissa != "position")
        Fail(n["against"], what + ": 'against' must be \"time\" or \"position\", got '" + t.abscissa + "'" +
                               DidYouMean(t.abscissa, {"time", "position"}));
      if (time_only && t.abscissa != "time") Fail(n["against"], what + " must be given against \"time\"");
    }
    const Dimension x_dimension = t.abscissa == "time" ? dimensions::Time() : dimensions::Dimensionless();
    std::string x_unit, y_unit;
    if (n.has("unit")) {
      const Node u = n["unit"];
      if (!u.value.is_array() || u.value.size() != 2 || !u.value[0].is_string() || !u.value[1].is_string())
        Fail(u, what + ": 'unit' must be two unit strings [abscissa, value], e.g. [\"s\", \"kN*m\"]");
      x_unit = u.value[0].get<std::string>();
      y_unit = u.value[1].get<std::string>();
      try {
        ConvertToSI(1.0, x_unit, &x_dimension, x_unit);
      } catch (QuantityError& e) {
        FailQuantity(u[0], e, what + ": abscissa unit: ");
      }
      try {
        ConvertToSI(1.0, y_unit, &y_dimension, y_unit);
      } catch (QuantityError& e) {
        FailQuantity(u[1], e, what + ": value unit: ");
      }
    }
    Require(n, "points", what);
    const Node points = n["points"];
    RequireArray(points, what + ": 'points'");
    if (points.value.empty()) Fail(points, what + ": 'points' is empty; give at least one [x, y] pair");
    for (std::size_t i = 0; i < points.value.size(); ++i) {
      const Node pt = points[i];
      if (!pt.value.is_array() || pt.value.size() != 2 || !pt.value[0].is_number() || !pt.value[1].is_number())
        Fail(pt, what + ": point " + std::to_string(i) + " must be a pair of numbers [x, y], got " + pt.value.dump());
      const double x = x_unit.empty() ? pt.value[0].get<double>() : ToSI(pt.value[0].get<double>(), x_unit, x_dimension);
      const double y = y_unit.empty() ? pt.value[1].get<double>() : ToSI(pt.value[1].get<double>(), y_unit, y_dimension);
      if (!t.x.empty() && !(x > t.x.back()))
        Fail(pt, what + ": point " + std::to_string(i) + " does not increase the abscissa (" +
                     FormatNumber(pt.value[0].get<double>(), 8) + " after " +
                     points.value[i - 1][0].dump() + "); sort the points by x");
      t.x.push_back(x);
      t.y.push_back(y);
    }
    return t;
  }

  void ReadLoadCases(const Node& n, Project& p) const {
    RequireArray(n, "'load_cases'");
    for (std::size_t i = 0; i < n.value.size(); ++i) {
      const Node item = n[i];
      const std::string anonymous = "load case " + std::to_string(i);
      RequireObject(item, anonymous);
      Require(item, "name", anonymous);
      LoadCase lc;
      lc.name = String(item["name"], anonymous + ": 'name'");
      CheckName(item["name"], lc.name, "load case name");
      const std::string what = "load case '" + lc.name + "'";
      CheckKeys(item, {"name", "description", "direction", "pdu_speed", "actuator_loads", "values"}, what);
      if (item.has("description")) lc.description = String(item["description"], what + ": 'description'");
      if (item.has("direction")) {
        lc.direction = String(item["direction"], what + ": 'direction'");
        if (lc.direction != "extend" && lc.direction != "retract")
          Fail(item["direction"], what + ": 'direction' must be \"extend\" or \"retract\", got '" + lc.direction + "'" +
                                      DidYouMean(lc.direction, {"extend", "retract"}));
      }
      if (item.has("pdu_speed"))
        lc.pdu_speed = ReadTable(item["pdu_speed"], dimensions::AngularVelocity(), what + ": 'pdu_speed'", true);
      if (item.has("actuator_loads")) {
        const Node loads = item["actuator_loads"];
        RequireObject(loads, what + ": 'actuator_loads'");
        for (const auto& [key, value] : loads.value.items())
          lc.actuator_loads[key] = ReadTable(loads[key], dimensions::Torque(), what + ": load of '" + key + "'", false);
      }
      if (item.has("values")) lc.values = Values(item["values"], what + ": value");
      lc.where = Where(item);
      for (const auto& other : p.load_cases)
        if (other.name == lc.name)
          Fail(item["name"], "duplicate load case name '" + lc.name + "' (also at line " +
                                 std::to_string(other.where.line) + "); give every load case a unique name");
      p.load_cases.push_back(std::move(lc));
    }
  }

  // {"component": id, "time": quantity}
  std::pair<std::string, double> ReadEvent(const Node& n, const std::string& what) const {
    RequireObject(n, what);
    CheckKeys(n, {"component", "time"}, what);
    Require(n, "component", what);
    Require(n, "time", what);
    const std::string component = String(n["component"], what + ": 'component'");
    const double time = Scalar(n["time"], dimensions::Time(), what + ": 'time'");
    if (time < 0) Fail(n["time"], what + ": 'time' must be >= 0");
    return {component, time};
  }

  void ReadScenarios(const Node& n, Project& p) const {
    RequireArray(n, "'scenarios'");
    const std::vector<std::string> kinds = {"extension", kJamKind, "rupture"};
    for (std::size_t i = 0; i < n.value.size(); ++i) {
      const Node item = n[i];
      const std::string anonymous = "scenario " + std::to_string(i);
      RequireObject(item, anonymous);
      Require(item, "name", anonymous);
      Scenario s;
      s.name = String(item["name"], anonymous + ": 'name'");
      CheckName(item["name"], s.name, "scenario name");
      const std::string what = "scenario '" + s.name + "'";
      CheckKeys(item, {"name", "kind", "description", "load_case", "stop_time", "output_interval", kJamKind, "rupture", "wtb",
                       "values"},
                what);
      Require(item, "kind", what);
      s.kind = String(item["kind"], what + ": 'kind'");
      if (std::find(kinds.begin(), kinds.end(), s.kind) == kinds.end())
        Fail(item["kind"], what + ": unknown kind '" + s.kind + "'" + SuggestionHint(s.kind, kinds, "valid kinds"));
      if (item.has("description")) s.description = String(item["description"], what + ": 'description'");
      if (item.has("load_case")) s.load_case = String(item["load_case"], what + ": 'load_case'");
      if (item.has("stop_time")) {
        s.stop_time = Scalar(item["stop_time"], dimensions::Time(), what + ": 'stop_time'");
        if (!(s.stop_time > 0)) Fail(item["stop_time"], what + ": 'stop_time' must be > 0");
      }
      if (item.has("output_interval")) {
        s.output_interval = Scalar(item["output_interval"], dimensions::Time(), what + ": 'output_interval'");
        if (!(*s.output_interval > 0))
          Fail(item["output_interval"], what + ": 'output_interval' must be > 0 (e.g. \"10 ms\")");
      }
      if (s.kind == kJamKind && !item.has(kJamKind))
        Fail(item, what + ": kind \"jam\" needs \"jam\": {\"component\": ..., \"time\": ...}");
      if (s.kind == "rupture" && !item.has("rupture"))
        Fail(item, what + ": kind \"rupture\" needs \"rupture\": {\"component\": ..., \"time\": ...}");
      if (item.has(kJamKind)) {
        if (s.kind != kJamKind)
          Fail(item[kJamKind], what + ": 'jam' is only allowed with kind \"jam\" (kind is \"" + s.kind + "\")");
        auto [component, time] = ReadEvent(item[kJamKind], what + ": 'jam'");
        s.jam_component = component;
        s.jam_time = time;
      }
      if (item.has("rupture")) {
        if (s.kind != "rupture")
          Fail(item["rupture"], what + ": 'rupture' is only allowed with kind \"rupture\" (kind is \"" + s.kind + "\")");
        auto [component, time] = ReadEvent(item["rupture"], what + ": 'rupture'");
        s.rupture_component = component;
        s.rupture_time = time;
      }
      if (item.has("wtb")) {
        const Node w = item["wtb"];
        const std::string wwhat = what + ": 'wtb'";
        RequireObject(w, wwhat);
        CheckKeys(w, {"trigger", "time"}, wwhat);
        if (w.has("trigger")) {
          s.wtb_trigger = String(w["trigger"], wwhat + ": 'trigger'");
          if (s.wtb_trigger != "monitor" && s.wtb_trigger != "time")
            Fail(w["trigger"], wwhat + ": 'trigger' must be \"monitor\" or \"time\", got '" + s.wtb_trigger + "'" +
                                   DidYouMean(s.wtb_trigger, {"monitor", "time"}));
        }
        if (w.has("time")) {
          s.wtb_time = Scalar(w["time"], dimensions::Time(), wwhat + ": 'time'");
          if (*s.wtb_time < 0) Fail(w["time"], wwhat + ": 'time' must be >= 0");
        }
        if (s.wtb_trigger == "time" && !s.wtb_time)
          Fail(w, wwhat + ": trigger \"time\" needs \"time\": the moment the brakes are applied");
      }
      if (item.has("values")) s.values = Values(item["values"], what + ": value");
      s.where = Where(item);
      for (const auto& other : p.scenarios)
        if (other.name == s.name)
          Fail(item["name"], "duplicate scenario name '" + s.name + "' (also at line " + std::to_string(other.where.line) +
                                 "); give every scenario a unique name");
      p.scenarios.push_back(std::move(s));
    }
  }

  const detail::LocatedJson& doc_;
  std::string file_;
  std::map<std::string, std::pair<SourceLocation, std::string>> ids_;
};

// ---------------------------------------------------------------------------------------------
// Writing

json Bound(double v) {
  if (std::isinf(v)) return v > 0 ? json("inf") : json("-inf");
  return v;
}

bool IsDefault(const Parameter& p, const ParameterSpec& spec) {
  return p.provenance == Provenance::kDefault && p.nominal == spec.nominal && p.domain == spec.default_domain &&
         p.note == spec.source && p.database_part.empty();
}

json ParameterToJson(const Parameter& p) {
  const bool plain_point = p.nominal && p.domain == Domain::Point(*p.nominal);
  if (p.provenance == Provenance::kUser && p.note.empty() && p.database_part.empty() && plain_point && !p.design)
    return *p.nominal;
  json o = json::object();
  if (!p.database_part.empty()) o["part"] = p.database_part;
  if (p.nominal) o["value"] = *p.nominal;
  if (!plain_point) {
    o["min"] = Bound(p.domain.lo);
    o["max"] = Bound(p.domain.hi);
  }
  if (!p.note.empty()) o["note"] = p.note;
  const Provenance implied = p.database_part.empty() ? Provenance::kUser : Provenance::kDatabase;
  if (p.provenance != implied) o["provenance"] = ToString(p.provenance);
  if (p.design) o["design"] = true;
  return o;
}

json IntegerToJson(const Parameter& p, const ParameterSpec& spec) {
  json value = spec.kind == ParameterKind::kBoolean ? json(p.nominal.value_or(0) != 0)
                                                    : json(static_cast<long long>(std::llround(p.nominal.value_or(0))));
  if (p.provenance == Provenance::kUser && p.note.empty()) return value;
  json o = {{"value", value}};
  if (!p.note.empty()) o["note"] = p.note;
  if (p.provenance != Provenance::kUser) o["provenance"] = ToString(p.provenance);
  return o;
}

json ComponentToJson(const Component& c, const ComponentTypeSpec* spec) {
  json o = {{"id", c.id}, {"type", c.type}};
  if (!c.description.empty()) o["description"] = c.description;
  if (!c.labels.empty()) o["labels"] = c.labels;
  json parameters = json::object();
  for (const auto& [name, p] : c.parameters) {
    const ParameterSpec* ps = spec ? spec->FindParameter(name) : nullptr;
    if (ps && IsDefault(p, *ps)) continue;
    if (ps && (ps->kind == ParameterKind::kInteger || ps->kind == ParameterKind::kBoolean)) {
      parameters[name] = IntegerToJson(p, *ps);
    } else {
      parameters[name] = ParameterToJson(p);
    }
  }
  for (const auto& [name, rows] : c.tables) parameters[name] = rows;
  for (const auto& [name, text] : c.texts) parameters[name] = text;
  if (!parameters.empty()) o["parameters"] = parameters;
  return o;
}

json ConnectionsToJson(const std::vector<Connection>& connections) {
  json a = json::array();
  for (const auto& c : connections) a.push_back({c.a.ToString(), c.b.ToString()});
  return a;
}

json TableToJson(const Table& t) {
  json points = json::array();
  for (std::size_t i = 0; i < t.x.size(); ++i) points.push_back({t.x[i], t.y[i]});
  return {{"against", t.abscissa}, {"points", points}};
}

}  // namespace

// ---------------------------------------------------------------------------------------------

namespace {

/// The text of a project file, read in blocks. Reading stops at the first byte that cannot
/// start a JSON document (`validate /dev/zero` stops at its first NUL: the parser then names it
/// at line 1, column 1), and a file that is not a regular file (a device, a FIFO) is read up to
/// kMaxStreamBytes: its size is not known beforehand and it may never end.
std::string ReadProjectText(std::istream& in, const std::filesystem::path& file, const SourceLocation& where) {
  constexpr std::size_t kBlock = 1 << 16;
  constexpr std::size_t kMaxStreamBytes = std::size_t{256} << 20;  // 256 MiB
  std::error_code ec;
  const bool regular = std::filesystem::is_regular_file(file, ec);
  std::string text;
  bool started = false;  // the first byte other than white space was seen and can start JSON
  char block[kBlock];
  while (in.read(block, kBlock) || in.gcount() > 0) {
    const auto got = static_cast<std::size_t>(in.gcount());
    if (!started) {
      for (std::size_t i = 0; i < got; ++i) {
        const char c = block[i];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
        // A value's first byte, or the first byte of a UTF-8 byte-order mark (the parser names it).
        if (std::string_view("{[\"-0123456789tfn\xEF").find(c) == std::string_view::npos) {
          text.append(block, i + 1);
          return text;  // the parser reports the byte at its line and column
        }
        started = true;
        break;
      }
    }
    text.append(block, got);
    if (!regular && text.size() > kMaxStreamBytes)
      throw InputError("the project file is not a regular file and gives more than " +
                           std::to_string(kMaxStreamBytes >> 20) +
                           " MiB without ending; give a project file (a regular file)",
                       where);
  }
  return text;
}

}  // namespace

Project ParseProject(const std::string& text, const std::string& file_name) {
  const detail::LocatedJson doc = detail::ParseLocatedJson(text, file_name);
  Reader reader(doc, file_name);
  Project project = reader.Read();
  // A closed loop breaks every analysis (sizing, lumped models, modes, peaks, the simulator's
  // drive model): rejected here, like a duplicate id, so no command runs on it.
  const ComponentGraph graph(project);
  if (!graph.LoopConnections().empty()) {
    const std::size_t first = graph.LoopConnections().front();
    throw InputError(DescribeLoop(graph, project, first), project.connections[first].where);
  }
  return project;
}

Project LoadProject(const std::filesystem::path& file) {
  SourceLocation where;
  where.file = file.string();
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw InputError("the project path is a directory; give the project's .json file", where);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError("cannot open the project file; check the path", where);
  RegisterInputFile(file);
  return ParseProject(ReadProjectText(in, file, where), file.string());
}

Parameter ParseQuantity(const nlohmann::json& value, const Dimension& expected, const SourceLocation& where) {
  try {
    Parameter p = QuantityFromJson(value, expected, Domain::Whole());
    p.where = where;
    return p;
  } catch (const QuantityError& e) {
    SourceLocation w = where;
    w.json_pointer += e.sub;
    throw InputError(e.message, w);
  }
}

nlohmann::json ProjectToJson(const Project& project) {
  json o;
  o["format"] = kFormat;
  o["name"] = project.name;
  if (!project.description.empty()) o["description"] = project.description;
  if (!project.sources.empty()) o["sources"] = project.sources;
  json settings = {{"shaft_elements", project.settings.shaft_elements},
                   {"relative_tolerance", project.settings.relative_tolerance},
                   {"output_interval", project.settings.output_interval},
                   {"structural_damping", project.settings.structural_damping}};
  if (project.settings.absolute_tolerance) settings["absolute_tolerance"] = *project.settings.absolute_tolerance;
  if (project.settings.initial != "given") settings["initial"] = project.settings.initial;
  if (!project.settings.values.empty()) settings["values"] = project.settings.values;
  o["settings"] = settings;
  if (!project.components.empty()) {
    json a = json::array();
    for (const auto& c : project.components) a.push_back(ComponentToJson(c, FindComponentType(c.type)));
    o["components"] = a;
  }
  if (!project.connections.empty()) o["connections"] = ConnectionsToJson(project.connections);
  if (!project.elements.empty()) {
    json a = json::array();
    for (const auto& c : project.elements) a.push_back(ComponentToJson(c, FindElementType(c.type)));
    o["elements"] = a;
  }
  if (!project.element_connections.empty()) o["element_connections"] = ConnectionsToJson(project.element_connections);
  if (!project.requirements.empty()) {
    json a = json::array();
    for (const auto& r : project.requirements) {
      json item = {{"id", r.id}, {"expression", r.expression}};
      if (!r.description.empty()) item["description"] = r.description;
      a.push_back(item);
    }
    o["requirements"] = a;
  }
  if (!project.load_cases.empty()) {
    json a = json::array();
    for (const auto& lc : project.load_cases) {
      json item = {{"name", lc.name}, {"direction", lc.direction}};
      if (!lc.description.empty()) item["description"] = lc.description;
      if (lc.pdu_speed) item["pdu_speed"] = TableToJson(*lc.pdu_speed);
      if (!lc.actuator_loads.empty()) {
        json loads = json::object();
        for (const auto& [id, t] : lc.actuator_loads) loads[id] = TableToJson(t);
        item["actuator_loads"] = loads;
      }
      if (!lc.values.empty()) item["values"] = lc.values;
      a.push_back(item);
    }
    o["load_cases"] = a;
  }
  if (!project.scenarios.empty()) {
    json a = json::array();
    for (const auto& s : project.scenarios) {
      json item = {{"name", s.name}, {"kind", s.kind}, {"stop_time", s.stop_time}};
      if (s.output_interval) item["output_interval"] = *s.output_interval;
      if (!s.description.empty()) item["description"] = s.description;
      if (!s.load_case.empty()) item["load_case"] = s.load_case;
      if (s.jam_component) item[kJamKind] = {{"component", *s.jam_component}, {"time", s.jam_time.value_or(0.0)}};
      if (s.rupture_component)
        item["rupture"] = {{"component", *s.rupture_component}, {"time", s.rupture_time.value_or(0.0)}};
      if (s.wtb_trigger != "monitor" || s.wtb_time) {
        json w = {{"trigger", s.wtb_trigger}};
        if (s.wtb_time) w["time"] = *s.wtb_time;
        item["wtb"] = w;
      }
      if (!s.values.empty()) item["values"] = s.values;
      a.push_back(item);
    }
    o["scenarios"] = a;
  }
  if (project.experiment) {
    const Experiment& x = *project.experiment;
    json e = {{"StartTime", x.start_time}, {"StopTime", x.stop_time}};
    if (x.interval) e["Interval"] = *x.interval;
    if (x.tolerance) e["Tolerance"] = *x.tolerance;
    o["experiment"] = e;
  }
  return o;
}

void SaveProject(const Project& project, const std::filesystem::path& file) {
  WriteOutputFile(file, ProjectToJson(project).dump(2) + "\n", "project file");
}

}  // namespace highlift
