#include "render/camera_projection_gl.hpp"

namespace facadeslam::render {

std::string vertex_shader_with_camera_projection(const char* body) {
  return std::string(R"(#version 450 core
uniform vec4 projection;  // 2fx/W, 2(cx+0.5)/W - 1, 2fy/H, 2(cy+0.5)/H - 1 (render/projection.hpp)
uniform float near_plane;
vec4 clip_from_camera(vec3 p_c) {
  return vec4(projection.x * p_c.x + projection.y * p_c.z,
              projection.z * p_c.y + projection.w * p_c.z, near_plane, p_c.z);
}
)") + body;
}

void set_camera_projection(const GlFunctions& gl, const GlProgram& program, const PinholeIntrinsics& k, double near) {
  const double w = k.width, h = k.height;
  gl.Uniform4f(program.uniform("projection"), static_cast<float>(2.0 * k.fx / w),
               static_cast<float>(2.0 * (k.cx + 0.5) / w - 1.0), static_cast<float>(2.0 * k.fy / h),
               static_cast<float>(2.0 * (k.cy + 0.5) / h - 1.0));
  gl.Uniform1f(program.uniform("near_plane"), static_cast<float>(near));
}

}  // namespace facadeslam::render
