#pragma once
// Column sums shared by the keypoints of one image row.
//
// Every keypoint patch is 2r+1 columns of 2r+1 rows. Keypoints whose patch
// centres lie on the same row share those rows, and neighbours on a row
// (a grid, corners along an edge) share most columns too, so the vertical
// half of a patch sum is computed once per column and centre row, and each
// keypoint only adds up its 2r+1 columns. A column's sums depend only on the
// plane, the column and the centre row, never on which other keypoints share
// the strip, so a keypoint's values do not depend on the batch it comes in.
//
// Two kinds of sums, each for the planes that need them:
//  - statistics (mean and sigma modules): per column the sum of the values
//    and of their squares, in double; the rows are first summed in float as
//    deviations from the column's centre-row value, which keeps precision for
//    planes with a large offset, then turned into plain sums;
//  - regions (gradient-angle module): per column the sum of the r rows
//    above and of the r rows below the centre row (the centre row itself is
//    read from the plane);
//  - moments (moment, Hu and affine-invariant modules): per colour channel
//    and column the sums of dy^q I over the rows, q up to the channel's
//    moment order (patch_moments.hpp), so that a keypoint only does the
//    horizontal half; bit-identical to compute_patch_moments.
#include <array>
#include <utility>
#include <vector>

#include "semantics/descriptor/modules/mean_std.hpp"
#include "semantics/descriptor/modules/patch_moments.hpp"
#include "semantics/descriptor/planes.hpp"
#include "semantics/descriptor/prepared_image.hpp"

namespace facadeslam::semantics {

class StripSums {
 public:
  // Which planes get which sums (others are left alone); moment_order[c]
  // is colour channel c's moment order, -1 for none.
  void configure(const PreparedImage& image, int radius, PlaneSet statistics, PlaneSet regions,
                 const std::array<int, 3>& moment_order = {-1, -1, -1});

  // Sums for the patches centred on image row `row` at the image columns
  // `centres` (sorted ascending): every column within the radius of one.
  void compute(int row, const std::vector<int>& centres);

  bool has_statistics(PlaneId p) const { return statistics_.test(plane_bit(p)); }
  bool has_regions(PlaneId p) const { return regions_.test(plane_bit(p)); }
  bool has_moments(int channel) const { return moment_order_[static_cast<std::size_t>(channel)] >= 0; }
  bool any() const { return (statistics_ | regions_).any() || has_moments(0) || has_moments(1) || has_moments(2); }

  // The patch centred on image column x of the computed row (x must be one of
  // the centres given to compute()). Same definitions as patch_mean_std and
  // gradient_region_means.
  MeanStd mean_std(PlaneId p, int x) const;
  std::array<double, 5> region_means(PlaneId p, int x) const;
  // Moments up to the configured order of colour channel c's patch.
  void moments(int channel, int x, PatchMoments& out) const;

 private:
  struct Columns {
    std::vector<float> sum, squares;           // statistics: deviations from the centre value
    std::vector<double> total, total_squares;  // statistics: sums of values and squares
    std::vector<float> top, bottom;            // regions (the centre row is read from the plane)
    std::vector<float> moments;                // moments: sum of dy^q I, interleaved (kMomentColumnStride per column)
  };
  void compute_statistics(const cv::Mat& plane, int first, int last, Columns& c) const;
  void compute_regions(const cv::Mat& plane, int first, int last, Columns& c) const;
  void compute_moments(const cv::Mat& plane, int order, int first, int last, Columns& c) const;

  const PreparedImage* image_ = nullptr;
  int radius_ = 0;
  int row_ = -1;
  PlaneSet statistics_, regions_;
  std::array<int, 3> moment_order_{-1, -1, -1};
  std::array<Columns, kPlaneCount> columns_;  // per plane; each vector indexed by padded column
  std::vector<std::pair<int, int>> spans_;    // merged padded column ranges [first, last)
};

}  // namespace facadeslam::semantics
