// What error messages echo of a user's input: printable, and short.
#include "core/util/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace facadeslam {
namespace {

using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(ErrorText, ControlBytesAreEscapedValidUtf8Kept) {
  EXPECT_EQ(printable("a\x1b[31mb\xff"), "a\\x1b[31mb\\xff");
  EXPECT_EQ(printable("Stra\xc3\x9f"
                      "e"),
            "Stra\xc3\x9f"
            "e");
}

TEST(ErrorText, AQuotedEchoOfAHugeLineIsCut) {
  EXPECT_EQ(quoted_for_message("12.5x"), "'12.5x'");
  const std::string line(1 << 20, '7');
  const std::string quoted = quoted_for_message(line);
  EXPECT_LT(quoted.size(), 120u);
  EXPECT_THAT(quoted, StartsWith("'7777"));
  EXPECT_THAT(quoted, EndsWith("...' (1048576 bytes)"));
}

TEST(ErrorText, AOneLineMessageKeepsItsStartAndEnd) {
  const std::string message = "rgb.txt: line 3: " + std::string(100000, 'x') + " (expected a number of seconds)";
  const std::string line = one_line_message(message);
  EXPECT_LE(line.size(), 480u);
  EXPECT_THAT(line, StartsWith("rgb.txt: line 3: xxx"));
  EXPECT_THAT(line, HasSubstr(" ... "));
  EXPECT_THAT(line, EndsWith("(expected a number of seconds)"));
  EXPECT_EQ(one_line_message("short\nmessage"), "short\\x0amessage");
  // Never cut inside a UTF-8 character.
  const std::string umlauts = one_line_message(std::string(50, 'a') + [] {
    std::string u;
    for (int i = 0; i < 400; ++i) u.append("\xc3\xa4");
    return u;
  }());
  EXPECT_EQ(printable(umlauts), umlauts) << "still valid UTF-8";
}

}  // namespace
}  // namespace facadeslam
