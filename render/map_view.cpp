#include "render/map_view.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/util/error.hpp"
#include "render/camera_projection_gl.hpp"
#include "render/gl_program.hpp"
#include "render/map_view_legend.hpp"
#include "render/osmesa_context.hpp"

namespace facadeslam::render {
// Named, so that the unity build's other render files cannot clash with these.
namespace map_view_detail {
namespace {

// Points and lines share one program: vertices arrive in the camera frame
// (transformed on the CPU in double precision) and are projected exactly as
// the mesh renderer does (render/projection.hpp: reversed z, no y flip).
const char* const kVertexShaderBody = R"(
layout(location = 0) in vec3 p_c;
layout(location = 1) in vec4 colour;
uniform float point_size;
out vec4 v_colour;
void main() {
  gl_Position = clip_from_camera(p_c);
  gl_PointSize = point_size;
  v_colour = colour;
}
)";

// Round dots: fragments outside the disc are dropped, the outer ring is
// darkened (the dots' outline). Lines pass their colour through.
const char* const kFragmentShader = R"(#version 450 core
in vec4 v_colour;
uniform int round_points;
uniform float point_size;
uniform float outline;
layout(location = 0) out vec4 out_colour;
void main() {
  vec3 c = v_colour.rgb;
  if (round_points != 0) {
    float d = length(gl_PointCoord - vec2(0.5)) * point_size;
    if (d > 0.5 * point_size) discard;
    if (d > 0.5 * point_size - outline) c *= 0.55;
  }
  out_colour = vec4(c, 1.0);
}
)";

struct GpuVertex {
  float x, y, z;
  std::uint8_t r, g, b, a;
};

GpuVertex vertex(const Eigen::Vector3d& p_c, const cv::Vec3b& bgr) {
  return {static_cast<float>(p_c.x()),
          static_cast<float>(p_c.y()),
          static_cast<float>(p_c.z()),
          bgr[2],
          bgr[1],
          bgr[0],
          255};
}

// A keyframe as a pyramid: apex at the camera centre, base at
// `depth` along the optical axis, about a 62 x 48 degree field of view.
void add_pyramid(const Eigen::Isometry3d& T_view_kf, double depth, const cv::Vec3b& bgr,
                 std::vector<GpuVertex>& lines) {
  const double w = 0.6 * depth, h = 0.45 * depth;
  const Eigen::Vector3d apex = T_view_kf * Eigen::Vector3d::Zero();
  const std::array<Eigen::Vector3d, 4> base{
      T_view_kf * Eigen::Vector3d(-w, -h, depth), T_view_kf * Eigen::Vector3d(w, -h, depth),
      T_view_kf * Eigen::Vector3d(w, h, depth), T_view_kf * Eigen::Vector3d(-w, h, depth)};
  for (int i = 0; i < 4; ++i) {
    lines.push_back(vertex(apex, bgr));
    lines.push_back(vertex(base[i], bgr));
    lines.push_back(vertex(base[i], bgr));
    lines.push_back(vertex(base[(i + 1) % 4], bgr));
  }
}

}  // namespace
}  // namespace map_view_detail

struct MapView::Impl {
  OsMesaContext context;
  const GlFunctions& gl;
  GlProgram program;
  GLuint vao = 0, vbo = 0;
  GLuint fbo = 0, colour_buffer = 0, depth_buffer = 0;
  int target_width = 0, target_height = 0;
  float max_line_width = 1.f;

  Impl()
      : gl(context.gl()),
        program(gl, "map view", vertex_shader_with_camera_projection(map_view_detail::kVertexShaderBody).c_str(),
                map_view_detail::kFragmentShader) {
    using map_view_detail::GpuVertex;
    gl.GenVertexArrays(1, &vao);
    gl.GenBuffers(1, &vbo);
    gl.BindVertexArray(vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(GpuVertex), nullptr);
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(GpuVertex),
                           reinterpret_cast<const void*>(offsetof(GpuVertex, r)));
    gl.BindVertexArray(0);

    gl.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    gl.Enable(GL_PROGRAM_POINT_SIZE);
    gl.Disable(GL_BLEND);
    gl.Disable(GL_DITHER);
    gl.Disable(GL_MULTISAMPLE);
    gl.Disable(GL_LINE_SMOOTH);  // exact colours: nothing blends with the background
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    GLfloat range[2] = {1.f, 1.f};
    gl.GetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
    max_line_width = std::max(1.f, range[1]);
    check("setting up the map view");
  }

  ~Impl() {
    release_targets();
    gl.DeleteBuffers(1, &vbo);
    gl.DeleteVertexArrays(1, &vao);
  }

  void check(const std::string& what) const {
    const GLenum error = gl.GetError();
    if (error != GL_NO_ERROR) throw Error("render: OpenGL error " + std::to_string(error) + " while " + what);
  }

  void release_targets() {
    if (fbo) gl.DeleteFramebuffers(1, &fbo);
    if (colour_buffer) gl.DeleteRenderbuffers(1, &colour_buffer);
    if (depth_buffer) gl.DeleteRenderbuffers(1, &depth_buffer);
    fbo = colour_buffer = depth_buffer = 0;
    target_width = target_height = 0;
  }

  void ensure_targets(int width, int height) {
    if (fbo && width == target_width && height == target_height) return;
    release_targets();
    gl.GenRenderbuffers(1, &colour_buffer);
    gl.BindRenderbuffer(GL_RENDERBUFFER, colour_buffer);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl.GenRenderbuffers(1, &depth_buffer);
    gl.BindRenderbuffer(GL_RENDERBUFFER, depth_buffer);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_buffer);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0};
    gl.DrawBuffers(1, buffers);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw Error("render: the " + std::to_string(width) + "x" + std::to_string(height) +
                  " map view targets are incomplete");
    target_width = width;
    target_height = height;
    check("creating the map view targets");
  }

  void upload(const std::vector<map_view_detail::GpuVertex>& vertices) {
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(vertices[0])), vertices.data(),
                  GL_STREAM_DRAW);
  }
};

MapView::MapView() : impl_(std::make_unique<Impl>()) {}
MapView::~MapView() {
  try {
    impl_->context.make_current();
  } catch (...) {
  }
}

cv::Mat MapView::render(const MapViewContent& content, const MapViewCamera& camera, const MapViewStyle& style) {
  using map_view_detail::GpuVertex;
  using map_view_detail::vertex;
  const PinholeIntrinsics& k = camera.intrinsics;
  if (content.points_w.size() != content.colours_bgr.size())
    throw Error("render: the map view got " + std::to_string(content.points_w.size()) + " points but " +
                std::to_string(content.colours_bgr.size()) + " colours");
  if (k.width < 16 || k.height < 16 || k.width > 8192 || k.height > 8192)
    throw Error("render: a map view of " + std::to_string(k.width) + "x" + std::to_string(k.height) +
                " pixels (expected 16..8192 per side)");

  Impl& m = *impl_;
  const GlFunctions& gl = m.gl;
  m.context.make_current();
  m.ensure_targets(k.width, k.height);
  gl.BindFramebuffer(GL_FRAMEBUFFER, m.fbo);
  gl.Viewport(0, 0, k.width, k.height);
  const GLfloat background[] = {static_cast<GLfloat>(style.background_bgr[2] / 255.0),
                                static_cast<GLfloat>(style.background_bgr[1] / 255.0),
                                static_cast<GLfloat>(style.background_bgr[0] / 255.0), 1.f};
  const GLfloat zero[] = {0.f};
  gl.ClearBufferfv(GL_COLOR, 0, background);
  gl.DepthMask(GL_TRUE);
  gl.ClearBufferfv(GL_DEPTH, 0, zero);  // reversed z: 0 is infinitely far
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_GREATER);

  gl.UseProgram(m.program.id());
  set_camera_projection(gl, m.program, k, camera.near);
  gl.Uniform1f(m.program.uniform("point_size"), std::max(1.f, style.point_size));
  gl.Uniform1f(m.program.uniform("outline"), std::max(0.f, style.outline_pixels));
  gl.BindVertexArray(m.vao);
  gl.BindBuffer(GL_ARRAY_BUFFER, m.vbo);

  const Eigen::Isometry3d T_c_w = camera.T_w_c.inverse();
  std::vector<GpuVertex> vertices;
  vertices.reserve(content.points_w.size());
  for (std::size_t i = 0; i < content.points_w.size(); ++i)
    vertices.push_back(vertex(T_c_w * content.points_w[i].cast<double>(), content.colours_bgr[i]));
  if (!vertices.empty()) {
    gl.Uniform1i(m.program.uniform("round_points"), 1);
    m.upload(vertices);
    gl.DrawArrays(GL_POINTS, 0, static_cast<GLsizei>(vertices.size()));
  }

  // Pyramids thin, the trajectory drawn after them and wider, so that the
  // path stays visible through a dense row of keyframes.
  const auto draw_lines = [&](const std::vector<GpuVertex>& lines, float width) {
    if (lines.empty()) return;
    gl.Uniform1i(m.program.uniform("round_points"), 0);
    gl.LineWidth(std::clamp(width, 1.f, m.max_line_width));
    m.upload(lines);
    gl.DrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size()));
  };
  vertices.clear();
  for (const Eigen::Isometry3d& T_kf_w : content.keyframes_T_c_w)
    map_view_detail::add_pyramid(T_c_w * T_kf_w.inverse(), style.frustum_depth, style.keyframe_bgr, vertices);
  draw_lines(vertices, style.frustum_line_width);
  vertices.clear();
  for (std::size_t i = 1; i < content.trajectory_w.size(); ++i) {
    vertices.push_back(vertex(T_c_w * content.trajectory_w[i - 1], style.trajectory_bgr));
    vertices.push_back(vertex(T_c_w * content.trajectory_w[i], style.trajectory_bgr));
  }
  draw_lines(vertices, style.trajectory_line_width);

  // Window row v is image row v (render/projection.hpp), so the read-back
  // is the image top-down with no flip.
  cv::Mat image(k.height, k.width, CV_8UC3);
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl.ReadPixels(0, 0, k.width, k.height, GL_BGR, GL_UNSIGNED_BYTE, image.data);
  gl.BindVertexArray(0);
  gl.UseProgram(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  m.check("drawing the map view");

  if (!content.legend.empty()) draw_legend(image, content.legend, style.background_bgr);
  return image;
}

}  // namespace facadeslam::render
