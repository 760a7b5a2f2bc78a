#include "semantics/invariance/transformed_image.hpp"

namespace facadeslam::semantics {

TransformedImage same_geometry(cv::Mat bgr) {
  TransformedImage out;
  out.valid = cv::Mat(bgr.size(), CV_8U, cv::Scalar(255));
  out.bgr = std::move(bgr);
  return out;
}

cv::Point2d map_point(const cv::Matx23d& m, cv::Point2d p) {
  return {m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2), m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2)};
}

}  // namespace facadeslam::semantics
