#include "semantics/point_descriptors/edd_descriptor.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "semantics/descriptor/canny_edges.hpp"
#include "semantics/descriptor/colour_conversion.hpp"
#include "semantics/descriptor/edge_distance.hpp"
#include "semantics/point_descriptors/edd_patch_moments.hpp"

namespace facadeslam::semantics {
namespace {

static_assert(EddDescriptor::kRadius == kEddRadius);
constexpr int kRadius = kEddRadius;
constexpr int kSide = kEddSide;
constexpr double kTwoPi = 6.283185307179586;

// The eight channels, interleaved per pixel (edd_patch_moments.hpp).
enum Channel { kR, kG, kB, kH, kS, kV, kSinH, kCosH, kChannels };
static_assert(kChannels == kEddChannels);

// Every channel is a function of one byte: R, G, B of the image's bytes as
// convert_colour maps them, H, S, V of the 8-bit HSV bytes as convert_colour
// scales them (byte_values), and sin / cos of 2 pi H. So the planes are
// filled from tables built through those same conversions: the same floats,
// without a float pass, a call to std::sin or a split per pixel.
struct ChannelTables {
  std::array<float, 256> rgb{}, sin_hue{}, cos_hue{};
};

const ChannelTables& channel_tables() {
  static const ChannelTables tables = [] {
    ChannelTables t;
    cv::Mat ramp(1, 256, CV_8UC3), red(1, 256, CV_32F);
    for (int k = 0; k < 256; ++k) ramp.at<cv::Vec3b>(0, k) = cv::Vec3b::all(static_cast<uchar>(k));
    convert_colour(ramp, ColourSpace::rgb, {&red, nullptr, nullptr});
    for (std::size_t k = 0; k < 256; ++k) {
      t.rgb[k] = red.at<float>(0, static_cast<int>(k));
      t.sin_hue[k] = static_cast<float>(std::sin(kTwoPi * byte_values()[k]));
      t.cos_hue[k] = static_cast<float>(std::cos(kTwoPi * byte_values()[k]));
    }
    return t;
  }();
  return tables;
}

// The interleaved channels of `bgr` (and its HSV bytes), padded by the
// patch radius with BORDER_REFLECT_101 (as often as a tiny image needs).
void fill_colour(const cv::Mat& bgr, const cv::Mat& hsv, std::vector<int>& source_x, cv::Mat& out) {
  const ChannelTables& t = channel_tables();
  const std::array<float, 256>& scaled = byte_values();
  out.create(bgr.rows + 2 * kRadius, bgr.cols + 2 * kRadius, CV_32FC(kChannels));
  source_x.resize(static_cast<std::size_t>(out.cols));
  for (int px = 0; px < out.cols; ++px)
    source_x[static_cast<std::size_t>(px)] = cv::borderInterpolate(px - kRadius, bgr.cols, cv::BORDER_REFLECT_101);
  for (int py = 0; py < out.rows; ++py) {
    const int y = cv::borderInterpolate(py - kRadius, bgr.rows, cv::BORDER_REFLECT_101);
    const uchar* colour_row = bgr.ptr<uchar>(y);
    const uchar* hsv_row = hsv.ptr<uchar>(y);
    float* o = out.ptr<float>(py);
    for (const int x : source_x) {
      const uchar* c = colour_row + 3 * x;
      const uchar* h = hsv_row + 3 * x;
      o[kR] = t.rgb[c[2]];
      o[kG] = t.rgb[c[1]];
      o[kB] = t.rgb[c[0]];
      o[kH] = scaled[h[0]];
      o[kS] = scaled[h[1]];
      o[kV] = scaled[h[2]];
      o[kSinH] = t.sin_hue[h[0]];
      o[kCosH] = t.cos_hue[h[0]];
      o += kChannels;
    }
  }
}

}  // namespace

struct EddDescriptor::Planes {
  cv::Mat colour;    // CV_32FC(8), padded by kRadius (BORDER_REFLECT_101)
  cv::Mat distance;  // CV_32F, padded the same way
  cv::Mat hsv, grey, edges, unpadded_distance;
  CannyBuffers canny;
  std::vector<int> source_x;

  void compute(const cv::Mat& bgr) {
    convert_colour_bytes(bgr, ColourSpace::hsv, hsv);
    fill_colour(bgr, hsv, source_x, colour);
    cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
    canny_edges(grey, 3, 50, 150, edges, canny);  // = cv::Canny(grey, edges, 50, 150, 3)
    unpadded_distance.create(bgr.size(), CV_32F);
    distance_to_edges(edges, unpadded_distance);
    cv::copyMakeBorder(unpadded_distance, distance, kRadius, kRadius, kRadius, kRadius, cv::BORDER_REFLECT_101);
  }
};

EddDescriptor::EddDescriptor() : planes_(std::make_unique<Planes>()) {}
EddDescriptor::~EddDescriptor() = default;

cv::Mat EddDescriptor::compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) {
  check_descriptor_input(name(), bgr, keypoints);
  cv::Mat rows(static_cast<int>(keypoints.size()), kWidth, CV_32F);
  if (keypoints.empty()) return rows;
  planes_->compute(bgr);
  const Planes& planes = *planes_;
  const auto colour_stride = static_cast<std::ptrdiff_t>(planes.colour.step1());
  EddPatchSums sums;
  for (std::size_t k = 0; k < keypoints.size(); ++k) {
    const cv::Point2f& p = keypoints[k];
    // Padded coordinates of the patch's top-left corner = image pixel - r + r.
    const int x = cvRound(p.x), y = cvRound(p.y);
    float* out = rows.ptr<float>(static_cast<int>(k));
    out[0] = p.x / static_cast<float>(bgr.cols);
    out[1] = p.y / static_cast<float>(bgr.rows);
    edd_patch_sums(planes.colour.ptr<float>(y) + kChannels * x, colour_stride, sums);
    int column = 2;
    for (const Channel c : {kR, kG, kB, kS, kSinH, kCosH}) out[column++] = static_cast<float>(sums.mean(c));
    for (const Channel c : {kR, kG, kB, kH, kS, kV}) {
      edd_weighted_moments(sums, c, out + column);
      column += 4;
    }
    for (int dy = 0; dy < kSide; ++dy, column += kSide)
      std::memcpy(out + column, planes.distance.ptr<float>(y + dy) + x, kSide * sizeof(float));
  }
  return rows;
}

}  // namespace facadeslam::semantics
