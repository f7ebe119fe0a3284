// format_text (common/format_text.h): printf-style text of any length.
#include <gtest/gtest.h>

#include <string>

#include "common/format_text.h"

namespace qd {
namespace {

using common::format_text;

TEST(FormatText, ReturnsATextLongerThanAnyFixedBufferWhole) {
  const std::string word(5000, 'x');
  const std::string text = format_text("<%s|%d>", word.c_str(), 7);
  ASSERT_EQ(text.size(), 5004u);
  EXPECT_EQ(text.front(), '<');
  EXPECT_EQ(text.substr(5000), "x|7>");
}

TEST(FormatText, WritesNumbersAsTheFormatSays) {
  EXPECT_EQ(format_text("%.3g", 3.14159), "3.14");
  EXPECT_EQ(format_text("%.3g", 123456.0), "1.23e+05");
  EXPECT_EQ(format_text("%d pieces", -12), "-12 pieces");
  EXPECT_EQ(format_text("%+.2f %%", 0.5), "+0.50 %");
}

TEST(FormatText, GivesAnEmptyTextForAnEmptyFormat) { EXPECT_EQ(format_text("%s", ""), ""); }

}  // namespace
}  // namespace qd
