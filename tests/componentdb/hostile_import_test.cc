// Hostile input to the component database (issue 19): text that is not UTF-8, byte-order marks
// and control characters are rejected at import with the line, so `db export` and every JSON
// output keep working; `db find --where` ranges give readable errors; `db export` never
// overwrites the database it reads.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/run_cli.h"
#include "highlift/componentdb/database.h"
#include "highlift/componentdb/io.h"
#include "highlift/core/error.h"
#include "test_util.h"

namespace highlift {
namespace {

using highlift::testing::RunCli;
using highlift::testing::ScratchDirectory;

// HIGHLIFT_DATA_DIR: set by ctest, or by db_cli_test.cc in this same executable.

const std::string kHeader = "type,designation,program,supplier,note,parameter,value,min,max,unit,tag,source\n";

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(HostileImport, CsvWithLatin1IsRejectedWithTheLine) {
  const std::string text = kHeader + "jam,J1,,,,stiffness,1e5,,,N*m/rad,E,test\njam,J\xE9,,,,stiffness,1e5,,,N*m/rad,E,test\n";
  const std::string message = ErrorOf([&] { componentdb::ParseCsv(text, "parts.csv"); });
  EXPECT_NE(message.find("parts.csv line 3, byte 6: invalid UTF-8 (the byte 0xE9)"), std::string::npos) << message;
}

TEST(HostileImport, CsvWithABomInsideOrAControlCharacterIsRejected) {
  EXPECT_NE(ErrorOf([&] { componentdb::ParseCsv(kHeader + "jam,\xEF\xBB\xBFJ1,,,,stiffness,1,,,N*m/rad,E,t\n", "p.csv"); })
                .find("byte-order mark"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] { componentdb::ParseCsv(kHeader + "jam,J\x1b,,,,stiffness,1,,,N*m/rad,E,t\n", "p.csv"); })
                .find("a control character (the byte 0x1B)"),
            std::string::npos);
  // A byte-order mark at the very start of the file is what spreadsheet programs write: accepted.
  EXPECT_NO_THROW(componentdb::ParseCsv("\xEF\xBB\xBF" + kHeader + "jam,J1,,,,stiffness,1,,,N*m/rad,E,t\n", "p.csv"));
}

TEST(HostileImport, JsonWithInvalidUtf8IsRejectedWithoutTheLibraryText) {
  const std::string text = "{\"format\": \"highlift-componentdb/1\",\n \"materials\": [{\"name\": \"st\xFF\"}]}";
  const std::string message = ErrorOf([&] { componentdb::ParseJson(text, "db.json"); });
  EXPECT_NE(message.find("db.json line 2: invalid UTF-8 (the byte 0xFF)"), std::string::npos) << message;
  const std::string syntax = ErrorOf([] { componentdb::ParseJson("{\"format\": ", "db.json"); });
  EXPECT_EQ(syntax.find("[json.exception"), std::string::npos) << syntax;
  EXPECT_NE(syntax.find("db.json: not valid JSON: parse error at line 1"), std::string::npos) << syntax;
}

TEST(HostileWhere, ThreeBoundsSayWhatIsWrong) {
  // Was: "unknown unit ':3'".
  const std::string message = ErrorOf([] { componentdb::ParseRangeCondition("stiffness=1:2:3", "torque_shaft"); });
  EXPECT_NE(message.find("more than one ':'; a range has two bounds, LO:HI"), std::string::npos) << message;
}

TEST(HostileWhere, NonFiniteBoundsAreRejected) {
  EXPECT_NE(ErrorOf([] { componentdb::ParseRangeCondition("ratio=nan:3", "geared_rotary_actuator"); })
                .find("'nan' is not a finite number"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { componentdb::ParseRangeCondition("ratio=1:inf", "geared_rotary_actuator"); })
                .find("not a finite number"),
            std::string::npos);
}

TEST(HostileWhere, UnitPowerOverflowIsAnInputError) {
  const std::string message =
      ErrorOf([] { componentdb::ParseRangeCondition("output_torque_rating=1:2 m^200 m^56", "geared_rotary_actuator"); });
  EXPECT_NE(message.find("the power of m is 256"), std::string::npos) << message;
}

TEST(HostileDbCli, ExportNeverOverwritesTheDatabaseItReads) {
  ScratchDirectory dir;
  const std::string db = (dir / "x.json").string();
  std::ofstream(dir / "parts.csv") << kHeader << "jam,J1,,,,stiffness,1e5,,,N*m/rad,E,test\n";
  ASSERT_EQ(RunCli({"db", "import", (dir / "parts.csv").string(), "--db", db}).exit_code, 0);
  const auto size_before = std::filesystem::file_size(db);
  const auto r = RunCli({"db", "export", db, "--db", db});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is an input of this command"), std::string::npos) << r.err;
  EXPECT_EQ(std::filesystem::file_size(db), size_before);
  EXPECT_EQ(RunCli({"db", "list", "--db", db}).exit_code, 0);  // still a database
}

TEST(HostileDbCli, ImportOfLatin1ExitsTwoAndJsonSaysWhy) {
  ScratchDirectory dir;
  std::ofstream(dir / "bad.csv") << kHeader << "jam,J\xE9,,,,stiffness,1e5,,,N*m/rad,E,test\n";
  const auto r = RunCli({"db", "import", (dir / "bad.csv").string(), "--db", (dir / "db.sqlite").string(), "--json"});
  EXPECT_EQ(r.exit_code, 2);
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["ok"], false);
  EXPECT_EQ(doc["status"], "invalid_input");
  EXPECT_NE(doc["error"]["message"].get<std::string>().find("invalid UTF-8"), std::string::npos) << r.out;
}

TEST(HostileDbCli, WhereWithThreeBoundsPrintsAJsonError) {
  const auto r = RunCli({"db", "find", "torque_shaft", "--where", "stiffness=1:2:3", "--json"});
  EXPECT_EQ(r.exit_code, 2);
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["command"], "db find");
  EXPECT_NE(doc["error"]["message"].get<std::string>().find("more than one ':'"), std::string::npos);
}

}  // namespace
}  // namespace highlift
