#include "core/util/byte_stream.hpp"

#include <cstdint>
#include <functional>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::string failure_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ByteStream, ValuesAndTextRoundTripLittleEndian) {
  ByteWriter w;
  w.put(std::uint32_t{0x04030201});
  w.put(-2.5);
  w.put(std::int16_t{-7});
  w.put_text("facade");
  ASSERT_EQ(w.bytes().size(), 4u + 8u + 2u + 4u + 6u);
  EXPECT_EQ(w.bytes().substr(0, 4), std::string("\x01\x02\x03\x04", 4));

  ByteReader r(w.bytes(), "x.bin", "damaged test file");
  EXPECT_EQ(r.get<std::uint32_t>("a"), 0x04030201u);
  EXPECT_EQ(r.get<double>("b"), -2.5);
  EXPECT_EQ(r.get<std::int16_t>("c"), -7);
  EXPECT_FALSE(r.at_end());
  EXPECT_EQ(r.text("d"), "facade");
  EXPECT_TRUE(r.at_end());
  EXPECT_EQ(r.position(), w.bytes().size());
}

TEST(ByteStream, AShortReadNamesTheFileWhatAndWhere) {
  ByteWriter w;
  w.put(std::uint16_t{1});
  ByteReader r(w.bytes(), "cut.bin", "damaged test file");
  EXPECT_THAT(
      failure_of([&] { r.get<std::uint32_t>("the version"); }),
      AllOf(HasSubstr("cut.bin"), HasSubstr("damaged test file"), HasSubstr("the version"), HasSubstr("byte 0 of 2")));
}

TEST(ByteStream, ACountIsBoundedByItsMaximumAndByTheBytesLeft) {
  ByteWriter w;
  w.put(std::uint32_t{5});
  w.put_bytes("abcdefgh", 8);
  {
    ByteReader r(w.bytes(), "n.bin", "damaged test file");
    EXPECT_THAT(failure_of([&] { r.count("the node count", 1, 4); }), HasSubstr("expected at most 4"));
  }
  {
    ByteReader r(w.bytes(), "n.bin", "damaged test file");
    EXPECT_THAT(failure_of([&] { r.count("the node count", 2, 100); }), HasSubstr("only 8 bytes follow"));
  }
  ByteReader r(w.bytes(), "n.bin", "damaged test file");
  EXPECT_EQ(r.count("the node count", 1, 100), 5u);
}

// Found by fuzz_map_file under UBSan: an image header of N rows and 0
// columns read each empty row into Mat::ptr(), which is null.
TEST(ByteStream, ReadingNoBytesIntoNowhereIsAllowed) {
  ByteReader r("x", "e.bin", "damaged test file");
  r.get_bytes(nullptr, 0, "an empty row");
  EXPECT_EQ(r.position(), 0u);
}

TEST(ByteStream, TextLongerThanAllowedIsRejected) {
  ByteWriter w;
  w.put_text("a much too long class name");
  ByteReader r(w.bytes(), "t.bin", "damaged test file");
  EXPECT_THAT(failure_of([&] { r.text("a class name", 8); }), HasSubstr("a class name is 26"));
}

}  // namespace
}  // namespace facadeslam
