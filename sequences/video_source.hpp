#pragma once
// A video file read through cv::VideoCapture (any container/codec the
// installed OpenCV backends decode).
//
// Timestamps: the decoder's CAP_PROP_POS_MSEC while it is sane, else
// continued at the container's frame rate (SequenceOptions::fps when the
// container has none); see VideoTimestamps.
// End of stream: the first frame the decoder cannot deliver ends the
// sequence (a decoder cannot tell a damaged frame from the end), with a
// warning when the container announced more frames. So ReadStats never
// counts corrupt frames for a video.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "sequences/frame_source.hpp"
#include "sequences/sequence_options.hpp"
#include "sequences/video_timestamps.hpp"

namespace cv {
class VideoCapture;
}

namespace facadeslam {

class VideoSource : public FrameSource {
 public:
  // Opens the file and decodes its first frame. Error naming the file when
  // it is missing, cannot be opened or holds no decodable frame.
  VideoSource(const std::filesystem::path& file, const SequenceOptions& options);
  ~VideoSource() override;

  std::optional<Frame> next() override;
  // Frames selected out of the container's frame count; 0 when it has none.
  std::size_t size_hint() const override;
  std::string description() const override;

  double frame_rate() const { return fps_; }
  cv::Size frame_size() const { return size_; }

 private:
  struct Raw {
    cv::Mat image;
    double position_ms = 0.0;
  };
  // Decodes (or, when `decode` is false, only advances past) the next raw frame.
  std::optional<Raw> read_raw(bool decode);
  void warn_if_short() const;

  std::filesystem::path path_;
  SequenceOptions options_;
  std::unique_ptr<cv::VideoCapture> capture_;
  double fps_ = 0.0;
  std::size_t frame_count_ = 0;  // from the container; 0 = unknown
  cv::Size size_;
  std::optional<Raw> first_;    // frame 0, decoded when opening
  std::size_t next_index_ = 0;  // index of the next raw frame
  bool ended_ = false;
  VideoTimestamps timestamps_{1.0};  // rate set once the container is open
  bool reported_rate_fallback_ = false;
};

}  // namespace facadeslam
