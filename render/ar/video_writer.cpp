#include "render/ar/video_writer.hpp"

#include <system_error>

#include <opencv2/videoio.hpp>

#include "core/util/error.hpp"

namespace facadeslam::render::ar {

Mp4Writer::Mp4Writer(std::filesystem::path path, double fps, cv::Size frame_size)
    : path_(std::move(path)), size_(frame_size) {
  // Same folder (rename stays atomic), same extension (the container is
  // chosen by it).
  // Built by appending: GCC 12 warns falsely on "." + s.
  std::string name = ".";
  name.append(path_.stem().string()).append(".partial").append(path_.extension().string());
  temporary_ = path_.parent_path() / name;
  // H.264 first; Debian's OpenCV reaches it through FFmpeg's libx264 when
  // that is present. Each attempt is a real open of the file, the only way
  // to learn whether an encoder exists.
  for (const char* candidate : {"avc1", "mp4v"}) {
    auto writer = std::make_unique<cv::VideoWriter>();
    const int code = cv::VideoWriter::fourcc(candidate[0], candidate[1], candidate[2], candidate[3]);
    if (writer->open(temporary_.string(), cv::CAP_FFMPEG, code, fps, size_, true) && writer->isOpened()) {
      writer_ = std::move(writer);
      fourcc_ = candidate;
      break;
    }
  }
  if (!writer_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    throw Error(path_.string() + ": OpenCV cannot write an MP4 file here (neither avc1 nor mp4v opens)");
  }
}

Mp4Writer::~Mp4Writer() {
  if (finished_) return;
  if (writer_) writer_->release();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

std::string Mp4Writer::codec_name() const { return fourcc_ == "avc1" ? "H.264" : "MPEG-4 part 2"; }

void Mp4Writer::write(const cv::Mat& frame) {
  if (finished_) throw Error(path_.string() + ": the video is already finished");
  if (frame.size() != size_ || frame.type() != CV_8UC3)
    throw Error(path_.string() + ": a video frame must be 8-bit BGR of " + std::to_string(size_.width) + "x" +
                std::to_string(size_.height) + " pixels");
  writer_->write(frame);
  ++frames_;
}

void Mp4Writer::finish() {
  if (finished_) return;
  writer_->release();
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error) throw Error(path_.string() + ": cannot move the finished video into place: " + error.message());
  finished_ = true;
}

}  // namespace facadeslam::render::ar
