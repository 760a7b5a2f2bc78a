#pragma once
// A region-level detector of moving things (cars), from the forest's own
// calls. One by one the forest calls a close-up car's points building,
// pavement or road (street-traffic: 20 % of them car by their own votes),
// but where it does call car it is mostly right (80 % precision on a dense
// grid of the scene's frames), and the car fills a region. So the keyframe
// is classified on a grid of cells too, each cell's call (the arg-max of its
// votes times the class prior) marked where it is a moving class, the marks
// smoothed (a Gaussian of `sigma_cells`), and a point lies in a moving
// region where the smoothed density reaches `min_density`: a tenth of the
// cells around it called a moving class. The grid's cells go through the
// descriptor with the keyframe's points (its planes are computed once per
// image), ~1200 more points on a 640 x 480 keyframe at a 16-pixel step.
#include <vector>

#include <opencv2/core.hpp>

#include "core/map/map_point.hpp"
#include "core/map/semantic_classes.hpp"

namespace facadeslam::semantics {

struct MovingRegionOptions {
  int step = 16;             // grid cell size, pixels; 0 = no region detection
  double sigma_cells = 3.0;  // smoothing of the moving calls, cells
  double min_density = 0.1;  // share of (smoothed) moving calls that makes a region
};

class MovingRegions {
 public:
  // Throws Error for options out of range (a step of 0 included: no grid).
  static void check(const MovingRegionOptions& options);
  // The grid of an image of `size`; throws Error for options out of range.
  MovingRegions(cv::Size size, const MovingRegionOptions& options);

  // Cell centres to classify, row by row.
  const std::vector<cv::Point2f>& cells() const { return cells_; }

  // The forest's vote shares at the cells (one row per cell, one column per
  // entry of `columns`, the forest's class ids), weighed by `class_weights`
  // (the class prior) before each cell's arg-max; `moving`: the classes
  // that move.
  void set_calls(const cv::Mat& shares, const std::vector<int>& columns, const ClassVotes& class_weights,
                 const ClassSet& moving);

  // The smoothed density of moving calls at a pixel (0 before set_calls),
  // and whether it makes a region.
  double density(const cv::Point2f& pixel) const;
  bool contains(const cv::Point2f& pixel) const { return density(pixel) >= options_.min_density; }

 private:
  MovingRegionOptions options_;
  int columns_ = 0, rows_ = 0;
  std::vector<cv::Point2f> cells_;
  cv::Mat density_;  // CV_32F, rows_ x columns_
};

}  // namespace facadeslam::semantics
