#include "core/config/config_node.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;

using ::testing::AllOf;
using ::testing::HasSubstr;

TEST(ConfigNode, ReadsValuesOfEveryType) {
  const auto c = ConfigNode::parse_string(
      "name: demo\nrate: 2.5\ncount: 7\nflag: true\nlist: [1, 2, 3]\nnested: {x: 1}\n", "t.yaml");
  EXPECT_EQ(c.get_string("name"), "demo");
  EXPECT_DOUBLE_EQ(c.get_double("rate", Range::positive()), 2.5);
  EXPECT_EQ(c.get_int("count", Range::closed(0, 10)), 7);
  EXPECT_TRUE(c.get_bool("flag"));
  EXPECT_EQ(c.get_doubles("list", 3), (std::vector<double>{1, 2, 3}));
  const auto nested = c.child("nested");
  EXPECT_DOUBLE_EQ(nested.get_double("x"), 1.0);
  EXPECT_NO_THROW(nested.finish());
  EXPECT_NO_THROW(c.finish());
}

TEST(ConfigNode, ListsOfNamesAreCheckedAgainstTheAllowedOnes) {
  const auto c = ConfigNode::parse_string("ok: [car, sky]\nempty: []\nbad: [car, cat]\ntwice: [sky, sky]\n", "s.yaml");
  const std::vector<std::string> allowed{"car", "sky", "road"};
  EXPECT_EQ(c.get_choices("ok", allowed), (std::vector<std::string>{"car", "sky"}));
  EXPECT_TRUE(c.get_choices("empty", allowed).empty());
  EXPECT_THAT(error_of([&] { c.get_choices("bad", allowed); }),
              AllOf(HasSubstr("s.yaml"), HasSubstr("'bad'"), HasSubstr("cat"), HasSubstr("car sky road")));
  EXPECT_THAT(error_of([&] { c.get_choices("twice", allowed); }), HasSubstr("distinct"));
}

TEST(ConfigNode, FallbacksApplyOnlyWhenKeyIsAbsent) {
  const auto c = ConfigNode::parse_string("a: 3\n", "t.yaml");
  EXPECT_EQ(c.get_int("a", Range{}, 9), 3);
  EXPECT_EQ(c.get_int("b", Range{}, 9), 9);
  EXPECT_EQ(c.get_choice("mode", {"x", "y"}, "y"), "y");
  EXPECT_NO_THROW(c.finish());
}

TEST(ConfigNode, UnknownKeyNamesFileAndKey) {
  const auto c = ConfigNode::parse_string("fx: 500\nfxx: 1\n", "cam.yaml");
  c.get_double("fx");
  EXPECT_THAT(error_of([&] { c.finish(); }),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'fxx'"), HasSubstr("unknown key")));
}

// Found by fuzz_camera_yaml: yaml-cpp's own conversion error escaped.
TEST(ConfigNode, KeysThatAreNotNamesAreRejected) {
  for (const std::string yaml : {"[a]: 1\n", "~: 1\n", "{x: 1}: 2\n", "n: {[a]: 1}\n"}) {
    const auto c = ConfigNode::parse_string(yaml, "k.yaml");
    EXPECT_THAT(error_of([&] {
                  if (c.has("n")) c.child("n").finish();
                  c.finish();
                }),
                AllOf(HasSubstr("k.yaml"), HasSubstr("plain names")))
        << yaml;
  }
}

TEST(ConfigNode, ListsOfMappingsNameEachItemInMessages) {
  const auto c = ConfigNode::parse_string(
      "cars: [{width: 4}, {width: 5, colour: red}]\nnone: []\nscalar: 3\nmixed: [{width: 1}, 7]\n", "scene.yaml");
  const std::vector<ConfigNode> cars = c.get_mappings("cars");
  ASSERT_EQ(cars.size(), 2u);
  EXPECT_DOUBLE_EQ(cars[1].get_double("width"), 5.0);
  EXPECT_THAT(error_of([&] { cars[1].finish(); }), AllOf(HasSubstr("scene.yaml"), HasSubstr("'cars[1].colour'")));
  EXPECT_TRUE(c.get_mappings("none").empty());
  EXPECT_TRUE(c.get_mappings("absent").empty());
  EXPECT_THAT(error_of([&] { c.get_mappings("scalar"); }),
              AllOf(HasSubstr("'scalar'"), HasSubstr("a list of mappings")));
  EXPECT_THAT(error_of([&] { c.get_mappings("mixed"); }), AllOf(HasSubstr("'mixed[1]'"), HasSubstr("a mapping")));
  EXPECT_NO_THROW(c.finish());  // every key above was read
}

TEST(ConfigNode, AValueOfHundredsOfCharactersIsShownByItsStart) {
  const auto c = ConfigNode::parse_string("mode: " + std::string(500, 'x') + "\n", "long.yaml");
  const std::string message = error_of([&] { c.get_choice("mode", {"a", "b"}); });
  EXPECT_THAT(message, AllOf(HasSubstr("long.yaml"), HasSubstr("'mode'"), HasSubstr("xxx...' (500 characters)")));
  EXPECT_LT(message.size(), 200u);
}

TEST(ConfigNode, UnknownNestedKeyGivesFullPath) {
  const auto c = ConfigNode::parse_string("tracker:\n  coarse: {points: 50, radiuss: 3}\n", "slam.yaml");
  const auto coarse = c.child("tracker").child("coarse");
  coarse.get_int("points");
  EXPECT_THAT(error_of([&] { coarse.finish(); }), HasSubstr("'tracker.coarse.radiuss'"));
}

TEST(ConfigNode, MissingRequiredKey) {
  const auto c = ConfigNode::parse_string("fx: 500\n", "cam.yaml");
  EXPECT_THAT(error_of([&] { c.get_double("fy"); }),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'fy'"), HasSubstr("missing")));
}

TEST(ConfigNode, WrongType) {
  const auto c = ConfigNode::parse_string("fx: fast\nlist: 3\nflag: maybe\nn: 2.5\nm: {a: 1}\n", "cam.yaml");
  EXPECT_THAT(error_of([&] { c.get_double("fx"); }), AllOf(HasSubstr("'fx'"), HasSubstr("got 'fast'")));
  EXPECT_THAT(error_of([&] { c.get_doubles("list"); }), HasSubstr("expected a list of numbers"));
  EXPECT_THAT(error_of([&] { c.get_bool("flag"); }), HasSubstr("true or false"));
  EXPECT_THAT(error_of([&] { c.get_int("n"); }), AllOf(HasSubstr("an integer"), HasSubstr("'2.5'")));
  EXPECT_THAT(error_of([&] { c.get_string("m"); }), HasSubstr("got 'a mapping'"));
}

TEST(ConfigNode, OutOfRangeValue) {
  const auto c = ConfigNode::parse_string("fx: -3\nlevels: 9\nmodel: fisheye\nd: [1, 2]\n", "cam.yaml");
  EXPECT_THAT(error_of([&] { c.get_double("fx", Range::positive()); }),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'fx'"), HasSubstr("> 0"), HasSubstr("'-3'")));
  EXPECT_THAT(error_of([&] { c.get_int("levels", Range::closed(1, 4)); }), HasSubstr("[1, 4]"));
  EXPECT_THAT(error_of([&] {
                c.get_choice("model", {"pinhole", "atan"});
              }),
              AllOf(HasSubstr("'pinhole', 'atan'"), HasSubstr("'fisheye'")));
  EXPECT_THAT(error_of([&] { c.get_doubles("d", 5); }), HasSubstr("a list of 5 numbers"));
}

TEST(ConfigNode, NonFiniteIsOutOfRange) {
  const auto c = ConfigNode::parse_string("x: .nan\n", "t.yaml");
  EXPECT_THROW(c.get_double("x"), Error);
}

TEST(ConfigNode, FileErrors) {
  test::TempDir dir;
  EXPECT_THAT(error_of([&] { ConfigNode::load_file(dir / "absent.yaml"); }),
              AllOf(HasSubstr("absent.yaml"), HasSubstr("cannot open")));
  test::write_text(dir / "bad.yaml", "a: [1, 2\nb: 3\n");
  EXPECT_THAT(error_of([&] { ConfigNode::load_file(dir / "bad.yaml"); }),
              AllOf(HasSubstr("bad.yaml"), HasSubstr("not valid YAML"), HasSubstr("line")));
  test::write_text(dir / "list.yaml", "- 1\n- 2\n");
  EXPECT_THAT(error_of([&] { ConfigNode::load_file(dir / "list.yaml"); }), HasSubstr("mapping"));
  test::write_text(dir / "empty.yaml", "");
  EXPECT_THAT(error_of([&] { ConfigNode::load_file(dir / "empty.yaml"); }), HasSubstr("mapping"));
}

}  // namespace
}  // namespace facadeslam
