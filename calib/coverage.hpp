#pragma once
// How well the accepted views cover the image. Distortion is only known
// where corners were seen: a calibration whose corners all sit in the
// centre extrapolates wildly towards the borders, whatever its RMS says.
#include <vector>

#include <opencv2/core.hpp>

#include "calib/view_collection.hpp"

namespace facadeslam::calib {

// The image is split into kCoverageColumns x kCoverageRows equal cells.
inline constexpr int kCoverageColumns = 8;
inline constexpr int kCoverageRows = 6;

struct CoverageFigures {
  // Share of grid cells holding at least one detected corner, [0, 1].
  double cell_fraction = 0.0;
  // Area of the axis-aligned bounding box of all corners / image area.
  double bounding_box_fraction = 0.0;
  // Area of the convex hull of all corners / image area.
  double hull_fraction = 0.0;
  // Corners per cell, row-major (kCoverageRows x kCoverageColumns).
  std::vector<int> cell_counts;
};

// The cell (column, row) a pixel falls in, clamped into the grid. The image
// area spans [-0.5, size - 0.5] (pixel centres at integer coordinates).
cv::Point coverage_cell(const cv::Point2f& px, const cv::Size& image_size);

CoverageFigures compute_coverage(const std::vector<AcceptedView>& views, const cv::Size& image_size);

}  // namespace facadeslam::calib
