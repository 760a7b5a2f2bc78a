#include "slam/init/corner_tracks.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <tuple>

#include <opencv2/video/tracking.hpp>

#include "core/util/error.hpp"
#include "core/util/assert.hpp"

namespace facadeslam {

std::vector<int> spread_strongest_corners(const std::vector<Corner>& corners, int max_count, int cell_px) {
  if (max_count <= 0) return {};
  // Strongest first; equal scores in row-major order so the result never
  // depends on the input's sort stability.
  std::vector<int> order(corners.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Corner& ca = corners[static_cast<std::size_t>(a)];
    const Corner& cb = corners[static_cast<std::size_t>(b)];
    return std::make_tuple(-ca.score, ca.y, ca.x, a) < std::make_tuple(-cb.score, cb.y, cb.x, b);
  });
  // Rank of each corner within its cell; taking rank 0 of every cell, then
  // rank 1, ... spreads the selection before it deepens it.
  std::map<std::pair<int, int>, int> seen_in_cell;
  std::vector<std::pair<int, int>> rank_and_order;  // (rank in cell, position in `order`)
  rank_and_order.reserve(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Corner& c = corners[static_cast<std::size_t>(order[k])];
    const std::pair<int, int> cell{c.x / cell_px, c.y / cell_px};
    rank_and_order.emplace_back(seen_in_cell[cell]++, static_cast<int>(k));
  }
  std::sort(rank_and_order.begin(), rank_and_order.end());
  std::vector<int> chosen;
  const std::size_t count = std::min(rank_and_order.size(), static_cast<std::size_t>(max_count));
  chosen.reserve(count);
  for (std::size_t k = 0; k < count; ++k) chosen.push_back(order[static_cast<std::size_t>(rank_and_order[k].second)]);
  return chosen;
}

CornerTracks::CornerTracks(CornerTrackOptions options) : options_(options) { validate(options_); }

void CornerTracks::check_image(const cv::Mat& grey, const char* what) const {
  if (grey.empty() || grey.type() != CV_8UC1)
    throw Error(std::string("corner tracks: ") + what + " must be a non-empty 8-bit single-channel image");
}

std::vector<cv::Mat> CornerTracks::build_pyramid(const cv::Mat& grey) const {
  // Built once per frame and reused for the forward and the backward pass
  // (and as the next frame's previous pyramid); it must use the same window
  // and level count as calcOpticalFlowPyrLK.
  std::vector<cv::Mat> pyramid;
  cv::buildOpticalFlowPyramid(grey, pyramid, cv::Size(options_.window_size, options_.window_size), options_.max_level);
  return pyramid;
}

void CornerTracks::reset(const cv::Mat& grey, const std::vector<Corner>& corners) {
  check_image(grey, "the reference image");
  for (const Corner& c : corners)
    if (c.x < 0 || c.y < 0 || c.x >= grey.cols || c.y >= grey.rows)
      throw Error("corner tracks: corner (" + std::to_string(c.x) + ", " + std::to_string(c.y) + ") lies outside the " +
                  std::to_string(grey.cols) + "x" + std::to_string(grey.rows) +
                  " reference image (corners must be level-0 pixels)");
  image_size_ = grey.size();
  previous_pyramid_ = build_pyramid(grey);
  reference_.clear();
  current_.clear();
  corner_index_.clear();
  frames_tracked_ = 0;
  for (int i : spread_strongest_corners(corners, options_.max_corners, options_.spread_cell_px)) {
    const Corner& c = corners[static_cast<std::size_t>(i)];
    reference_.emplace_back(c.x, c.y);
    current_.emplace_back(c.x, c.y);
    corner_index_.push_back(i);
  }
}

std::size_t CornerTracks::track(const cv::Mat& grey) {
  FACADESLAM_ASSERT(has_reference(), "corner tracks are reset() on a reference before track()");
  check_image(grey, "the tracked image");
  if (grey.size() != image_size_)
    throw Error("corner tracks: the tracked image is " + std::to_string(grey.cols) + "x" + std::to_string(grey.rows) +
                " but the reference was " + std::to_string(image_size_.width) + "x" +
                std::to_string(image_size_.height));
  std::vector<cv::Mat> pyramid = build_pyramid(grey);
  ++frames_tracked_;
  if (current_.empty()) {
    previous_pyramid_ = std::move(pyramid);
    return 0;
  }

  std::vector<cv::Point2f> previous, forward, backward;
  previous.reserve(current_.size());
  for (const Eigen::Vector2d& p : current_) previous.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  const cv::Size window(options_.window_size, options_.window_size);
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, options_.max_iterations,
                                  options_.epsilon);
  std::vector<unsigned char> forward_ok, backward_ok;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(previous_pyramid_, pyramid, previous, forward, forward_ok, error, window, options_.max_level,
                           criteria);
  // Backward pass starts from the forward result (no initial guess flag), so
  // it is an independent check rather than a copy of the forward flow.
  cv::calcOpticalFlowPyrLK(pyramid, previous_pyramid_, forward, backward, backward_ok, error, window,
                           options_.max_level, criteria);

  const double max_fb2 = options_.max_forward_backward_px * options_.max_forward_backward_px;
  const double border = options_.border_px;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < previous.size(); ++i) {
    if (!forward_ok[i] || !backward_ok[i]) continue;
    const double dx = backward[i].x - previous[i].x, dy = backward[i].y - previous[i].y;
    if (dx * dx + dy * dy > max_fb2) continue;
    const Eigen::Vector2d p(forward[i].x, forward[i].y);
    if (!(p.x() >= border && p.y() >= border && p.x() <= image_size_.width - 1 - border &&
          p.y() <= image_size_.height - 1 - border))
      continue;
    reference_[kept] = reference_[i];
    current_[kept] = p;
    corner_index_[kept] = corner_index_[i];
    ++kept;
  }
  reference_.resize(kept);
  current_.resize(kept);
  corner_index_.resize(kept);
  previous_pyramid_ = std::move(pyramid);
  return kept;
}

double CornerTracks::median_motion_px() const {
  if (reference_.empty()) return 0.0;
  std::vector<double> motion(reference_.size());
  for (std::size_t i = 0; i < motion.size(); ++i) motion[i] = (current_[i] - reference_[i]).norm();
  auto mid = motion.begin() + static_cast<std::ptrdiff_t>(motion.size() / 2);
  std::nth_element(motion.begin(), mid, motion.end());
  return *mid;
}

}  // namespace facadeslam
