#pragma once
// The invariance evaluation (thesis IV.5, `facadeslam evaluate invariance`):
// for every image and every value of every case, the image is changed, the
// reference grid keypoints move with it (keypoint_mapping.hpp), every
// descriptor describes the reference keypoints in the original and their
// counterparts in the changed image, and brute-force L2 matching gives the
// match rate (match_rate.hpp).
//
// Aggregation: a curve point is the mean of the per-image match rates (each
// image weighs the same, the thesis' "average match rate"); the pooled counts
// (compared, matched) are kept as well. An image that keeps no keypoint for a
// value (e.g. shrunk below the margin) does not enter that point's mean.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "semantics/invariance/invariance_cases.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

// Around each keypoint, the square that must show the original image, in the
// reference and the changed image: ORB's 31 x 31 patch, the largest of the
// descriptors (the modular one covers at most 21 x 21, SIFT the same).
inline constexpr int kDefaultInvarianceMargin = 15;
inline constexpr int kDefaultInvarianceStep = 9;  // the thesis' grid

struct InvarianceCaseRun {
  InvarianceCase id;
  std::vector<double> values;
};

// Every case with its default values, in kInvarianceCases order.
std::vector<InvarianceCaseRun> default_invariance_cases();

struct InvarianceOptions {
  std::vector<InvarianceCaseRun> cases = default_invariance_cases();
  int step = kDefaultInvarianceStep;
  int margin = kDefaultInvarianceMargin;
};

struct InvarianceCaseResult {
  InvarianceCase id;
  std::vector<double> values;
  // Indexed [descriptor][value].
  std::vector<std::vector<double>> match_rate;
  std::vector<std::vector<std::size_t>> compared, matched;
  // Indexed [descriptor][value][image]; NaN where the image kept no keypoint.
  std::vector<std::vector<std::vector<double>>> per_image;
};

struct InvarianceResult {
  std::vector<std::filesystem::path> images;
  std::vector<std::string> descriptors;
  std::vector<int> descriptor_widths;
  int step = 0, margin = 0;
  std::size_t reference_keypoints = 0;  // grid keypoints over all images
  std::vector<InvarianceCaseResult> cases;
  double seconds = 0;
};

// Throws Error for bad options (step < 1, margin < 0, no case, a repeated
// case, a bad case value), no descriptor, no image, an image that cannot be
// read or is too small for one keypoint. Options and image headers are
// checked before the long work. Progress bar on a terminal.
InvarianceResult run_invariance(const std::vector<std::filesystem::path>& images,
                                const std::vector<PointDescriptor*>& descriptors, const InvarianceOptions& options);

}  // namespace facadeslam::semantics
