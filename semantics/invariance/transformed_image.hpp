#pragma once
// What every invariance case produces from an image: the changed image and
// where each original pixel position went, so that the keypoints can follow
// the image (thesis IV.5: "the same transformation matrix converts the
// keypoints and image pixels").
#include <opencv2/core.hpp>

namespace facadeslam::semantics {

struct TransformedImage {
  cv::Mat bgr;  // CV_8UC3, the changed image
  // Original pixel coordinates -> coordinates in `bgr` (pixel (0,0) is the
  // centre of the top-left pixel). The identity for photometric changes.
  cv::Matx23d point_map = cv::Matx23d(1, 0, 0, 0, 1, 0);
  // CV_8U, same size as `bgr`: 255 where `bgr` shows the original image,
  // 0 where a warp filled in black (corners of a rotated image).
  cv::Mat valid;
};

// An unchanged geometry: `bgr` with the identity map and an all-valid mask.
TransformedImage same_geometry(cv::Mat bgr);

// p mapped by `map`.
cv::Point2d map_point(const cv::Matx23d& map, cv::Point2d p);

}  // namespace facadeslam::semantics
