#include "semantics/evaluation/training_set.hpp"

#include <spdlog/spdlog.h>

#include "core/map/semantic_classes.hpp"
#include "core/util/error.hpp"
#include "core/util/progress.hpp"
#include "core/util/stopwatch.hpp"
#include "semantics/evaluation/labelled_keypoints.hpp"
#include "semantics/evaluation/training_sample.hpp"

namespace facadeslam::semantics {

TrainingSet build_training_set(const std::vector<LabelledImage>& images, const TrainingSetOptions& options,
                               PointDescriptor& descriptor, const LabelledImageLoader& load) {
  constexpr int kClasses = static_cast<int>(kSemanticClasses.size());
  TrainingSet set;
  TrainingSetStats& stats = set.stats;
  std::vector<std::vector<cv::Point2f>> points(images.size());
  std::vector<SampleCandidate> candidates;
  stats.keypoints_per_class.assign(kClasses, 0);
  {
    Progress progress("reading training labels", images.size());
    for (std::size_t i = 0; i < images.size(); ++i) {
      const LoadedLabelledImage loaded = load(images[i]);
      LabelledKeypoints kps = options.keypoints == KeypointSource::grid
                                  ? labelled_keypoints(loaded.label, options.step)
                                  : labelled_keypoints(loaded.label, corner_keypoints(loaded.bgr));
      stats.unlabelled_keypoints += kps.unlabelled;
      for (std::size_t k = 0; k < kps.points.size(); ++k) {
        candidates.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k), kps.classes[k]});
        ++stats.keypoints_per_class[kps.classes[k]];
      }
      points[i] = std::move(kps.points);
      progress.update(i + 1);
    }
  }
  stats.keypoints = candidates.size();
  if (candidates.empty()) throw Error("training: the training images have no labelled grid keypoint");

  SampleOptions sample_options;
  sample_options.balance = options.balance;
  sample_options.balance_power = options.balance_power;
  sample_options.max_samples = options.max_samples;
  sample_options.seed = options.seed;
  const std::vector<SampleCandidate> sample = choose_training_sample(candidates, kClasses, sample_options);
  stats.samples = sample.size();
  stats.samples_per_class.assign(kClasses, 0);
  for (const SampleCandidate& c : sample) ++stats.samples_per_class[c.class_id];
  if (!options.quiet)
    spdlog::info("training sample: {} of {} labelled keypoints{}", sample.size(), candidates.size(),
                 options.balance ? " (class-balanced)" : "");

  set.samples.create(static_cast<int>(sample.size()), descriptor.width(), CV_32F);
  set.labels.reserve(sample.size());
  Progress progress("describing training images", images.size());
  std::size_t row = 0;
  while (row < sample.size()) {
    // The chosen keypoints of one image (sorted, possibly repeated).
    const std::uint32_t image = sample[row].image;
    std::size_t end = row;
    std::vector<cv::Point2f> unique;
    std::vector<int> unique_index;  // per chosen row, its row in `unique`
    while (end < sample.size() && sample[end].image == image) {
      if (end == row || sample[end].keypoint != sample[end - 1].keypoint)
        unique.push_back(points[image][sample[end].keypoint]);
      unique_index.push_back(static_cast<int>(unique.size()) - 1);
      ++end;
    }
    const cv::Mat bgr = load(images[image]).bgr;
    const Stopwatch described;
    const cv::Mat rows = descriptor.compute(bgr, unique);
    stats.extraction_seconds += described.elapsed_s();
    for (std::size_t r = row; r < end; ++r) {
      rows.row(unique_index[r - row]).copyTo(set.samples.row(static_cast<int>(r)));
      set.labels.push_back(sample[r].class_id);
    }
    row = end;
    progress.update(image + 1);
  }
  progress.finish();
  return set;
}

}  // namespace facadeslam::semantics
