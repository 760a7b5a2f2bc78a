#pragma once
// Scenes and an independent CPU reference for the renderer tests.
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/camera/camera.hpp"
#include "render/mesh.hpp"

namespace facadeslam::test {

// A grey checkerboard of `columns` x `rows` squares of `square` texels each
// (black/white with mid-grey-free edges).
cv::Mat checkerboard(int columns, int rows, int square);

// A camera pose looking from `eye` towards `target` with the image "up"
// towards world `up`, rolled by `roll` radians about the optical axis.
Eigen::Isometry3d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                          const Eigen::Vector3d& up = Eigen::Vector3d::UnitZ(), double roll = 0.0);

// A planar rectangle as the renderer sees it (same parameters as
// render::make_textured_quad) plus the CPU-side texture of labels.
struct ReferenceQuad {
  Eigen::Vector3d top_left, right, down;
  cv::Mat labels;  // CV_8UC1; empty: `label` everywhere
  std::uint8_t label = 0;
};

struct ReferenceHit {
  int quad = -1;   // -1: nothing
  double z = 0.0;  // z-depth in the camera frame
  std::uint8_t label = 0;
  double a = 0.0, b = 0.0;  // position on the quad, in [0, 1)
};

// Casts the ray of pixel (x, y) (Camera::unproject) against every quad and
// returns the nearest hit in front of the camera, its label looked up at
// the texel containing (a, b); texels holding render::kTransparentLabel are
// holes the ray passes through. Independent of OpenGL: the reference the
// renderer is tested against.
ReferenceHit cast_ray(const std::vector<ReferenceQuad>& quads, const Camera& camera, const Eigen::Isometry3d& T_w_c,
                      double x, double y);
// The same for a camera-frame ray with z = 1.
ReferenceHit cast_ray(const std::vector<ReferenceQuad>& quads, const Eigen::Isometry3d& T_w_c,
                      const Eigen::Vector3d& ray_c);

}  // namespace facadeslam::test
