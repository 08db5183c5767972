#include "schema.h"

#include <string>
#include <vector>

#include "highlift/componentdb/database.h"
#include "highlift/core/error.h"

namespace highlift::componentdb {

const std::vector<std::string>& SchemaMigrations() {
  static const std::vector<std::string> migrations{
      // 0 -> 1: parts with parameters, materials with properties.
      R"sql(
CREATE TABLE parts (
  id          INTEGER PRIMARY KEY,
  type        TEXT NOT NULL,                 -- catalogue component type
  designation TEXT NOT NULL UNIQUE,
  program     TEXT NOT NULL DEFAULT '',      -- aircraft program or class
  supplier    TEXT NOT NULL DEFAULT '',
  note        TEXT NOT NULL DEFAULT ''
);
CREATE INDEX parts_by_type ON parts (type, designation);
CREATE TABLE part_parameters (
  part_id  INTEGER NOT NULL REFERENCES parts (id) ON DELETE CASCADE,
  name     TEXT NOT NULL,                    -- catalogue parameter name
  value    REAL,                             -- nominal, in `unit` (NULL: unknown)
  lo       REAL,                             -- interval, in `unit` (NULL: none given)
  hi       REAL,
  unit     TEXT NOT NULL,                    -- as given
  value_si REAL,
  lo_si    REAL NOT NULL,                    -- SI domain: the interval, or [value, value]
  hi_si    REAL NOT NULL,
  tag      TEXT NOT NULL CHECK (tag IN ('P', 'P-low', 'E')),
  source   TEXT NOT NULL,
  PRIMARY KEY (part_id, name),
  CHECK (lo_si <= hi_si)
);
CREATE INDEX part_parameters_by_name ON part_parameters (name, lo_si, hi_si);
CREATE TABLE materials (
  id   INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  note TEXT NOT NULL DEFAULT ''
);
CREATE TABLE material_properties (
  material_id INTEGER NOT NULL REFERENCES materials (id) ON DELETE CASCADE,
  name     TEXT NOT NULL CHECK (name IN ('shear_modulus', 'density', 'allowable_shear_stress')),
  value    REAL,
  lo       REAL,
  hi       REAL,
  unit     TEXT NOT NULL,
  value_si REAL,
  lo_si    REAL NOT NULL,
  hi_si    REAL NOT NULL,
  tag      TEXT NOT NULL CHECK (tag IN ('P', 'P-low', 'E')),
  source   TEXT NOT NULL,
  PRIMARY KEY (material_id, name),
  CHECK (lo_si <= hi_si)
);
)sql",
      // 1 -> 2: a log of imports, and part lookups by program.
      R"sql(
CREATE TABLE imports (
  id        INTEGER PRIMARY KEY,
  time      TEXT NOT NULL,                   -- UTC, ISO 8601
  parts     INTEGER NOT NULL,
  materials INTEGER NOT NULL
);
CREATE INDEX parts_by_program ON parts (program);
)sql",
  };
  return migrations;
}

void Migrate(sqlite::Connection& connection, int target) {
  const auto& migrations = SchemaMigrations();
  HIGHLIFT_CHECK(target >= 0 && static_cast<std::size_t>(target) <= migrations.size(), "migration target out of range");
  // The version is read inside the transaction, so two processes migrating at once cannot both
  // apply the same step (BEGIN IMMEDIATE serialises them).
  if (connection.QueryInteger("PRAGMA user_version") >= target) return;
  for (;;) {
    sqlite::Transaction transaction(connection);
    const int version = static_cast<int>(connection.QueryInteger("PRAGMA user_version"));
    if (version >= target) return;
    connection.Execute(migrations[static_cast<std::size_t>(version)]);
    // PRAGMA takes no bound parameters; the value is our own integer.
    connection.Execute("PRAGMA user_version = " + std::to_string(version + 1));
    transaction.Commit();
  }
}

}  // namespace highlift::componentdb
