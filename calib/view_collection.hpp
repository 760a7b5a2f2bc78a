#pragma once
// Reads the calibration images one at a time, finds the board in each and
// sorts them into usable views and rejected images (with a reason each):
//   - the file cannot be decoded as an image,
//   - no complete board was found,
//   - the board is blurred (edge width above the threshold),
//   - the view duplicates an earlier accepted one.
// Images are processed in the given (sorted) order, so of two duplicates the
// first is kept.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "calib/board.hpp"
#include "calib/view_quality.hpp"

namespace facadeslam::calib {

// Zhang's method needs at least three views of a plane to determine the
// four pinhole intrinsics plus distortion; fewer is an error. (More, and
// varied, views make the result trustworthy: 10-20 is a good number.)
inline constexpr std::size_t kMinimumViews = 3;

struct AcceptedView {
  std::filesystem::path file;
  std::vector<cv::Point2f> corners;  // board.corner_count(), row by row
  double edge_width_px = 0.0;        // black-to-white rise width; NaN when not measurable
  bool sector_based = false;         // corners from the fallback detector
};

struct RejectedImage {
  std::filesystem::path file;
  std::string reason;
};

struct ViewCollection {
  cv::Size image_size;  // shared by every decoded image
  std::size_t image_count = 0;
  std::vector<AcceptedView> views;
  std::vector<RejectedImage> rejected;
};

// Throws Error when
//   - a decoded image differs in size from the first one (naming that file,
//     its size and the expected size),
//   - no image contains the board ("no image of N contained a 9x6 board"),
//   - fewer than kMinimumViews views are usable (listing the rejections).
ViewCollection collect_views(const std::vector<std::filesystem::path>& files, const BoardSpec& board,
                             const QualityThresholds& thresholds = {});

// "640x480"
std::string size_text(const cv::Size& size);

}  // namespace facadeslam::calib
