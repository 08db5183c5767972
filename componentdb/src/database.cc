#include "highlift/componentdb/database.h"

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "highlift/componentdb/io.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/core/units.h"
#include "schema.h"
#include "highlift/componentdb/sqlite.h"

namespace highlift::componentdb {

struct ComponentDatabase::Impl {
  Impl(const std::filesystem::path& file, sqlite::Connection::Mode mode) : connection(file, mode) {}
  sqlite::Connection connection;
};

namespace {

// Infinite bounds are stored as REAL +-Inf; SQLite keeps them. NULL means "not given".
void BindQuantity(sqlite::Statement& s, int first, const Quantity& q) {
  s.Bind(first, q.name);
  s.Bind(first + 1, q.value);
  s.Bind(first + 2, q.lo);
  s.Bind(first + 3, q.hi);
  s.Bind(first + 4, q.unit);
  s.Bind(first + 5, q.value_si);
  s.Bind(first + 6, q.domain_si.lo);
  s.Bind(first + 7, q.domain_si.hi);
  s.Bind(first + 8, ToString(q.tag));
  s.Bind(first + 9, q.source);
}

// Columns: name, value, lo, hi, unit, value_si, lo_si, hi_si, tag, source starting at `first`.
Quantity ReadQuantity(const sqlite::Statement& s, int first) {
  Quantity q;
  q.name = s.Text(first);
  q.value = s.OptionalReal(first + 1);
  q.lo = s.OptionalReal(first + 2);
  q.hi = s.OptionalReal(first + 3);
  q.unit = s.Text(first + 4);
  q.value_si = s.OptionalReal(first + 5);
  q.domain_si = {s.Real(first + 6), s.Real(first + 7)};
  q.tag = TagFromString(s.Text(first + 8)).value_or(Tag::kEstimate);
  q.source = s.Text(first + 9);
  return q;
}

constexpr const char* kQuantityColumns = "name, value, lo, hi, unit, value_si, lo_si, hi_si, tag, source";

std::vector<Part> ReadParts(sqlite::Connection& c, const std::string& where, const std::vector<std::string>& binds) {
  std::vector<Part> parts;
  sqlite::ReadSnapshot snapshot(c);  // the parts and their parameters from one state of the file
  {
    sqlite::Statement s(c, "SELECT id, type, designation, program, supplier, note FROM parts " + where +
                               " ORDER BY type, designation");
    for (std::size_t i = 0; i < binds.size(); ++i) s.Bind(static_cast<int>(i + 1), binds[i]);
    std::vector<std::int64_t> ids;
    while (s.Step()) {
      Part p;
      ids.push_back(s.Integer(0));
      p.type = s.Text(1);
      p.designation = s.Text(2);
      p.program = s.Text(3);
      p.supplier = s.Text(4);
      p.note = s.Text(5);
      parts.push_back(std::move(p));
    }
    sqlite::Statement q(c, std::string("SELECT ") + kQuantityColumns +
                               " FROM part_parameters WHERE part_id = ?1 ORDER BY rowid");
    for (std::size_t i = 0; i < parts.size(); ++i) {
      q.Reset();
      q.Bind(1, ids[i]);
      while (q.Step()) parts[i].parameters.push_back(ReadQuantity(q, 0));
    }
  }
  return parts;
}

std::vector<Material> ReadMaterials(sqlite::Connection& c, const std::string& where, const std::vector<std::string>& binds) {
  std::vector<Material> materials;
  std::vector<std::int64_t> ids;
  sqlite::ReadSnapshot snapshot(c);  // the materials and their properties from one state of the file
  sqlite::Statement s(c, "SELECT id, name, note FROM materials " + where + " ORDER BY name");
  for (std::size_t i = 0; i < binds.size(); ++i) s.Bind(static_cast<int>(i + 1), binds[i]);
  while (s.Step()) {
    ids.push_back(s.Integer(0));
    Material m;
    m.name = s.Text(1);
    m.note = s.Text(2);
    materials.push_back(std::move(m));
  }
  sqlite::Statement q(c, std::string("SELECT ") + kQuantityColumns +
                             " FROM material_properties WHERE material_id = ?1 ORDER BY rowid");
  for (std::size_t i = 0; i < materials.size(); ++i) {
    q.Reset();
    q.Bind(1, ids[i]);
    while (q.Step()) materials[i].properties.push_back(ReadQuantity(q, 0));
  }
  return materials;
}

}  // namespace

ComponentDatabase::ComponentDatabase(std::unique_ptr<Impl> impl, std::filesystem::path file)
    : impl_(std::move(impl)), file_(std::move(file)) {}
ComponentDatabase::ComponentDatabase(ComponentDatabase&&) noexcept = default;
ComponentDatabase& ComponentDatabase::operator=(ComponentDatabase&&) noexcept = default;
ComponentDatabase::~ComponentDatabase() = default;

ComponentDatabase ComponentDatabase::Open(const std::filesystem::path& file, Mode mode) {
  const bool exists = std::filesystem::exists(file);
  if (!exists && mode != Mode::kCreate)
    throw InputError("component database '" + file.string() +
                     "' does not exist; give an existing database with --db, or leave --db out to use the default");
  if (exists) RegisterInputFile(file);  // `db export F --db F` must not overwrite the database
  using CMode = sqlite::Connection::Mode;
  std::unique_ptr<Impl> impl;
  try {
    impl = std::make_unique<Impl>(file, mode == Mode::kReadOnly ? CMode::kReadOnly
                                        : mode == Mode::kReadWrite ? CMode::kReadWrite
                                                                   : CMode::kReadWriteCreate);
    auto& c = impl->connection;
    const int version = static_cast<int>(c.QueryInteger("PRAGMA user_version"));
    if (version > kSchemaVersion)
      throw InputError("component database '" + file.string() + "' has schema version " + std::to_string(version) +
                       ", newer than this highlift understands (" + std::to_string(kSchemaVersion) +
                       "); use a newer highlift or export the data with it");
    if (version == 0) {
      // Either a fresh file or a foreign SQLite file: only the former is acceptable.
      const auto tables = c.QueryInteger("SELECT count(*) FROM sqlite_schema WHERE type = 'table'");
      if (tables != 0)
        throw InputError("'" + file.string() + "' is an SQLite database but not a highlift component database (no schema version); choose another file");
    }
    if (mode == Mode::kReadOnly) {
      if (version < kSchemaVersion)
        throw InputError("component database '" + file.string() + "' has schema version " + std::to_string(version) +
                         " and must be upgraded to " + std::to_string(kSchemaVersion) +
                         "; open it once for writing (e.g. highlift db import) to migrate it");
    } else {
      c.Execute("PRAGMA journal_mode = WAL");
      Migrate(c, kSchemaVersion);
    }
  } catch (const sqlite::Error& e) {
    throw InputError(std::string("cannot open the component database ") + e.what());  // 'file': reason; remedy
  }
  return ComponentDatabase(std::move(impl), file);
}

int ComponentDatabase::schema_version() const {
  return static_cast<int>(impl_->connection.QueryInteger("PRAGMA user_version"));
}

std::string ComponentDatabase::journal_mode() const {
  sqlite::Statement s(impl_->connection, "PRAGMA journal_mode");
  s.Step();
  return s.Text(0);
}

Counts ComponentDatabase::CountRows() const {
  auto& c = impl_->connection;
  sqlite::ReadSnapshot snapshot(c);
  Counts n;
  n.parts = c.QueryInteger("SELECT count(*) FROM parts");
  n.part_parameters = c.QueryInteger("SELECT count(*) FROM part_parameters");
  n.materials = c.QueryInteger("SELECT count(*) FROM materials");
  n.material_properties = c.QueryInteger("SELECT count(*) FROM material_properties");
  return n;
}

std::string ComponentDatabase::IntegrityCheck() const {
  sqlite::Statement s(impl_->connection, "PRAGMA integrity_check");
  std::string out;
  while (s.Step()) out += (out.empty() ? "" : "\n") + s.Text(0);
  sqlite::Statement f(impl_->connection, "PRAGMA foreign_key_check");
  while (f.Step()) out += "\nforeign key violation in table " + f.Text(0);
  return out;
}

std::vector<Part> ComponentDatabase::Parts(const std::string& type) const {
  if (type.empty()) return ReadParts(impl_->connection, "", {});
  return ReadParts(impl_->connection, "WHERE type = ?1", {type});
}

std::optional<Part> ComponentDatabase::FindPart(const std::string& designation) const {
  auto parts = ReadParts(impl_->connection, "WHERE designation = ?1", {designation});
  if (parts.empty()) return std::nullopt;
  return std::move(parts.front());
}

std::vector<Part> ComponentDatabase::Find(const PartQuery& query) const {
  auto& c = impl_->connection;
  // One prepared statement per condition would do; a single query with bound values is simpler:
  // the candidate set comes from the type, each condition is checked by an EXISTS subquery.
  std::string sql = "SELECT designation FROM parts WHERE 1";
  int index = 1;
  if (!query.type.empty()) sql += " AND type = ?" + std::to_string(index++);
  for (std::size_t i = 0; i < query.conditions.size(); ++i) {
    sql += " AND EXISTS (SELECT 1 FROM part_parameters pp WHERE pp.part_id = parts.id AND pp.name = ?" +
           std::to_string(index) + " AND pp.hi_si >= ?" + std::to_string(index + 1) + " AND pp.lo_si <= ?" +
           std::to_string(index + 2) + ")";
    index += 3;
  }
  sql += " ORDER BY designation";
  sqlite::ReadSnapshot snapshot(c);  // the designations and then each part from one state of the file
  sqlite::Statement s(c, sql);
  index = 1;
  if (!query.type.empty()) s.Bind(index++, query.type);
  for (const auto& cond : query.conditions) {
    s.Bind(index++, cond.parameter);
    s.Bind(index++, cond.domain.lo);
    s.Bind(index++, cond.domain.hi);
  }
  std::vector<std::string> designations;
  while (s.Step()) designations.push_back(s.Text(0));
  std::vector<Part> parts;
  for (const auto& d : designations)
    if (auto p = FindPart(d)) parts.push_back(std::move(*p));
  return parts;
}

std::vector<Material> ComponentDatabase::Materials() const { return ReadMaterials(impl_->connection, "", {}); }

std::optional<Material> ComponentDatabase::FindMaterial(const std::string& name) const {
  auto m = ReadMaterials(impl_->connection, "WHERE name = ?1", {name});
  if (m.empty()) return std::nullopt;
  return std::move(m.front());
}

ImportReport ComponentDatabase::Import(Records records, const ImportOptions& options) {
  ValidateRecords(records);  // before any write: a bad row leaves the database untouched
  auto& c = impl_->connection;
  ImportReport report;
  try {
    sqlite::Transaction transaction(c);
    sqlite::Statement find_material(c, "SELECT id FROM materials WHERE name = ?1");
    sqlite::Statement delete_material(c, "DELETE FROM materials WHERE id = ?1");
    sqlite::Statement insert_material(c, "INSERT INTO materials (name, note) VALUES (?1, ?2)");
    sqlite::Statement insert_property(
        c, std::string("INSERT INTO material_properties (material_id, ") + kQuantityColumns +
               ") VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)");
    for (const auto& m : records.materials) {
      find_material.Reset();
      find_material.Bind(1, m.name);
      const std::optional<std::int64_t> existing_material =
          find_material.Step() ? std::optional<std::int64_t>(find_material.Integer(0)) : std::nullopt;
      find_material.Reset();  // no statement stays active across the writes
      if (existing_material) {
        if (!options.replace)
          throw InputError(m.origin + ": material '" + m.name + "' is already in the database '" + file_.string() +
                           "'; rename it, leave it out, or import with --replace");
        delete_material.Reset();
        delete_material.Bind(1, *existing_material).Run();
        ++report.materials_replaced;
      } else {
        ++report.materials_added;
      }
      insert_material.Reset();
      insert_material.Bind(1, m.name).Bind(2, m.note).Run();
      const std::int64_t id = c.LastInsertRowId();
      for (const auto& q : m.properties) {
        insert_property.Reset();
        insert_property.Bind(1, id);
        BindQuantity(insert_property, 2, q);
        insert_property.Run();
      }
    }
    sqlite::Statement find_part(c, "SELECT id FROM parts WHERE designation = ?1");
    sqlite::Statement delete_part(c, "DELETE FROM parts WHERE id = ?1");
    sqlite::Statement insert_part(
        c, "INSERT INTO parts (type, designation, program, supplier, note) VALUES (?1, ?2, ?3, ?4, ?5)");
    sqlite::Statement insert_parameter(
        c, std::string("INSERT INTO part_parameters (part_id, ") + kQuantityColumns +
               ") VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)");
    std::size_t written = 0;
    for (const auto& p : records.parts) {
      find_part.Reset();
      find_part.Bind(1, p.designation);
      const std::optional<std::int64_t> existing_part =
          find_part.Step() ? std::optional<std::int64_t>(find_part.Integer(0)) : std::nullopt;
      find_part.Reset();
      if (existing_part) {
        if (!options.replace)
          throw InputError(p.origin + ": part '" + p.designation + "' is already in the database '" + file_.string() +
                           "'; rename it, leave it out, or import with --replace");
        delete_part.Reset();
        delete_part.Bind(1, *existing_part).Run();
        ++report.parts_replaced;
      } else {
        ++report.parts_added;
      }
      insert_part.Reset();
      insert_part.Bind(1, p.type).Bind(2, p.designation).Bind(3, p.program).Bind(4, p.supplier).Bind(5, p.note).Run();
      const std::int64_t id = c.LastInsertRowId();
      for (const auto& q : p.parameters) {
        insert_parameter.Reset();
        insert_parameter.Bind(1, id);
        BindQuantity(insert_parameter, 2, q);
        insert_parameter.Run();
      }
      ++written;
      if (options.progress) options.progress(written);
    }
    sqlite::Statement log(c, "INSERT INTO imports (time, parts, materials) VALUES (strftime('%Y-%m-%dT%H:%M:%SZ', 'now'), ?1, ?2)");
    log.Bind(1, static_cast<std::int64_t>(records.parts.size()))
        .Bind(2, static_cast<std::int64_t>(records.materials.size()))
        .Run();
    transaction.Commit();
  } catch (const sqlite::Error& e) {
    throw InputError(std::string("the import failed and was rolled back, nothing was written into ") + e.what());
  }
  return report;
}

Records ComponentDatabase::Export() const {
  Records r;
  r.materials = Materials();
  r.parts = Parts();
  return r;
}

std::string ImportReport::BriefReport() const {
  return std::to_string(parts_added) + " parts added, " + std::to_string(parts_replaced) + " replaced; " +
         std::to_string(materials_added) + " materials added, " + std::to_string(materials_replaced) + " replaced";
}

RangeCondition ParseRangeCondition(const std::string& text, const std::string& type) {
  const std::string forms = "use NAME=LO:HI with an optional unit, e.g. ratio=150:250, "
                            "output_torque=2:25 kN*m, ratio=150: (no upper bound), ratio=:250";
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError("range '" + text + "': no parameter name; " + forms);
  RangeCondition cond;
  cond.parameter = text.substr(0, eq);
  while (!cond.parameter.empty() && cond.parameter.back() == ' ') cond.parameter.pop_back();
  std::string rest = text.substr(eq + 1);
  const auto colon = rest.find(':');
  if (colon == std::string::npos) throw InputError("range '" + text + "': no ':' between the bounds; " + forms);
  if (rest.find(':', colon + 1) != std::string::npos)
    throw InputError("range '" + text + "': more than one ':'; a range has two bounds, LO:HI; " + forms);
  std::string lo_text = rest.substr(0, colon), hi_and_unit = rest.substr(colon + 1);
  // The unit follows the upper bound after a space, or directly after the number.
  const auto trim = [](std::string s) {
    const auto b = s.find_first_not_of(' ');
    if (b == std::string::npos) return std::string();
    return s.substr(b, s.find_last_not_of(' ') - b + 1);
  };
  hi_and_unit = trim(hi_and_unit);
  lo_text = trim(lo_text);
  std::size_t number_end = 0;
  while (number_end < hi_and_unit.size() &&
         (std::isdigit(static_cast<unsigned char>(hi_and_unit[number_end])) || hi_and_unit[number_end] == '.' ||
          hi_and_unit[number_end] == '-' || hi_and_unit[number_end] == '+' ||
          ((hi_and_unit[number_end] == 'e' || hi_and_unit[number_end] == 'E') && number_end > 0 &&
           number_end + 1 < hi_and_unit.size() &&
           (std::isdigit(static_cast<unsigned char>(hi_and_unit[number_end + 1])) ||
            hi_and_unit[number_end + 1] == '-' || hi_and_unit[number_end + 1] == '+'))))
    ++number_end;
  const std::string hi_text = hi_and_unit.substr(0, number_end);
  const std::string unit = trim(hi_and_unit.substr(number_end));
  {
    std::string word = unit;
    for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (word == "inf" || word == "infinity" || word == "nan")
      throw InputError("range '" + text + "': '" + unit + "' is not a finite number; leave a bound out for no bound; " +
                       forms);
  }
  const auto number = [&](const std::string& s, double fallback) {
    if (s.empty()) return fallback;
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data() + (s[0] == '+' ? 1 : 0), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size())
      throw InputError("range '" + text + "': '" + s + "' is not a number; " + forms);
    if (!std::isfinite(v))
      throw InputError("range '" + text + "': '" + s + "' is not a finite number; leave a bound out for no bound; " + forms);
    return v;
  };
  double lo = number(lo_text, -HUGE_VAL), hi = number(hi_text, HUGE_VAL);
  const ComponentTypeSpec* spec = type.empty() ? nullptr : FindComponentType(type);
  const ParameterSpec* parameter = spec ? spec->FindParameter(cond.parameter) : nullptr;
  if (spec && !parameter) {
    std::vector<std::string> names;
    for (const auto& p : spec->parameters) names.push_back(p.name);
    const auto s = Suggest(cond.parameter, names);
    std::string all;
    for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
    throw InputError("range '" + text + "': type '" + type + "' has no parameter '" + cond.parameter + "'" +
                     (s.empty() ? "" : "; did you mean '" + s.front() + "'?") + " Valid parameters: " + all);
  }
  if (!unit.empty()) {
    const Dimension expected = parameter ? parameter->dimension : ParseUnit(unit).dimension;
    if (!std::isinf(lo)) lo = ToSI(lo, unit, expected);
    if (!std::isinf(hi)) hi = ToSI(hi, unit, expected);
  }
  if (lo > hi) throw InputError("range '" + text + "': the lower bound exceeds the upper bound; " + forms);
  cond.domain = {lo, hi};
  return cond;
}

}  // namespace highlift::componentdb
