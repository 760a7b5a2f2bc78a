#pragma once
// The part shared by the image-folder and TUM-list readers: a list of image
// files with their timestamps, decoded one at a time as next() is called.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "sequences/frame_source.hpp"
#include "sequences/sequence_options.hpp"

namespace facadeslam {

struct ImageEntry {
  std::size_t index = 0;  // position in the whole sequence
  double timestamp = 0.0;
  std::filesystem::path path;
};

// Keeps the entries that start/stride/limit select. Error naming `origin`
// when none are left although the sequence is not empty.
std::vector<ImageEntry> select_entries(std::vector<ImageEntry> all, const SequenceOptions& options,
                                       const std::filesystem::path& origin);

class ImageListSource : public FrameSource {
 public:
  // `selected` are the frames to deliver, in order (already through
  // select_entries); `what` names the input for description(), e.g.
  // "image folder data/seq", to which the frame count is appended.
  ImageListSource(std::vector<ImageEntry> selected, CorruptPolicy on_corrupt, std::string what);

  // Decodes the next image. An undecodable one is an Error naming it under
  // CorruptPolicy::stop, or a warning + ReadStats count under skip. An image
  // whose size differs from the first frame's is always an Error.
  std::optional<Frame> next() override;
  std::size_t size_hint() const override { return entries_.size(); }
  std::string description() const override;
  std::vector<std::filesystem::path> image_files() const override;

 private:
  void check_size(const cv::Mat& image, const std::filesystem::path& path);

  std::vector<ImageEntry> entries_;
  CorruptPolicy on_corrupt_;
  std::string what_;
  std::size_t next_entry_ = 0;
  cv::Size expected_size_;
  std::filesystem::path first_path_;
};

}  // namespace facadeslam
