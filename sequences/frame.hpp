#pragma once
// One image of an input sequence, as every reader delivers it.
#include <cstddef>
#include <filesystem>

#include <opencv2/core.hpp>

namespace facadeslam {

struct Frame {
  // Position in the whole sequence (0-based, counted before start/stride/limit
  // are applied), so a frame can always be traced back to its file or to a
  // ground-truth row.
  std::size_t index = 0;
  // Seconds; strictly increasing along a sequence.
  double timestamp = 0.0;
  // Always 8-bit BGR (CV_8UC3), whatever the file held.
  cv::Mat image;
  // The image file, or the video file the frame came from.
  std::filesystem::path source;
};

}  // namespace facadeslam
