#pragma once
// One interface for every descriptor the label evaluation compares: the
// modular descriptor and the baselines (SIFT, Opponent SIFT, ORB, EDD).
// All of them describe the same given keypoints (no detection), upright,
// and return exactly one row per keypoint so that rows line up with the
// keypoints' ground-truth classes.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/descriptor/genome.hpp"

namespace facadeslam::semantics {

class PointDescriptor {
 public:
  virtual ~PointDescriptor() = default;

  virtual std::string_view name() const = 0;
  // Values per keypoint (columns of compute()'s result).
  virtual int width() const = 0;
  // `bgr`: non-empty CV_8UC3 image. Every keypoint must round to a pixel of
  // the image (Error otherwise). Returns a keypoints.size() x width() CV_32F
  // matrix, row i describing keypoint i. Not const: implementations reuse
  // per-image buffers between calls.
  virtual cv::Mat compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) = 0;
};

// The names make_point_descriptor accepts, in the order reports list them.
inline constexpr std::string_view kPointDescriptorNames[] = {"modular", "sift", "opponent-sift", "orb", "edd"};

// The names a `--descriptor` option gave (comma-split already), with "all"
// expanded to kPointDescriptorNames and repeats dropped, first mention first.
std::vector<std::string> expand_descriptor_names(const std::vector<std::string>& given);

// A descriptor by name. `genome` configures the modular descriptor and sets
// the patch the SIFT variants cover (2r+1 pixels, r = the genome's patch
// radius), so that they describe the same neighbourhood. Throws Error for an
// unknown name, listing the known ones.
std::unique_ptr<PointDescriptor> make_point_descriptor(std::string_view name, const Genome& genome);

// Checks the arguments of compute() (shared by the implementations).
void check_descriptor_input(std::string_view descriptor, const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints);

}  // namespace facadeslam::semantics
