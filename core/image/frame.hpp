#pragma once
// One input frame, the only frame type: a sequence reader creates it, the
// system adds its pyramid, the tracker tracks it, and a frame the tracker
// chooses becomes a keyframe holding the same images. `index` traces it back
// to its file and to a ground-truth row everywhere (reports, keyframes, logs).
#include <cstddef>
#include <filesystem>
#include <memory>

#include <opencv2/core.hpp>

#include "core/image/image_pyramid.hpp"

namespace facadeslam {

struct Frame {
  // Position in the whole sequence (0-based, counted before start/stride/limit
  // are applied).
  std::size_t index = 0;
  // Seconds; strictly increasing along a sequence.
  double timestamp = 0.0;
  // Always 8-bit BGR (CV_8UC3), whatever the file held; may be empty in
  // tests that work on grey pyramids only.
  cv::Mat colour;
  // The image file, or the video file the frame came from (empty for
  // frames made in memory).
  std::filesystem::path source{};
  // Grey pyramid with FAST corners per level; made once per frame by the
  // system (System::process) and shared, never copied, from then on.
  std::shared_ptr<const ImagePyramid> pyramid{};
};

}  // namespace facadeslam
