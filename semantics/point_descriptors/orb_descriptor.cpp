#include "semantics/point_descriptors/orb_descriptor.hpp"

#include <opencv2/imgproc.hpp>

#include "semantics/point_descriptors/keypoint_rows.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kPatchSize = 31;

// 32 bytes per row -> 256 values 0/1 (bit b of byte j -> column 8j + b).
cv::Mat unpack_bits(const cv::Mat& packed) {
  cv::Mat bits(packed.rows, packed.cols * 8, CV_8U);
  for (int r = 0; r < packed.rows; ++r) {
    const uchar* in = packed.ptr<uchar>(r);
    uchar* out = bits.ptr<uchar>(r);
    for (int j = 0; j < packed.cols; ++j)
      for (int b = 0; b < 8; ++b) out[8 * j + b] = static_cast<uchar>((in[j] >> b) & 1);
  }
  return bits;
}

}  // namespace

OrbDescriptor::OrbDescriptor()
    : orb_(cv::ORB::create(500, 1.2f, 1, kPadding - 1, 0, 2, cv::ORB::HARRIS_SCORE, kPatchSize)) {}

cv::Mat OrbDescriptor::compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) {
  check_descriptor_input(name(), bgr, keypoints);
  if (keypoints.empty()) return cv::Mat(0, width(), CV_32F);
  cv::cvtColor(bgr, grey_, cv::COLOR_BGR2GRAY);
  cv::copyMakeBorder(grey_, padded_, kPadding, kPadding, kPadding, kPadding, cv::BORDER_REFLECT_101);
  const float offset = static_cast<float>(kPadding);
  std::vector<cv::KeyPoint> kps = upright_keypoints(keypoints, static_cast<float>(kPatchSize), {offset, offset});
  cv::Mat packed;
  orb_->compute(padded_, kps, packed);
  return rows_by_index(kps, packed.empty() ? packed : unpack_bits(packed), keypoints.size(), width());
}

}  // namespace facadeslam::semantics
