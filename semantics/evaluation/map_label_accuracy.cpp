#include "semantics/evaluation/map_label_accuracy.hpp"

#include <cmath>
#include <map>

#include "core/util/error.hpp"
#include "semantics/evaluation/label_image.hpp"

namespace facadeslam::semantics {

std::optional<double> MapLabelAccuracy::accuracy() const {
  if (evaluated == 0) return std::nullopt;
  return static_cast<double>(correct) / static_cast<double>(evaluated);
}

std::optional<double> MapLabelAccuracy::class_accuracy(std::size_t c) const {
  if (c >= per_class_points.size() || per_class_points[c] == 0) return std::nullopt;
  return static_cast<double>(per_class_correct[c]) / static_cast<double>(per_class_points[c]);
}

std::optional<std::pair<std::size_t, std::size_t>> MapLabelAccuracy::commonest_mistake(std::size_t c) const {
  if (c >= confusion.size()) return std::nullopt;
  std::optional<std::pair<std::size_t, std::size_t>> worst;
  for (std::size_t l = 0; l < confusion[c].size(); ++l)
    if (l != c && confusion[c][l] > 0 && (!worst || confusion[c][l] > worst->second)) worst = {{l, confusion[c][l]}};
  return worst;
}

std::optional<std::size_t> true_class_at(const cv::Mat& truth, const Eigen::Vector2d& pixel) {
  const int x = static_cast<int>(std::lround(pixel.x())), y = static_cast<int>(std::lround(pixel.y()));
  if (truth.empty() || x < 0 || y < 0 || x >= truth.cols || y >= truth.rows) return std::nullopt;
  const std::size_t c = truth.at<std::uint8_t>(y, x);
  if (c >= kSemanticClasses.size()) return std::nullopt;
  return c;
}

MapLabelAccuracy map_label_accuracy(const Map& map, const GroundTruthLabels& truth) {
  std::map<KeyFrame::Id, cv::Mat> truth_of_keyframe;
  for (const KeyFrameSnapshot& kf : map.snapshot_keyframes()) {
    cv::Mat ids = truth(kf.keyframe->frame_index());
    const cv::Size size = kf.keyframe->pyramid()->level(0).image.size();
    if (!ids.empty() && (ids.type() != CV_8UC1 || ids.size() != size))
      throw Error("ground-truth labels of frame " + std::to_string(kf.keyframe->frame_index()) + " are " +
                  std::to_string(ids.cols) + "x" + std::to_string(ids.rows) + ", the frame is " +
                  std::to_string(size.width) + "x" + std::to_string(size.height));
    truth_of_keyframe.emplace(kf.keyframe->id(), std::move(ids));
  }
  MapLabelAccuracy out;
  for (const PointSnapshot& p : map.snapshot_points()) {
    const SemanticLabel label = p.point->label();
    if (label.label == kUnlabelled) {
      ++out.unlabelled;
      continue;
    }
    const auto it = truth_of_keyframe.find(p.source.keyframe_id);
    const auto found = it == truth_of_keyframe.end() ? std::nullopt : true_class_at(it->second, p.source.pixel_level0);
    if (!found) {
      ++out.without_truth;
      continue;
    }
    const std::size_t true_class = *found;
    ++out.evaluated;
    ++out.per_class_points[true_class];
    if (label.label < out.confusion.size()) ++out.confusion[true_class][label.label];
    if (label.label == true_class) {
      ++out.correct;
      ++out.per_class_correct[true_class];
    }
  }
  return out;
}

}  // namespace facadeslam::semantics
