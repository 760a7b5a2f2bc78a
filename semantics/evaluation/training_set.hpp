#pragma once
// The forest's training rows from a list of labelled images: pass 1 reads
// the labels only and draws the sample (training_sample.hpp), pass 2
// describes just the chosen keypoints, image by image.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/evaluation/corner_keypoints.hpp"
#include "semantics/evaluation/facade_dataset.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

struct TrainingSetOptions {
  int step = 9;                                     // grid step
  KeypointSource keypoints = KeypointSource::grid;  // where the rows are described
  bool balance = false;                             // training_sample.hpp
  double balance_power = 1.0;                       // with balance: 1 = fully, (0, 1) partly (training_sample.hpp)
  std::size_t max_samples = 0;                      // 0 = every labelled keypoint
  std::uint64_t seed = 1;
  bool quiet = false;  // no info line (the optimiser builds hundreds of sets)
};

struct TrainingSetStats {
  std::size_t keypoints = 0;                                        // labelled grid keypoints of the images
  std::size_t samples = 0;                                          // rows drawn from them
  std::vector<std::size_t> keypoints_per_class, samples_per_class;  // by class id
  std::size_t unlabelled_keypoints = 0;                             // grid points of no class colour
  double extraction_seconds = 0;                                    // descriptor time only
};

struct TrainingSet {
  cv::Mat samples;          // CV_32F, one descriptor per row
  std::vector<int> labels;  // class id per row
  TrainingSetStats stats;
};

// Shows progress bars on a terminal. Throws Error when the images have no
// labelled keypoint, or (naming the file) when an image cannot be read.
// `load` gives an entry's pixels (a DecodedImageCache in the optimiser).
TrainingSet build_training_set(const std::vector<LabelledImage>& images, const TrainingSetOptions& options,
                               PointDescriptor& descriptor, const LabelledImageLoader& load = load_labelled_image);

}  // namespace facadeslam::semantics
