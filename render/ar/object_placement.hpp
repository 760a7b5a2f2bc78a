#pragma once
// Where the augmented view's object stands: on the ground, as phone AR and
// PTAM's own demo put objects, in front of the reference camera; on the
// map's dominant plane (often a facade, which it then sticks out of) only
// when the map shows no ground.
//
// The ground, in order of evidence: the points labelled road or pavement,
// else the lowest points below the cameras; either way a plane whose normal
// is within 30 degrees of the cameras' up (the keyframes are upright) with
// the cameras above it. The anchor is among the plane's points from the
// median to the 80th percentile of depth in front of the reference camera,
// so that the object stands ahead rather than at its feet or the street's end.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "render/ar/plane_finder.hpp"
#include "render/ar/virtual_object.hpp"

namespace facadeslam::render::ar {

struct PlacementPoint {
  Eigen::Vector3d p_w;
  bool labelled_ground = false;  // road or pavement
};

struct ObjectPlacement {
  VirtualObject object;
  PlaneFit fit;            // inliers index the points given
  bool on_ground = false;  // else the dominant plane
  // On the ground: points this near its plane are the ground itself, which
  // never hides what stands on it (the occluders leave them out).
  double ground_band = 0.0;
  std::string reason;  // which evidence found the plane, for the report
};

// Nothing when no plane has enough points. `keyframes_T_c_w`: at least one
// (the last is the reference camera).
std::optional<ObjectPlacement> place_object(const std::vector<PlacementPoint>& points,
                                            const std::vector<Eigen::Isometry3d>& keyframes_T_c_w,
                                            const PlacementOptions& options = {});

}  // namespace facadeslam::render::ar
