#pragma once
// SIFT and Opponent SIFT baselines (cv::SIFT::compute on the given,
// upright keypoints).
//
// Patch: SIFT's descriptor spans 4 x 4 cells of 3 sigma with sigma =
// KeyPoint::size / 2, i.e. a square of 6 x size pixels; size = side / 6
// makes it cover the same side x side patch as the modular descriptor (21 x
// 21 for the thesis genome), the like-for-like comparison of
// bench_semantics_modules.
//
// Opponent SIFT (van de Sande et al.): SIFT of each opponent channel,
// concatenated O1 | O2 | O3 (3 x 128 = 384 values). Channels as 8-bit images:
// O1 = (R - G + 255) / 2, O2 = (R + G - 2B + 510) / 4, O3 = (R + G + B) / 3,
// the opponent axes (R-G)/sqrt2, (R+G-2B)/sqrt6, (R+G+B)/sqrt3 mapped onto
// 0..255 (SIFT normalises each descriptor, so the axis scales do not matter).
#include <opencv2/features2d.hpp>

#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

// The three opponent channels of a BGR image, each CV_8U (formulas above).
std::vector<cv::Mat> opponent_channels(const cv::Mat& bgr);

class SiftDescriptor : public PointDescriptor {
 public:
  enum class Channels { grey, opponent };

  // `patch_side`: side in pixels of the square patch to cover (>= 3).
  SiftDescriptor(Channels channels, int patch_side);

  std::string_view name() const override { return channels_ == Channels::grey ? "sift" : "opponent-sift"; }
  int width() const override { return channels_ == Channels::grey ? 128 : 384; }
  float keypoint_size() const { return keypoint_size_; }
  cv::Mat compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) override;

 private:
  cv::Mat describe(const cv::Mat& channel, const std::vector<cv::Point2f>& keypoints);

  Channels channels_;
  float keypoint_size_;
  cv::Ptr<cv::SIFT> sift_;
};

}  // namespace facadeslam::semantics
