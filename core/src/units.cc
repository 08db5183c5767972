// Units through UDUNITS-2: one lazily initialised unit system guarded by a mutex (UDUNITS-2 is not
// thread-safe), parsed units cached by their text; the units of the examples and the catalogue
// come from a built-in table of what UDUNITS-2 gives for them (unit_table.h), so that loading
// a project need not read the unit database.
#include "highlift/core/units.h"

#include <udunits2.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <vector>
#include <mutex>
#include <stdexcept>
#include <string>

#include "highlift/core/error.h"
#include "unit_table.h"

namespace highlift {

// ---------------------------------------------------------------------------------------------
// Dimension

Dimension Dimension::operator*(const Dimension& o) const {
  Dimension r;
  for (std::size_t i = 0; i < exponents.size(); ++i) r.exponents[i] = exponents[i] + o.exponents[i];
  return r;
}

Dimension Dimension::operator/(const Dimension& o) const {
  Dimension r;
  for (std::size_t i = 0; i < exponents.size(); ++i) r.exponents[i] = exponents[i] - o.exponents[i];
  return r;
}

Dimension Dimension::pow(int n) const {
  Dimension r;
  for (std::size_t i = 0; i < exponents.size(); ++i) r.exponents[i] = exponents[i] * n;
  return r;
}

namespace {
// Index order of Dimension::exponents.
constexpr std::array<const char*, 7> kBaseSymbols = {"m", "kg", "s", "A", "K", "mol", "cd"};
// Display order: kg before m, as in "kg*m^2*s^-2".
constexpr std::array<int, 7> kDisplayOrder = {1, 0, 2, 3, 4, 5, 6};

Dimension Make(int m, int kg, int s) {
  Dimension d;
  d.exponents[0] = m;
  d.exponents[1] = kg;
  d.exponents[2] = s;
  return d;
}
}  // namespace

std::string Dimension::ToString() const {
  std::string out;
  for (int i : kDisplayOrder) {
    const int e = exponents[static_cast<std::size_t>(i)];
    if (e == 0) continue;
    if (!out.empty()) out += "*";
    out += kBaseSymbols[static_cast<std::size_t>(i)];
    if (e != 1) out += "^" + std::to_string(e);
  }
  return out.empty() ? "1" : out;
}

namespace dimensions {
Dimension Dimensionless() { return {}; }
Dimension Length() { return Make(1, 0, 0); }
Dimension Mass() { return Make(0, 1, 0); }
Dimension Time() { return Make(0, 0, 1); }
Dimension AngularVelocity() { return Make(0, 0, -1); }
Dimension AngularAcceleration() { return Make(0, 0, -2); }
Dimension Torque() { return Make(2, 1, -2); }
Dimension RotationalDamping() { return Make(2, 1, -1); }
Dimension Inertia() { return Make(2, 1, 0); }
Dimension Force() { return Make(1, 1, -2); }
Dimension Pressure() { return Make(-1, 1, -2); }
Dimension Density() { return Make(-3, 1, 0); }
Dimension LinearDensity() { return Make(-1, 1, 0); }
Dimension TorquePerLength() { return Make(1, 1, -2); }
Dimension Power() { return Make(2, 1, -3); }
Dimension Area() { return Make(2, 0, 0); }
Dimension Volume() { return Make(3, 0, 0); }
Dimension VolumeFlowRate() { return Make(3, 0, -1); }
Dimension Energy() { return Make(2, 1, -2); }
}  // namespace dimensions

namespace {
struct NamedDimension {
  Dimension dimension;
  const char* article;
  const char* name;
  const char* unit;
};

// First match wins: a torque and an energy share a dimension, and so do a force and a torque per
// length; the first name is the one used in this tool.
const std::vector<NamedDimension>& NamedDimensions() {
  using namespace dimensions;
  static const std::vector<NamedDimension> named = {
      {Dimensionless(), "a", "dimensionless number", "1"},
      {Length(), "a", "length", "m"},
      {Mass(), "a", "mass", "kg"},
      {Time(), "a", "time", "s"},
      {AngularVelocity(), "an", "angular velocity", "rad/s"},
      {AngularAcceleration(), "an", "angular acceleration", "rad/s^2"},
      {Torque(), "a", "torque", "N*m"},
      {RotationalDamping(), "a", "rotational damping", "N*m*s/rad"},
      {Inertia(), "an", "inertia", "kg*m^2"},
      {Force(), "a", "force", "N"},
      {Pressure(), "a", "pressure", "Pa"},
      {Density(), "a", "density", "kg/m^3"},
      {LinearDensity(), "a", "linear density", "kg/m"},
      {Power(), "a", "power", "W"},
      {Area(), "an", "area", "m^2"},
      {Volume(), "a", "volume", "m^3"},
      {VolumeFlowRate(), "a", "volume flow rate", "m^3/s"},
  };
  return named;
}

const NamedDimension* FindNamed(const Dimension& d) {
  for (const auto& n : NamedDimensions())
    if (n.dimension == d) return &n;
  return nullptr;
}

// "a torque (N*m)" or "a quantity of dimension kg*m^3 (<unit>)".
std::string WithArticle(const Dimension& d, const std::string& unit) {
  if (const auto* n = FindNamed(d)) return std::string(n->article) + " " + n->name + " (" + unit + ")";
  return "a quantity of dimension " + d.ToString() + " (" + unit + ")";
}

std::string CanonicalUnit(const Dimension& d) {
  if (const auto* n = FindNamed(d)) return n->unit;
  return d.ToString();
}
}  // namespace

std::string DescribeDimension(const Dimension& d) {
  if (const auto* n = FindNamed(d)) return n->name;
  return d.ToString();
}

// ---------------------------------------------------------------------------------------------
// UDUNITS-2

namespace {

std::mutex& UnitMutex() {
  static std::mutex m;
  return m;
}

// The unit system, created on first use (caller holds UnitMutex()). Never freed: it lives as
// long as the process.
ut_system* UnitSystem() {
  static ut_system* system = nullptr;
  if (system != nullptr) return system;
  ut_set_error_message_handler(ut_ignore);
  system = ut_read_xml(nullptr);
  if (system == nullptr)
    throw std::runtime_error(
        "the UDUNITS-2 unit database could not be read (status " + std::to_string(ut_get_status()) +
        "); install the udunits-bin/libudunits2-data package or set UDUNITS2_XML_PATH");
  // Aliases engineers write that UDUNITS-2 lacks. Symbols are case-sensitive.
  const std::pair<const char*, const char*> aliases[] = {
      {"rev", "revolution"}, {"deg", "arc_degree"}, {"Nm", "newton_meter"}, {"rpm", "revolution/minute"}};
  for (const auto& [symbol, definition] : aliases) {
    if (ut_unit* existing = ut_get_unit_by_symbol(system, symbol)) {
      ut_free(existing);
      continue;
    }
    ut_unit* unit = ut_parse(system, definition, UT_ASCII);
    if (unit == nullptr && std::string(definition) == "newton_meter") unit = ut_parse(system, "N.m", UT_ASCII);
    if (unit == nullptr && std::string(definition) == "arc_degree") unit = ut_parse(system, "degree", UT_ASCII);
    if (unit == nullptr) continue;
    ut_map_symbol_to_unit(symbol, UT_ASCII, unit);
    ut_free(unit);
  }
  return system;
}

// The largest power of a base unit in a unit (m^24); UDUNITS-2 itself stops at 255, and no
// physical quantity of this tool comes near.
constexpr int kMaxUnitPower = 24;

// Visitor collecting the base-unit exponents of a unit. Dimensionless basic units (radian,
// steradian) contribute nothing. Never throws (C callbacks).
struct DimensionCollector {
  Dimension dimension;
  bool ok = true;
};

ut_status VisitBasic(const ut_unit* unit, void* arg);
ut_status VisitProduct(const ut_unit* unit, int count, const ut_unit* const* basic, const int* powers,
                       void* arg);
ut_status VisitGalilean(const ut_unit* unit, double scale, const ut_unit* underlying, double offset,
                        void* arg);
ut_status VisitTimestamp(const ut_unit*, const ut_unit*, double, void* arg) {
  static_cast<DimensionCollector*>(arg)->ok = false;
  return UT_SUCCESS;
}
ut_status VisitLogarithmic(const ut_unit*, double, const ut_unit*, void* arg) {
  static_cast<DimensionCollector*>(arg)->ok = false;
  return UT_SUCCESS;
}

const ut_visitor kVisitor = {VisitBasic, VisitProduct, VisitGalilean, VisitTimestamp, VisitLogarithmic};

void AddBasic(const ut_unit* unit, int power, DimensionCollector* c) {
  if (ut_is_dimensionless(unit) != 0) return;
  const char* symbol = ut_get_symbol(unit, UT_ASCII);
  if (symbol == nullptr) {
    c->ok = false;
    return;
  }
  const std::string s = symbol;
  for (std::size_t i = 0; i < kBaseSymbols.size(); ++i) {
    if (s == kBaseSymbols[i]) {
      // saturate: ParseUnitLocked rejects powers beyond kMaxUnitPower, never overflows an int
      const long sum = static_cast<long>(c->dimension.exponents[i]) + power;
      c->dimension.exponents[i] = static_cast<int>(std::clamp(sum, -100000L, 100000L));
      return;
    }
  }
  c->ok = false;
}

ut_status VisitBasic(const ut_unit* unit, void* arg) {
  AddBasic(unit, 1, static_cast<DimensionCollector*>(arg));
  return UT_SUCCESS;
}

ut_status VisitProduct(const ut_unit*, int count, const ut_unit* const* basic, const int* powers, void* arg) {
  for (int i = 0; i < count; ++i) AddBasic(basic[i], powers[i], static_cast<DimensionCollector*>(arg));
  return UT_SUCCESS;
}

ut_status VisitGalilean(const ut_unit*, double, const ut_unit* underlying, double, void* arg) {
  return ut_accept_visitor(underlying, &kVisitor, arg);
}

struct UnitDeleter {
  void operator()(ut_unit* u) const { ut_free(u); }
};
using UnitPtr = std::unique_ptr<ut_unit, UnitDeleter>;

// The SI unit of a dimension (caller holds the mutex).
UnitPtr SiUnit(ut_system* system, const Dimension& d) {
  UnitPtr result(ut_get_dimensionless_unit_one(system));
  for (std::size_t i = 0; i < kBaseSymbols.size(); ++i) {
    if (d.exponents[i] == 0) continue;
    UnitPtr base(ut_get_unit_by_symbol(system, kBaseSymbols[i]));
    HIGHLIFT_CHECK(base != nullptr, "UDUNITS-2 has no base unit symbol");
    UnitPtr raised(ut_raise(base.get(), d.exponents[i]));
    HIGHLIFT_CHECK(raised != nullptr, "UDUNITS-2 could not raise a base unit");
    result.reset(ut_multiply(result.get(), raised.get()));
    HIGHLIFT_CHECK(result != nullptr, "UDUNITS-2 could not multiply base units");
  }
  return result;
}

std::string Trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

// UDUNITS-2 reads an exponent into an int without an overflow check: "m^4294967297" is m^1.
// Every exponent written in the unit text (after '^' or '**', or right after a unit symbol as
// in "m2" or "s-1") of 1000 or more is therefore refused here, before UDUNITS-2 sees it. Digits that belong to
// a number ("1e3", "0.5") are not exponents.
void CheckWrittenExponents(const std::string& unit) {
  const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  const auto is_letter = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (static_cast<unsigned char>(c) >= 0x80);
  };
  std::size_t i = 0;
  bool in_number = false;  // inside a numeric literal (digits, '.', an 'e' exponent)
  while (i < unit.size()) {
    const char c = unit[i];
    if (!is_digit(c)) {
      if (in_number && (c == '.' || ((c == 'e' || c == 'E') && i + 1 < unit.size() &&
                                     (is_digit(unit[i + 1]) || unit[i + 1] == '-' || unit[i + 1] == '+')))) {
        i += (c == '.') ? 1 : 2;
        continue;
      }
      in_number = false;
      ++i;
      continue;
    }
    // A run of digits: an exponent when it follows '^', "**" or a unit symbol (with a sign).
    std::size_t before = i;
    if (before > 0 && (unit[before - 1] == '-' || unit[before - 1] == '+')) --before;
    const bool after_caret = before > 0 && unit[before - 1] == '^';
    const bool after_stars = before > 1 && unit[before - 1] == '*' && unit[before - 2] == '*';
    const bool after_symbol = !in_number && before > 0 && is_letter(unit[before - 1]);
    std::size_t end = i;
    while (end < unit.size() && is_digit(unit[end])) ++end;
    if (after_caret || after_stars || after_symbol) {
      const std::string digits = unit.substr(i, end - i);
      const std::size_t first = digits.find_first_not_of('0');
      const std::string shown = first == std::string::npos ? "0" : digits.substr(first);
      // Up to 999 the power is read correctly and the dimension check below names it.
      if (shown.size() > 3)
        throw InputError("unit '" + unit + "': the exponent " + (unit[i - 1] == '-' ? "-" : "") + shown +
                         " is beyond what highlift handles (-" + std::to_string(kMaxUnitPower) + " to " +
                         std::to_string(kMaxUnitPower) + "); check the exponents");
      in_number = false;
    } else {
      in_number = true;
    }
    i = end;
  }
}

UnitConversion ParseUnitLocked(const std::string& unit) {
  ut_system* system = UnitSystem();
  if (unit.empty() || unit == "1") return {};
  CheckWrittenExponents(unit);
  UnitPtr parsed(ut_parse(system, unit.c_str(), UT_UTF8));
  if (parsed == nullptr) throw InputError("unknown unit '" + unit + "'");
  DimensionCollector collector;
  if (ut_accept_visitor(parsed.get(), &kVisitor, &collector) != UT_SUCCESS || !collector.ok)
    throw InputError("unit '" + unit + "' is not a physical unit highlift can use (a time stamp or a logarithmic unit?)");
  for (std::size_t i = 0; i < kBaseSymbols.size(); ++i) {
    const long e = collector.dimension.exponents[i];
    if (e > kMaxUnitPower || e < -kMaxUnitPower)
      throw InputError("unit '" + unit + "': the power of " + kBaseSymbols[i] + " is " + std::to_string(e) +
                       ", beyond what highlift handles (-" + std::to_string(kMaxUnitPower) + " to " +
                       std::to_string(kMaxUnitPower) + "); check the exponents");
  }
  UnitPtr si = SiUnit(system, collector.dimension);
  cv_converter* converter = ut_get_converter(parsed.get(), si.get());
  HIGHLIFT_CHECK(converter != nullptr, "UDUNITS-2 cannot convert '" + unit + "' to its SI unit");
  UnitConversion c;
  c.offset = cv_convert_double(converter, 0.0);
  c.scale = cv_convert_double(converter, 1.0) - c.offset;
  cv_free(converter);
  c.dimension = collector.dimension;
  // A number in the unit expression ("5 mm") is a scaled unit; callers split value and unit.
  return c;
}

// The built-in table: the texts the examples and the catalogue use, with what UDUNITS-2 (Debian's
// 2.2, its default database, the aliases above) gives for each, as hexadecimal doubles (the
// decimal value after "//"). Exponents in the order of kBaseSymbols: m, kg, s, A, K, mol, cd.
constexpr std::array<detail::BuiltInUnit, 32> kBuiltInUnits = {{
    {"s", {0x1p+0, 0x0p+0, {{0, 0, 1, 0, 0, 0, 0}}}},  // 1
    {"s/rad", {0x1p+0, 0x0p+0, {{0, 0, 1, 0, 0, 0, 0}}}},  // 1
    {"rpm", {0x1.acee9f37bebd5p-4, 0x0p+0, {{0, 0, -1, 0, 0, 0, 0}}}},  // 0.10471975511965977
    {"rev", {0x1.921fb54442d18p+2, 0x0p+0, {{0, 0, 0, 0, 0, 0, 0}}}},  // 6.2831853071795862
    {"rad", {0x1p+0, 0x0p+0, {{0, 0, 0, 0, 0, 0, 0}}}},  // 1
    {"rad/s", {0x1p+0, 0x0p+0, {{0, 0, -1, 0, 0, 0, 0}}}},  // 1
    {"ms", {0x1.0624dd2f1a9fcp-10, 0x0p+0, {{0, 0, 1, 0, 0, 0, 0}}}},  // 0.001
    {"mm^2", {0x1.0c6f7a0b5ed8dp-20, 0x0p+0, {{2, 0, 0, 0, 0, 0, 0}}}},  // 9.9999999999999995e-07
    {"mm", {0x1.0624dd2f1a9fcp-10, 0x0p+0, {{1, 0, 0, 0, 0, 0, 0}}}},  // 0.001
    {"mm/rev", {0x1.4dc5a8d185aa3p-13, 0x0p+0, {{1, 0, 0, 0, 0, 0, 0}}}},  // 0.00015915494309189535
    {"m^3/(s*Pa)", {0x1p+0, 0x0p+0, {{4, -1, 1, 0, 0, 0, 0}}}},  // 1
    {"m", {0x1p+0, 0x0p+0, {{1, 0, 0, 0, 0, 0, 0}}}},  // 1
    {"kg", {0x1p+0, 0x0p+0, {{0, 1, 0, 0, 0, 0, 0}}}},  // 1
    {"kg/m^3", {0x1p+0, 0x0p+0, {{-3, 1, 0, 0, 0, 0, 0}}}},  // 1
    {"kg/m", {0x1p+0, 0x0p+0, {{-1, 1, 0, 0, 0, 0, 0}}}},  // 1
    {"kg*m^2", {0x1p+0, 0x0p+0, {{2, 1, 0, 0, 0, 0, 0}}}},  // 1
    {"kW", {0x1.f4p+9, 0x0p+0, {{2, 1, -3, 0, 0, 0, 0}}}},  // 1000
    {"kN", {0x1.f4p+9, 0x0p+0, {{1, 1, -2, 0, 0, 0, 0}}}},  // 1000
    {"kN*m", {0x1.f4p+9, 0x0p+0, {{2, 1, -2, 0, 0, 0, 0}}}},  // 1000
    {"deg", {0x1.1df46a2529d39p-6, 0x0p+0, {{0, 0, 0, 0, 0, 0, 0}}}},  // 0.017453292519943295
    {"cm^3", {0x1.0c6f7a0b5ed8ep-20, 0x0p+0, {{3, 0, 0, 0, 0, 0, 0}}}},  // 1.0000000000000002e-06
    {"cm^3/rev", {0x1.55c85af339004p-23, 0x0p+0, {{3, 0, 0, 0, 0, 0, 0}}}},  // 1.5915494309189538e-07
    {"bar", {0x1.86ap+16, 0x0p+0, {{-1, 1, -2, 0, 0, 0, 0}}}},  // 100000
    {"N*s/m", {0x1p+0, 0x0p+0, {{0, 1, -1, 0, 0, 0, 0}}}},  // 1
    {"N*m", {0x1p+0, 0x0p+0, {{2, 1, -2, 0, 0, 0, 0}}}},  // 1
    {"N*m/rad", {0x1p+0, 0x0p+0, {{2, 1, -2, 0, 0, 0, 0}}}},  // 1
    {"N*m/m", {0x1p+0, 0x0p+0, {{1, 1, -2, 0, 0, 0, 0}}}},  // 1
    {"N*m*s/rad", {0x1p+0, 0x0p+0, {{2, 1, -1, 0, 0, 0, 0}}}},  // 1
    {"MPa", {0x1.e848p+19, 0x0p+0, {{-1, 1, -2, 0, 0, 0, 0}}}},  // 1000000
    {"L", {0x1.0624dd2f1a9fdp-10, 0x0p+0, {{3, 0, 0, 0, 0, 0, 0}}}},  // 0.0010000000000000002
    {"GPa", {0x1.dcd65p+29, 0x0p+0, {{-1, 1, -2, 0, 0, 0, 0}}}},  // 1000000000
    {"psi", {0x1.aeec1ddf70f96p+12, 0x0p+0, {{-1, 1, -2, 0, 0, 0, 0}}}},  // 6894.757293168359
}};

// Whether the table may answer (see unit_table.h); decided once, under UnitMutex().
bool BuiltInUnitsApplyLocked() {
  static const bool apply = [] {
    ut_status status = UT_SUCCESS;
    const char* path = ut_get_path_xml(nullptr, &status);
    return status == UT_OPEN_DEFAULT && path != nullptr && access(path, R_OK) == 0;
  }();
  return apply;
}

const UnitConversion* FindBuiltInUnit(std::string_view unit) {
  for (const auto& b : kBuiltInUnits)
    if (b.text == unit) return &b.conversion;
  return nullptr;
}

}  // namespace

namespace detail {

std::span<const BuiltInUnit> BuiltInUnits() { return kBuiltInUnits; }

bool BuiltInUnitsApply() {
  std::lock_guard<std::mutex> lock(UnitMutex());
  return BuiltInUnitsApplyLocked();
}

UnitConversion ParseUnitWithDatabase(std::string_view unit_text) {
  const std::string unit = Trim(unit_text);
  std::lock_guard<std::mutex> lock(UnitMutex());
  return ParseUnitLocked(unit);
}

}  // namespace detail

UnitConversion ParseUnit(std::string_view unit_text) {
  const std::string unit = Trim(unit_text);
  std::lock_guard<std::mutex> lock(UnitMutex());
  if (BuiltInUnitsApplyLocked()) {
    if (unit.empty() || unit == "1") return {};
    if (const UnitConversion* b = FindBuiltInUnit(unit)) return *b;
  }
  static std::map<std::string, UnitConversion, std::less<>> cache;
  if (auto it = cache.find(unit); it != cache.end()) return it->second;
  UnitConversion c = ParseUnitLocked(unit);
  cache.emplace(unit, c);
  return c;
}

namespace {
UnitConversion CheckedUnit(std::string_view unit, const Dimension& expected) {
  UnitConversion c = ParseUnit(unit);
  if (c.dimension != expected)
    throw InputError("expected " + WithArticle(expected, CanonicalUnit(expected)) + ", got " +
                     WithArticle(c.dimension, Trim(unit).empty() ? "1" : Trim(unit)));
  return c;
}
}  // namespace

double ToSI(double value, std::string_view unit, const Dimension& expected) {
  const UnitConversion c = CheckedUnit(unit, expected);
  return c.scale * value + c.offset;
}

double FromSI(double value_si, std::string_view unit, const Dimension& expected) {
  const UnitConversion c = CheckedUnit(unit, expected);
  return (value_si - c.offset) / c.scale;
}

}  // namespace highlift
