#include "sequences/synth/contact_sheet.hpp"

#include <opencv2/imgproc.hpp>

namespace facadeslam::synth {

std::vector<int> contact_sheet_frames(int frames, int count) {
  std::vector<int> indices;
  if (frames <= 0 || count <= 0) return indices;
  if (count == 1 || frames == 1) return {0};
  for (int k = 0; k < count && k < frames; ++k) {
    const int index = static_cast<int>((static_cast<long long>(k) * (frames - 1)) / (std::min(count, frames) - 1));
    if (indices.empty() || indices.back() != index) indices.push_back(index);
  }
  return indices;
}

ContactSheet::ContactSheet(std::string title, int tile_width) : title_(std::move(title)), tile_width_(tile_width) {}

void ContactSheet::add(const std::string& caption, const cv::Mat& colour, const cv::Mat& labels_bgr) {
  const int height = tile_width_ * colour.rows / colour.cols;
  cv::Mat top, bottom;
  cv::resize(colour, top, {tile_width_, height}, 0, 0, cv::INTER_AREA);
  cv::resize(labels_bgr, bottom, {tile_width_, height}, 0, 0, cv::INTER_NEAREST);
  cv::putText(top, caption, {6, 18}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
  cv::putText(top, caption, {6, 18}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  cv::Mat tile;
  cv::vconcat(top, bottom, tile);
  cv::copyMakeBorder(tile, tile, 2, 2, 2, 2, cv::BORDER_CONSTANT, cv::Scalar(255, 255, 255));
  tiles_.push_back(tile);
}

cv::Mat ContactSheet::image() const {
  if (tiles_.empty()) return {};
  cv::Mat row;
  cv::hconcat(tiles_, row);
  cv::Mat banner(28, row.cols, CV_8UC3, cv::Scalar(40, 40, 40));
  cv::putText(banner, title_, {8, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  cv::Mat sheet;
  cv::vconcat(banner, row, sheet);
  return sheet;
}

}  // namespace facadeslam::synth
