#include "render/offscreen_renderer.hpp"

#include <cstdio>
#include <type_traits>

#include "core/util/error.hpp"
#include "render/camera_projection_gl.hpp"
#include "render/distortion_resampler.hpp"
#include "render/gl_program.hpp"
#include "render/osmesa_context.hpp"

namespace facadeslam::render {
namespace {

// Meshes: vertices arrive in the camera frame (transformed on the CPU in
// double precision, so float only ever holds camera-relative coordinates).
const char* const kMeshVertexShaderBody = R"(
layout(location = 0) in vec3 p_c;
layout(location = 1) in vec2 uv;
out vec2 v_uv;
out float v_z;
void main() {
  gl_Position = clip_from_camera(p_c);
  v_uv = uv;
  v_z = p_c.z;
}
)";

const char* const kMeshFragmentShader = R"(#version 450 core
in vec2 v_uv;
in float v_z;
uniform sampler2D colour_texture;
uniform usampler2D label_texture;
uniform int use_label_texture;
uniform uint constant_label;
layout(location = 0) out vec4 out_colour;
layout(location = 1) out uint out_label;
layout(location = 2) out float out_depth;
void main() {
  // Sampled before any discard so that the implicit derivatives (mip level,
  // anisotropy) are computed in uniform control flow.
  vec4 colour = texture(colour_texture, v_uv);
  uint label = constant_label;
  if (use_label_texture != 0) {
    ivec2 size = textureSize(label_texture, 0);
    ivec2 texel = clamp(ivec2(floor(v_uv * vec2(size))), ivec2(0), size - ivec2(1));
    label = texelFetch(label_texture, texel, 0).r;
    if (label == 255u) discard;  // kTransparentLabel: no surface here
  }
  out_colour = vec4(colour.rgb * 255.0, 1.0);
  out_label = label;
  out_depth = v_z;
}
)";

// The sky: one triangle covering the viewport; each fragment looks up the
// direction of its pixel's ray.
const char* const kSkyVertexShader = R"(#version 450 core
void main() {
  gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
}
)";

const char* const kSkyFragmentShader = R"(#version 450 core
uniform vec4 intrinsics;  // fx, fy, cx, cy
uniform mat3 R_sky_c;
uniform sampler2D sky_texture;
uniform uint sky_label;
layout(location = 0) out vec4 out_colour;
layout(location = 1) out uint out_label;
layout(location = 2) out float out_depth;
void main() {
  // Window row v is image row v (no flip, see render/projection.hpp); the
  // pixel centre is at window coordinate + 0.5.
  vec2 px = gl_FragCoord.xy - vec2(0.5);
  vec3 d = R_sky_c * vec3((px.x - intrinsics.z) / intrinsics.x, (px.y - intrinsics.w) / intrinsics.y, 1.0);
  float azimuth = atan(d.y, d.x);
  float elevation = atan(d.z, length(d.xy));
  vec2 uv = vec2(azimuth / 6.283185307 + 0.5, 0.5 - elevation / 3.141592654);
  out_colour = vec4(textureLod(sky_texture, uv, 0.0).rgb * 255.0, 1.0);
  out_label = sky_label;
  out_depth = 0.0;
}
)";

struct GpuVertex {
  float x, y, z, u, v;
};

bool same_camera(const Camera& a, const Camera& b) {
  if (a.width() != b.width() || a.height() != b.height() || a.model().index() != b.model().index()) return false;
  return a.visit([&](const auto& ma) {
    using M = std::decay_t<decltype(ma)>;
    const M& mb = std::get<M>(b.model());
    if constexpr (std::is_same_v<M, PinholeRadTan>)
      return ma.fx == mb.fx && ma.fy == mb.fy && ma.cx == mb.cx && ma.cy == mb.cy && ma.k1 == mb.k1 && ma.k2 == mb.k2 &&
             ma.p1 == mb.p1 && ma.p2 == mb.p2 && ma.k3 == mb.k3;
    else
      return ma.fx == mb.fx && ma.fy == mb.fy && ma.cx == mb.cx && ma.cy == mb.cy && ma.w == mb.w;
  });
}

std::string hex(unsigned value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04x", value);
  return buffer;
}

}  // namespace

struct Renderer::Impl {
  struct Texture {
    GLuint id = 0;
    bool is_label = false;
  };

  RendererSettings settings;
  OsMesaContext context;
  const GlFunctions& gl;
  GlProgram mesh_program;
  GlProgram sky_program;
  std::vector<Texture> textures;
  GLuint dummy_label_texture = 0;
  GLuint vao = 0, vbo = 0, ebo = 0, sky_vao = 0;
  GLuint fbo = 0, colour_target = 0, label_target = 0, depth_target = 0, depth_buffer = 0;
  int target_width = 0, target_height = 0;
  std::optional<Camera> resampled_camera;
  std::unique_ptr<DistortionResampler> resampler;
  std::vector<GpuVertex> vertices;
  std::vector<std::uint32_t> indices;

  explicit Impl(RendererSettings s)
      : settings(s),
        gl(context.gl()),
        mesh_program(gl, "mesh", vertex_shader_with_camera_projection(kMeshVertexShaderBody).c_str(),
                     kMeshFragmentShader),
        sky_program(gl, "sky", kSkyVertexShader, kSkyFragmentShader) {
    gl.GenVertexArrays(1, &vao);
    gl.GenVertexArrays(1, &sky_vao);
    gl.GenBuffers(1, &vbo);
    gl.GenBuffers(1, &ebo);
    gl.BindVertexArray(vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(GpuVertex), nullptr);
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(GpuVertex),
                           reinterpret_cast<const void*>(3 * sizeof(float)));
    gl.BindVertexArray(0);

    // Bound to the label unit for meshes without a label texture, so that
    // the usampler always refers to a complete integer texture.
    const cv::Mat zero(1, 1, CV_8UC1, cv::Scalar(0));
    dummy_label_texture = upload_label(zero);

    gl.UseProgram(mesh_program.id());
    gl.Uniform1i(mesh_program.uniform("colour_texture"), 0);
    gl.Uniform1i(mesh_program.uniform("label_texture"), 1);
    gl.UseProgram(sky_program.id());
    gl.Uniform1i(sky_program.uniform("sky_texture"), 0);
    gl.UseProgram(0);

    gl.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    gl.Disable(GL_DITHER);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    check("setting up the renderer");
  }

  ~Impl() {
    for (const auto& t : textures) gl.DeleteTextures(1, &t.id);
    gl.DeleteTextures(1, &dummy_label_texture);
    release_targets();
    gl.DeleteBuffers(1, &vbo);
    gl.DeleteBuffers(1, &ebo);
    gl.DeleteVertexArrays(1, &vao);
    gl.DeleteVertexArrays(1, &sky_vao);
  }

  void check(const std::string& what) const {
    const GLenum error = gl.GetError();
    if (error != GL_NO_ERROR) throw Error("render: OpenGL error " + hex(error) + " while " + what);
  }

  GLuint upload_label(const cv::Mat& labels) {
    GLuint id = 0;
    gl.GenTextures(1, &id);
    gl.BindTexture(GL_TEXTURE_2D, id);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    const cv::Mat data = labels.isContinuous() ? labels : labels.clone();
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, data.cols, data.rows, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, data.data);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    return id;
  }

  void release_targets() {
    if (fbo) gl.DeleteFramebuffers(1, &fbo);
    const GLuint targets[] = {colour_target, label_target, depth_target};
    for (GLuint t : targets)
      if (t) gl.DeleteTextures(1, &t);
    if (depth_buffer) gl.DeleteRenderbuffers(1, &depth_buffer);
    fbo = colour_target = label_target = depth_target = depth_buffer = 0;
    target_width = target_height = 0;
  }

  GLuint make_target(GLenum internal_format, GLenum format, GLenum type, int width, int height) {
    GLuint id = 0;
    gl.GenTextures(1, &id);
    gl.BindTexture(GL_TEXTURE_2D, id);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    gl.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format, type, nullptr);
    return id;
  }

  void ensure_targets(int width, int height) {
    if (fbo && width == target_width && height == target_height) return;
    release_targets();
    colour_target = make_target(GL_RGBA32F, GL_RGBA, GL_FLOAT, width, height);
    label_target = make_target(GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, width, height);
    depth_target = make_target(GL_R32F, GL_RED, GL_FLOAT, width, height);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.GenRenderbuffers(1, &depth_buffer);
    gl.BindRenderbuffer(GL_RENDERBUFFER, depth_buffer);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_target, 0);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, label_target, 0);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, depth_target, 0);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    gl.DrawBuffers(3, buffers);
    const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
      throw Error("render: the " + std::to_string(width) + "x" + std::to_string(height) +
                  " render targets are incomplete (status " + hex(status) + ")");
    target_width = width;
    target_height = height;
    check("creating the render targets");
  }

  const Texture& texture(TextureId id, bool label) const {
    if (id.index < 0 || id.index >= static_cast<int>(textures.size()) || textures[id.index].is_label != label)
      throw Error("render: mesh refers to " + std::string(label ? "label" : "colour") + " texture " +
                  std::to_string(id.index) + ", which this renderer does not hold");
    return textures[id.index];
  }

  // Camera-frame vertices of every mesh, packed into one buffer.
  void pack(const Scene& scene, const Eigen::Isometry3d& T_c_w) {
    vertices.clear();
    indices.clear();
    for (const Mesh& mesh : scene.meshes) {
      const auto base = static_cast<std::uint32_t>(vertices.size());
      for (const MeshVertex& v : mesh.vertices) {
        const Eigen::Vector3d p = T_c_w * v.p_w;
        vertices.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()),
                            static_cast<float>(v.uv.x()), static_cast<float>(v.uv.y())});
      }
      for (std::uint32_t i : mesh.indices) {
        if (i >= mesh.vertices.size()) throw Error("render: mesh index out of range");
        indices.push_back(base + i);
      }
    }
  }

  void draw(const Scene& scene, const PinholeIntrinsics& k, const Eigen::Isometry3d& T_w_c) {
    ensure_targets(k.width, k.height);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.Viewport(0, 0, k.width, k.height);

    const GLfloat background[] = {static_cast<GLfloat>(scene.background_colour[2]),
                                  static_cast<GLfloat>(scene.background_colour[1]),
                                  static_cast<GLfloat>(scene.background_colour[0]), 1.f};
    const GLuint background_label[] = {scene.background_label, 0, 0, 0};
    const GLfloat zero[] = {0.f, 0.f, 0.f, 0.f};
    gl.ClearBufferfv(GL_COLOR, 0, background);
    gl.ClearBufferuiv(GL_COLOR, 1, background_label);
    gl.ClearBufferfv(GL_COLOR, 2, zero);
    gl.DepthMask(GL_TRUE);
    gl.ClearBufferfv(GL_DEPTH, 0, zero);  // reversed z: 0 is infinitely far

    if (scene.sky) {
      gl.Disable(GL_DEPTH_TEST);
      gl.UseProgram(sky_program.id());
      gl.Uniform4f(sky_program.uniform("intrinsics"), static_cast<float>(k.fx), static_cast<float>(k.fy),
                   static_cast<float>(k.cx), static_cast<float>(k.cy));
      const Eigen::Matrix3f R_sky_c = (scene.sky->R_w_sky.transpose() * T_w_c.linear()).cast<float>();
      gl.UniformMatrix3fv(sky_program.uniform("R_sky_c"), 1, GL_FALSE, R_sky_c.data());
      gl.Uniform1ui(sky_program.uniform("sky_label"), scene.sky->label);
      gl.ActiveTexture(GL_TEXTURE0);
      gl.BindTexture(GL_TEXTURE_2D, texture(scene.sky->texture, false).id);
      gl.BindVertexArray(sky_vao);
      gl.DrawArrays(GL_TRIANGLES, 0, 3);
    }

    pack(scene, T_w_c.inverse());
    if (!indices.empty()) {
      gl.Enable(GL_DEPTH_TEST);
      gl.DepthFunc(GL_GREATER);
      gl.UseProgram(mesh_program.id());
      set_camera_projection(gl, mesh_program, k, settings.near);
      gl.BindVertexArray(vao);
      gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
      gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(GpuVertex)), vertices.data(),
                    GL_STREAM_DRAW);
      gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                    indices.data(), GL_STREAM_DRAW);
      const GLint use_label_texture = mesh_program.uniform("use_label_texture");
      const GLint constant_label = mesh_program.uniform("constant_label");
      std::size_t offset = 0;
      for (const Mesh& mesh : scene.meshes) {
        const std::size_t count = mesh.indices.size();
        if (count == 0) continue;
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_2D, texture(mesh.colour, false).id);
        gl.ActiveTexture(GL_TEXTURE1);
        gl.BindTexture(GL_TEXTURE_2D, mesh.labels.valid() ? texture(mesh.labels, true).id : dummy_label_texture);
        gl.Uniform1i(use_label_texture, mesh.labels.valid() ? 1 : 0);
        gl.Uniform1ui(constant_label, mesh.label);
        gl.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
                        reinterpret_cast<const void*>(offset * sizeof(std::uint32_t)));
        offset += count;
      }
    }
    gl.BindVertexArray(0);
    gl.UseProgram(0);
    check("drawing");
  }

  RenderResult read(const PinholeIntrinsics& k, unsigned layers) {
    RenderResult out;
    if (layers & kColour) {
      out.colour.create(k.height, k.width, CV_32FC3);
      gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
      gl.ReadPixels(0, 0, k.width, k.height, GL_BGR, GL_FLOAT, out.colour.data);
    }
    if (layers & kLabels) {
      out.labels.create(k.height, k.width, CV_8UC1);
      gl.ReadBuffer(GL_COLOR_ATTACHMENT1);
      gl.ReadPixels(0, 0, k.width, k.height, GL_RED_INTEGER, GL_UNSIGNED_BYTE, out.labels.data);
    }
    if (layers & kDepth) {
      out.depth.create(k.height, k.width, CV_32FC1);
      gl.ReadBuffer(GL_COLOR_ATTACHMENT2);
      gl.ReadPixels(0, 0, k.width, k.height, GL_RED, GL_FLOAT, out.depth.data);
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    check("reading the images back");
    return out;
  }
};

Renderer::Renderer(RendererSettings settings) : impl_(std::make_unique<Impl>(settings)) {}
Renderer::~Renderer() {
  try {
    impl_->context.make_current();
  } catch (...) {
  }
}

std::string Renderer::gl_renderer() const { return impl_->context.renderer(); }
std::string Renderer::gl_version() const { return impl_->context.version(); }

int Renderer::max_texture_size() const {
  impl_->context.make_current();
  GLint size = 0;
  impl_->gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  return size;
}

TextureId Renderer::add_colour_texture(const cv::Mat& image, bool wrap_horizontally) {
  if (image.empty() || (image.type() != CV_8UC3 && image.type() != CV_8UC1))
    throw Error("render: a colour texture must be a non-empty 8-bit BGR or grey image");
  const int limit = max_texture_size();
  if (image.cols > limit || image.rows > limit)
    throw Error("render: a " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                " texture exceeds the OpenGL limit of " + std::to_string(limit) + " pixels per side");
  const auto& gl = impl_->gl;
  cv::Mat data = image.isContinuous() ? image : image.clone();
  GLuint id = 0;
  gl.GenTextures(1, &id);
  gl.BindTexture(GL_TEXTURE_2D, id);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap_horizontally ? GL_REPEAT : GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (impl_->settings.anisotropy > 1.f)
    gl.TexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, impl_->settings.anisotropy);
  if (data.channels() == 1) {
    // Grey: replicate into RGB so that every texture samples the same way.
    const GLint swizzle[] = {GL_RED, GL_RED, GL_RED, GL_ONE};
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, data.cols, data.rows, 0, GL_RED, GL_UNSIGNED_BYTE, data.data);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_R, swizzle[0]);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, swizzle[1]);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_B, swizzle[2]);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_A, swizzle[3]);
  } else {
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, data.cols, data.rows, 0, GL_BGR, GL_UNSIGNED_BYTE, data.data);
  }
  gl.GenerateMipmap(GL_TEXTURE_2D);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  impl_->check("uploading a colour texture");
  impl_->textures.push_back({id, false});
  return TextureId{static_cast<int>(impl_->textures.size()) - 1};
}

TextureId Renderer::add_label_texture(const cv::Mat& labels) {
  if (labels.empty() || labels.type() != CV_8UC1)
    throw Error("render: a label texture must be a non-empty CV_8UC1 image of class ids");
  const int limit = max_texture_size();
  if (labels.cols > limit || labels.rows > limit)
    throw Error("render: a " + std::to_string(labels.cols) + "x" + std::to_string(labels.rows) +
                " label texture exceeds the OpenGL limit of " + std::to_string(limit) + " pixels per side");
  const GLuint id = impl_->upload_label(labels);
  impl_->check("uploading a label texture");
  impl_->textures.push_back({id, true});
  return TextureId{static_cast<int>(impl_->textures.size()) - 1};
}

RenderResult Renderer::render(const Scene& scene, const Camera& camera, const Eigen::Isometry3d& T_w_c,
                              unsigned layers) {
  impl_->context.make_current();
  if (!needs_resampling(camera)) {
    const PinholeIntrinsics k = pinhole_intrinsics(camera);
    impl_->draw(scene, k, T_w_c);
    return impl_->read(k, layers);
  }
  if (!impl_->resampled_camera || !same_camera(*impl_->resampled_camera, camera)) {
    impl_->resampler = std::make_unique<DistortionResampler>(camera);
    impl_->resampled_camera = camera;
  }
  const DistortionResampler& resampler = *impl_->resampler;
  impl_->draw(scene, resampler.virtual_camera(), T_w_c);
  RenderResult wide = impl_->read(resampler.virtual_camera(), layers);
  RenderResult out;
  if (layers & kColour) out.colour = resampler.resample_cubic(wide.colour);
  if (layers & kLabels) out.labels = resampler.resample_nearest(wide.labels);
  if (layers & kDepth) out.depth = resampler.resample_nearest(wide.depth);
  return out;
}

}  // namespace facadeslam::render
