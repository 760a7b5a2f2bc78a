#pragma once
// Training keypoints where the map's points are: FAST corners. The semantic
// worker describes map points, which the tracker and map maker made from
// FAST corners at pyramid levels 0-3, so they sit on window frames, door
// edges and texture corners, not on the thesis' regular grid. A forest
// trained on grid points has seen few such patches; one trained on corners
// sees the distribution it is asked about.
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/descriptor/descriptor_params.hpp"

namespace facadeslam::semantics {

enum class KeypointSource { grid, corners };

// "grid" or "corners"; throws Error naming the option otherwise.
KeypointSource parse_keypoint_source(const std::string& text, const std::string& option);
const char* keypoint_source_name(KeypointSource source);

inline constexpr int kCornerThreshold = 20;  // the tracker's FAST threshold on its levels

// FAST corners (non-maximum suppressed) of the image at full and half
// resolution (level 1 mapped back to level-0 pixels), each pixel once, at
// least `border` pixels from the edge, row by row.
std::vector<cv::Point2f> corner_keypoints(const cv::Mat& bgr, int border = kMaxPatchRadius,
                                          int threshold = kCornerThreshold);

}  // namespace facadeslam::semantics
