#include "semantics/evaluation/labelled_keypoints.hpp"

#include "semantics/evaluation/grid_keypoints.hpp"
#include "semantics/evaluation/label_image.hpp"

namespace facadeslam::semantics {

LabelledKeypoints labelled_keypoints(const cv::Mat& label_bgr, int step) {
  return labelled_keypoints(label_bgr, grid_keypoints(label_bgr.size(), step));
}

LabelledKeypoints labelled_keypoints(const cv::Mat& label_bgr, const std::vector<cv::Point2f>& grid) {
  LabelledKeypoints out;
  const std::vector<std::uint8_t> classes = classes_at(label_bgr, grid);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    if (classes[k] == kUnknownClass) {
      ++out.unlabelled;
      continue;
    }
    out.points.push_back(grid[k]);
    out.classes.push_back(classes[k]);
  }
  return out;
}

}  // namespace facadeslam::semantics
