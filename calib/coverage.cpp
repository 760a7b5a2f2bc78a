#include "calib/coverage.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace facadeslam::calib {

cv::Point coverage_cell(const cv::Point2f& px, const cv::Size& image_size) {
  const int col = static_cast<int>(std::floor((px.x + 0.5) * kCoverageColumns / image_size.width));
  const int row = static_cast<int>(std::floor((px.y + 0.5) * kCoverageRows / image_size.height));
  return {std::clamp(col, 0, kCoverageColumns - 1), std::clamp(row, 0, kCoverageRows - 1)};
}

CoverageFigures compute_coverage(const std::vector<AcceptedView>& views, const cv::Size& image_size) {
  CoverageFigures figures;
  figures.cell_counts.assign(kCoverageColumns * kCoverageRows, 0);
  std::vector<cv::Point2f> all;
  for (const AcceptedView& view : views)
    for (const cv::Point2f& c : view.corners) {
      const cv::Point cell = coverage_cell(c, image_size);
      ++figures.cell_counts[cell.y * kCoverageColumns + cell.x];
      all.push_back(c);
    }
  if (all.empty()) return figures;

  const double image_area = static_cast<double>(image_size.area());
  const auto covered =
      std::count_if(figures.cell_counts.begin(), figures.cell_counts.end(), [](int n) { return n > 0; });
  figures.cell_fraction = static_cast<double>(covered) / static_cast<double>(figures.cell_counts.size());
  float x0 = all[0].x, x1 = all[0].x, y0 = all[0].y, y1 = all[0].y;
  for (const cv::Point2f& c : all) {
    x0 = std::min(x0, c.x);
    x1 = std::max(x1, c.x);
    y0 = std::min(y0, c.y);
    y1 = std::max(y1, c.y);
  }
  figures.bounding_box_fraction = std::min(1.0, double(x1 - x0) * double(y1 - y0) / image_area);
  std::vector<cv::Point2f> hull;
  cv::convexHull(all, hull);
  figures.hull_fraction = std::min(1.0, cv::contourArea(hull) / image_area);
  return figures;
}

}  // namespace facadeslam::calib
