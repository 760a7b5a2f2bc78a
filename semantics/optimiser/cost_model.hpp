#pragma once
// The GA's time term: a genome's extraction cost relative to cv::SIFT's on
// the same keypoints, modelled from what the genome asks the descriptor to
// compute instead of measured, so that a genome's fitness depends on the
// genome and the data only (the same on 1 or 2 threads, MPI ranks, a resumed
// run and a loaded machine).
//
// Every cost is a share of cv::SIFT's CPU time on the calibration bench: a
// 640x480 facade, keypoints on a 9-pixel grid (3888), SIFT's patch matching
// a radius-10 patch, one OpenCV thread. Per-image costs (prepare(): the
// planes) and per-keypoint costs (extract(): the modules, for all the grid's
// keypoints) are both shares of that one figure, so their sum is the
// genome's ratio on the bench when SIFT's patch is radius 10; other radii
// divide by SIFT's own cost at that radius (`sift`). The costs come from
// `bench_ga_cost_model` (docs/benchmarks.md); configs/optimise.yaml holds the
// shipped numbers, the defaults below are the same.
#include <array>
#include <cstddef>

#include <nlohmann/json_fwd.hpp>

#include "semantics/descriptor/descriptor_params.hpp"

namespace facadeslam {
class ConfigNode;
template <class Options>
class SettingsTable;
}  // namespace facadeslam

namespace facadeslam::semantics {

struct CostModel {
  // Per image, paid once whatever the keypoints (prepare()).
  double equalise = 0.0092;      // equalising the luma and splitting the channels: any value reading a plane
  double blur_per_tap = 0.0020;  // Gaussian blur, per tap of its kernel (kernel 1: no blur)
  // Converting to each colour space (kColourSpaces order: RGB, Lab, Luv, XYZ,
  // HSV, HLS, YCrCb, opponent), beyond writing its planes; paid when a colour
  // or gradient plane is read.
  std::array<double, 8> colour_space{0.0001, 0.0376, 0.0412, 0.0004, 0.0112, 0.0133, 0.0000, 0.0004};
  double colour_plane = 0.0015;      // one colour channel as a float plane
  double angle_plane = 0.0050;       // one gradient-angle plane (Sobel or Scharr)
  double edge_distance = 0.0489;     // grey image, Canny and the distance to its edges
  double gevers_l_plane = 0.0018;    // one Gevers l plane
  double gevers_c_plane = 0.0039;    // one Gevers c plane (an arctangent per pixel)
  double geusebroek_plane = 0.0032;  // one Geusebroek plane (H or C)
  // Per keypoint, all the grid's keypoints, at patch radius 10.
  // Walking the keypoints and writing the rows (any active value; the
  // position values themselves cost next to nothing).
  double position = 0.0018;
  // Mean and sigma over the patch of one plane (colour, Gevers, Geusebroek, edge distance).
  double statistics_plane = 0.0031;
  // A colour channel's moments up to order 2, 3, 4, 5 (shared by the moment,
  // Hu and affine modules: the highest order any of them needs is paid once).
  std::array<double, 4> moments{0.0073, 0.0074, 0.0097, 0.0122};
  double hu = 0.0001;      // one Hu invariant, beyond its channel's moments
  double affine = 0.0005;  // one affine moment invariant, beyond its channel's moments
  // A channel's singular values sigma1..sigma_k for its highest active k = 1, 2, 3.
  std::array<double, 3> singular_values{0.0184, 0.0379, 0.0994};
  double gradient_angles = 0.0050;  // a channel's region means and differences of the gradient angles
  // Each active value: what the parts, each timed alone, miss together
  // (the values' columns, many planes sharing the cache), from the genome
  // with all 185 values.
  double per_value = 0.0;
  // How per-keypoint costs grow with the patch: cost at radius r is the cost
  // at 10 times ((2r+1)/21)^exponent, from radii 10 and 3 (the strip sums
  // shared along a row leave the statistics flat and the moments and angles
  // nearly so; the singular values' steps grow with the side).
  double statistics_exponent = 0.00, moments_exponent = 0.35, singular_values_exponent = 0.96,
         gradient_angles_exponent = 0.25;
  // cv::SIFT's cost with the patch of radius 3, 4, ..., 10 (its keypoint
  // size follows the genome's patch), relative to radius 10.
  std::array<double, 8> sift{0.2520, 0.3073, 0.3659, 0.4831, 0.5676, 0.6729, 0.7859, 1.0000};

  friend bool operator==(const CostModel&, const CostModel&) = default;
};

// One genome's modelled cost, split as the model adds it up (shares of
// cv::SIFT's time at radius 10; `ratio` divides by SIFT's at the genome's radius).
struct CostBreakdown {
  double per_image = 0.0;     // the planes
  double per_keypoint = 0.0;  // the modules
  double ratio = 0.0;         // (per_image + per_keypoint) / sift[radius]
};

CostBreakdown modelled_cost(const DescriptorParams& params, const CostModel& model);
// The modelled ratio of the genome's extraction time to cv::SIFT's on the same keypoints.
inline double modelled_time_ratio(const DescriptorParams& params, const CostModel& model) {
  return modelled_cost(params, model).ratio;
}

// Reads a `cost_model:` mapping over `model` (every key optional; unknown keys
// and negative costs are errors naming the file and key).
void read_cost_model(const ConfigNode& node, CostModel& model);
// The `cost_model:` keys, each bound once to its member (read and written).
const SettingsTable<CostModel>& cost_model_settings();
// Every figure of the model, in the config's layout (the run's settings).
nlohmann::json to_json(const CostModel& model);

}  // namespace facadeslam::semantics
