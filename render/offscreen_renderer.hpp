#pragma once
// Off-screen renderer (OSMesa / llvmpipe): draws textured meshes through a
// calibrated camera and returns, from the same geometry in the same pass,
//   colour: CV_32FC3, BGR, 0..255, textures filtered (trilinear, anisotropic),
//           unlit (lighting belongs to the caller: see sequences/synth);
//   labels: CV_8UC1 class ids, nearest texel, never blended;
//   depth:  CV_32FC1 z in the camera frame (metres along the optical axis),
//           0 where no surface was hit (sky / background).
// Every pixel samples the ray of its centre: a point that Camera::project()
// maps to (u, v) appears at pixel (u, v) (render/projection.hpp has the
// derivation). Distorted cameras are rendered through a wider pinhole and
// resampled (render/distortion_resampler.hpp).
//
// One Renderer owns one OSMesa context; use it from one thread at a time.
// llvmpipe's output does not depend on LP_NUM_THREADS (it splits the image
// into tiles, each rasterised the same way by whichever thread takes it), so
// the same input gives byte-identical images.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/camera/camera.hpp"
#include "render/mesh.hpp"
#include "render/projection.hpp"

namespace facadeslam::render {

// An environment infinitely far away, looked up by ray direction: an
// equirectangular colour texture whose columns run over azimuth -180..180
// degrees (azimuth measured from the sky frame's x axis towards its y axis)
// and whose rows run from the zenith (row 0) to the nadir. Its pixels get
// `label` and depth 0.
struct Sky {
  TextureId texture;
  Eigen::Matrix3d R_w_sky = Eigen::Matrix3d::Identity();  // sky frame (z up) in the world
  std::uint8_t label = 0;
};

struct Scene {
  std::vector<Mesh> meshes;
  std::optional<Sky> sky;
  // Where neither a mesh nor a sky is drawn.
  cv::Scalar background_colour{0, 0, 0};  // BGR, 0..255
  std::uint8_t background_label = 0;
};

struct RenderResult {
  cv::Mat colour;  // CV_32FC3 BGR 0..255 (empty unless requested)
  cv::Mat labels;  // CV_8UC1 class ids (empty unless requested)
  cv::Mat depth;   // CV_32FC1 z-depth in metres, 0 = nothing (empty unless requested)
};

// Which images render() reads back (the drawing is the same; skipping the
// read-back of labels and depth saves time for motion-blur sub-frames).
enum Layer : unsigned { kColour = 1u, kLabels = 2u, kDepth = 4u, kAllLayers = 7u };

struct RendererSettings {
  double near = 0.05;  // near clipping distance in metres (no far plane)
  // Maximum anisotropic filtering of colour textures (1 = off: trilinear
  // only). Anisotropy keeps surfaces seen at grazing angles (the road far
  // ahead) sharp, but llvmpipe takes its slow texture path for any value
  // above 1: a 640x480 frame costs about four times as much CPU.
  float anisotropy = 1.f;
};

class Renderer {
 public:
  // Creates the OSMesa context; Error if OSMesa cannot give OpenGL 4.5 core.
  explicit Renderer(RendererSettings settings = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string gl_renderer() const;
  std::string gl_version() const;
  int max_texture_size() const;

  // Uploads a colour texture (CV_8UC3 BGR or CV_8UC1 grey) with mipmaps.
  // `wrap_horizontally` repeats it across its left/right edges (sky
  // panoramas); otherwise edges are clamped. Error when empty, of another
  // type, or larger than max_texture_size().
  TextureId add_colour_texture(const cv::Mat& image, bool wrap_horizontally = false);
  // Uploads a label texture (CV_8UC1 class ids; kTransparentLabel = hole).
  TextureId add_label_texture(const cv::Mat& labels);

  // Renders the scene seen by `camera` at pose T_w_c (camera -> world;
  // camera frame x right, y down, z forward). Error on an invalid texture id
  // or an OpenGL failure.
  RenderResult render(const Scene& scene, const Camera& camera, const Eigen::Isometry3d& T_w_c,
                      unsigned layers = kAllLayers);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace facadeslam::render
