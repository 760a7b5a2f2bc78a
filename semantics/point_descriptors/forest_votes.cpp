#include "semantics/point_descriptors/forest_votes.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace facadeslam::semantics {

cv::Mat forest_vote_shares(PointDescriptor& descriptor, const RandomForest& forest, const cv::Mat& image,
                           const std::vector<cv::Point2f>& keypoints, double scale) {
  cv::Mat rows;
  if (scale == 1.0) {
    rows = descriptor.compute(image, keypoints);
  } else {
    cv::Mat shrunk;
    cv::resize(image, shrunk, cv::Size(), scale, scale, cv::INTER_AREA);
    std::vector<cv::Point2f> moved;
    moved.reserve(keypoints.size());
    for (const cv::Point2f& k : keypoints)
      moved.emplace_back(std::min(k.x * static_cast<float>(scale), shrunk.cols - 1.f),
                         std::min(k.y * static_cast<float>(scale), shrunk.rows - 1.f));
    rows = descriptor.compute(shrunk, moved);
  }
  cv::Mat shares;
  forest.predict(rows, shares);
  return shares;
}

}  // namespace facadeslam::semantics
