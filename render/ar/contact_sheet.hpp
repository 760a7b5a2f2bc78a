#pragma once
// A contact sheet of a replay's augmented frames: a bounded sample of the
// frames, spread evenly over the run, in a grid with captions and a title.
// Frames arrive one by one without a known total, so the sample keeps every
// stride-th frame and doubles the stride when it is full (memory stays
// bounded on any sequence length).
#include <cstddef>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::render::ar {

class FrameSampleSheet {
 public:
  // `tiles` frames on the sheet (at most), each scaled to `tile_width`
  // pixels wide, `columns` per row.
  FrameSampleSheet(std::string title, int tiles = 12, int columns = 3, int tile_width = 640);

  // Offers the n-th frame (counting from 0, one call per frame in order).
  void offer(const std::string& caption, const cv::Mat& frame_bgr);
  bool empty() const { return kept_.empty(); }
  // The sheet, CV_8UC3; empty when no frame was offered.
  cv::Mat image() const;

 private:
  struct Tile {
    std::size_t index;
    std::string caption;
    cv::Mat thumbnail;
  };
  std::string title_;
  std::size_t tiles_;
  int columns_, tile_width_;
  std::size_t offered_ = 0, stride_ = 1;
  std::vector<Tile> kept_;
};

}  // namespace facadeslam::render::ar
