#pragma once
// The modular descriptor (semantics/descriptor) behind the PointDescriptor
// interface: prepare() once per image, then extract() for the keypoints.
#include "semantics/descriptor/prepared_image.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

class ModularDescriptor : public PointDescriptor {
 public:
  // Throws Error when the genome has no active value (a 0-wide descriptor
  // cannot train a forest).
  explicit ModularDescriptor(const Genome& genome);

  std::string_view name() const override { return "modular"; }
  int width() const override { return params_.active_value_count(); }
  cv::Mat compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) override;

 private:
  DescriptorParams params_;
  PreparedImage prepared_;  // reused from image to image
};

}  // namespace facadeslam::semantics
