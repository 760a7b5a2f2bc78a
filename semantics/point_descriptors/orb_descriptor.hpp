#pragma once
// ORB baseline: cv::ORB's rBRIEF on the given keypoints, upright (angle 0,
// like every descriptor here), one pyramid level, OpenCV's default 31 x 31
// patch. The 256 binary tests are unpacked into 256 values 0/1: a forest
// splits on single bits, whereas the 32 packed bytes would mix unrelated
// tests into one number.
//
// Border policy: ORB drops keypoints closer than its edge threshold (31
// pixels) to the image edge. The image is padded by reflection first, so no
// keypoint inside the image is dropped and each gets a real descriptor; should
// OpenCV still drop one, its row stays zeros (keypoint_rows.hpp).
#include <opencv2/features2d.hpp>

#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

class OrbDescriptor : public PointDescriptor {
 public:
  OrbDescriptor();

  std::string_view name() const override { return "orb"; }
  int width() const override { return 256; }
  cv::Mat compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) override;

  // Reflected border added around the image (ORB's edge threshold + 1).
  static constexpr int kPadding = 32;

 private:
  cv::Ptr<cv::ORB> orb_;
  cv::Mat grey_, padded_;
};

}  // namespace facadeslam::semantics
