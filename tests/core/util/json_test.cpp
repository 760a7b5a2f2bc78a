#include "core/util/json.hpp"

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

TEST(Json, ReportsKeepInsertionOrder) {
  Json j = Json::object();
  j["b"] = 1;
  j["a"] = "x\"y\n";
  j["c"] = true;
  EXPECT_EQ(j.dump(), R"({"b":1,"a":"x\"y\n","c":true})");
}

TEST(Json, TextIsIndentedAndEndsWithANewline) {
  Json j = Json::object();
  j["v"] = Json::array({1.5, 2, -3});
  const std::string text = json_text(j);
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text.find("\n  \"v\": ["), std::string::npos) << text;
  EXPECT_EQ(Json::parse(text), j);
}

TEST(Json, NonFiniteNumbersBecomeNull) {
  Json j = Json::object();
  j["nan"] = std::numeric_limits<double>::quiet_NaN();
  j["inf"] = std::numeric_limits<double>::infinity();
  const Json back = Json::parse(json_text(j));
  EXPECT_TRUE(back["nan"].is_null());
  EXPECT_TRUE(back["inf"].is_null());
}

TEST(Json, InvalidUtf8IsReplacedNotThrown) {
  Json j = Json::object();
  j["file"] = std::string("caf\xe9.png");  // Latin-1, not UTF-8
  std::string text;
  ASSERT_NO_THROW(text = json_text(j));
  EXPECT_EQ(Json::parse(text)["file"].get<std::string>(), "caf\xef\xbf\xbd.png");
}

TEST(Json, WriteJsonReplacesTheFileAtomically) {
  const auto dir = std::filesystem::temp_directory_path() / "facadeslam_json_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto path = dir / "report.json";
  Json j = Json::object();
  j["k"] = 2.25;
  write_json(path, j);
  j["k"] = 3;
  write_json(path, j);
  std::ifstream in(path);
  std::stringstream content;
  content << in.rdbuf();
  EXPECT_EQ(Json::parse(content.str())["k"].get<int>(), 3);
  // Only the report: no temporary file left beside it.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace facadeslam
