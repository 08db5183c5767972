// Import and export: validation with row numbers, all-or-nothing writes, round trips.
#include <gtest/gtest.h>

#include <fstream>

#include "highlift/componentdb/database.h"
#include "highlift/componentdb/io.h"
#include "highlift/core/error.h"
#include "test_util.h"

namespace highlift::componentdb {
namespace {

using highlift::testing::ScratchDirectory;

const std::string kHeader = "type,designation,program,supplier,note,parameter,value,min,max,unit,tag,source\n";

std::string CsvImportError(const std::string& body) {
  try {
    Records r = ParseCsv(kHeader + body, "parts.csv");
    ValidateRecords(r);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

void ExpectContains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "message: " << text << "\nexpected to contain: " << part;
}

TEST(ComponentDatabaseImport, BadRowsNameTheRowTheProblemAndWhatIsValid) {
  const std::string good = "geared_rotary_actuator,G1,x,,,ratio,200,,,1,E,s\n";
  EXPECT_EQ(CsvImportError(good), "(no error)");
  ExpectContains(CsvImportError(good + "geared_rotary_actuatr,G2,x,,,ratio,200,,,1,E,s\n"),
                 "parts.csv row 3: unknown component type 'geared_rotary_actuatr'; did you mean 'geared_rotary_actuator'? Valid types: pdu,");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G1,,,,ration,200,,,1,E,s\n"),
                 "parts.csv row 3: part 'G1' (geared_rotary_actuator) has no parameter 'ration'; did you mean 'ratio'? Valid parameters: ratio, eta_opposing");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G1,,,,output_torque_rating,20,,,kg,E,s\n"),
                 "parts.csv row 3: part 'G1' (geared_rotary_actuator) parameter 'output_torque_rating': unit 'kg' is");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G1,,,,output_torque_rating,20,,,kg,E,s\n"),
                 "is mass, expected torque (e.g. 'kN*m')");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G1,,,,eta_opposing,,0.9,0.8,1,E,s\n"),
                 "row 3: part 'G1' (geared_rotary_actuator) parameter 'eta_opposing': min 0.9 exceeds max 0.8");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G1,,,,eta_opposing,1.2,,,1,E,s\n"),
                 "row 3: part 'G1' (geared_rotary_actuator) parameter 'eta_opposing': 1.2 1 is outside its valid range [0.01, 1] (SI)");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G1,,,,eta_opposing,0.8,,,1,X,s\n"),
                 "parts.csv row 3: column 'tag' must be P, P-low or E, got 'X'");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G1,,,,eta_opposing,abc,,,1,E,s\n"),
                 "parts.csv row 3: column 'value' must be a number (or inf, -inf), got 'abc'");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G1,,,,eta_opposing,0.8,,,1,E,\n"),
                 "row 3: part 'G1' (geared_rotary_actuator) parameter 'eta_opposing': no source");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G1,,,,ratio,150,,,1,E,s\n"),
                 "row 3: part 'G1' (geared_rotary_actuator) parameter 'ratio' is given twice");
  ExpectContains(CsvImportError(good + "pdu,G1,,,,ratio,15,,,1,E,s\n"),
                 "row 3: part 'G1' has type 'pdu' but type 'geared_rotary_actuator' at row 2");
  ExpectContains(CsvImportError(good + "geared_rotary_actuator,G3,,,,ratio,200,1\n"),
                 "row 3: expected 12 columns");
  ExpectContains(CsvImportError("material,Ti,,,,density,4420,,,kg/m^3,P,s\n"),
                 "row 2: material 'Ti' lacks property 'shear_modulus'");
  ExpectContains(CsvImportError("geared_rotary_actuator,G1,,,,ratio,2.5,,,1,E,\"unterminated\n"),
                 "parts.csv row 2: a quoted field is not closed");
}

TEST(ComponentDatabaseImport, BadRowLeavesTheDatabaseExactlyAsItWas) {
  ScratchDirectory dir;
  auto db = ComponentDatabase::Open(dir / "db.sqlite", ComponentDatabase::Mode::kCreate);
  db.Import(SeedRecords());
  const Counts before = db.CountRows();
  const Records exported = db.Export();
  // 50 good rows, then a bad one at row 52.
  std::string body;
  for (int i = 0; i < 50; ++i) body += "jam,NEW-" + std::to_string(i) + ",,,,stiffness,1e5,,,N*m/rad,E,s\n";
  body += "jam,NEW-X,,,,stiffness,1e5,,,N*m,E,s\n";  // fine: N*m/rad and N*m have the same dimension
  body += "jam,NEW-Y,,,,stifness,1e5,,,N*m/rad,E,s\n";
  std::ofstream(dir / "bad.csv") << kHeader << body;
  try {
    db.Import(ReadRecords(dir / "bad.csv"));
    FAIL() << "import of a bad row did not fail";
  } catch (const InputError& e) {
    ExpectContains(e.what(), "bad.csv row 53: part 'NEW-Y' (jam) has no parameter 'stifness'; did you mean 'stiffness'?");
  }
  EXPECT_EQ(db.CountRows(), before);
  // A designation already in the database is caught inside the transaction: rolled back too.
  std::ofstream(dir / "dup.csv") << kHeader << "jam,NEW-1,,,,stiffness,1e5,,,N*m/rad,E,s\n"
                                 << "jam,JAM-GROUND,,,,stiffness,1e5,,,N*m/rad,E,s\n";
  try {
    db.Import(ReadRecords(dir / "dup.csv"));
    FAIL() << "import of an existing designation did not fail";
  } catch (const InputError& e) {
    ExpectContains(e.what(), "dup.csv row 3: part 'JAM-GROUND' is already in the database");
    ExpectContains(e.what(), "import with --replace");
  }
  EXPECT_EQ(db.CountRows(), before);
  EXPECT_EQ(db.Export(), exported);
  EXPECT_EQ(db.IntegrityCheck(), "ok");
}

TEST(ComponentDatabaseImport, ExportThenImportIntoAnEmptyDatabaseRoundTrips) {
  ScratchDirectory dir;
  auto a = ComponentDatabase::Open(dir / "a.sqlite", ComponentDatabase::Mode::kCreate);
  a.Import(SeedRecords());
  const Records original = a.Export();
  for (const char* name : {"out.json", "out.csv"}) {
    WriteRecords(original, dir / name);
    auto b = ComponentDatabase::Open(dir / (std::string(name) + ".sqlite"), ComponentDatabase::Mode::kCreate);
    b.Import(ReadRecords(dir / name));
    EXPECT_EQ(b.Export(), original) << name;
    EXPECT_EQ(b.CountRows(), a.CountRows()) << name;
  }
  // The seed text itself survives CSV parsing and writing unchanged in content.
  Records seed = SeedRecords();
  Records again = ParseCsv(ToCsv(seed), "again.csv");
  ValidateRecords(again);
  EXPECT_EQ(again, seed);
}

TEST(ComponentDatabaseImport, JsonRejectsUnknownKeysWithThePartNumber) {
  const std::string text = R"({"format": "highlift-componentdb/1", "parts": [
    {"type": "jam", "designation": "J1", "parameters": {"stiffness": {"value": 1e5, "unit": "N*m/rad", "tag": "E", "source": "s"}}},
    {"type": "jam", "designation": "J2", "parameters": {"stiffness": {"value": 1e5, "unti": "N*m/rad", "tag": "E", "source": "s"}}}]})";
  try {
    ParseJson(text, "parts.json");
    FAIL();
  } catch (const InputError& e) {
    ExpectContains(e.what(), "parts.json /parts/1/parameters/stiffness: unknown key 'unti'; did you mean 'unit'?");
  }
}

}  // namespace
}  // namespace highlift::componentdb
