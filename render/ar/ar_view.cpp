#include "render/ar/ar_view.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "render/camera_projection_gl.hpp"
#include "render/distortion_resampler.hpp"
#include "render/gl_program.hpp"
#include "render/map_view_legend.hpp"
#include "render/osmesa_context.hpp"

namespace facadeslam::render::ar {
// Named, so that the unity build's other render files cannot clash with these.
namespace ar_view_detail {
namespace {

// The object: vertices in the camera frame (transformed on the CPU in double
// precision), projected as every renderer of render/ does.
const char* const kObjectVertexShaderBody = R"(
layout(location = 0) in vec3 p_c;
layout(location = 1) in vec3 normal_c;
layout(location = 2) in vec2 face_uv;
out vec3 v_normal;
out vec2 v_uv;
out float v_z;
void main() {
  gl_Position = clip_from_camera(p_c);
  v_normal = normal_c;
  v_uv = face_uv;
  v_z = p_c.z;
}
)";

// Lambert shading of a two-tone checker; alpha 1 marks the object's pixels
// for the composite pass.
const char* const kObjectFragmentShader = R"(#version 450 core
in vec3 v_normal;
in vec2 v_uv;
in float v_z;
uniform vec4 light_c;   // xyz: unit direction towards the light, camera frame; w: ambient share
uniform vec4 body_rgb;
uniform vec4 checker_rgb;
uniform float squares;
uniform sampler2D occluders;  // the map's nearest occluder z per pixel (+inf: none)
uniform int use_occluders;
layout(location = 0) out vec4 out_colour;
// The share of a 3x3 neighbourhood whose occluder lies behind the fragment:
// 1 in the open, 0 behind a surface, in between along an occluder's edge
// (a soft edge of three pixels rather than a jagged one).
float visibility() {
  if (use_occluders == 0) return 1.0;
  ivec2 px = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(occluders, 0) - ivec2(1);
  float open = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      float z = texelFetch(occluders, clamp(px + ivec2(dx, dy), ivec2(0), last), 0).r;
      open += z >= 0.99 * v_z ? 1.0 : 0.0;
    }
  return open / 9.0;
}
// The checker box-filtered over the pixel's footprint (its extent in face
// coordinates, from the derivatives): anti-aliased edges without moving the
// squares' corners, since the filter is symmetric.
float checker_share(vec2 p) {
  vec2 w = fwidth(p) + vec2(1e-5);
  vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
  return 0.5 - 0.5 * i.x * i.y;
}
void main() {
  vec3 albedo = mix(body_rgb.rgb, checker_rgb.rgb, checker_share(v_uv * squares));
  float diffuse = max(dot(normalize(v_normal), light_c.xyz), 0.0);
  // Premultiplied by the visibility, as the composite pass expects.
  float a = visibility();
  out_colour = vec4(a * albedo * (light_c.w + (1.0 - light_c.w) * diffuse), a);
}
)";

// One triangle covering the viewport.
const char* const kFullScreenVertexShader = R"(#version 450 core
void main() {
  gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
}
)";

// The image, and over it the object layer sampled where the real camera's
// pixel ray falls in it: the pixel itself for an undistorted camera, the
// resampler's lookup otherwise. The layer was cleared to transparent black,
// so its filtered colour is premultiplied by its filtered alpha.
const char* const kCompositeFragmentShader = R"(#version 450 core
uniform sampler2D background;
uniform sampler2D object_layer;
uniform sampler2D lookup;
uniform int use_object;
uniform int distorted;
uniform vec4 object_size;  // xy: the object layer's width and height
layout(location = 0) out vec4 out_colour;
void main() {
  // Window row v is image row v (render/projection.hpp): no flip.
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec3 image = texelFetch(background, px, 0).rgb;
  if (use_object == 0) {
    out_colour = vec4(image, 1.0);
    return;
  }
  vec2 source = distorted != 0 ? texelFetch(lookup, px, 0).rg : vec2(px);
  vec4 object = textureLod(object_layer, (source + vec2(0.5)) / object_size.xy, 0.0);
  out_colour = vec4(image * (1.0 - object.a) + object.rgb, 1.0);
}
)";

// Points arrive as pixel positions (Camera::project, distortion included);
// the centre of pixel (u, v) is at window (u + 0.5, v + 0.5).
const char* const kPointVertexShader = R"(#version 450 core
layout(location = 0) in vec2 pixel;
layout(location = 1) in vec4 colour;
uniform vec4 viewport_size;  // xy: width, height
uniform float point_size;
out vec4 v_colour;
void main() {
  gl_Position = vec4(2.0 * (pixel + vec2(0.5)) / viewport_size.xy - vec2(1.0), 0.0, 1.0);
  gl_PointSize = point_size;
  v_colour = colour;
}
)";

// Round dots with a darker ring, as the map view draws them.
const char* const kPointFragmentShader = R"(#version 450 core
in vec4 v_colour;
uniform float point_size;
uniform float outline;
layout(location = 0) out vec4 out_colour;
void main() {
  float d = length(gl_PointCoord - vec2(0.5)) * point_size;
  if (d > 0.5 * point_size) discard;
  vec3 c = v_colour.rgb;
  if (d > 0.5 * point_size - outline) c *= 0.45;
  out_colour = vec4(c, 1.0);
}
)";

struct ObjectGpuVertex {
  float x, y, z, nx, ny, nz, u, v;
};

struct PointGpuVertex {
  float u, v;
  std::uint8_t r, g, b, a;
};

std::string gl_error_text(GLenum error) { return std::to_string(static_cast<unsigned>(error)); }

}  // namespace
}  // namespace ar_view_detail

struct ArView::Impl {
  Camera camera;
  ArViewStyle style;
  OsMesaContext context;
  const GlFunctions& gl;
  GlProgram object_program, composite_program, point_program;
  std::unique_ptr<DistortionResampler> resampler;  // distorted cameras only
  PinholeIntrinsics object_camera;                 // the object layer's pinhole
  GLuint object_vao = 0, object_vbo = 0, point_vao = 0, point_vbo = 0, empty_vao = 0;
  GLuint background_texture = 0, lookup_texture = 0, occluder_texture = 0;
  GLuint object_fbo = 0, object_colour = 0, object_depth = 0;
  GLuint output_fbo = 0, output_colour = 0;
  cv::Mat background_bgr;  // reused upload buffer for grey images

  Impl(const Camera& c, const ArViewStyle& s)
      : camera(c),
        style(s),
        gl(context.gl()),
        object_program(gl, "AR object",
                       vertex_shader_with_camera_projection(ar_view_detail::kObjectVertexShaderBody).c_str(),
                       ar_view_detail::kObjectFragmentShader),
        composite_program(gl, "AR composite", ar_view_detail::kFullScreenVertexShader,
                          ar_view_detail::kCompositeFragmentShader),
        point_program(gl, "AR points", ar_view_detail::kPointVertexShader, ar_view_detail::kPointFragmentShader) {
    using ar_view_detail::ObjectGpuVertex;
    using ar_view_detail::PointGpuVertex;
    if (needs_resampling(camera)) {
      resampler = std::make_unique<DistortionResampler>(camera);
      object_camera = resampler->virtual_camera();
    } else {
      object_camera = pinhole_intrinsics(camera);
    }

    gl.GenVertexArrays(1, &object_vao);
    gl.GenBuffers(1, &object_vbo);
    gl.BindVertexArray(object_vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, object_vbo);
    for (GLuint attribute = 0; attribute < 3; ++attribute) gl.EnableVertexAttribArray(attribute);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ObjectGpuVertex), nullptr);
    gl.VertexAttribPointer(
        1, 3, GL_FLOAT, GL_FALSE, sizeof(ObjectGpuVertex),
        reinterpret_cast<const void*>(  // NOLINT(performance-no-int-to-ptr): GL takes offsets as pointers
            offsetof(ObjectGpuVertex, nx)));
    gl.VertexAttribPointer(
        2, 2, GL_FLOAT, GL_FALSE, sizeof(ObjectGpuVertex),
        reinterpret_cast<const void*>(  // NOLINT(performance-no-int-to-ptr): GL takes offsets as pointers
            offsetof(ObjectGpuVertex, u)));
    gl.GenVertexArrays(1, &point_vao);
    gl.GenBuffers(1, &point_vbo);
    gl.BindVertexArray(point_vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, point_vbo);
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(PointGpuVertex), nullptr);
    gl.VertexAttribPointer(
        1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(PointGpuVertex),
        reinterpret_cast<const void*>(  // NOLINT(performance-no-int-to-ptr): GL takes offsets as pointers
            offsetof(PointGpuVertex, r)));
    gl.GenVertexArrays(1, &empty_vao);
    gl.BindVertexArray(0);

    background_texture = make_texture(GL_NEAREST);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, camera.width(), camera.height(), 0, GL_BGR, GL_UNSIGNED_BYTE, nullptr);
    // The lookup: per output pixel, where its ray falls in the object layer.
    lookup_texture = make_texture(GL_NEAREST);
    if (resampler) {
      cv::Mat lookup(camera.height(), camera.width(), CV_32FC2);
      for (int y = 0; y < camera.height(); ++y)
        for (int x = 0; x < camera.width(); ++x) lookup.at<cv::Vec2f>(y, x) = resampler->source(x, y);
      gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, lookup.cols, lookup.rows, 0, GL_RG, GL_FLOAT, lookup.data);
    } else {
      const float zero[2] = {0.f, 0.f};
      gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, 1, 1, 0, GL_RG, GL_FLOAT, zero);
    }

    occluder_texture = make_texture(GL_NEAREST);
    const float nothing = std::numeric_limits<float>::infinity();
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R32F, 1, 1, 0, GL_RED, GL_FLOAT, &nothing);
    gl.UseProgram(object_program.id());
    gl.Uniform1i(object_program.uniform("occluders"), 3);
    gl.UseProgram(0);

    object_colour = make_texture(GL_LINEAR);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, object_camera.width, object_camera.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                  nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.GenRenderbuffers(1, &object_depth);
    gl.BindRenderbuffer(GL_RENDERBUFFER, object_depth);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, object_camera.width, object_camera.height);
    gl.GenFramebuffers(1, &object_fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, object_fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, object_colour, 0);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, object_depth);
    require_complete("object layer");

    gl.GenRenderbuffers(1, &output_colour);
    gl.BindRenderbuffer(GL_RENDERBUFFER, output_colour);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, camera.width(), camera.height());
    gl.GenFramebuffers(1, &output_fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, output_fbo);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, output_colour);
    require_complete("output");
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);

    gl.UseProgram(composite_program.id());
    gl.Uniform1i(composite_program.uniform("background"), 0);
    gl.Uniform1i(composite_program.uniform("object_layer"), 1);
    gl.Uniform1i(composite_program.uniform("lookup"), 2);
    gl.Uniform1i(composite_program.uniform("distorted"), resampler ? 1 : 0);
    gl.Uniform4f(composite_program.uniform("object_size"), static_cast<float>(object_camera.width),
                 static_cast<float>(object_camera.height), 0.f, 0.f);
    gl.UseProgram(0);

    gl.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    gl.Enable(GL_PROGRAM_POINT_SIZE);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    gl.Disable(GL_DITHER);
    gl.Disable(GL_MULTISAMPLE);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    check("setting up the AR view");
  }

  ~Impl() {
    gl.DeleteFramebuffers(1, &object_fbo);
    gl.DeleteFramebuffers(1, &output_fbo);
    gl.DeleteRenderbuffers(1, &object_depth);
    gl.DeleteRenderbuffers(1, &output_colour);
    const GLuint textures[] = {background_texture, lookup_texture, object_colour, occluder_texture};
    gl.DeleteTextures(4, textures);
    gl.DeleteBuffers(1, &object_vbo);
    gl.DeleteBuffers(1, &point_vbo);
    gl.DeleteVertexArrays(1, &object_vao);
    gl.DeleteVertexArrays(1, &point_vao);
    gl.DeleteVertexArrays(1, &empty_vao);
  }

  void check(const std::string& what) const {
    const GLenum error = gl.GetError();
    if (error != GL_NO_ERROR)
      throw Error("render: OpenGL error " + ar_view_detail::gl_error_text(error) + " while " + what);
  }

  void require_complete(const std::string& what) const {
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw Error("render: the AR view's " + what + " target is incomplete");
  }

  GLuint make_texture(GLint filter) {
    GLuint id = 0;
    gl.GenTextures(1, &id);
    gl.BindTexture(GL_TEXTURE_2D, id);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    return id;
  }

  // The object into its layer (transparent black where it is not).
  void draw_object(const VirtualObject& object, const Eigen::Isometry3d& T_c_w, const cv::Mat& occluders) {
    using ar_view_detail::ObjectGpuVertex;
    std::vector<ObjectGpuVertex> vertices;
    for (const ObjectVertex& v : object_triangles(object)) {
      const Eigen::Vector3d p = T_c_w * v.p_w;
      const Eigen::Vector3d n = T_c_w.linear() * v.normal_w;
      vertices.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()),
                          static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z()),
                          static_cast<float>(v.face_uv.x()), static_cast<float>(v.face_uv.y())});
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, object_fbo);
    gl.Viewport(0, 0, object_camera.width, object_camera.height);
    const GLfloat transparent[] = {0.f, 0.f, 0.f, 0.f};
    const GLfloat far_depth[] = {0.f};  // reversed z: 0 is infinitely far
    gl.ClearBufferfv(GL_COLOR, 0, transparent);
    gl.DepthMask(GL_TRUE);
    gl.ClearBufferfv(GL_DEPTH, 0, far_depth);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_GREATER);
    gl.UseProgram(object_program.id());
    set_camera_projection(gl, object_program, object_camera, style.near);
    const Eigen::Vector3d light_c = (T_c_w.linear() * object.T_w_o.linear() * style.light_o).normalized();
    gl.Uniform4f(object_program.uniform("light_c"), static_cast<float>(light_c.x()), static_cast<float>(light_c.y()),
                 static_cast<float>(light_c.z()), static_cast<float>(style.ambient));
    const auto set_colour = [&](const char* name, const cv::Vec3b& bgr) {
      gl.Uniform4f(object_program.uniform(name), bgr[2] / 255.f, bgr[1] / 255.f, bgr[0] / 255.f, 1.f);
    };
    set_colour("body_rgb", style.object_bgr);
    set_colour("checker_rgb", style.checker_bgr);
    gl.Uniform1f(object_program.uniform("squares"), static_cast<float>(object.checker_squares));
    const bool occluded = !occluders.empty();
    if (occluded) {
      if (occluders.cols != object_camera.width || occluders.rows != object_camera.height ||
          occluders.type() != CV_32FC1 || !occluders.isContinuous())
        throw Error("render: the occluder depth must be a continuous 32-bit float image of " +
                    std::to_string(object_camera.width) + "x" + std::to_string(object_camera.height) + " pixels");
      gl.ActiveTexture(GL_TEXTURE3);
      gl.BindTexture(GL_TEXTURE_2D, occluder_texture);
      gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R32F, occluders.cols, occluders.rows, 0, GL_RED, GL_FLOAT, occluders.data);
      gl.ActiveTexture(GL_TEXTURE0);
    }
    gl.Uniform1i(object_program.uniform("use_occluders"), occluded ? 1 : 0);
    gl.BindVertexArray(object_vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, object_vbo);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(ObjectGpuVertex)), vertices.data(),
                  GL_STREAM_DRAW);
    gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
    gl.Disable(GL_DEPTH_TEST);
  }

  void upload_background(const cv::Mat& image) {
    if (image.cols != camera.width() || image.rows != camera.height() ||
        (image.type() != CV_8UC3 && image.type() != CV_8UC1))
      throw Error("render: the AR view needs an 8-bit BGR or grey image of " + std::to_string(camera.width()) + "x" +
                  std::to_string(camera.height()) + " pixels, got " + std::to_string(image.cols) + "x" +
                  std::to_string(image.rows));
    if (image.type() == CV_8UC1)
      cv::cvtColor(image, background_bgr, cv::COLOR_GRAY2BGR);
    else if (!image.isContinuous())
      background_bgr = image.clone();
    const cv::Mat& data = image.type() == CV_8UC3 && image.isContinuous() ? image : background_bgr;
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, background_texture);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, data.cols, data.rows, 0, GL_BGR, GL_UNSIGNED_BYTE, data.data);
  }

  // The points in front of the camera and not hidden by the object (which
  // stands in front of the map's surfaces: a point behind it would otherwise
  // show through it).
  std::size_t draw_points(const std::vector<ArPoint>& points, const Eigen::Isometry3d& T_c_w,
                          const std::optional<VirtualObject>& object) {
    using ar_view_detail::PointGpuVertex;
    std::vector<PointGpuVertex> vertices;
    vertices.reserve(points.size());
    const double margin = style.point_size;  // dots partly inside still show
    const Eigen::Vector3d eye_w = T_c_w.inverse().translation();
    for (const ArPoint& point : points) {
      const Eigen::Vector3d p_c = T_c_w * point.p_w;
      if (p_c.z() <= 0.0) continue;
      if (object && hides(*object, eye_w, point.p_w)) continue;
      const Eigen::Vector2d px = camera.project(p_c);
      if (!(px.x() > -margin && px.y() > -margin && px.x() < camera.width() - 1 + margin &&
            px.y() < camera.height() - 1 + margin))
        continue;
      vertices.push_back({static_cast<float>(px.x()), static_cast<float>(px.y()), point.colour_bgr[2],
                          point.colour_bgr[1], point.colour_bgr[0], 255});
    }
    if (vertices.empty()) return 0;
    gl.UseProgram(point_program.id());
    gl.Uniform4f(point_program.uniform("viewport_size"), static_cast<float>(camera.width()),
                 static_cast<float>(camera.height()), 0.f, 0.f);
    gl.Uniform1f(point_program.uniform("point_size"), std::max(1.f, style.point_size));
    gl.Uniform1f(point_program.uniform("outline"), std::max(0.f, style.outline_pixels));
    gl.BindVertexArray(point_vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, point_vbo);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(PointGpuVertex)), vertices.data(),
                  GL_STREAM_DRAW);
    gl.DrawArrays(GL_POINTS, 0, static_cast<GLsizei>(vertices.size()));
    return vertices.size();
  }

  cv::Mat render(const ArFrameContent& content, ArFrameStats& stats) {
    context.make_current();
    upload_background(content.image);
    const bool with_object = content.T_w_c && content.object;
    std::optional<Eigen::Isometry3d> T_c_w;
    if (content.T_w_c) T_c_w = content.T_w_c->inverse();
    if (with_object) draw_object(*content.object, *T_c_w, content.occluder_depth);
    stats.object_drawn = with_object;

    gl.BindFramebuffer(GL_FRAMEBUFFER, output_fbo);
    gl.Viewport(0, 0, camera.width(), camera.height());
    gl.UseProgram(composite_program.id());
    gl.Uniform1i(composite_program.uniform("use_object"), with_object ? 1 : 0);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, background_texture);
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, object_colour);
    gl.ActiveTexture(GL_TEXTURE2);
    gl.BindTexture(GL_TEXTURE_2D, lookup_texture);
    gl.BindVertexArray(empty_vao);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);

    stats.points_drawn = T_c_w ? draw_points(content.points, *T_c_w, content.object) : 0;

    cv::Mat image(camera.height(), camera.width(), CV_8UC3);
    gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.ReadPixels(0, 0, camera.width(), camera.height(), GL_BGR, GL_UNSIGNED_BYTE, image.data);
    gl.BindVertexArray(0);
    gl.UseProgram(0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    check("drawing the AR view");
    if (!content.legend.empty() && T_c_w) draw_legend(image, content.legend, cv::Scalar(238, 238, 238));
    return image;
  }
};

ArView::ArView(const Camera& camera, const ArViewStyle& style) : impl_(std::make_unique<Impl>(camera, style)) {}
ArView::~ArView() {
  try {
    impl_->context.make_current();
  } catch (...) {
  }
}

cv::Mat ArView::render(const ArFrameContent& content, ArFrameStats* stats) {
  ArFrameStats local;
  return impl_->render(content, stats ? *stats : local);
}

const Camera& ArView::camera() const { return impl_->camera; }
const PinholeIntrinsics& ArView::object_intrinsics() const { return impl_->object_camera; }
std::string ArView::gl_renderer() const { return impl_->context.renderer(); }

}  // namespace facadeslam::render::ar
