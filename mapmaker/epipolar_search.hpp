#pragma once
// New map points for a new keyframe (PTAM's AddSomeMapPoints): each strong
// FAST corner of the new keyframe that is not near an existing measurement
// defines a ray; the ray's plausible depth range (from the keyframe's scene
// depth statistics) projects to a segment of the epipolar line in a
// neighbouring keyframe; the FAST corners of the same pyramid level near that
// segment are compared with the corner's 8x8 patch (zero-mean SSD), the best
// is refined to sub-pixel and triangulated, and the point is kept if it
// reprojects well in both views with enough parallax.
//
// Map maker thread only: it reads keyframe measurements and poses (poses
// under the map's shared lock, taken inside).
#include <array>
#include <memory>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/map/map.hpp"
#include "mapmaker/map_maker_options.hpp"

namespace facadeslam {

struct EpipolarSearchStats {
  int candidates = 0;                                        // corners tried
  int matched = 0;                                           // a patch match was found
  int triangulated = 0;                                      // kept as new points
  std::array<int, kPyramidLevels> triangulated_per_level{};  // ... by source level
};

// Creates points with their source in `newest` and measurements in both
// keyframes; returns them unpublished (the caller adds them to the map).
NewPoints epipolar_new_points(Map& map, const Camera& camera, const std::shared_ptr<KeyFrame>& newest,
                              const std::shared_ptr<KeyFrame>& other, const EpipolarSearchOptions& options,
                              EpipolarSearchStats* stats = nullptr);

// Linear (DLT) triangulation of a point from two unit-plane rays and poses;
// returns nothing when the rays are near parallel or the point is behind
// either camera.
std::optional<Eigen::Vector3d> triangulate_rays(const SE3d& T_a_w, const Eigen::Vector3d& ray_a, const SE3d& T_b_w,
                                                const Eigen::Vector3d& ray_b);

}  // namespace facadeslam
