// Numbers and text in messages (issue 27 item 19): one formatter for the numbers of every message,
// and message text that is UTF-8 and cut only between characters.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "highlift/core/error.h"
#include "highlift/core/message_number.h"
#include "highlift/core/utf8.h"

namespace highlift {
namespace {

TEST(FormatMessageNumber, ShortestFormWithoutNoiseDigits) {
  // Was (std::to_string): 309 digits for 1e308, "-0.000000" for -1e-12, "0.000000" for 5e-324.
  EXPECT_EQ(FormatMessageNumber(1e308), "1e308");
  EXPECT_EQ(FormatMessageNumber(std::numeric_limits<double>::max()), "1.79769e308");
  EXPECT_EQ(FormatMessageNumber(-1e-12), "-1e-12");
  EXPECT_EQ(FormatMessageNumber(-0.0), "0");
  EXPECT_EQ(FormatMessageNumber(0.0), "0");
  EXPECT_EQ(FormatMessageNumber(5e-324), "4.94066e-324");
  EXPECT_EQ(FormatMessageNumber(0.01), "0.01");
  EXPECT_EQ(FormatMessageNumber(25.3), "25.3");
  EXPECT_EQ(FormatMessageNumber(1e-6), "1e-6");
  EXPECT_EQ(FormatMessageNumber(470), "470");
  EXPECT_EQ(FormatMessageNumber(123456789.0), "1.23457e8");
  EXPECT_EQ(FormatMessageNumber(1.0 / 3.0, 3), "0.333");
  EXPECT_EQ(FormatMessageNumber(std::nan("")), "nan");
  EXPECT_EQ(FormatMessageNumber(-std::nan("")), "nan");
  EXPECT_EQ(FormatMessageNumber(-std::numeric_limits<double>::infinity()), "-inf");
  for (const double x : {1e308, -1e-300, 0.1, 7.0, 1e7})
    EXPECT_LE(FormatMessageNumber(x).size(), 13u) << x;
}

TEST(CleanText, BytesThatAreNotUtf8AreEscaped) {
  // Was: a Latin-1 byte (a file name) passed into the message and broke its UTF-8.
  EXPECT_EQ(CleanText("caf\xe9.json"), "caf\\xe9.json");
  EXPECT_EQ(CleanText("\xc3\xa4 ok"), "\xc3\xa4 ok");
  EXPECT_EQ(CleanText("cut \xe2\x82"), "cut \\xe2\\x82");
  EXPECT_FALSE(FindTextProblem(CleanText("x\xff\xfe\x80y\x1b")).has_value());
}

TEST(CleanText, LinesAreCutBetweenCharacters) {
  // 'ä' is two bytes: a cut after an odd number of bytes must not split it.
  std::string text = "a";
  for (int i = 0; i < 2000; ++i) text += "\xc3\xa4";
  const std::string cleaned = CleanText(text, 2000);
  EXPECT_FALSE(FindTextProblem(cleaned).has_value()) << cleaned.substr(1990);
  EXPECT_NE(cleaned.find(" more bytes]"), std::string::npos);
  EXPECT_LE(cleaned.find(" [..."), 2002u);
}

}  // namespace
}  // namespace highlift
