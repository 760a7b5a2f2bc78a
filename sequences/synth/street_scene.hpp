#pragma once
// The street of a SceneSpec turned into renderer geometry: procedural road
// and pavements (tiled along the street), the facade photos on their planes,
// the sky panorama, and the moving objects at any time t (cars driving,
// vegetation swaying). Textures are uploaded once, at construction.
#include <vector>

#include "render/offscreen_renderer.hpp"
#include "sequences/synth/scene.hpp"

namespace facadeslam::synth {

// The world-space rectangle of a photo standing on the ground: bottom centre
// `position`, outward normal at azimuth `facing_deg`, `width` metres wide and
// as tall as the photo's aspect ratio makes it. Returns (top_left, right,
// down) as render::make_textured_quad takes them; seen from the front, the
// photo is upright and not mirrored.
struct Placement {
  Eigen::Vector3d top_left, right, down;
};
Placement stand_upright(const Eigen::Vector3d& position, double facing_deg, double width, const cv::Size& photo);

// Where a car is at time t; false while it is not on its path.
bool car_position(const CarSpec& car, double t, Eigen::Vector2d& position);

class StreetScene {
 public:
  StreetScene(const SceneSpec& spec, render::Renderer& renderer);

  // Everything at time t (seconds).
  render::Scene at(double t) const;
  // Only the static part (ground, facades, sky).
  const render::Scene& static_scene() const { return static_; }

 private:
  struct CutOut {
    render::TextureId colour, labels;
  };
  const SceneSpec& spec_;
  render::Scene static_;
  std::vector<CutOut> cars_;
  std::vector<CutOut> vegetation_;
};

// A photo's pixels of class `keep` as a cut-out: their labels, and
// render::kTransparentLabel elsewhere. Colour under the transparent pixels is
// replaced by the nearest kept pixel's colour, so that texture filtering
// at the outline does not blend in the photo's background.
void cut_out(const Photo& photo, std::uint8_t keep, cv::Mat& colour, cv::Mat& labels);

}  // namespace facadeslam::synth
