#include "semantics/descriptor/colour_conversion.hpp"

#include <vector>

#include <opencv2/imgproc.hpp>

#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

// Output channel = w[0] B + w[1] G + w[2] R + w[3] for 8-bit B, G, R.
using LinearRow = std::array<float, 4>;

bool is_linear(ColourSpace space) {
  return space == ColourSpace::rgb || space == ColourSpace::xyz || space == ColourSpace::ycrcb ||
         space == ColourSpace::opponent;
}

std::array<LinearRow, 3> linear_map(ColourSpace space) {
  constexpr float s = 1.0f / 255.0f;
  switch (space) {
    case ColourSpace::rgb: return {{{0, 0, s, 0}, {0, s, 0, 0}, {s, 0, 0, 0}}};
    case ColourSpace::xyz:
      return {{{0.180423f * s, 0.357580f * s, 0.412453f * s, 0},
               {0.072169f * s, 0.715160f * s, 0.212671f * s, 0},
               {0.950227f * s, 0.119193f * s, 0.019334f * s, 0}}};
    case ColourSpace::ycrcb: {
      // Y = .299R + .587G + .114B; Cr = .713 (R - Y) + .5; Cb = .564 (B - Y) + .5
      const float yr = 0.299f, yg = 0.587f, yb = 0.114f;
      return {{{yb * s, yg * s, yr * s, 0},
               {-0.713f * yb * s, -0.713f * yg * s, 0.713f * (1 - yr) * s, 0.5f},
               {0.564f * (1 - yb) * s, -0.564f * yg * s, -0.564f * yr * s, 0.5f}}};
    }
    case ColourSpace::opponent:
      return {{{0, -0.5f * s, 0.5f * s, 0.5f}, {-0.5f * s, 0.25f * s, 0.25f * s, 0.5f}, {s / 3, s / 3, s / 3, 0}}};
    default: break;
  }
  CV_Error(cv::Error::StsBadArg, "not a linear colour space");
}

int opencv_code(ColourSpace space) {
  switch (space) {
    case ColourSpace::lab: return cv::COLOR_BGR2Lab;
    case ColourSpace::luv: return cv::COLOR_BGR2Luv;
    case ColourSpace::hsv: return cv::COLOR_BGR2HSV_FULL;
    case ColourSpace::hls: return cv::COLOR_BGR2HLS_FULL;
    default: break;
  }
  CV_Error(cv::Error::StsBadArg, "colour space has no 8-bit OpenCV conversion here");
}

// A non-linear space's 8-bit channel as floats (into an existing CV_32F matrix).
void scale_bytes(const cv::Mat& bytes, cv::Mat& out) { bytes.convertTo(out, CV_32F, 1.0 / 255.0); }

FACADESLAM_KERNEL
void linear_channel(const BgrPlanes& in, const LinearRow& w, cv::Mat& out) {
  for (int y = 0; y < out.rows; ++y) {
    const uchar* b = in.b.ptr<uchar>(y);
    const uchar* g = in.g.ptr<uchar>(y);
    const uchar* r = in.r.ptr<uchar>(y);
    float* o = out.ptr<float>(y);
    for (int x = 0; x < out.cols; ++x) o[x] = w[0] * b[x] + w[1] * g[x] + w[2] * r[x] + w[3];
  }
}

}  // namespace

void convert_colour(const cv::Mat& bgr, const BgrPlanes& planes, ColourSpace space,
                    const std::array<cv::Mat*, 3>& outputs) {
  CV_Assert(bgr.type() == CV_8UC3);
  for (const cv::Mat* out : outputs) CV_Assert(!out || (out->type() == CV_32F && out->size() == bgr.size()));
  if (is_linear(space)) {
    const auto map = linear_map(space);
    for (int c = 0; c < 3; ++c)
      if (outputs[static_cast<std::size_t>(c)])
        linear_channel(planes, map[static_cast<std::size_t>(c)], *outputs[static_cast<std::size_t>(c)]);
    return;
  }
  cv::Mat converted;
  convert_colour_bytes(bgr, space, converted);
  std::vector<cv::Mat> channels;
  cv::split(converted, channels);
  for (int c = 0; c < 3; ++c)
    if (outputs[static_cast<std::size_t>(c)])
      scale_bytes(channels[static_cast<std::size_t>(c)], *outputs[static_cast<std::size_t>(c)]);
}

void convert_colour_bytes(const cv::Mat& bgr, ColourSpace space, cv::Mat& bytes) {
  CV_Assert(bgr.type() == CV_8UC3);
  cv::cvtColor(bgr, bytes, opencv_code(space));
}

const std::array<float, 256>& byte_values() {
  static const std::array<float, 256> values = [] {
    cv::Mat bytes(1, 256, CV_8U), scaled(1, 256, CV_32F);
    for (int k = 0; k < 256; ++k) bytes.at<uchar>(0, k) = static_cast<uchar>(k);
    scale_bytes(bytes, scaled);
    std::array<float, 256> v{};
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = scaled.at<float>(0, static_cast<int>(k));
    return v;
  }();
  return values;
}

void convert_colour(const cv::Mat& bgr, ColourSpace space, const std::array<cv::Mat*, 3>& outputs) {
  std::vector<cv::Mat> split;
  cv::split(bgr, split);
  convert_colour(bgr, BgrPlanes{split[0], split[1], split[2]}, space, outputs);
}

std::array<const char*, 3> channel_names(ColourSpace space) {
  switch (space) {
    case ColourSpace::rgb: return {"R", "G", "B"};
    case ColourSpace::lab: return {"L", "a", "b"};
    case ColourSpace::luv: return {"L", "u", "v"};
    case ColourSpace::xyz: return {"X", "Y", "Z"};
    case ColourSpace::hsv: return {"H", "S", "V"};
    case ColourSpace::hls: return {"H", "L", "S"};
    case ColourSpace::ycrcb: return {"Y", "Cr", "Cb"};
    case ColourSpace::opponent: return {"O1", "O2", "O3"};
  }
  return {"c0", "c1", "c2"};
}

}  // namespace facadeslam::semantics
