#include "semantics/invariance/keypoint_mapping.hpp"

#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {

KeypointPairs map_keypoints(const std::vector<cv::Point2f>& reference, const TransformedImage& changed, int margin) {
  if (margin < 0) throw Error(cat("keypoint mapping: the margin must be >= 0 pixels, got ", margin));
  if (changed.valid.type() != CV_8U || changed.valid.size() != changed.bgr.size())
    throw Error("keypoint mapping: the valid-pixel mask must be 8-bit and as large as the image");
  // A pixel survives the erosion when its whole (2 margin + 1)^2 square is
  // valid; outside the canvas counts as invalid.
  cv::Mat usable;
  const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * margin + 1, 2 * margin + 1));
  cv::erode(changed.valid, usable, square, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));

  KeypointPairs pairs;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const cv::Point2d moved = map_point(changed.point_map, reference[i]);
    // Descriptors describe the pixel a keypoint rounds to.
    const int x = cvRound(moved.x), y = cvRound(moved.y);
    if (x < 0 || y < 0 || x >= usable.cols || y >= usable.rows || usable.at<uchar>(y, x) == 0) continue;
    pairs.reference.push_back(static_cast<int>(i));
    pairs.moved.emplace_back(static_cast<float>(moved.x), static_cast<float>(moved.y));
  }
  return pairs;
}

}  // namespace facadeslam::semantics
