#pragma once
// A forest's votes for keypoints of an image, optionally seen in the image
// shrunk by a scale: the semantic worker adds the votes at full size and at
// its context scale (the descriptor's patch then covers 1/scale times more
// of the scene around the point), and `evaluate labels --context-scale`
// scores the same sum.
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/forest/random_forest.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

// One row per keypoint, one column per forest class (RandomForest::classes()):
// the share of the trees voting for it, for the descriptor computed at the
// keypoints in `image` resized by `scale` (1 = as it is).
cv::Mat forest_vote_shares(PointDescriptor& descriptor, const RandomForest& forest, const cv::Mat& image,
                           const std::vector<cv::Point2f>& keypoints, double scale);

}  // namespace facadeslam::semantics
