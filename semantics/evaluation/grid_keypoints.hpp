#pragma once
// The evaluation's keypoints (thesis IV.5): a regular grid over the image,
// the same for every descriptor. The grid keeps `border` pixels from the
// image edge so that the largest patch of the modular descriptor (radius
// kMaxPatchRadius = 10) lies inside the image for every keypoint.
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/descriptor/descriptor_params.hpp"

namespace facadeslam::semantics {

inline constexpr int kDefaultGridStep = 9;  // the thesis' grid
inline constexpr int kDefaultGridBorder = kMaxPatchRadius;

// Points (x, y) = (border + i step, border + j step) with
// border <= x < width - border, row by row. Empty when the image is too
// small. Throws Error when step < 1 or border < 0.
std::vector<cv::Point2f> grid_keypoints(cv::Size image_size, int step = kDefaultGridStep,
                                        int border = kDefaultGridBorder);

}  // namespace facadeslam::semantics
