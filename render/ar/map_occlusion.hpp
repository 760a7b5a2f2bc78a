#pragma once
// What of the map stands in front of the virtual object, as a depth image
// (the camera-frame z of the nearest occluding map surface per pixel) that
// the AR view tests the object's fragments against.
//
// Labels decide what may occlude: a facade (building, window, door) is a
// surface, so its points' splats are grown and their gaps closed; a tree, a
// car or an unlabelled point is sparse structure, drawn as splats only; the
// sky is at infinity and the ground (road, pavement) is what the object
// stands on: neither occludes. A splat's radius is a share of the map's
// point spacing seen at the point's depth, so that sparse maps still cover
// their surfaces and dense ones keep their detail.
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "render/ar/virtual_object.hpp"
#include "render/projection.hpp"

namespace facadeslam::render::ar {

enum class OccluderKind : std::uint8_t { none, surface, sparse };

struct OccluderPoint {
  Eigen::Vector3d p_w;
  OccluderKind kind = OccluderKind::sparse;
};

struct OcclusionOptions {
  double surface_radius = 1.5;  // x the point spacing: splats that touch their neighbours
  double sparse_radius = 0.6;   // x the point spacing
  // A point near the camera covers no more than this: the few points just in
  // front of the object, grown larger, hid its base where nothing stands
  // (24 px lowered the occlusion IoU of the demo and street-walk; benchmarks).
  double max_radius_px = 8.0;
  int surface_close_px = 5;  // gaps of a facade's splats up to this wide are closed
};

// The median distance from a point to its nearest neighbour (over at most
// 400 evenly spread points): the map's point spacing. 0 for fewer than 2.
double point_spacing(const std::vector<OccluderPoint>& points);

// The spacing of a growing map, measured again only when the map has grown
// by a tenth: it changes slowly, the measure is quadratic in the points, and
// a stable splat size adds no flicker.
class MapSpacing {
 public:
  double of(const std::vector<OccluderPoint>& points) {
    if (spacing_ == 0.0 || points.size() > measured_at_ + measured_at_ / 10) {
      spacing_ = point_spacing(points);
      measured_at_ = points.size();
    }
    return spacing_;
  }
  // Another map (a reset): its own scale.
  void reset() { *this = MapSpacing(); }

 private:
  double spacing_ = 0.0;
  std::size_t measured_at_ = 0;
};

// CV_32FC1 of the intrinsics' size: the nearest occluder's z per pixel,
// +infinity where nothing occludes. Only `region` is drawn (the object's box:
// nothing outside it can hide the object; none: the whole image; empty:
// nothing), which keeps the cost with the object's size, not the image's.
cv::Mat occluder_depth(const std::vector<OccluderPoint>& points, const Eigen::Isometry3d& T_c_w,
                       const PinholeIntrinsics& intrinsics, double spacing, const OcclusionOptions& options = {},
                       std::optional<cv::Rect> region = std::nullopt);

// The pixels `object` covers seen through `intrinsics` from T_c_w, as a box
// clipped to the image (the whole image when a corner is behind the camera,
// empty when the object is off-screen): the region for occluder_depth.
cv::Rect object_region(const VirtualObject& object, const Eigen::Isometry3d& T_c_w,
                       const PinholeIntrinsics& intrinsics);

}  // namespace facadeslam::render::ar
