// Schema, migrations, the seed, queries and the default database.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cstdlib>
#include <set>

#include "highlift/componentdb/database.h"
#include "highlift/componentdb/io.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "test_util.h"

namespace highlift::componentdb {
namespace {

using highlift::testing::ScratchDirectory;

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// Runs SQL on a raw connection, outside the library.
void RawExecute(const std::filesystem::path& file, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  char* message = nullptr;
  const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message);
  const std::string text = message ? message : "";
  sqlite3_free(message);
  sqlite3_close(db);
  ASSERT_EQ(rc, SQLITE_OK) << text;
}

TEST(ComponentDatabaseSchema, NewDatabaseHasCurrentVersionWalAndForeignKeys) {
  ScratchDirectory dir;
  auto db = ComponentDatabase::Open(dir / "new.sqlite", ComponentDatabase::Mode::kCreate);
  EXPECT_EQ(db.schema_version(), ComponentDatabase::kSchemaVersion);
  EXPECT_EQ(db.journal_mode(), "wal");
  EXPECT_EQ(db.CountRows(), Counts{});
  EXPECT_EQ(db.IntegrityCheck(), "ok");
  // Replacing a part deletes its parameters through the foreign key cascade.
  Records r;
  r.parts.push_back({"jam", "J1", "", "", "", {highlift::testing::PointQuantity("stiffness", 1e5, "N*m/rad")}, ""});
  db.Import(r);
  EXPECT_EQ(db.CountRows().part_parameters, 1);
  ImportOptions replace;
  replace.replace = true;
  const auto report = db.Import(r, replace);
  EXPECT_EQ(report.parts_replaced, 1u);
  EXPECT_EQ(db.CountRows().part_parameters, 1);
}

TEST(ComponentDatabaseSchema, MigratesVersionOneAndKeepsItsRows) {
  ScratchDirectory dir;
  const auto file = dir / "v1.sqlite";
  RawExecute(file, SchemaMigrations().at(0) + "; PRAGMA user_version = 1;" +
                       "INSERT INTO parts (type, designation) VALUES ('jam', 'OLD-JAM');"
                       "INSERT INTO part_parameters (part_id, name, value, unit, value_si, lo_si, hi_si, tag, source) "
                       "VALUES (1, 'stiffness', 2e4, 'N*m/rad', 2e4, 2e4, 2e4, 'E', 'old');");
  // Read-only access refuses an old schema with the remedy.
  EXPECT_NE(ErrorOf([&] { ComponentDatabase::Open(file, ComponentDatabase::Mode::kReadOnly); })
                .find("has schema version 1 and must be upgraded to 2"),
            std::string::npos);
  auto db = ComponentDatabase::Open(file, ComponentDatabase::Mode::kReadWrite);
  EXPECT_EQ(db.schema_version(), 2);
  const auto part = db.FindPart("OLD-JAM");
  ASSERT_TRUE(part.has_value());
  ASSERT_EQ(part->parameters.size(), 1u);
  EXPECT_EQ(part->parameters[0].domain_si, Domain::Point(2e4));
  // The version-2 table (import log) exists and works.
  Records r;
  r.parts.push_back({"jam", "NEW-JAM", "", "", "", {highlift::testing::PointQuantity("stiffness", 3e4, "N*m/rad")}, ""});
  db.Import(r);
  EXPECT_EQ(db.CountRows().parts, 2);
}

TEST(ComponentDatabaseSchema, RefusesNewerSchemaAndForeignFiles) {
  ScratchDirectory dir;
  RawExecute(dir / "newer.sqlite", "PRAGMA user_version = 99;");
  EXPECT_NE(ErrorOf([&] { ComponentDatabase::Open(dir / "newer.sqlite", ComponentDatabase::Mode::kReadWrite); })
                .find("schema version 99, newer than this highlift understands (2); use a newer highlift"),
            std::string::npos);
  RawExecute(dir / "foreign.sqlite", "CREATE TABLE t (x);");
  EXPECT_NE(ErrorOf([&] { ComponentDatabase::Open(dir / "foreign.sqlite", ComponentDatabase::Mode::kReadWrite); })
                .find("is an SQLite database but not a highlift component database"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] { ComponentDatabase::Open(dir / "missing.sqlite", ComponentDatabase::Mode::kReadOnly); })
                .find("does not exist"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing.sqlite"));
}

TEST(ComponentDatabaseSeed, HasSixtyPartsCoveringEveryTypeWithTagsAndSources) {
  const Records seed = SeedRecords();
  EXPECT_GE(seed.parts.size(), 60u);
  std::set<std::string> types;
  for (const auto& p : seed.parts) {
    types.insert(p.type);
    EXPECT_FALSE(p.parameters.empty()) << p.designation;
    for (const auto& q : p.parameters) EXPECT_FALSE(q.source.empty()) << p.designation << " " << q.name;
  }
  for (const auto& t : ComponentTypes()) EXPECT_TRUE(types.count(t.name)) << "no seed part of type " << t.name;
  EXPECT_EQ(seed.materials.size(), 4u);
  // A published number keeps its tag; the A380-class set is an estimate.
  const Material* ti = nullptr;
  for (const auto& m : seed.materials)
    if (m.name == "Ti-6Al-4V") ti = &m;
  ASSERT_NE(ti, nullptr);
  EXPECT_EQ(ti->Find("density")->tag, Tag::kPublished);
  EXPECT_EQ(ti->Find("shear_modulus")->tag, Tag::kPublishedLow);
  EXPECT_EQ(ti->Find("shear_modulus")->domain_si, (Domain{43e9, 51e9}));
}

TEST(ComponentDatabaseQuery, FindsGrasByRatioRange) {
  ScratchDirectory dir;
  auto db = ComponentDatabase::Open(dir / "seed.sqlite", ComponentDatabase::Mode::kCreate);
  db.Import(SeedRecords());
  PartQuery q;
  q.type = "geared_rotary_actuator";
  q.conditions.push_back(ParseRangeCondition("ratio=150:250", q.type));
  const auto parts = db.Find(q);
  ASSERT_FALSE(parts.empty());
  std::set<std::string> names;
  for (const auto& p : parts) {
    names.insert(p.designation);
    const double ratio = p.Find("ratio")->Representative();
    EXPECT_GE(ratio, 150);
    EXPECT_LE(ratio, 250);
  }
  EXPECT_TRUE(names.count("GRA-200-A380C"));
  EXPECT_TRUE(names.count("GRA-150-A320C-SLAT"));
  EXPECT_FALSE(names.count("GRA-300-A320C-FLAP"));
  // Units in a range are converted to SI; two conditions must both hold.
  q.conditions.push_back(ParseRangeCondition("output_torque_rating=10:25 kN*m", q.type));
  EXPECT_DOUBLE_EQ(q.conditions.back().domain.lo, 10e3);
  for (const auto& p : db.Find(q)) EXPECT_GE(p.Find("output_torque_rating")->Representative(), 10e3);
  EXPECT_LT(db.Find(q).size(), parts.size());
}

TEST(ComponentDatabaseQuery, RangeConditionErrorsNameTheAcceptedForms) {
  EXPECT_NE(ErrorOf([] { ParseRangeCondition("ratio150:250", "geared_rotary_actuator"); }).find("use NAME=LO:HI"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { ParseRangeCondition("ration=1:2", "geared_rotary_actuator"); })
                .find("type 'geared_rotary_actuator' has no parameter 'ration'; did you mean 'ratio'?"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { ParseRangeCondition("output_torque_rating=1:2 m", "geared_rotary_actuator"); }),
            "(no error)");
  const auto open = ParseRangeCondition("ratio=150:", "geared_rotary_actuator");
  EXPECT_EQ(open.domain.lo, 150);
  EXPECT_TRUE(std::isinf(open.domain.hi));
}

TEST(ComponentDatabaseDefault, CreatedFromTheSeedOnFirstUseInTheDataDirectory) {
  ScratchDirectory dir;
  const char* old = std::getenv("HIGHLIFT_DATA_DIR");
  const std::string saved = old ? old : "";
  ::setenv("HIGHLIFT_DATA_DIR", (dir / "home").c_str(), 1);
  EXPECT_EQ(DefaultDatabasePath(), dir / "home" / "components.sqlite");
  {
    auto db = OpenDatabase("", ComponentDatabase::Mode::kReadOnly);
    EXPECT_EQ(db.file(), dir / "home" / "components.sqlite");
    EXPECT_EQ(static_cast<std::size_t>(db.CountRows().parts), SeedRecords().parts.size());
  }
  // No temporary files are left beside it.
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir / "home"))
    files += e.path().filename().string().find(".tmp-") == std::string::npos ? 0 : 1;
  EXPECT_EQ(files, 0u);
  // --db PATH that does not exist is an error for reading, not a silent empty database.
  EXPECT_NE(ErrorOf([&] { OpenDatabase((dir / "nope.sqlite").string(), ComponentDatabase::Mode::kReadOnly); })
                .find("does not exist"),
            std::string::npos);
  if (old) ::setenv("HIGHLIFT_DATA_DIR", saved.c_str(), 1);
  else ::unsetenv("HIGHLIFT_DATA_DIR");
}

}  // namespace
}  // namespace highlift::componentdb
