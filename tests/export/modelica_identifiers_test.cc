// Identifiers, strings and numbers in generated Modelica text.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "highlift/core/error.h"
#include "highlift/export/modelica.h"

namespace highlift {
namespace {

TEST(ModelicaIdentifiers, KeywordsAreRecognised) {
  for (const char* k : {"model", "end", "equation", "der", "connect", "within", "initial", "stream",
                        "pure", "impure", "operator", "true", "false"})
    EXPECT_TRUE(IsModelicaKeyword(k)) << k;
  for (const char* n : {"inertia1", "Model", "End", "time", "J", "flange_a"})
    EXPECT_FALSE(IsModelicaKeyword(n)) << n;
}

TEST(ModelicaIdentifiers, ValidIdentifiers) {
  EXPECT_TRUE(IsModelicaIdentifier("inertia1"));
  EXPECT_TRUE(IsModelicaIdentifier("_x"));
  EXPECT_FALSE(IsModelicaIdentifier(""));
  EXPECT_FALSE(IsModelicaIdentifier("1st"));
  EXPECT_FALSE(IsModelicaIdentifier("shaft-l1"));
  EXPECT_FALSE(IsModelicaIdentifier("end"));
  EXPECT_FALSE(IsModelicaIdentifier("a.b"));
}

TEST(ModelicaIdentifiers, SanitizerReplacesLeadsAndEscapesKeywords) {
  EXPECT_EQ(SanitizeModelicaIdentifier("shaft_l1"), "shaft_l1");
  EXPECT_EQ(SanitizeModelicaIdentifier("shaft-l1"), "shaft_l1");
  EXPECT_EQ(SanitizeModelicaIdentifier("1st"), "x_1st");
  EXPECT_EQ(SanitizeModelicaIdentifier(""), "x_");
  EXPECT_EQ(SanitizeModelicaIdentifier("end"), "end_");
  EXPECT_EQ(SanitizeModelicaIdentifier("model"), "model_");
  EXPECT_EQ(SanitizeModelicaIdentifier("wtb left (tip)"), "wtb_left__tip_");
  EXPECT_EQ(SanitizeModelicaIdentifier("\xc3\xa9tage"), "etage");  // Latin letters lose their accents
  EXPECT_EQ(SanitizeModelicaIdentifier("\xce\xb7_gear"), "__gear");  // other letters: one '_' each
  for (const char* s : {"a b", "9", "for", "x.y", "\xce\xb7", "'q'"})
    EXPECT_TRUE(IsModelicaIdentifier(SanitizeModelicaIdentifier(s))) << s;
}

// Issue 28, item 6: the Latin letters of a name keep their base letter instead of vanishing.
TEST(ModelicaIdentifiers, TransliteratesLatinLettersToAscii) {
  EXPECT_EQ(TransliterateToAscii("Ünïcödé Rig"), "Unicode Rig");
  EXPECT_EQ(TransliterateToAscii("Straße"), "Strasse");                              // ß
  EXPECT_EQ(TransliterateToAscii("Æsir Œuvre"), "AEsir OEuvre");               // Æ, Œ
  EXPECT_EQ(TransliterateToAscii("Łódź"), "Lodz");
  EXPECT_EQ(TransliterateToAscii("3×4"), "3_4");        // × is no letter
  EXPECT_EQ(TransliterateToAscii("\xce\xb7=0.9"), "_=0.9");     // Greek: no ASCII letter
  EXPECT_EQ(TransliterateToAscii(std::string("a\xff" "b")), "a_b");  // no UTF-8
  EXPECT_EQ(TransliterateToAscii("\xc3"), "_");                   // truncated sequence
}

// Issue 27, item 20: the names of the predefined types are no instance names.
TEST(ModelicaIdentifiers, PredefinedTypeNamesAreReserved) {
  for (const char* name : {"Real", "Integer", "Boolean", "String", "Clock", "StateSelect", "ExternalObject",
                           "AssertionLevel", "Connections", "model", "end", "der", "initial"}) {
    EXPECT_TRUE(IsModelicaReservedName(name)) << name;
    EXPECT_FALSE(IsModelicaIdentifier(name)) << name;
    EXPECT_EQ(SanitizeModelicaIdentifier(name), std::string(name) + "_") << name;
    EXPECT_TRUE(IsModelicaIdentifier(SanitizeModelicaIdentifier(name))) << name;
  }
  for (const char* name : {"real", "Real_", "RealGear", "time", "Modelica"}) EXPECT_FALSE(IsModelicaReservedName(name)) << name;
  ModelicaExportOptions options;
  options.model_name = "Boolean";
  EXPECT_THROW(options.Validate(), InputError);
}

TEST(ModelicaIdentifiers, MapResolvesCollisionsInInsertionOrder) {
  IdentifierMap ids({"time", "Modelica"});
  EXPECT_EQ(ids.Add("end_"), "end_");
  EXPECT_EQ(ids.Add("end"), "end__2");  // "end" sanitises to the taken "end_"
  EXPECT_EQ(ids.Add("a-b"), "a_b");
  EXPECT_EQ(ids.Add("a.b"), "a_b_2");
  EXPECT_EQ(ids.Add("a b"), "a_b_3");
  EXPECT_EQ(ids.Add("time"), "time_2");  // reserved by the generator
  EXPECT_EQ(ids.Add("a-b"), "a_b");      // stable for a name added before
  EXPECT_EQ(ids.Get("a.b"), "a_b_2");
  const auto renamed = ids.Renamed();
  EXPECT_EQ(renamed.size(), 5u);
  EXPECT_EQ(renamed.at("end"), "end__2");
  EXPECT_EQ(renamed.count("end_"), 0u);
  EXPECT_THROW(ids.Get("unknown"), InternalError);
}

TEST(ModelicaStrings, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(EscapeModelicaString("plain"), "plain");
  EXPECT_EQ(EscapeModelicaString("say \"hi\""), "say \\\"hi\\\"");
  EXPECT_EQ(EscapeModelicaString("C:\\dir"), "C:\\\\dir");
  EXPECT_EQ(EscapeModelicaString("a\nb\tc"), "a\\nb\\tc");
  EXPECT_EQ(EscapeModelicaString(std::string("x\x01y", 3)), "xy");
  EXPECT_EQ(EscapeModelicaString("\xc2\xb0" "C"), "\xc2\xb0" "C");  // UTF-8 kept
}

TEST(ModelicaNumbers, ShortestRoundTripText) {
  EXPECT_EQ(FormatModelicaReal(0.1), "0.1");
  EXPECT_EQ(FormatModelicaReal(10), "10");
  EXPECT_EQ(FormatModelicaReal(-2.5), "-2.5");
  EXPECT_EQ(FormatModelicaReal(-0.0), "0");
  EXPECT_EQ(FormatModelicaReal(1e-6), "1e-06");
  for (double v : {1.0 / 3.0, 15.915494309189533, 7657.123456789, 1e300, 2.2250738585072014e-308}) {
    EXPECT_EQ(std::stod(FormatModelicaReal(v)), v) << FormatModelicaReal(v);
  }
}

TEST(ModelicaNumbers, RejectsNonFiniteValuesNamingThem) {
  try {
    FormatModelicaReal(std::numeric_limits<double>::infinity(), "component 'wtb' parameter 'J'");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("component 'wtb' parameter 'J' = inf"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("give a finite value"), std::string::npos) << e.what();
  }
  EXPECT_THROW(FormatModelicaReal(std::nan("")), InputError);
}

TEST(ModelicaExportOptions, ResolutionRoundTripsAndRejectsUnknownNames) {
  EXPECT_EQ(ModelResolutionFromString(ToString(ModelResolution::kFull)), ModelResolution::kFull);
  EXPECT_EQ(ModelResolutionFromString(ToString(ModelResolution::kReduced)), ModelResolution::kReduced);
  try {
    ModelResolutionFromString("coarse");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown model resolution 'coarse'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("'full'"), std::string::npos);
  }
}

TEST(ModelicaExportOptions, DefaultsAreValidAndBadModelNamesAreRejected) {
  ModelicaExportOptions options;
  EXPECT_NO_THROW(options.Validate());
  options.model_name = "my model";
  try {
    options.Validate();
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'my model' is no Modelica identifier"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("'my_model'"), std::string::npos);
  }
  options.model_name = "HighLift";
  EXPECT_THROW(options.Validate(), InputError);
}

}  // namespace
}  // namespace highlift
