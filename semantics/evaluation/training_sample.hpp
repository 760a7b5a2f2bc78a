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
//
// Partly balanced (`--balance-power p`, 0 < p < 1): class c gets
// T * (n_c / T)^(1 - p) rows (n_c its keypoints), scaled down together to
// fit max_samples: p = 1 is the balanced sample above, p -> 0 the raw
// proportions. Why: on street frames the raw proportions make a forest that
// calls vegetation and pavement building (CamVid's test drive: 59 % overall,
// 49 % average) and the balanced one loses the common classes (54 / 54).
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
  double balance_power = 1.0;  // with balance: 1 = every class alike, (0, 1) partly (see above)
};

// Rows per class of a balanced sample for these per-class counts (see above).
std::size_t balanced_class_target(const std::vector<std::size_t>& class_counts, std::size_t max_samples);
// Rows per class (by class id) of a balanced or partly balanced sample.
std::vector<std::size_t> balanced_class_rows(const std::vector<std::size_t>& class_counts, std::size_t max_samples,
                                             double balance_power);

// The chosen candidates sorted by (image, keypoint); with `balance` a
// candidate may appear more than once. Deterministic for a given seed.
// Candidates' class ids must be < `classes` (Error otherwise).
std::vector<SampleCandidate> choose_training_sample(const std::vector<SampleCandidate>& candidates, int classes,
                                                    const SampleOptions& options);

}  // namespace facadeslam::semantics
