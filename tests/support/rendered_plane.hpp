#pragma once
// A textured plane rendered exactly from any camera pose, for the tracker
// tests: world frame = the source camera's frame, plane Z = plane_depth,
// texture centred on the optical axis. Views are homography warps of the
// texture rendered at 4x resolution and box-averaged down (no aliasing, and
// the same pixel-centre convention as the pyramid).
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera/camera.hpp"
#include "core/image/image_pyramid.hpp"
#include "core/lie/se3.hpp"
#include "core/map/map_point.hpp"

namespace facadeslam::test {

struct RenderedPlane {
  cv::Mat texture;           // 8-bit grey
  double texel = 0.004;      // metres per texture pixel
  double plane_depth = 2.0;  // plane Z in the world (= source camera) frame
};

// Random rectangles of many sizes and grey levels, lightly blurred; deterministic.
RenderedPlane make_plane(int seed = 1);

// 640x480 pinhole camera, f = 500.
Camera test_camera();

// The plane seen from T_c_w through `camera` (a distortion-free pinhole).
cv::Mat render(const RenderedPlane& plane, const Camera& camera, const SE3d& T_c_w);

// Camera pose at `distance` from the plane along the world Z axis (looking
// straight at it), shifted by (dx, dy), rolled by `roll` radians about its
// optical axis and tilted by `tilt` radians about its x axis (the tilt
// rotates about the point where the optical axis meets the plane).
SE3d view_pose(const RenderedPlane& plane, double distance, double roll, double tilt = 0.0, double dx = 0.0,
               double dy = 0.0);

// A map point on the plane at a FAST corner of `level` of the source view
// (T_c_w = identity), with fronto-parallel geometry.
struct PlanePoint {
  PatchSource source;
  PointGeometry geometry;
};
std::vector<PlanePoint> points_from_source(const RenderedPlane& plane, const Camera& camera,
                                           const std::shared_ptr<const ImagePyramid>& source, int level,
                                           int max_points);

}  // namespace facadeslam::test
