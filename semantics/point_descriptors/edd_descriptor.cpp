#include "semantics/point_descriptors/edd_descriptor.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "semantics/descriptor/canny_edges.hpp"
#include "semantics/descriptor/colour_conversion.hpp"
#include "semantics/descriptor/edge_distance.hpp"
#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kRadius = EddDescriptor::kRadius;
constexpr int kSide = 2 * kRadius + 1;
constexpr double kTwoPi = 6.283185307179586;

// The eight colour channels, interleaved per pixel so that one vector load
// brings all of a pixel's values: every patch sum below runs on the eight
// channels at once.
enum Channel { kR, kG, kB, kH, kS, kV, kSinH, kCosH, kChannels };
static_assert(kChannels == kLanes);

// Every channel is a function of one byte: R, G, B of the image's bytes as
// convert_colour maps them, H, S, V of OpenCV's 8-bit HSV (256 hue levels)
// divided by 255 as convert_colour does, and sin / cos of 2 pi H. So the
// planes are filled from tables built through those same conversions: the
// same floats, without a float pass, a call to std::sin or a split per pixel.
struct ChannelTables {
  std::array<float, 256> rgb{}, hsv{}, sin_hue{}, cos_hue{};
};

const ChannelTables& channel_tables() {
  static const ChannelTables tables = [] {
    ChannelTables t;
    cv::Mat ramp(1, 256, CV_8UC3), red(1, 256, CV_32F), hue(1, 256, CV_32F), s(1, 256, CV_32F), v(1, 256, CV_32F);
    for (int k = 0; k < 256; ++k) ramp.at<cv::Vec3b>(0, k) = cv::Vec3b::all(static_cast<uchar>(k));
    convert_colour(ramp, ColourSpace::rgb, {&red, nullptr, nullptr});
    cv::Mat bytes;
    cv::extractChannel(ramp, bytes, 0);
    bytes.convertTo(hue, CV_32F, 1.0 / 255.0);  // convert_colour's scaling of OpenCV's HSV bytes
    for (std::size_t k = 0; k < 256; ++k) {
      t.rgb[k] = red.at<float>(0, static_cast<int>(k));
      t.hsv[k] = hue.at<float>(0, static_cast<int>(k));
      t.sin_hue[k] = static_cast<float>(std::sin(kTwoPi * t.hsv[k]));
      t.cos_hue[k] = static_cast<float>(std::cos(kTwoPi * t.hsv[k]));
    }
    return t;
  }();
  return tables;
}

}  // namespace

struct EddDescriptor::Planes {
  cv::Mat colour;    // CV_32FC(8), padded by kRadius (BORDER_REFLECT_101)
  cv::Mat distance;  // CV_32F, padded the same way
  cv::Mat hsv, grey, edges, unpadded_distance;
  CannyBuffers canny;
  std::vector<int> source_x;

  void compute(const cv::Mat& bgr);
};

namespace {

void fill_colour(const cv::Mat& bgr, const cv::Mat& hsv, std::vector<int>& source_x, cv::Mat& out) {
  const ChannelTables& t = channel_tables();
  out.create(bgr.rows + 2 * kRadius, bgr.cols + 2 * kRadius, CV_32FC(kChannels));
  source_x.resize(static_cast<std::size_t>(out.cols));
  for (int px = 0; px < out.cols; ++px) source_x[static_cast<std::size_t>(px)] = cv::borderInterpolate(px - kRadius, bgr.cols, cv::BORDER_REFLECT_101);
  for (int py = 0; py < out.rows; ++py) {
    const int y = cv::borderInterpolate(py - kRadius, bgr.rows, cv::BORDER_REFLECT_101);
    const uchar* c = bgr.ptr<uchar>(y);
    const uchar* h = hsv.ptr<uchar>(y);
    float* o = out.ptr<float>(py);
    for (const int x : source_x) {
      const uchar* bgr_px = c + 3 * x;
      const uchar* hsv_px = h + 3 * x;
      o[kR] = t.rgb[bgr_px[2]];
      o[kG] = t.rgb[bgr_px[1]];
      o[kB] = t.rgb[bgr_px[0]];
      o[kH] = t.hsv[hsv_px[0]];
      o[kS] = t.hsv[hsv_px[1]];
      o[kV] = t.hsv[hsv_px[2]];
      o[kSinH] = t.sin_hue[hsv_px[0]];
      o[kCosH] = t.cos_hue[hsv_px[0]];
      o += kChannels;
    }
  }
}

}  // namespace

void EddDescriptor::Planes::compute(const cv::Mat& bgr) {
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV_FULL);
  fill_colour(bgr, hsv, source_x, colour);
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  canny_edges(grey, 3, 50, 150, edges, canny);  // = cv::Canny(grey, edges, 50, 150, 3)
  unpadded_distance.create(bgr.size(), CV_32F);
  distance_to_edges(edges, unpadded_distance);
  cv::copyMakeBorder(unpadded_distance, distance, kRadius, kRadius, kRadius, kRadius, cv::BORDER_REFLECT_101);
}

namespace {

// Per channel, over one 9 x 9 patch: the largest value and the raw moments
// S_pq = sum x^p y^q v for p + q <= 3, with x, y measured from the patch
// centre (-4..4), in double. Index of S_pq in `sums`: kMoment[p][q].
constexpr int kMoment[4][4] = {{0, 1, 2, 3}, {4, 5, 6, -1}, {7, 8, -1, -1}, {9, -1, -1, -1}};
struct PatchSums {
  double sums[10][kChannels];
  float top[kChannels];
};

FACADESLAM_KERNEL
void patch_sums(const float* top_left, std::ptrdiff_t row_stride, PatchSums& out) {
  using Halves = std::array<DoubleLanes, 2>;  // channels 0-3 and 4-7
  FloatLanes top;
  load_lanes(top, top_left);
  Halves s[10] = {};
  for (int dy = 0; dy < kSide; ++dy) {
    const float* row = top_left + dy * row_stride;
    Halves by_x[4] = {};  // sum over the row of x^p v, p = 0..3
    for (int dx = 0; dx < kSide; ++dx) {
      FloatLanes v;
      load_lanes(v, row + kChannels * dx);
      top = v > top ? v : top;
      const Halves d = {__builtin_convertvector(__builtin_shufflevector(v, v, 0, 1, 2, 3), DoubleLanes),
                        __builtin_convertvector(__builtin_shufflevector(v, v, 4, 5, 6, 7), DoubleLanes)};
      const double x = dx - kRadius;
      for (int h = 0; h < 2; ++h) {
        by_x[0][h] += d[h];
        by_x[1][h] += x * d[h];
        by_x[2][h] += (x * x) * d[h];
        by_x[3][h] += (x * x * x) * d[h];
      }
    }
    const double y = dy - kRadius;
    for (int h = 0; h < 2; ++h) {
      for (int p = 0; p < 4; ++p) s[kMoment[p][0]][h] += by_x[p][h];
      for (int p = 0; p < 3; ++p) s[kMoment[p][1]][h] += y * by_x[p][h];
      for (int p = 0; p < 2; ++p) s[kMoment[p][2]][h] += (y * y) * by_x[p][h];
      s[kMoment[0][3]][h] += (y * y * y) * by_x[0][h];
    }
  }
  for (int m = 0; m < 10; ++m)
    for (int h = 0; h < 2; ++h) std::memcpy(&out.sums[m][4 * h], &s[m][h], sizeof s[m][h]);
  std::memcpy(out.top, &top, sizeof out.top);
}

// mu30, mu21, mu12, mu03 of channel c's patch weighted by I_norm =
// (top - v) / mean(top - v) (see the header): the weights' raw moments are
// (top G_pq - S_pq) / spread with G_pq the patch grid's own moments
// (G00 = 81, G20 = G02 = 540, the others 0 about the centre), then the
// usual shift to the weights' centroid.
void third_order_moments(const PatchSums& p, int c, float* out) {
  const auto S = [&](int i, int j) { return p.sums[kMoment[i][j]][c]; };
  constexpr double kArea = kSide * kSide;
  constexpr double kSecond = kSide * 60.0;  // sum over the patch of x^2: 9 * (2 * (1 + 4 + 9 + 16))
  const double top = p.top[c];
  const double spread = top - S(0, 0) / kArea;
  double W[4][4] = {};
  if (spread > 1e-9) {
    const auto w = [&](int i, int j, double grid) { W[i][j] = (top * grid - S(i, j)) / spread; };
    w(0, 0, kArea);
    w(1, 0, 0), w(0, 1, 0), w(1, 1, 0);
    w(2, 0, kSecond), w(0, 2, kSecond);
    w(3, 0, 0), w(2, 1, 0), w(1, 2, 0), w(0, 3, 0);
  } else {  // a flat patch: uniform weights, whose odd moments vanish
    W[0][0] = kArea;
    W[2][0] = W[0][2] = kSecond;
  }
  const double cx = W[1][0] / W[0][0], cy = W[0][1] / W[0][0];
  const double mu30 = W[3][0] - 3 * cx * W[2][0] + 3 * cx * cx * W[1][0] - cx * cx * cx * W[0][0];
  const double mu03 = W[0][3] - 3 * cy * W[0][2] + 3 * cy * cy * W[0][1] - cy * cy * cy * W[0][0];
  const double mu21 = W[2][1] - 2 * cx * W[1][1] - cy * W[2][0] + cx * cx * W[0][1] + 2 * cx * cy * W[1][0] -
                      cx * cx * cy * W[0][0];
  const double mu12 = W[1][2] - 2 * cy * W[1][1] - cx * W[0][2] + cy * cy * W[1][0] + 2 * cx * cy * W[0][1] -
                      cy * cy * cx * W[0][0];
  out[0] = static_cast<float>(mu30);
  out[1] = static_cast<float>(mu21);
  out[2] = static_cast<float>(mu12);
  out[3] = static_cast<float>(mu03);
}

}  // namespace

EddDescriptor::EddDescriptor() : planes_(std::make_unique<Planes>()) {}
EddDescriptor::~EddDescriptor() = default;

cv::Mat EddDescriptor::compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) {
  check_descriptor_input(name(), bgr, keypoints);
  cv::Mat rows(static_cast<int>(keypoints.size()), kWidth, CV_32F);
  if (keypoints.empty()) return rows;
  planes_->compute(bgr);
  const Planes& planes = *planes_;
  const auto colour_stride = static_cast<std::ptrdiff_t>(planes.colour.step1());
  PatchSums sums;
  for (std::size_t k = 0; k < keypoints.size(); ++k) {
    const cv::Point2f& p = keypoints[k];
    // Padded coordinates of the patch's top-left corner = image pixel - r + r.
    const int x = cvRound(p.x), y = cvRound(p.y);
    float* out = rows.ptr<float>(static_cast<int>(k));
    out[0] = p.x / static_cast<float>(bgr.cols);
    out[1] = p.y / static_cast<float>(bgr.rows);
    patch_sums(planes.colour.ptr<float>(y) + kChannels * x, colour_stride, sums);
    int column = 2;
    for (const Channel c : {kR, kG, kB, kS, kSinH, kCosH})
      out[column++] = static_cast<float>(sums.sums[kMoment[0][0]][c] / (kSide * kSide));
    for (const Channel c : {kR, kG, kB, kH, kS, kV}) {
      third_order_moments(sums, c, out + column);
      column += 4;
    }
    for (int dy = 0; dy < kSide; ++dy, column += kSide)
      std::memcpy(out + column, planes.distance.ptr<float>(y + dy) + x, kSide * sizeof(float));
  }
  return rows;
}

}  // namespace facadeslam::semantics
