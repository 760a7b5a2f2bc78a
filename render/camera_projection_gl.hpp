#pragma once
// The camera projection every vertex shader of render/ uses, in one place:
// the GLSL taking a camera-frame point to clip space exactly as
// render/projection.hpp derives it (reversed z, no y flip, pixel centres),
// and the uniforms it reads, set from the intrinsics. Internal to render/.
#include <string>

#include "render/gl_functions.hpp"
#include "render/gl_program.hpp"
#include "render/projection.hpp"

namespace facadeslam::render {

// A vertex shader: the #version line, then the uniforms `projection` and
// `near_plane` with `vec4 clip_from_camera(vec3 p_c)`, then `body`.
std::string vertex_shader_with_camera_projection(const char* body);

// Sets the uniforms for a camera with intrinsics `k` and near plane `near`
// (`program` must be in use).
void set_camera_projection(const GlFunctions& gl, const GlProgram& program, const PinholeIntrinsics& k, double near);

}  // namespace facadeslam::render
