#include "render/ar/contact_sheet.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace facadeslam::render::ar {

FrameSampleSheet::FrameSampleSheet(std::string title, int tiles, int columns, int tile_width)
    : title_(std::move(title)),
      tiles_(static_cast<std::size_t>(std::max(1, tiles))),
      columns_(std::max(1, columns)),
      tile_width_(std::max(16, tile_width)) {}

void FrameSampleSheet::offer(const std::string& caption, const cv::Mat& frame_bgr) {
  const std::size_t index = offered_++;
  if (index % stride_ != 0) return;
  const double scale = static_cast<double>(tile_width_) / frame_bgr.cols;
  cv::Mat thumbnail;
  cv::resize(frame_bgr, thumbnail, cv::Size(tile_width_, std::max(1, static_cast<int>(frame_bgr.rows * scale + 0.5))),
             0, 0, cv::INTER_AREA);
  kept_.push_back({index, caption, thumbnail});
  // Twice the tiles kept: halve them, keeping every other stride.
  if (kept_.size() >= 2 * tiles_) {
    stride_ *= 2;
    std::erase_if(kept_, [&](const Tile& t) { return t.index % stride_ != 0; });
  }
}

cv::Mat FrameSampleSheet::image() const {
  if (kept_.empty()) return {};
  // `tiles_` of the kept frames, evenly spread, first and last included.
  std::vector<const Tile*> chosen;
  const std::size_t n = std::min(tiles_, kept_.size());
  for (std::size_t i = 0; i < n; ++i) chosen.push_back(&kept_[n == 1 ? 0 : i * (kept_.size() - 1) / (n - 1)]);
  const int tile_height = chosen.front()->thumbnail.rows;
  const int caption_height = 22, title_height = 34, gap = 6;
  const int columns = std::min<int>(columns_, static_cast<int>(chosen.size()));
  const int rows = (static_cast<int>(chosen.size()) + columns - 1) / columns;
  cv::Mat sheet(title_height + rows * (tile_height + caption_height + gap) + gap, columns * (tile_width_ + gap) + gap,
                CV_8UC3, cv::Scalar(40, 40, 40));
  cv::putText(sheet, title_, {gap + 2, title_height - 11}, cv::FONT_HERSHEY_SIMPLEX, 0.7, cv::Scalar::all(235), 1,
              cv::LINE_AA);
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const int column = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    const int x = gap + column * (tile_width_ + gap);
    const int y = title_height + row * (tile_height + caption_height + gap);
    const cv::Mat& thumbnail = chosen[i]->thumbnail;
    thumbnail(cv::Rect(0, 0, thumbnail.cols, std::min(thumbnail.rows, tile_height)))
        .copyTo(sheet(cv::Rect(x, y, thumbnail.cols, std::min(thumbnail.rows, tile_height))));
    cv::putText(sheet, chosen[i]->caption, {x + 2, y + tile_height + caption_height - 7}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                cv::Scalar::all(220), 1, cv::LINE_AA);
  }
  return sheet;
}

}  // namespace facadeslam::render::ar
