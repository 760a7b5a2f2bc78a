#pragma once
// The tracker's 4-level grey pyramid (PTAM): level 0 is the full-resolution
// grey image, each further level a 2x2 box half-sample of the previous, each
// with its own FAST corners.
#include <array>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/image/fast_detector.hpp"

namespace facadeslam {

inline constexpr int kPyramidLevels = 4;

struct PyramidOptions {
  // Per-level FAST settings. Coarse levels are blurrier (box averaging), so
  // their threshold is lower; their cells are smaller in pixels because the
  // image is.
  std::array<FastOptions, kPyramidLevels> fast{{{10, 32, 12, 4}, {8, 24, 8, 4}, {8, 16, 6, 4}, {6, 12, 6, 4}}};
  bool detect_corners = true;
};

struct PyramidLevel {
  cv::Mat image;                // 8-bit grey
  std::vector<Corner> corners;  // FAST corners at this level's resolution
};

class ImagePyramid {
 public:
  ImagePyramid() = default;
  // `image` is 8-bit grey or BGR (converted to grey); it must be at least
  // 8 * 2^(levels-1) pixels on each side so that the top level is usable.
  ImagePyramid(const cv::Mat& image, const PyramidOptions& options = {});
  // Rebuilds a pyramid from stored levels (map loading); no detection runs.
  explicit ImagePyramid(std::array<PyramidLevel, kPyramidLevels> levels) : levels_(std::move(levels)) {}

  const PyramidLevel& level(int l) const { return levels_.at(static_cast<std::size_t>(l)); }
  int levels() const { return kPyramidLevels; }

  // Pixel-centre-exact coordinate changes between level 0 and level l.
  static Eigen::Vector2d level0_to_level(const Eigen::Vector2d& x0, int level);
  static Eigen::Vector2d level_to_level0(const Eigen::Vector2d& xl, int level);
  static double level_scale(int level) { return static_cast<double>(1 << level); }

 private:
  std::array<PyramidLevel, kPyramidLevels> levels_;
};

// BGR -> grey with OpenCV's weights; grey input is returned as is (shared).
cv::Mat to_grey(const cv::Mat& image);

}  // namespace facadeslam
