#include "semantics/point_descriptors/edd_descriptor.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "semantics/descriptor/colour_conversion.hpp"
#include "semantics/descriptor/edge_distance.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kSide = 2 * EddDescriptor::kRadius + 1;
constexpr int kArea = kSide * kSide;
constexpr double kTwoPi = 6.283185307179586;

enum EddPlane { kR, kG, kB, kH, kS, kV, kSinH, kCosH, kDistance, kEddPlaneCount };

// Padded float planes of the image, so every patch is a plain 9 x 9 block.
std::array<cv::Mat, kEddPlaneCount> padded_planes(const cv::Mat& bgr) {
  std::array<cv::Mat, kEddPlaneCount> planes;
  for (cv::Mat& p : planes) p.create(bgr.size(), CV_32F);
  convert_colour(bgr, ColourSpace::rgb, {&planes[kR], &planes[kG], &planes[kB]});
  convert_colour(bgr, ColourSpace::hsv, {&planes[kH], &planes[kS], &planes[kV]});
  for (int y = 0; y < bgr.rows; ++y) {
    const float* h = planes[kH].ptr<float>(y);
    float* s = planes[kSinH].ptr<float>(y);
    float* c = planes[kCosH].ptr<float>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      s[x] = static_cast<float>(std::sin(kTwoPi * h[x]));
      c[x] = static_cast<float>(std::cos(kTwoPi * h[x]));
    }
  }
  cv::Mat grey, edges;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Canny(grey, edges, 50, 150, 3);
  distance_to_edges(edges, planes[kDistance]);
  const int r = EddDescriptor::kRadius;
  for (cv::Mat& p : planes) {
    cv::Mat padded;
    cv::copyMakeBorder(p, padded, r, r, r, r, cv::BORDER_REFLECT_101);
    p = padded;
  }
  return planes;
}

// The 9 x 9 values of a plane around image pixel (x, y), row by row.
std::array<float, kArea> patch(const cv::Mat& padded, int x, int y) {
  std::array<float, kArea> values{};
  for (int dy = 0; dy < kSide; ++dy) {
    const float* row = padded.ptr<float>(y + dy) + x;
    std::copy(row, row + kSide, values.begin() + dy * kSide);
  }
  return values;
}

float mean(const std::array<float, kArea>& values) {
  double sum = 0;
  for (const float v : values) sum += v;
  return static_cast<float>(sum / kArea);
}

// mu30, mu21, mu12, mu03 of the patch weighted by I_norm (see the header).
void third_order_moments(const std::array<float, kArea>& values, float* out) {
  const float top = *std::max_element(values.begin(), values.end());
  double spread = 0;
  for (const float v : values) spread += top - v;
  spread /= kArea;
  std::array<double, kArea> w{};
  for (int i = 0; i < kArea; ++i) w[static_cast<std::size_t>(i)] = spread > 1e-9 ? (top - values[static_cast<std::size_t>(i)]) / spread : 1.0;
  double m00 = 0, m10 = 0, m01 = 0;
  for (int i = 0; i < kArea; ++i) {
    const double x = i % kSide, y = i / kSide, wi = w[static_cast<std::size_t>(i)];
    m00 += wi;
    m10 += x * wi;
    m01 += y * wi;
  }
  const double cx = m10 / m00, cy = m01 / m00;
  double mu30 = 0, mu21 = 0, mu12 = 0, mu03 = 0;
  for (int i = 0; i < kArea; ++i) {
    const double dx = i % kSide - cx, dy = i / kSide - cy, wi = w[static_cast<std::size_t>(i)];
    mu30 += dx * dx * dx * wi;
    mu21 += dx * dx * dy * wi;
    mu12 += dx * dy * dy * wi;
    mu03 += dy * dy * dy * wi;
  }
  out[0] = static_cast<float>(mu30);
  out[1] = static_cast<float>(mu21);
  out[2] = static_cast<float>(mu12);
  out[3] = static_cast<float>(mu03);
}

}  // namespace

cv::Mat EddDescriptor::compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) {
  check_descriptor_input(name(), bgr, keypoints);
  cv::Mat rows(static_cast<int>(keypoints.size()), kWidth, CV_32F);
  if (keypoints.empty()) return rows;
  const std::array<cv::Mat, kEddPlaneCount> planes = padded_planes(bgr);
  for (std::size_t k = 0; k < keypoints.size(); ++k) {
    const cv::Point2f& p = keypoints[k];
    // Padded coordinates of the patch's top-left corner = image pixel - r + r.
    const int x = cvRound(p.x), y = cvRound(p.y);
    float* out = rows.ptr<float>(static_cast<int>(k));
    out[0] = p.x / static_cast<float>(bgr.cols);
    out[1] = p.y / static_cast<float>(bgr.rows);
    int column = 2;
    for (const EddPlane plane : {kR, kG, kB, kS, kSinH, kCosH}) out[column++] = mean(patch(planes[plane], x, y));
    for (const EddPlane plane : {kR, kG, kB, kH, kS, kV}) {
      third_order_moments(patch(planes[plane], x, y), out + column);
      column += 4;
    }
    const std::array<float, kArea> distance = patch(planes[kDistance], x, y);
    std::copy(distance.begin(), distance.end(), out + column);
  }
  return rows;
}

}  // namespace facadeslam::semantics
