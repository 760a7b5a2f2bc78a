#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "sequences/synth/label_classes.hpp"

namespace facadeslam::synth {
namespace {

TEST(LabelClasses, TheNineLabelMeFacadeClassesInOrder) {
  const auto& classes = facade_classes();
  ASSERT_EQ(classes.size(), 9u);
  EXPECT_EQ(classes[1].name, "building");
  EXPECT_EQ(classes[1].rgb, cv::Vec3b(128, 0, 0));
  EXPECT_EQ(classes[5].name, "road");
  EXPECT_EQ(classes[5].rgb, cv::Vec3b(128, 64, 0));
  EXPECT_EQ(classes[6].rgb, cv::Vec3b(0, 128, 128));  // sky
  EXPECT_EQ(class_by_name("window"), FacadeClass::window);
  EXPECT_FALSE(class_by_name("roof"));
}

TEST(LabelClasses, ColoursRoundTripThroughIds) {
  cv::Mat ids(3, 3, CV_8UC1);
  for (int i = 0; i < 9; ++i) ids.at<std::uint8_t>(i / 3, i % 3) = static_cast<std::uint8_t>(i);
  const cv::Mat bgr = colours_from_label_ids(ids);
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 1), cv::Vec3b(0, 0, 128));  // building (128,0,0) as BGR
  const cv::Mat back = label_ids_from_colours(bgr, "x.png");
  EXPECT_EQ(cv::countNonZero(back != ids), 0);
}

TEST(LabelClasses, AnUnknownColourNamesTheFileAndPixel) {
  cv::Mat bgr(4, 4, CV_8UC3, cv::Scalar(0, 0, 128));
  bgr.at<cv::Vec3b>(2, 3) = {0, 64, 64};  // 0/64/128 values, but no class
  EXPECT_THAT([&] { label_ids_from_colours(bgr, "maps/a.png"); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("maps/a.png: pixel (3, 2) has colour (64, 64, 0)")));
}

TEST(LabelClasses, TableListsIdNameAndColour) {
  const std::string table = class_table_text();
  EXPECT_THAT(table, ::testing::HasSubstr("\n0 various 0 0 0\n"));
  EXPECT_THAT(table, ::testing::HasSubstr("\n8 window 0 0 128\n"));
}

}  // namespace
}  // namespace facadeslam::synth
