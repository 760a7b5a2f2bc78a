#pragma once
// Which labelled grid keypoints train the forest. Chosen from the labels
// alone, before any descriptor is computed, so that only the chosen
// keypoints are described.
//
// Default: every keypoint, or a uniform random subset of max_samples
// (which keeps the class proportions).
//
// Balanced (`--balance`): every class present in the training images gets
// the same number T of rows, T = the median of the present classes'
// keypoint counts (capped at max_samples / classes when a cap is given).
// Larger classes are subsampled without replacement; smaller ones keep all
// their keypoints and are topped up by drawing their keypoints again at
// random (oversampling). Why: on LabelMeFacade, building has ~40 times as
// many keypoints as door; a forest trained on the raw proportions never
// predicts door or window (the thesis' tables show 0 %), which is useless to
// a user. Undersampling everything to the rarest class would throw away
// ~95 % of the data; the median keeps the common classes well described
// while rare ones get equal weight in the votes.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace facadeslam::semantics {

struct SampleCandidate {
  std::uint32_t image = 0;     // index into the training image list
  std::uint32_t keypoint = 0;  // index into that image's grid keypoints
  std::uint8_t class_id = 0;
  friend bool operator==(const SampleCandidate&, const SampleCandidate&) = default;
};

struct SampleOptions {
  bool balance = false;
  std::size_t max_samples = 0;  // 0 = no cap
  std::uint64_t seed = 1;
};

// Rows per class of a balanced sample for these per-class counts (see above).
std::size_t balanced_class_target(const std::vector<std::size_t>& class_counts, std::size_t max_samples);

// The chosen candidates sorted by (image, keypoint); with `balance` a
// candidate may appear more than once. Deterministic for a given seed.
// Candidates' class ids must be < `classes` (Error otherwise).
std::vector<SampleCandidate> choose_training_sample(const std::vector<SampleCandidate>& candidates, int classes,
                                                    const SampleOptions& options);

}  // namespace facadeslam::semantics
