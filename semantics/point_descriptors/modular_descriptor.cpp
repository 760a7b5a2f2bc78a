#include "semantics/point_descriptors/modular_descriptor.hpp"

#include "core/util/error.hpp"
#include "semantics/descriptor/extraction.hpp"

namespace facadeslam::semantics {

ModularDescriptor::ModularDescriptor(const Genome& genome) : params_(genome.decode()) {
  validate(params_);
  if (params_.active_value_count() == 0) throw Error("modular descriptor: the genome activates no value");
}

cv::Mat ModularDescriptor::compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) {
  check_descriptor_input(name(), bgr, keypoints);
  prepare(bgr, params_, prepared_);
  return extract(prepared_, keypoints, params_);
}

}  // namespace facadeslam::semantics
