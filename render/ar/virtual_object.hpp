#pragma once
// The virtual object of the augmented view: a cube standing on a plane of the
// map (the ground, or a facade it then sticks out of), anchored in the world:
// its pose is fixed once, when it is placed, so it stays put while the camera
// moves. Its faces carry a checker pattern (placed corners a test can find)
// and are lit by a light fixed in the object's frame.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "render/ar/plane_finder.hpp"

namespace facadeslam::render::ar {

struct VirtualObject {
  // Object frame: origin at the centre of the face resting on the plane, z
  // along the plane's normal on the cameras' side, x and y in the plane.
  Eigen::Isometry3d T_w_o = Eigen::Isometry3d::Identity();
  double size = 1.0;  // edge length, map units
  // Per face edge; odd, so that every face has the body colour in all four
  // corners: at each corner of the cube three faces of one colour meet, and
  // their different shading makes the corner a clean junction.
  int checker_squares = 5;

  // The cube's 8 corners in the world: bottom face (z = 0) first, counter-
  // clockwise about z, then the top face in the same order.
  std::array<Eigen::Vector3d, 8> corners_w() const;
  // The interior checker corners (X-junctions) of each face, in the world,
  // with the outward normal of their face: (checker_squares - 1)^2 per face.
  struct FacePoint {
    Eigen::Vector3d p_w, face_normal_w;
  };
  std::vector<FacePoint> checker_corners_w() const;
};

// Whether the segment from `eye_w` to `p_w` passes through the cube before
// it reaches p_w (p_w hidden behind or inside it, seen from eye_w). Points on
// the cube's surface itself count as visible.
bool hides(const VirtualObject& object, const Eigen::Vector3d& eye_w, const Eigen::Vector3d& p_w);

// A triangle mesh of the cube for drawing: per vertex the world position,
// the face's outward normal and the face coordinates (0..1 along each edge).
struct ObjectVertex {
  Eigen::Vector3d p_w, normal_w;
  Eigen::Vector2d face_uv;
};
std::vector<ObjectVertex> object_triangles(const VirtualObject& object);

struct PlacementOptions {
  // Edge length as a fraction of the distance from the reference camera to
  // the anchor point, so that the cube looks the same size in any map scale.
  double size_fraction = 0.15;
  // Turned about the plane's normal from the camera's x axis, so that the
  // camera sees two of its sides and not one square face.
  double yaw_deg = 30.0;
};

// Stands a cube on `fit` (inliers among `points_w`), seen from the reference
// camera T_w_ref (camera -> world; the newest keyframe, say): its anchor is
// the per-axis median of the inliers nearest the camera's optical axis,
// projected onto the plane; its x axis is the camera's x axis in the plane
// turned by yaw_deg, its up side the camera's side. Nothing if the plane passes through the
// camera or has no inliers.
std::optional<VirtualObject> place_on_plane(const PlaneFit& fit, const std::vector<Eigen::Vector3d>& points_w,
                                            const Eigen::Isometry3d& T_w_ref, const PlacementOptions& options = {});

}  // namespace facadeslam::render::ar
