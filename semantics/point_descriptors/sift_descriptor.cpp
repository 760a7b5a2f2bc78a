#include "semantics/point_descriptors/sift_descriptor.hpp"

#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "semantics/point_descriptors/keypoint_rows.hpp"

namespace facadeslam::semantics {

std::vector<cv::Mat> opponent_channels(const cv::Mat& bgr) {
  std::vector<cv::Mat> out(3);
  for (cv::Mat& m : out) m.create(bgr.size(), CV_8U);
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3b* in = bgr.ptr<cv::Vec3b>(y);
    uchar* o1 = out[0].ptr<uchar>(y);
    uchar* o2 = out[1].ptr<uchar>(y);
    uchar* o3 = out[2].ptr<uchar>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      const int b = in[x][0], g = in[x][1], r = in[x][2];
      // Integer rounding of the halves, quarters and thirds (ranges stay 0..255).
      o1[x] = static_cast<uchar>((r - g + 255 + 1) / 2);
      o2[x] = static_cast<uchar>((r + g - 2 * b + 510 + 2) / 4);
      o3[x] = static_cast<uchar>((r + g + b + 1) / 3);
    }
  }
  return out;
}

SiftDescriptor::SiftDescriptor(Channels channels, int patch_side)
    : channels_(channels), keypoint_size_(static_cast<float>(patch_side) / 6.0f), sift_(cv::SIFT::create()) {
  if (patch_side < 3) throw Error("SIFT descriptor: the patch side must be at least 3 pixels");
}

cv::Mat SiftDescriptor::describe(const cv::Mat& channel, const std::vector<cv::Point2f>& keypoints) {
  std::vector<cv::KeyPoint> kps = upright_keypoints(keypoints, keypoint_size_);
  cv::Mat computed;
  sift_->compute(channel, kps, computed);
  return rows_by_index(kps, computed, keypoints.size(), 128);
}

cv::Mat SiftDescriptor::compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) {
  check_descriptor_input(name(), bgr, keypoints);
  if (keypoints.empty()) return cv::Mat(0, width(), CV_32F);
  if (channels_ == Channels::grey) {
    cv::Mat grey;
    cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
    return describe(grey, keypoints);
  }
  std::vector<cv::Mat> parts;
  for (const cv::Mat& channel : opponent_channels(bgr)) parts.push_back(describe(channel, keypoints));
  cv::Mat rows;
  cv::hconcat(parts, rows);
  return rows;
}

}  // namespace facadeslam::semantics
