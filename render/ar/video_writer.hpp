#pragma once
// An MP4 file of rendered frames through cv::VideoWriter (OpenCV's FFmpeg
// back end): H.264 ("avc1") when the build offers an encoder for it, else
// MPEG-4 part 2 ("mp4v"). Written to a temporary file beside the target and
// renamed into place by finish(), so that an interrupted run never leaves a
// half-written video under the final name.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

namespace cv {
class VideoWriter;
}

namespace facadeslam::render::ar {

class Mp4Writer {
 public:
  // Opens the temporary file; Error naming the file when no codec opens.
  Mp4Writer(std::filesystem::path path, double fps, cv::Size frame_size);
  ~Mp4Writer();  // without finish(): the temporary file is removed
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;

  // "avc1" or "mp4v".
  const std::string& fourcc() const { return fourcc_; }
  // A readable name of the codec: "H.264" or "MPEG-4 part 2".
  std::string codec_name() const;

  // A CV_8UC3 BGR frame of the size given at construction.
  void write(const cv::Mat& frame);
  std::size_t frames() const { return frames_; }
  // Closes the file and renames it into place.
  void finish();

 private:
  std::filesystem::path path_, temporary_;
  cv::Size size_;
  std::string fourcc_;
  std::unique_ptr<cv::VideoWriter> writer_;
  std::size_t frames_ = 0;
  bool finished_ = false;
};

}  // namespace facadeslam::render::ar
