// The `highlift db` command: list, show, find, import, export.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "common/run_cli.h"
#include "highlift/componentdb/database.h"
#include "test_util.h"

namespace highlift {
namespace {

using highlift::testing::RunCli;
using highlift::testing::ScratchDirectory;

// ctest sets HIGHLIFT_DATA_DIR; when the executable is run by hand, keep the default database
// out of the user's home, in a folder of this process that goes when every test passed.
const bool kDataDirectorySet = [] {
  if (!std::getenv("HIGHLIFT_DATA_DIR")) {
    const auto home = std::filesystem::temp_directory_path() /
                      ("highlift_db_cli_test_home_" + std::to_string(::getpid()));
    ::setenv("HIGHLIFT_DATA_DIR", testing::RemoveAtTheEnd(home).c_str(), 1);
  }
  return true;
}();

TEST(DbCli, FindSelectsGrasByRatioAsJson) {
  ScratchDirectory dir;
  const std::string db = (dir / "seed.sqlite").string();
  // Import the seed export of the default database into a fresh file, then query it.
  auto exported = RunCli({"db", "export", (dir / "seed.json").string()});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  ASSERT_EQ(RunCli({"db", "import", (dir / "seed.json").string(), "--db", db}).exit_code, 0);
  const auto r = RunCli({"db", "find", "geared_rotary_actuator", "--where", "ratio=150:250", "--db", db, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_GT(doc["count"].get<int>(), 3);
  bool found = false;
  for (const auto& p : doc["parts"]) {
    const double ratio = p["parameters"]["ratio"]["value"].get<double>();
    EXPECT_GE(ratio, 150);
    EXPECT_LE(ratio, 250);
    found = found || p["designation"] == "GRA-200-A380C";
  }
  EXPECT_TRUE(found);
  const auto text = RunCli({"db", "show", "GRA-200-A380C", "--db", db});
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("output_torque_rating"), std::string::npos);
  EXPECT_NE(text.out.find("20 kN*m"), std::string::npos);
}

TEST(DbCli, BadImportExitsTwoNamesTheRowAndChangesNothing) {
  ScratchDirectory dir;
  const std::string db = (dir / "db.sqlite").string();
  std::ofstream(dir / "good.csv") << "type,designation,program,supplier,note,parameter,value,min,max,unit,tag,source\n"
                                  << "jam,J1,,,,stiffness,1e5,,,N*m/rad,E,test\n";
  ASSERT_EQ(RunCli({"db", "import", (dir / "good.csv").string(), "--db", db}).exit_code, 0);
  std::ofstream(dir / "bad.csv") << "type,designation,program,supplier,note,parameter,value,min,max,unit,tag,source\n"
                                 << "jam,J2,,,,stiffness,1e5,,,N*m/rad,E,test\n"
                                 << "jam,J3,,,,stiffness,1e5,,,kg,E,test\n";
  const auto r = RunCli({"db", "import", (dir / "bad.csv").string(), "--db", db});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.csv row 3: part 'J3' (jam) parameter 'stiffness': unit 'kg' is"), std::string::npos) << r.err;
  const auto list = RunCli({"db", "list", "--db", db, "--json"});
  ASSERT_EQ(list.exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(list.out)["count"], 1);
  // A missing --db for reading is an error, not a new empty database.
  const auto missing = RunCli({"db", "list", "--db", (dir / "nope.sqlite").string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("does not exist"), std::string::npos);
}

TEST(DbCli, ExportImportRoundTripsThroughCsv) {
  ScratchDirectory dir;
  ASSERT_EQ(RunCli({"db", "export", (dir / "a.csv").string()}).exit_code, 0);
  ASSERT_EQ(RunCli({"db", "import", (dir / "a.csv").string(), "--db", (dir / "b.sqlite").string()}).exit_code, 0);
  const auto a = RunCli({"db", "export", "--format", "csv"});
  const auto b = RunCli({"db", "export", "--format", "csv", "--db", (dir / "b.sqlite").string()});
  ASSERT_EQ(a.exit_code, 0);
  EXPECT_EQ(a.out, b.out);
  EXPECT_GT(a.out.size(), 10000u);
}

}  // namespace
}  // namespace highlift

namespace highlift {
namespace {

/// Sets HIGHLIFT_DATA_DIR for the life of the object, and puts the previous value back.
class DataDirectory {
 public:
  explicit DataDirectory(const std::filesystem::path& dir) {
    if (const char* old = std::getenv("HIGHLIFT_DATA_DIR")) old_ = old;
    ::setenv("HIGHLIFT_DATA_DIR", dir.c_str(), 1);
  }
  ~DataDirectory() {
    if (old_) {
      ::setenv("HIGHLIFT_DATA_DIR", old_->c_str(), 1);
    } else {
      ::unsetenv("HIGHLIFT_DATA_DIR");
    }
  }

 private:
  std::optional<std::string> old_;
};

// A default database created by an earlier highlift (or edited) keeps its parts: the estimating
// commands say that it differs from the shipped seed and how to take the new parts, and
// `db import --seed --replace` does, keeping the parts the user added.
TEST(DbCli, AnOutdatedDefaultDatabaseIsNotedAndTheSeedImportUpdatesItKeepingTheUsersParts) {
  const ScratchDirectory scratch;
  const std::filesystem::path dir = scratch.path();
  const DataDirectory data(dir);
  const std::string note = "note: the component database " + (dir / "components.sqlite").string();
  auto fresh = RunCli({"estimate", "examples/a380_class_flaps.json"});
  ASSERT_EQ(fresh.exit_code, 0) << fresh.err;
  EXPECT_EQ(fresh.err.find(note), std::string::npos) << fresh.err;  // created from this seed

  {  // An older seed: one shipped part with another note, one missing; and a part of the user's.
    auto db = componentdb::ComponentDatabase::Open(dir / "components.sqlite",
                                                   componentdb::ComponentDatabase::Mode::kReadWrite);
    componentdb::Records edited;
    edited.parts.push_back(*db.FindPart("GRA-200-A380C"));
    edited.parts.back().note += " (an older estimate)";
    componentdb::Part own = edited.parts.back();
    own.designation = "GRA-MY-OWN";
    edited.parts.push_back(own);
    componentdb::ImportOptions replace;
    replace.replace = true;
    db.Import(edited, replace);
    EXPECT_EQ(componentdb::DifferencesFromSeed(db), std::vector<std::string>{"GRA-200-A380C"});
  }
  const auto stale = RunCli({"check", "examples/a380_class_flaps.json"});
  EXPECT_EQ(stale.exit_code, 0) << stale.err;
  EXPECT_NE(stale.err.find(note + " lacks or holds with other values 1 of the parts"), std::string::npos) << stale.err;
  EXPECT_NE(stale.err.find("(e.g. 'GRA-200-A380C')"), std::string::npos) << stale.err;
  EXPECT_NE(stale.err.find("run 'highlift db import --seed --replace'"), std::string::npos) << stale.err;
  // An explicit --db is the user's choice: nothing to compare with.
  const auto chosen = RunCli({"estimate", "examples/a380_class_flaps.json", "--db", (dir / "components.sqlite").string()});
  EXPECT_EQ(chosen.err.find("note: the component database"), std::string::npos) << chosen.err;

  const auto update = RunCli({"db", "import", "--seed", "--replace"});
  ASSERT_EQ(update.exit_code, 0) << update.err;
  EXPECT_NE(update.out.find("imported the shipped seed into"), std::string::npos) << update.out;
  const auto after = RunCli({"estimate", "examples/a380_class_flaps.json"});
  EXPECT_EQ(after.err.find(note), std::string::npos) << after.err;
  const auto db = componentdb::ComponentDatabase::Open(dir / "components.sqlite",
                                                       componentdb::ComponentDatabase::Mode::kReadOnly);
  EXPECT_TRUE(componentdb::DifferencesFromSeed(db).empty());
  EXPECT_TRUE(db.FindPart("GRA-MY-OWN").has_value());

  // Neither a file nor --seed, or both: a usage error that says what to give.
  const auto neither = RunCli({"db", "import"});
  EXPECT_EQ(neither.exit_code, 2);
  EXPECT_NE(neither.err.find("give a .csv or .json file to import, or --seed"), std::string::npos) << neither.err;
  EXPECT_EQ(RunCli({"db", "import", "x.csv", "--seed"}).exit_code, 2);
}

}  // namespace
}  // namespace highlift
