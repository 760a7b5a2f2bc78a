#include "sequences/video_source.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include <opencv2/core/utils/logger.hpp>
#include <opencv2/videoio.hpp>
#include <spdlog/spdlog.h>

#include "core/util/error.hpp"
#include "sequences/frame_selection.hpp"
#include "sequences/image_decoding.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

constexpr const char* kExpectedVideo = "expected a video file readable by OpenCV";

// Containers report 0, NaN or absurd rates when they do not know.
bool plausible_fps(double fps) { return std::isfinite(fps) && fps > 0.0 && fps <= 1000.0; }

}  // namespace

VideoSource::VideoSource(const fs::path& file, const SequenceOptions& options)
    : path_(file), options_(options), capture_(std::make_unique<cv::VideoCapture>()) {
  validate(options);
  std::error_code ec;
  if (!fs::exists(file, ec)) fail_file(file, std::string("no such file (") + kExpectedVideo + ")");
  if (fs::is_directory(file, ec)) fail_file(file, std::string("is a folder (") + kExpectedVideo + ")");
  bool opened = false;
  {
    // OpenCV tries every backend and logs each failure (GStreamer pipeline,
    // image-sequence pattern...) to stderr; our one Error below says it all,
    // so that noise is muted unless the user asked for debug output.
    const bool quiet = !spdlog::should_log(spdlog::level::debug);
    const auto previous = cv::utils::logging::getLogLevel();
    if (quiet) cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    try {
      opened = capture_->open(file.string());
    } catch (const cv::Exception&) {
      opened = false;
    }
    if (quiet) cv::utils::logging::setLogLevel(previous);
  }
  if (!opened) fail_file(file, std::string("cannot be opened as a video (") + kExpectedVideo + ")");

  const double container_fps = capture_->get(cv::CAP_PROP_FPS);
  fps_ = plausible_fps(container_fps) ? container_fps : options.fps;
  timestamps_ = VideoTimestamps(fps_);
  const double count = capture_->get(cv::CAP_PROP_FRAME_COUNT);
  frame_count_ = std::isfinite(count) && count >= 1.0 ? static_cast<std::size_t>(count) : 0;

  // Decoding the first frame now turns "opens but is not really a video"
  // into an error at open time rather than an empty sequence later.
  first_ = read_raw(true);
  if (!first_) fail_file(file, std::string("holds no decodable frame (") + kExpectedVideo + ")");
  size_ = first_->image.size();
}

VideoSource::~VideoSource() = default;

std::optional<VideoSource::Raw> VideoSource::read_raw(bool decode) {
  if (ended_) return std::nullopt;
  Raw raw;
  bool ok = false;
  try {
    ok = decode ? capture_->read(raw.image) : capture_->grab();
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok || (decode && raw.image.empty())) {
    ended_ = true;
    warn_if_short();
    return std::nullopt;
  }
  raw.position_ms = capture_->get(cv::CAP_PROP_POS_MSEC);
  ++next_index_;
  return raw;
}

void VideoSource::warn_if_short() const {
  // Container counts are estimates for some formats; only a clear shortfall
  // (a truncated or damaged file) is worth a warning.
  if (frame_count_ > next_index_ + 1)
    spdlog::warn("{}: video ended after {} frames although it announces {}", path_.string(), next_index_, frame_count_);
}

std::optional<Frame> VideoSource::next() {
  if (options_.limit != 0 && stats_.frames_read >= options_.limit) return std::nullopt;
  for (;;) {
    const std::size_t index = next_index_ - (first_ ? 1 : 0);
    const bool wanted = passes_start_and_stride(index, options_);
    std::optional<Raw> raw;
    if (first_) {
      raw = std::exchange(first_, std::nullopt);
    } else {
      // Frames before start and between strides are only grabbed, not
      // converted, which is what makes a large start cheap.
      raw = read_raw(wanted);
    }
    if (!raw) return std::nullopt;
    if (!wanted) continue;

    cv::Mat image = to_bgr8(raw->image, path_);
    if (image.size() != size_) {
      std::ostringstream what;
      what << "frame " << index << " is " << image.cols << "x" << image.rows << " but the first frame is "
           << size_.width << "x" << size_.height << " (expected every frame to have the same size)";
      fail_file(path_, what.str());
    }
    ++stats_.frames_read;
    const double timestamp = timestamps_.next(index, raw->position_ms);
    if (!timestamps_.using_positions() && !reported_rate_fallback_) {
      reported_rate_fallback_ = true;
      spdlog::debug("{}: decoder positions unusable from frame {}, timestamps at {} fps", path_.string(), index, fps_);
    }
    return Frame{index, timestamp, std::move(image), path_};
  }
}

std::size_t VideoSource::size_hint() const { return frame_count_ == 0 ? 0 : selected_count(frame_count_, options_); }

std::string VideoSource::description() const {
  std::ostringstream out;
  out << "video " << path_.string() << " (" << size_.width << "x" << size_.height << ", ";
  if (frame_count_ > 0) out << frame_count_ << " frames, ";
  out << fps_ << " fps)";
  return out.str();
}

}  // namespace facadeslam
