#pragma once
// The interface every sequence reader implements. Frames are decoded one at
// a time as next() is called: a long sequence is never held in memory.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/image/frame.hpp"

namespace facadeslam {

struct ReadStats {
  std::size_t frames_read = 0;             // frames delivered by next()
  std::size_t frames_skipped_corrupt = 0;  // undecodable images passed over (policy skip)
  std::vector<std::filesystem::path> corrupt_paths;
  // The time added to each pass's timestamps when the frames are played
  // more than once (looping_source.hpp): {0, ...}; empty for a single pass.
  std::vector<double> pass_time_offsets_s;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  FrameSource() = default;
  FrameSource(const FrameSource&) = delete;
  FrameSource& operator=(const FrameSource&) = delete;

  // The next frame, or nothing at the end of the sequence. Throws
  // facadeslam::Error on bad input (see the readers for the cases).
  virtual std::optional<Frame> next() = 0;
  // Frames expected after start/stride/limit (corrupt images not yet known
  // are included); 0 when unknown (a video without a frame count).
  virtual std::size_t size_hint() const = 0;
  virtual const ReadStats& stats() const { return stats_; }
  // One line for logs and reports, e.g. "image folder data/seq (218 images)".
  virtual std::string description() const = 0;
  // The image files the frames will be decoded from, in order, when the
  // reader knows them before reading (image folders and lists; empty for a
  // video): what goes with each frame can be checked before the run.
  virtual std::vector<std::filesystem::path> image_files() const { return {}; }

 protected:
  ReadStats stats_;
};

}  // namespace facadeslam
