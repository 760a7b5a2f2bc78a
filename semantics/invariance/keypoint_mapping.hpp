#pragma once
// Moves the reference keypoints with the image and keeps those that a
// descriptor can still describe in the changed image: the keypoint's pixel
// and the square of `margin` pixels around it must show the original image
// (inside the canvas, not in the black fill of a warp). Keypoints whose
// patch would cover fill are dropped rather than counted as misses: the
// cases measure invariance, not how the image was cropped.
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/invariance/transformed_image.hpp"

namespace facadeslam::semantics {

struct KeypointPairs {
  std::vector<int> reference;      // index into the reference keypoints
  std::vector<cv::Point2f> moved;  // its position in the changed image
};

// Throws Error when margin < 0 or the mask does not match the image.
KeypointPairs map_keypoints(const std::vector<cv::Point2f>& reference, const TransformedImage& changed, int margin);

}  // namespace facadeslam::semantics
