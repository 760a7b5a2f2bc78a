// EDD (edd_descriptor.hpp): known values on hand-made images, and every
// value against the definition written out pixel by pixel (the reference
// below: one patch at a time, weights per pixel, sums in double), which the
// descriptor computes from tables and moment sums instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "semantics/descriptor/colour_conversion.hpp"
#include "semantics/descriptor/edge_distance.hpp"
#include "semantics/point_descriptors/edd_descriptor.hpp"
#include "tests/semantics/semantics_test_util.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kSide = 9, kArea = kSide * kSide;

// The 9 x 9 values of `plane` around (x, y), reflected at the borders.
std::array<double, kArea> reference_patch(const cv::Mat& plane, int x, int y) {
  std::array<double, kArea> values{};
  for (int dy = 0; dy < kSide; ++dy)
    for (int dx = 0; dx < kSide; ++dx) {
      const int sx = cv::borderInterpolate(x + dx - 4, plane.cols, cv::BORDER_REFLECT_101);
      const int sy = cv::borderInterpolate(y + dy - 4, plane.rows, cv::BORDER_REFLECT_101);
      values[static_cast<std::size_t>(dy * kSide + dx)] = plane.at<float>(sy, sx);
    }
  return values;
}

double reference_mean(const std::array<double, kArea>& v) {
  double sum = 0;
  for (const double x : v) sum += x;
  return sum / kArea;
}

// mu30 mu21 mu12 mu03 weighted by I_norm = (max - I) / mean(max - I).
std::array<double, 4> reference_moments(const std::array<double, kArea>& v) {
  const double top = *std::max_element(v.begin(), v.end());
  double spread = 0;
  for (const double x : v) spread += top - x;
  spread /= kArea;
  std::array<double, kArea> w{};
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = spread > 1e-9 ? (top - v[i]) / spread : 1.0;
  double m00 = 0, m10 = 0, m01 = 0;
  for (int i = 0; i < kArea; ++i) {
    m00 += w[static_cast<std::size_t>(i)];
    m10 += (i % kSide) * w[static_cast<std::size_t>(i)];
    m01 += (i / kSide) * w[static_cast<std::size_t>(i)];
  }
  const double cx = m10 / m00, cy = m01 / m00;
  std::array<double, 4> mu{};
  for (int i = 0; i < kArea; ++i) {
    const double dx = i % kSide - cx, dy = i / kSide - cy, wi = w[static_cast<std::size_t>(i)];
    mu[0] += dx * dx * dx * wi;
    mu[1] += dx * dx * dy * wi;
    mu[2] += dx * dy * dy * wi;
    mu[3] += dy * dy * dy * wi;
  }
  return mu;
}

// EDD of one keypoint from the definition (edd_descriptor.hpp).
std::array<double, EddDescriptor::kWidth> reference_edd(const cv::Mat& bgr, cv::Point2f p) {
  cv::Mat r(bgr.size(), CV_32F), g(bgr.size(), CV_32F), b(bgr.size(), CV_32F), h(bgr.size(), CV_32F),
      s(bgr.size(), CV_32F), v(bgr.size(), CV_32F), sin_h(bgr.size(), CV_32F), cos_h(bgr.size(), CV_32F);
  convert_colour(bgr, ColourSpace::rgb, {&r, &g, &b});
  convert_colour(bgr, ColourSpace::hsv, {&h, &s, &v});
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      sin_h.at<float>(y, x) = static_cast<float>(std::sin(2 * CV_PI * h.at<float>(y, x)));
      cos_h.at<float>(y, x) = static_cast<float>(std::cos(2 * CV_PI * h.at<float>(y, x)));
    }
  cv::Mat grey, edges, distance(bgr.size(), CV_32F);
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Canny(grey, edges, 50, 150, 3);
  distance_to_edges(edges, distance);

  const int x = cvRound(p.x), y = cvRound(p.y);
  std::array<double, EddDescriptor::kWidth> out{};
  out[0] = p.x / static_cast<float>(bgr.cols);
  out[1] = p.y / static_cast<float>(bgr.rows);
  std::size_t column = 2;
  for (const cv::Mat* plane : {&r, &g, &b, &s, &sin_h, &cos_h})
    out[column++] = reference_mean(reference_patch(*plane, x, y));
  for (const cv::Mat* plane : {&r, &g, &b, &h, &s, &v})
    for (const double mu : reference_moments(reference_patch(*plane, x, y))) out[column++] = mu;
  for (const double d : reference_patch(distance, x, y)) out[column++] = d;
  return out;
}

// Column c of a computed row against the definition's value: position and
// distances are the same floats; means are sums of the same floats in
// another order, and moments come from raw sums instead of per-pixel
// weights (~1e-12 relative in double), before the float.
void expect_value(float got, double want, int column) {
  if (column < 2 || column >= 32) {
    EXPECT_EQ(got, static_cast<float>(want)) << "column " << column;
  } else {
    const double tolerance = column >= 8 ? 1e-6 * std::max(1.0, std::abs(want)) : 1e-6;
    EXPECT_NEAR(got, want, tolerance) << "column " << column;
  }
}

TEST(EddDescriptor, EveryValueMatchesTheDefinition) {
  const cv::Mat image = test_util::textured_image(cv::Size(90, 70), 3);
  std::vector<cv::Point2f> keypoints;
  for (int y = 0; y < image.rows; y += 7)
    for (int x = 0; x < image.cols; x += 8) keypoints.emplace_back(static_cast<float>(x), static_cast<float>(y));
  keypoints.emplace_back(static_cast<float>(image.cols - 1), static_cast<float>(image.rows - 1));
  EddDescriptor edd;
  const cv::Mat rows = edd.compute(image, keypoints);
  int moments_checked = 0;
  for (std::size_t k = 0; k < keypoints.size(); ++k) {
    const auto expected = reference_edd(image, keypoints[k]);
    const float* row = rows.ptr<float>(static_cast<int>(k));
    for (int c = 0; c < EddDescriptor::kWidth; ++c) {
      expect_value(row[c], expected[static_cast<std::size_t>(c)], c);
      if (c >= 8 && c < 32 && std::abs(expected[static_cast<std::size_t>(c)]) > 1e-3) ++moments_checked;
    }
    if (testing::Test::HasFailure()) FAIL() << "keypoint " << keypoints[k];
  }
  EXPECT_GT(moments_checked, 200) << "the image must give the moments something to measure";
}

TEST(EddDescriptor, KeptBuffersFollowTheImageSize) {
  // The planes are kept between calls: a second image of another size must
  // get the same rows as a fresh descriptor gives it.
  const cv::Mat large = test_util::textured_image(cv::Size(90, 70), 4);
  const cv::Mat small = test_util::textured_image(cv::Size(33, 21), 5);
  const std::vector<cv::Point2f> keypoints = {{0, 0}, {16, 10}, {32, 20}};
  EddDescriptor reused;
  reused.compute(large, {cv::Point2f(45, 35)});
  const cv::Mat again = reused.compute(small, keypoints);
  EXPECT_EQ(cv::norm(again, EddDescriptor().compute(small, keypoints), cv::NORM_INF), 0.0);
}

TEST(EddDescriptor, ImagesSmallerThanThePatch) {
  // Reflection repeats the image as often as the 9 x 9 patch needs.
  for (const cv::Size size : {cv::Size(1, 1), cv::Size(3, 2), cv::Size(2, 7), cv::Size(6, 5)}) {
    cv::Mat image = test_util::textured_image(size, 6);
    image.colRange(0, (size.width + 1) / 2).setTo(cv::Scalar(20, 30, 40));  // an edge where the image is wide enough
    image.colRange((size.width + 1) / 2, size.width).setTo(cv::Scalar(220, 180, 90));
    EddDescriptor edd;
    const cv::Mat row = edd.compute(image, {cv::Point2f(0, 0)});
    ASSERT_EQ(row.cols, EddDescriptor::kWidth);
    EXPECT_TRUE(cv::checkRange(row)) << size;
    const auto expected = reference_edd(image, cv::Point2f(0, 0));
    for (int c = 0; c < EddDescriptor::kWidth; ++c)
      expect_value(row.at<float>(0, c), expected[static_cast<std::size_t>(c)], c);
    if (testing::Test::HasFailure()) FAIL() << size;
  }
}

TEST(EddDescriptor, FlatImageHasMeansPositionAndNoMoments) {
  cv::Mat image(40, 50, CV_8UC3, cv::Scalar(51, 102, 204));  // BGR
  EddDescriptor edd;
  const cv::Mat row = edd.compute(image, {cv::Point2f(25, 10)});
  ASSERT_EQ(row.cols, 113);
  EXPECT_FLOAT_EQ(row.at<float>(0, 0), 25.f / 50.f);
  EXPECT_FLOAT_EQ(row.at<float>(0, 1), 10.f / 40.f);
  EXPECT_NEAR(row.at<float>(0, 2), 204.f / 255.f, 1e-5);  // R
  EXPECT_NEAR(row.at<float>(0, 3), 102.f / 255.f, 1e-5);  // G
  EXPECT_NEAR(row.at<float>(0, 4), 51.f / 255.f, 1e-5);   // B
  EXPECT_NEAR(row.at<float>(0, 5), 0.75f, 0.01);          // S = (204 - 51) / 204
  // Hue of (204, 102, 51) is 20 degrees.
  EXPECT_NEAR(row.at<float>(0, 6), std::sin(20.0 * CV_PI / 180.0), 0.02);
  EXPECT_NEAR(row.at<float>(0, 7), std::cos(20.0 * CV_PI / 180.0), 0.02);
  for (int c = 8; c < 32; ++c) EXPECT_NEAR(row.at<float>(0, c), 0.f, 1e-3) << "moment column " << c;
  // No edge anywhere: every distance is the image diagonal.
  for (int c = 32; c < 113; ++c) EXPECT_NEAR(row.at<float>(0, c), std::hypot(50.0, 40.0), 1.0);
}

TEST(EddDescriptor, DistancesGrowAwayFromAnEdge) {
  // A vertical step edge at x = 20.
  cv::Mat image(40, 40, CV_8UC3, cv::Scalar::all(30));
  image.colRange(20, 40).setTo(cv::Scalar::all(220));
  EddDescriptor edd;
  const cv::Mat row = edd.compute(image, {cv::Point2f(20, 20)});
  // Distance columns are the 9 x 9 patch row by row: the centre row.
  const float* centre_row = row.ptr<float>(0) + 32 + 4 * 9;
  EXPECT_LE(std::min(centre_row[3], centre_row[4]), 0.5f) << "an edge pixel at the centre";
  EXPECT_GT(centre_row[0], centre_row[3]);
  EXPECT_GT(centre_row[8], centre_row[5]);
}

TEST(EddDescriptor, MomentsSeeAnAsymmetricPatch) {
  // A dark column beside two grey ones in a bright patch: I_norm weighs only
  // the darker pixels (weights 2 : 1 : 1 at x = 0, 1, 2 of the patch), a
  // skewed distribution, so mu30 is clearly non-zero (22.8 by hand) while
  // mu03 stays 0 (every row is the same).
  cv::Mat image(30, 30, CV_8UC3, cv::Scalar::all(200));
  image(cv::Rect(11, 0, 1, 30)).setTo(cv::Scalar::all(20));
  image(cv::Rect(12, 0, 2, 30)).setTo(cv::Scalar::all(110));
  EddDescriptor edd;
  const cv::Mat row = edd.compute(image, {cv::Point2f(15, 15)});
  const float mu30_r = row.at<float>(0, 8), mu03_r = row.at<float>(0, 11);
  EXPECT_NEAR(mu30_r, 22.78f, 0.05f);
  EXPECT_NEAR(mu03_r, 0.f, 1e-3);
}

}  // namespace
}  // namespace facadeslam::semantics
