#pragma once
// The rendered frames of `replay --render` written on their own thread: PNG
// and H.264 encoding cost several times the drawing, and on the replay thread
// they would hold up the next frame's tracking. The queue is bounded (a few
// frames), so a slow disk slows the replay rather than filling memory; the
// replay thread waits on a condition variable when it is full, never a sleep.
// Frames are written in the order given (the video needs it).
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>

#include <opencv2/core.hpp>

#include "render/ar/contact_sheet.hpp"
#include "render/ar/video_writer.hpp"

namespace facadeslam::apps {

class RenderFrameWriter {
 public:
  // Writes into `video` and `sheet`, which must outlive it (or finish()).
  RenderFrameWriter(render::ar::Mp4Writer& video, render::ar::FrameSampleSheet& sheet, std::size_t capacity = 4);
  ~RenderFrameWriter();  // stops after the queued frames; errors are dropped (use finish())
  RenderFrameWriter(const RenderFrameWriter&) = delete;
  RenderFrameWriter& operator=(const RenderFrameWriter&) = delete;

  // Queues a frame (CV_8UC3; the writer keeps this Mat, so do not draw into
  // it again) for `png` (atomically), the video and the contact sheet. Waits
  // while the queue is full. Rethrows the writer thread's error, if any.
  void write(std::filesystem::path png, std::string caption, cv::Mat frame);
  // Writes what is queued, stops the thread; rethrows its error, if any.
  void finish();

 private:
  struct Item {
    std::filesystem::path png;
    std::string caption;
    cv::Mat frame;
  };
  void run();
  void rethrow_error();

  render::ar::Mp4Writer& video_;
  render::ar::FrameSampleSheet& sheet_;
  const std::size_t capacity_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Item> items_;
  bool closed_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: starts once the members above exist
};

}  // namespace facadeslam::apps
