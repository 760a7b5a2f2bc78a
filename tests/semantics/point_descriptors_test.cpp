// Every descriptor behind the PointDescriptor interface: one row per
// keypoint with its documented width, including keypoints at the image
// corners, and known values for the opponent channels (EDD's values:
// edd_descriptor_test.cpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "semantics/point_descriptors/keypoint_rows.hpp"
#include "semantics/point_descriptors/orb_descriptor.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"
#include "semantics/point_descriptors/sift_descriptor.hpp"
#include "tests/semantics/semantics_test_util.hpp"

namespace facadeslam::semantics {
namespace {

using ::testing::HasSubstr;

// A grid plus the four corners and edge midpoints: ORB and SIFT would drop
// or mishandle these without the documented border policy.
std::vector<cv::Point2f> keypoints_for(cv::Size size) {
  std::vector<cv::Point2f> points;
  for (int y = 5; y < size.height; y += 11)
    for (int x = 3; x < size.width; x += 13) points.emplace_back(static_cast<float>(x), static_cast<float>(y));
  const float w = static_cast<float>(size.width - 1), h = static_cast<float>(size.height - 1);
  for (const cv::Point2f p : {cv::Point2f(0, 0), cv::Point2f(w, 0), cv::Point2f(0, h), cv::Point2f(w, h),
                              cv::Point2f(w / 2, 0), cv::Point2f(0, h / 2)})
    points.push_back(p);
  return points;
}

struct Expected {
  const char* name;
  int width;
};

class EveryDescriptor : public ::testing::TestWithParam<Expected> {};

TEST_P(EveryDescriptor, OneRowPerKeypointWithItsWidth) {
  const Expected e = GetParam();
  const auto descriptor = make_point_descriptor(e.name, Genome::thesis_best());
  EXPECT_EQ(descriptor->name(), e.name);
  EXPECT_EQ(descriptor->width(), e.width);
  const cv::Mat image = test_util::textured_image({97, 71}, 3);
  const std::vector<cv::Point2f> keypoints = keypoints_for(image.size());
  const cv::Mat rows = descriptor->compute(image, keypoints);
  EXPECT_EQ(rows.type(), CV_32F);
  EXPECT_EQ(rows.rows, static_cast<int>(keypoints.size()));
  EXPECT_EQ(rows.cols, e.width);
  EXPECT_TRUE(cv::checkRange(rows));
  // Every keypoint got a real description (no zero row from a dropped keypoint).
  for (int r = 0; r < rows.rows; ++r) EXPECT_GT(cv::norm(rows.row(r), cv::NORM_L1), 0.0) << "row " << r;
  // The same again (buffers reused) gives the same rows.
  EXPECT_EQ(cv::norm(rows, descriptor->compute(image, keypoints), cv::NORM_INF), 0.0);
  // No keypoints: an empty matrix of the right width.
  const cv::Mat none = descriptor->compute(image, {});
  EXPECT_EQ(none.rows, 0);
  EXPECT_EQ(none.cols, e.width);
}

TEST_P(EveryDescriptor, RowsFollowTheKeypointOrder) {
  const auto descriptor = make_point_descriptor(GetParam().name, Genome::thesis_best());
  const cv::Mat image = test_util::textured_image({80, 64}, 9);
  std::vector<cv::Point2f> keypoints = keypoints_for(image.size());
  const cv::Mat forward = descriptor->compute(image, keypoints);
  std::reverse(keypoints.begin(), keypoints.end());
  const cv::Mat backward = descriptor->compute(image, keypoints);
  for (int r = 0; r < forward.rows; ++r)
    EXPECT_EQ(cv::norm(forward.row(r), backward.row(forward.rows - 1 - r), cv::NORM_INF), 0.0) << "row " << r;
}

TEST_P(EveryDescriptor, RejectsBadInput) {
  const auto descriptor = make_point_descriptor(GetParam().name, Genome::thesis_best());
  const cv::Mat image = test_util::textured_image({40, 30}, 2);
  EXPECT_THAT([&] { descriptor->compute(image, {cv::Point2f(40.5f, 3.f)}); },
              ::testing::ThrowsMessage<Error>(HasSubstr("keypoint 0")));
  EXPECT_THROW(descriptor->compute(image, {cv::Point2f(std::nanf(""), 3.f)}), Error);
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  EXPECT_THROW(descriptor->compute(grey, {cv::Point2f(3.f, 3.f)}), Error);
  EXPECT_THROW(descriptor->compute(cv::Mat(), {}), Error);
}

INSTANTIATE_TEST_SUITE_P(PointDescriptors, EveryDescriptor,
                         ::testing::Values(Expected{"modular", 93}, Expected{"sift", 128},
                                           Expected{"opponent-sift", 384}, Expected{"orb", 256}, Expected{"edd", 113}),
                         [](const auto& info) {
                           std::string name = info.param.name;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(PointDescriptorFactory, UnknownNameListsTheKnownOnes) {
  EXPECT_THAT([] { make_point_descriptor("surf", Genome::thesis_best()); },
              ::testing::ThrowsMessage<Error>(HasSubstr("modular, sift, opponent-sift, orb, edd")));
  EXPECT_THROW(make_point_descriptor("modular", Genome()), Error) << "a genome without active values";
}

TEST(SiftBaseline, CoversTheGenomePatch) {
  const SiftDescriptor sift(SiftDescriptor::Channels::grey, 21);
  EXPECT_FLOAT_EQ(sift.keypoint_size(), 3.5f);
}

TEST(SiftBaseline, MatchesOpenCvOnTheSameKeypoints) {
  const cv::Mat image = test_util::textured_image({90, 70}, 4);
  const std::vector<cv::Point2f> points{{20, 20}, {45, 33}, {70, 50}};
  SiftDescriptor ours(SiftDescriptor::Channels::grey, 21);
  std::vector<cv::KeyPoint> kps;
  for (const auto& p : points) kps.emplace_back(p, 3.5f, 0.f);
  cv::Mat grey, reference;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  cv::SIFT::create()->compute(grey, kps, reference);
  EXPECT_EQ(cv::norm(ours.compute(image, points), reference, cv::NORM_INF), 0.0);
}

TEST(OpponentSift, ChannelsFollowTheFormulas) {
  cv::Mat image(1, 3, CV_8UC3);
  image.at<cv::Vec3b>(0, 0) = cv::Vec3b(0, 0, 255);  // pure red (BGR)
  image.at<cv::Vec3b>(0, 1) = cv::Vec3b(255, 0, 0);  // pure blue
  image.at<cv::Vec3b>(0, 2) = cv::Vec3b(30, 60, 90);
  const auto o = opponent_channels(image);
  ASSERT_EQ(o.size(), 3u);
  EXPECT_EQ(o[0].at<uchar>(0, 0), 255);  // (255 - 0 + 255) / 2
  EXPECT_EQ(o[1].at<uchar>(0, 0), 191);  // (255 + 0 - 0 + 510) / 4 = 191.25
  EXPECT_EQ(o[2].at<uchar>(0, 0), 85);   // 255 / 3
  EXPECT_EQ(o[0].at<uchar>(0, 1), 128);  // (0 - 0 + 255) / 2 = 127.5
  EXPECT_EQ(o[1].at<uchar>(0, 1), 0);    // (0 + 0 - 510 + 510) / 4
  EXPECT_EQ(o[0].at<uchar>(0, 2), 143);  // (90 - 60 + 255) / 2 = 142.5
  EXPECT_EQ(o[1].at<uchar>(0, 2), 150);  // (90 + 60 - 60 + 510) / 4
  EXPECT_EQ(o[2].at<uchar>(0, 2), 60);
}

TEST(OrbBaseline, UnpacksTheBitsOfOpenCvsDescriptor) {
  const cv::Mat image = test_util::textured_image({120, 100}, 6);
  const std::vector<cv::Point2f> points{{50, 50}, {60, 45}};
  OrbDescriptor ours;
  const cv::Mat rows = ours.compute(image, points);
  double ones = 0;
  for (int c = 0; c < rows.cols; ++c) {
    const float v = rows.at<float>(0, c);
    EXPECT_TRUE(v == 0.f || v == 1.f);
    ones += v;
  }
  EXPECT_GT(ones, 30);
  EXPECT_LT(ones, 226);
}

TEST(KeypointRows, DroppedKeypointsBecomeZeroRows) {
  std::vector<cv::KeyPoint> survivors = upright_keypoints({{1, 1}, {2, 2}, {3, 3}}, 5.f);
  EXPECT_EQ(survivors[2].class_id, 2);
  EXPECT_EQ(survivors[1].angle, 0.f);
  survivors.erase(survivors.begin() + 1);
  const cv::Mat computed = (cv::Mat_<uchar>(2, 2) << 1, 2, 3, 4);
  const cv::Mat rows = rows_by_index(survivors, computed, 3, 2);
  EXPECT_EQ(rows.type(), CV_32F);
  EXPECT_EQ(rows.at<float>(0, 1), 2.f);
  EXPECT_EQ(cv::norm(rows.row(1), cv::NORM_L1), 0.0);
  EXPECT_EQ(rows.at<float>(2, 0), 3.f);
}

}  // namespace
}  // namespace facadeslam::semantics
