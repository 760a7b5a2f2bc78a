#pragma once
// KLT tracks of a reference frame's FAST corners, followed frame to frame
// until the two-view initialiser finds enough parallax. Each track keeps its
// reference pixel and its pixel in the latest frame; tracks that fail the
// forward-backward check or leave the image die and are removed.
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/image/fast_detector.hpp"
#include "slam/init/init_options.hpp"

namespace facadeslam {

class CornerTracks {
 public:
  explicit CornerTracks(CornerTrackOptions options = {});

  // Starts new tracks at up to options.max_corners of `corners` (level-0
  // FAST corners of `grey`, 8-bit single channel), strongest first but
  // spread over the image. Throws Error for an empty or non-8-bit-grey image
  // or a corner outside it.
  void reset(const cv::Mat& grey, const std::vector<Corner>& corners);

  // Tracks every live track from the previous frame into `grey` (same size
  // and type as the reference) and drops those that fail. Returns how many
  // survive. Throws Error before reset() or for a wrong image.
  std::size_t track(const cv::Mat& grey);

  std::size_t size() const { return reference_.size(); }
  bool empty() const { return reference_.empty(); }
  bool has_reference() const { return !previous_pyramid_.empty(); }
  // Frames tracked since reset().
  int frames_tracked() const { return frames_tracked_; }

  // Per live track, level-0 pixels (pixel (0,0) = centre of the top-left pixel).
  const std::vector<Eigen::Vector2d>& reference_pixels() const { return reference_; }
  const std::vector<Eigen::Vector2d>& current_pixels() const { return current_; }
  // Per live track, its index in the corner list given to reset().
  const std::vector<int>& corner_indices() const { return corner_index_; }

  // Median |current - reference| in pixels (0 without tracks).
  double median_motion_px() const;

 private:
  std::vector<cv::Mat> build_pyramid(const cv::Mat& grey) const;
  void check_image(const cv::Mat& grey, const char* what) const;

  CornerTrackOptions options_;
  cv::Size image_size_;
  std::vector<cv::Mat> previous_pyramid_;
  std::vector<Eigen::Vector2d> reference_;
  std::vector<Eigen::Vector2d> current_;
  std::vector<int> corner_index_;
  int frames_tracked_ = 0;
};

// The corners kept by CornerTracks::reset: indices into `corners`, at most
// max_count, taken by rank within cells of cell_px pixels (every cell's
// strongest first, then every cell's second, ...), ties broken by position
// so the choice is deterministic.
std::vector<int> spread_strongest_corners(const std::vector<Corner>& corners, int max_count, int cell_px);

}  // namespace facadeslam
