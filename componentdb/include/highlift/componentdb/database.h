// The component database: an SQLite file of existing parts and materials.
//
// - Versioned schema (PRAGMA user_version) brought up to date by migrations when a database is
//   opened for writing; a database newer than this program is refused.
// - Foreign keys on, WAL journal (readers keep working while an import runs), every write in
//   one transaction (an import is all or nothing), only prepared statements with bound values.
// - The shipped default database is created on first use from the seed compiled into the
//   library (data/components.csv), in the user's data directory (DefaultDatabasePath()).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "highlift/componentdb/records.h"
#include "highlift/core/domain.h"

namespace highlift::componentdb {

/// A range condition on a part parameter, in SI: a part matches when the parameter is present
/// and its value (or interval) overlaps [domain.lo, domain.hi].
struct RangeCondition {
  std::string parameter;
  Domain domain;
};

/// Parses "ratio=150:250", "output_torque=2:25 kN*m", "ratio=150:" (open above), ":250".
/// Bounds without a unit are SI; with a unit they are converted (dimension checked against the
/// catalogue parameter of `type`). Throws InputError with the accepted forms.
RangeCondition ParseRangeCondition(const std::string& text, const std::string& type);

struct PartQuery {
  std::string type;                        ///< catalogue type; empty: every type
  std::vector<RangeCondition> conditions;  ///< all must hold
};

struct ImportOptions {
  bool replace = false;  ///< replace parts/materials with the same designation/name instead of failing
  /// Called inside the import transaction after each part is written, with the count so far.
  /// Used for progress reports and by tests that interrupt an import.
  std::function<void(std::size_t parts_written)> progress;
};

struct ImportReport {
  std::size_t parts_added = 0;
  std::size_t parts_replaced = 0;
  std::size_t materials_added = 0;
  std::size_t materials_replaced = 0;
  std::string BriefReport() const;
};

/// Row counts of every table.
struct Counts {
  std::int64_t parts = 0;
  std::int64_t part_parameters = 0;
  std::int64_t materials = 0;
  std::int64_t material_properties = 0;
  friend bool operator==(const Counts&, const Counts&) = default;
};

class ComponentDatabase {
 public:
  /// The schema version this program writes (PRAGMA user_version).
  static constexpr int kSchemaVersion = 2;

  enum class Mode {
    kReadOnly,   ///< the file must exist and have a schema no newer than kSchemaVersion
    kReadWrite,  ///< the file must exist; its schema is migrated to kSchemaVersion
    kCreate,     ///< as kReadWrite, creating an empty database when the file is missing
  };

  /// Opens a database file. Throws InputError when the file is missing (kReadOnly, kReadWrite),
  /// is not a highlift database, or was written by a newer highlift.
  static ComponentDatabase Open(const std::filesystem::path& file, Mode mode);

  ComponentDatabase(ComponentDatabase&&) noexcept;
  ComponentDatabase& operator=(ComponentDatabase&&) noexcept;
  ~ComponentDatabase();

  const std::filesystem::path& file() const { return file_; }
  int schema_version() const;
  std::string journal_mode() const;
  Counts CountRows() const;
  /// PRAGMA integrity_check: "ok" or the problems found.
  std::string IntegrityCheck() const;

  /// Parts of `type` (every type when empty), ordered by type and designation.
  std::vector<Part> Parts(const std::string& type = "") const;
  std::optional<Part> FindPart(const std::string& designation) const;
  /// Parts matching a query, ordered by designation.
  std::vector<Part> Find(const PartQuery& query) const;
  std::vector<Material> Materials() const;
  std::optional<Material> FindMaterial(const std::string& name) const;

  /// Validates `records` (ValidateRecords) and writes them in one transaction: either every
  /// record is written or, on any error, the database is left exactly as it was. A designation
  /// or material name already present is an error naming it, unless options.replace.
  ImportReport Import(Records records, const ImportOptions& options = {});
  /// Every part and material, in a form Import() takes back unchanged.
  Records Export() const;

 private:
  struct Impl;
  explicit ComponentDatabase(std::unique_ptr<Impl> impl, std::filesystem::path file);
  std::unique_ptr<Impl> impl_;
  std::filesystem::path file_;
};

/// The SQL of each schema migration: entry i takes a database from version i to i + 1.
const std::vector<std::string>& SchemaMigrations();

/// The user's data directory: $HIGHLIFT_DATA_DIR if set, else $XDG_DATA_HOME/highlift, else
/// ~/.local/share/highlift.
std::filesystem::path UserDataDirectory();
/// UserDataDirectory() / "components.sqlite".
std::filesystem::path DefaultDatabasePath();
/// The seed CSV compiled into the library from data/components.csv.
const std::string& SeedCsv();
/// The seed parsed and validated.
Records SeedRecords();

/// The seed's parts (designations) and materials (names) that `db` lacks or holds with other
/// values, in seed order: empty when the database has this version's seed as it ships. A
/// database created by an earlier highlift from an older seed, or edited, lists them.
std::vector<std::string> DifferencesFromSeed(const ComponentDatabase& db);
/// Creates a database at `file` from the seed. The database is built beside it under a
/// temporary name and renamed into place, so a concurrent or interrupted first use never
/// leaves a half-built database. Throws InputError when `file` exists.
void CreateDatabaseFromSeed(const std::filesystem::path& file);

/// The database the CLI uses: `path` when not empty (it must exist unless `mode` is kCreate),
/// else the default database, created from the seed on first use.
ComponentDatabase OpenDatabase(const std::string& path, ComponentDatabase::Mode mode);

}  // namespace highlift::componentdb
