#pragma once
// From a pinhole camera (fx, fy, cx, cy, image size) to OpenGL clip space,
// so that rasterisation samples exactly the rays Camera::project() describes.
//
// Pixel conventions. Ours: pixel (0,0) is the CENTRE of the top-left pixel,
// u to the right, v down. OpenGL: the viewport maps normalised device
// coordinates x_ndc in [-1, 1] to window x_w in [0, W]; pixel column i has its
// centre at x_w = i + 0.5, and fragments are shaded at pixel centres. So the
// point projecting to u must land on x_w = u + 0.5:
//   x_ndc = 2 (u + 0.5) / W - 1,  u = fx x / z + cx
//   =>  clip_x = (2 fx / W) x + (2 (cx + 0.5) / W - 1) z,   clip_w = z.
// The same holds for rows with v, fy, cy, H. We do NOT flip y: image row v is
// window row v, which is the row glReadPixels returns at memory row v — and
// glReadPixels returns window row 0 first — so the read-back buffer is the
// image in top-down order with no flip. (A flip in the projection and another
// at read-back would cancel; doing neither is the same and simpler.) The
// triangle winding is mirrored by this, which does not matter: face culling
// is off.
//
// Depth uses "reversed z" with an infinite far plane and glClipControl(
// GL_LOWER_LEFT, GL_ZERO_TO_ONE): clip_z = near, so window depth = near / z,
// 1 at the near plane falling towards 0 at infinity (test GL_GREATER, clear
// to 0). With a 32-bit float depth buffer this keeps relative depth precision
// nearly constant over distance, so a car 3 cm above the road never fights
// with it, even 80 m away. Points with z < near are clipped.
#include <Eigen/Core>

namespace facadeslam::render {

struct PinholeIntrinsics {
  int width = 0;
  int height = 0;
  double fx = 1.0;
  double fy = 1.0;
  double cx = 0.0;
  double cy = 0.0;

  // u = fx x / z + cx, v = fy y / z + cy.
  Eigen::Vector2d project(const Eigen::Vector3d& p_c) const {
    return {fx * p_c.x() / p_c.z() + cx, fy * p_c.y() / p_c.z() + cy};
  }
};

// The 4x4 matrix taking camera-frame points (x right, y down, z forward,
// metres) to clip coordinates, as described above.
Eigen::Matrix4d clip_from_camera(const PinholeIntrinsics& intrinsics, double near);

// Where OpenGL puts a clip-space point in our pixel coordinates: the inverse
// of the mapping above (perspective divide, viewport, minus the half pixel).
Eigen::Vector2d pixel_from_clip(const PinholeIntrinsics& intrinsics, const Eigen::Vector4d& clip);

}  // namespace facadeslam::render
