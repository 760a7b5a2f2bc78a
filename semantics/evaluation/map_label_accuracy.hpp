#pragma once
// How right a replay's labels are: the share of labelled map points whose
// label equals the ground-truth class at the point's patch centre in its
// source keyframe's ground-truth label image, overall and per true class.
// (Synthetic sequences write a label image per frame; `replay --gt-labels`.)
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <utility>

#include <opencv2/core.hpp>

#include "core/map/map.hpp"
#include "core/map/semantic_classes.hpp"

namespace facadeslam::semantics {

// The ground-truth class ids (CV_8UC1, kUnknownClass for no class) of the
// frame with this index, or an empty Mat when that frame has none.
using GroundTruthLabels = std::function<cv::Mat(std::size_t frame_index)>;

struct MapLabelAccuracy {
  std::size_t evaluated = 0;  // labelled points with a ground-truth class
  std::size_t correct = 0;
  std::size_t without_truth = 0;  // labelled, but no ground truth at the point
  std::size_t unlabelled = 0;     // not labelled (yet): not counted above
  std::array<std::size_t, kSemanticClasses.size()> per_class_points{}, per_class_correct{};  // by true class
  // confusion[true class][label]: where each class's points went.
  std::array<std::array<std::size_t, kSemanticClasses.size()>, kSemanticClasses.size()> confusion{};

  // correct / evaluated; nullopt when nothing was evaluated.
  std::optional<double> accuracy() const;
  // Of the points whose true class is `c`, the share labelled `c`.
  std::optional<double> class_accuracy(std::size_t c) const;
  // The label most often given to points of true class `c` other than `c`
  // itself, and how many got it; nullopt when none was mislabelled.
  std::optional<std::pair<std::size_t, std::size_t>> commonest_mistake(std::size_t c) const;
};

// The ground-truth class at a level-0 pixel (rounded) of a label image;
// nullopt outside the image or where the image has no class there.
std::optional<std::size_t> true_class_at(const cv::Mat& truth, const Eigen::Vector2d& pixel);

// Throws Error when a ground-truth image is not the size of the keyframe it
// belongs to.
MapLabelAccuracy map_label_accuracy(const Map& map, const GroundTruthLabels& truth);

}  // namespace facadeslam::semantics
