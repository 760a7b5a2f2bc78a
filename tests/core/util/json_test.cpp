#include "core/util/json.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

TEST(Json, ObjectKeepsInsertionOrderAndEscapes) {
  Json j = Json::object();
  j["b"] = 1;
  j["a"] = "x\"y\n";
  j["c"] = true;
  EXPECT_EQ(j.dump(0), R"({"b":1,"a":"x\"y\n","c":true})");
}

TEST(Json, NonFiniteNumbersBecomeNull) {
  Json j = Json::object();
  j["nan"] = std::numeric_limits<double>::quiet_NaN();
  j["inf"] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(j.dump(0), R"({"nan":null,"inf":null})");
}

TEST(Json, NestedArraysAndNumbers) {
  Json j = Json::object();
  j["v"] = Json::Array{1.5, 2, -3};
  Json rows = Json::array();
  rows.push_back(Json::Array{1, 2});
  rows.push_back(Json::Array{3, 4});
  j["m"] = rows;
  EXPECT_EQ(j.dump(0), R"({"v":[1.5, 2, -3],"m":[[1, 2],[3, 4]]})");
  EXPECT_DOUBLE_EQ(j.find("v") ? 1.0 : 0.0, 1.0);
  EXPECT_EQ(j.find("missing"), nullptr);
}

TEST(Json, ReassigningAKeyReplacesIt) {
  Json j;
  j["k"] = 1;
  j["k"] = 2.25;
  EXPECT_DOUBLE_EQ(j.find("k")->as_double(), 2.25);
  EXPECT_EQ(j.dump(0), R"({"k":2.25})");
}

}  // namespace
}  // namespace facadeslam
