#include "apps/replay/render_frame_writer.hpp"

#include <opencv2/imgcodecs.hpp>

#include "core/plot/png_file.hpp"
#include "core/util/error.hpp"

namespace facadeslam::apps {

RenderFrameWriter::RenderFrameWriter(render::ar::Mp4Writer& video, render::ar::FrameSampleSheet& sheet,
                                     std::size_t capacity)
    : video_(video), sheet_(sheet), capacity_(capacity == 0 ? 1 : capacity), thread_([this] { run(); }) {}

RenderFrameWriter::~RenderFrameWriter() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void RenderFrameWriter::rethrow_error() {
  if (error_) std::rethrow_exception(error_);
}

void RenderFrameWriter::write(std::filesystem::path png, std::string caption, cv::Mat frame) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return items_.size() < capacity_ || error_; });
  rethrow_error();
  items_.push_back({std::move(png), std::move(caption), std::move(frame)});
  lock.unlock();
  changed_.notify_all();
}

void RenderFrameWriter::finish() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
  rethrow_error();
}

void RenderFrameWriter::run() {
  for (;;) {
    Item item;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return !items_.empty() || closed_; });
      if (items_.empty()) return;  // closed and drained
      item = std::move(items_.front());
      items_.pop_front();
    }
    changed_.notify_all();  // room for the producer
    try {
      // zlib's fastest level: the frames are many and large, and level 9
      // took ~100 ms per 1280x480 frame for files only ~6 % smaller.
      plot::save_png(item.png, item.frame, {cv::IMWRITE_PNG_COMPRESSION, 1});
      video_.write(item.frame);
      sheet_.offer(item.caption, item.frame);
    } catch (...) {
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
      items_.clear();
      changed_.notify_all();
      return;
    }
  }
}

}  // namespace facadeslam::apps
