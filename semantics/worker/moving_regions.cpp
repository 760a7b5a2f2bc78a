#include "semantics/worker/moving_regions.hpp"

#include <algorithm>
#include <string>

#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"

namespace facadeslam::semantics {

void MovingRegions::check(const MovingRegionOptions& options) {
  const bool density_ok = options.min_density > 0.0 && options.min_density <= 1.0;
  if (options.step <= 0 || !(options.sigma_cells > 0.0) || !density_ok)
    throw Error("moving regions: a step > 0, sigma > 0 and a density in (0, 1], not step " +
                std::to_string(options.step) + ", sigma " + std::to_string(options.sigma_cells) + ", density " +
                std::to_string(options.min_density));
}

MovingRegions::MovingRegions(cv::Size size, const MovingRegionOptions& options) : options_(options) {
  check(options);
  if (size.width <= 0 || size.height <= 0) throw Error("moving regions: an empty image");
  columns_ = (size.width + options.step - 1) / options.step;
  rows_ = (size.height + options.step - 1) / options.step;
  cells_.reserve(static_cast<std::size_t>(columns_ * rows_));
  const float half = static_cast<float>(options.step) / 2.f;
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < columns_; ++c)
      cells_.emplace_back(std::min(static_cast<float>(c * options.step) + half, size.width - 1.f),
                          std::min(static_cast<float>(r * options.step) + half, size.height - 1.f));
}

void MovingRegions::set_calls(const cv::Mat& shares, const std::vector<int>& columns, const ClassVotes& class_weights,
                              const ClassSet& moving) {
  if (shares.type() != CV_32F || shares.rows != static_cast<int>(cells_.size()) ||
      shares.cols != static_cast<int>(columns.size()))
    throw Error("moving regions: one row of " + std::to_string(columns.size()) + " vote shares per cell (" +
                std::to_string(cells_.size()) + "), not " + std::to_string(shares.rows) + " x " +
                std::to_string(shares.cols));
  cv::Mat calls(rows_, columns_, CV_32F);
  for (int i = 0; i < shares.rows; ++i) {
    const float* row = shares.ptr<float>(i);
    std::size_t best = 0;
    float best_vote = -1.f;
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const float vote = row[k] * class_weights[static_cast<std::size_t>(columns[k])];
      if (vote > best_vote) {
        best_vote = vote;
        best = k;
      }
    }
    const auto call = static_cast<std::size_t>(columns[best]);
    calls.at<float>(i / columns_, i % columns_) = call < moving.size() && moving.test(call) ? 1.f : 0.f;
  }
  cv::GaussianBlur(calls, density_, cv::Size(0, 0), options_.sigma_cells, options_.sigma_cells, cv::BORDER_REFLECT);
}

double MovingRegions::density(const cv::Point2f& pixel) const {
  if (density_.empty()) return 0.0;
  const int c = std::clamp(static_cast<int>(pixel.x) / options_.step, 0, columns_ - 1);
  const int r = std::clamp(static_cast<int>(pixel.y) / options_.step, 0, rows_ - 1);
  return density_.at<float>(r, c);
}

}  // namespace facadeslam::semantics
