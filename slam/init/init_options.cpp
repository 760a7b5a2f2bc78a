#include "slam/init/init_options.hpp"

#include <cmath>
#include <string>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

void require(bool ok, const std::string& name, const std::string& expectation) {
  if (!ok) throw Error("two-view initialiser option " + name + ": expected " + expectation);
}

bool finite_positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

void validate(const CornerTrackOptions& o) {
  require(o.max_corners >= 8, "tracking.max_corners", "an integer >= 8");
  require(o.spread_cell_px >= 4, "tracking.spread_cell_px", "an integer >= 4");
  require(o.window_size >= 5 && o.window_size % 2 == 1, "tracking.window_size", "an odd integer >= 5");
  require(o.max_level >= 0 && o.max_level <= 6, "tracking.max_level", "an integer in [0, 6]");
  require(o.max_iterations >= 1, "tracking.max_iterations", "an integer >= 1");
  require(finite_positive(o.epsilon), "tracking.epsilon", "a number > 0");
  require(finite_positive(o.max_forward_backward_px), "tracking.max_forward_backward_px", "a number > 0");
  require(std::isfinite(o.border_px) && o.border_px >= 0.0, "tracking.border_px", "a number >= 0");
}

void validate(const TwoViewOptions& o) {
  validate(o.tracking);
  require(o.min_tracks >= 8, "min_tracks", "an integer >= 8 (the eight-point minimum)");
  require(std::isfinite(o.min_image_motion_fraction) && o.min_image_motion_fraction >= 0.0 &&
              o.min_image_motion_fraction < 1.0,
          "min_image_motion_fraction", "a number in [0, 1)");
  require(finite_positive(o.match_sigma_px), "match_sigma_px", "a number > 0");
  require(o.ransac_confidence > 0.0 && o.ransac_confidence < 1.0, "ransac_confidence", "a number in (0, 1)");
  require(o.ransac_max_iterations >= 1, "ransac_max_iterations", "an integer >= 1");
  require(o.homography_ratio_threshold > 0.0 && o.homography_ratio_threshold < 1.0, "homography_ratio_threshold",
          "a number in (0, 1)");
  require(std::isfinite(o.min_point_parallax_deg) && o.min_point_parallax_deg >= 0.0 && o.min_point_parallax_deg < 90.0,
          "min_point_parallax_deg", "a number in [0, 90)");
  require(
      std::isfinite(o.min_median_parallax_deg) && o.min_median_parallax_deg >= 0.0 && o.min_median_parallax_deg < 90.0,
      "min_median_parallax_deg", "a number in [0, 90)");
  require(finite_positive(o.max_reprojection_error_px), "max_reprojection_error_px", "a number > 0");
  require(o.min_points >= 8, "min_points", "an integer >= 8");
  require(o.min_triangulated_fraction >= 0.0 && o.min_triangulated_fraction <= 1.0, "min_triangulated_fraction",
          "a number in [0, 1]");
  require(o.ambiguity_ratio > 0.0 && o.ambiguity_ratio <= 1.0, "ambiguity_ratio", "a number in (0, 1]");
  require(std::isfinite(o.pure_rotation_max_translation) && o.pure_rotation_max_translation >= 0.0,
          "pure_rotation_max_translation", "a number >= 0");
}

}  // namespace facadeslam
