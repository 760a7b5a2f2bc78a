#include "sequences/synth/street_scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

#include "core/util/angles.hpp"
#include "sequences/synth/deterministic_random.hpp"
#include "sequences/synth/label_classes.hpp"
#include "sequences/synth/procedural_textures.hpp"

namespace facadeslam::synth {
namespace {

// Ground textures are tiled along the street in pieces of at most this many
// texels (seamless: the textures are functions of world coordinates).
constexpr int kTileTexels = 4096;
// Vegetation bends, so it is split into horizontal strips.
constexpr int kVegetationRows = 8;
enum SceneStream : std::uint64_t { kRoad = 11, kPavement, kSky, kSway };

// Where a street's ground lies: its own frame (x along the axis from
// `start` to `end`, y across) placed in the world by a rotation about z and
// a shift. The main street's placement is the identity.
struct GroundPlacement {
  double start = 0.0, end = 0.0;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  double heading = 0.0;  // radians
  Eigen::Vector3d to_world(const Eigen::Vector3d& v, bool point) const {
    const double c = std::cos(heading), s = std::sin(heading);
    Eigen::Vector3d w(c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z());
    if (point) w.head<2>() += origin;
    return w;
  }
};

void add_ground_strip(render::Scene& scene, render::Renderer& renderer, const StreetSpec& street,
                      const GroundPlacement& placement, double y_low, double y_high, std::uint8_t label, int side,
                      std::uint64_t seed) {
  // The strip is exactly y_high - y_low wide (neighbouring strips meet
  // without overlapping, so no two coplanar surfaces fight over a pixel);
  // its texels are stretched across by at most half a texel in all.
  const double height = y_high - y_low;
  const int rows = std::max(1, static_cast<int>(std::lround(height / street.texel)));
  const double length = placement.end - placement.start;
  const int columns = static_cast<int>(std::ceil(length / street.texel));
  for (int first = 0; first < columns; first += kTileTexels) {
    GroundArea area;
    area.x0 = placement.start + first * street.texel;
    area.y1 = y_high;
    area.columns = std::min(kTileTexels, columns - first);
    area.rows = rows;
    area.texel = street.texel;
    area.texel_y = height / rows;
    const cv::Mat texture = side == 0 ? road_texture(area, street, seed) : pavement_texture(area, street, side, seed);
    const Eigen::Vector3d top_left = placement.to_world({area.x0, area.y1, 0.0}, true);
    const Eigen::Vector3d right = placement.to_world({area.columns * street.texel, 0.0, 0.0}, false);
    const Eigen::Vector3d down = placement.to_world({0.0, -height, 0.0}, false);
    scene.meshes.push_back(
        render::make_textured_quad(top_left, right, down, renderer.add_colour_texture(texture), {}, label));
  }
}

}  // namespace

Placement stand_upright(const Eigen::Vector3d& position, double facing_deg, double width, const cv::Size& photo) {
  const double facing = deg_to_rad(facing_deg);
  // Seen from the front (looking along -normal), the photo's right is
  // (-sin facing, cos facing, 0).
  const Eigen::Vector3d right_unit(-std::sin(facing), std::cos(facing), 0.0);
  const double height = width * photo.height / photo.width;
  return {position - 0.5 * width * right_unit + Eigen::Vector3d(0, 0, height), width * right_unit,
          Eigen::Vector3d(0, 0, -height)};
}

bool car_position(const CarSpec& car, double t, Eigen::Vector2d& position) {
  if (car.speed <= 0.0) {  // parked
    position = car.from;
    return true;
  }
  const double length = (car.to - car.from).norm();
  double since = t - car.start;
  if (car.period > 0.0) since -= std::floor(since / car.period) * car.period;
  const double travelled = since * car.speed;
  if (since < 0.0 || travelled > length) return false;
  position = car.from + (car.to - car.from) * (travelled / length);
  return true;
}

void cut_out(const Photo& photo, std::uint8_t keep, cv::Mat& colour, cv::Mat& labels) {
  const cv::Mat kept = photo.labels == keep;
  labels = cv::Mat(photo.labels.size(), CV_8UC1, cv::Scalar(render::kTransparentLabel));
  labels.setTo(keep, kept);
  // Nearest kept pixel of every pixel: the distance transform's Voronoi
  // labels over the kept (zero) pixels.
  cv::Mat distance, nearest;
  cv::distanceTransform(~kept, distance, nearest, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  std::vector<cv::Point> seeds(static_cast<std::size_t>(photo.labels.total()) + 1);
  for (int y = 0; y < kept.rows; ++y)
    for (int x = 0; x < kept.cols; ++x)
      if (kept.at<std::uint8_t>(y, x)) seeds[static_cast<std::size_t>(nearest.at<int>(y, x))] = {x, y};
  colour = photo.colour.clone();
  for (int y = 0; y < kept.rows; ++y)
    for (int x = 0; x < kept.cols; ++x)
      if (!kept.at<std::uint8_t>(y, x))
        colour.at<cv::Vec3b>(y, x) = photo.colour.at<cv::Vec3b>(seeds[static_cast<std::size_t>(nearest.at<int>(y, x))]);
}

StreetScene::StreetScene(const SceneSpec& spec, render::Renderer& renderer) : spec_(spec) {
  const StreetSpec& street = spec.street;
  std::vector<GroundPlacement> streets{{street.start, street.end, Eigen::Vector2d::Zero(), 0.0}};
  for (std::size_t i = 0; i < street.branches.size(); ++i) {
    const StreetBranch& b = street.branches[i];
    // The textures are functions of the street's own coordinates: each
    // branch gets its own stretch of them, so no two streets look alike.
    const double offset = 100000.0 * static_cast<double>(i + 1);
    streets.push_back(
        {offset, offset + b.length,
         b.origin - offset * Eigen::Vector2d(std::cos(deg_to_rad(b.heading_deg)), std::sin(deg_to_rad(b.heading_deg))),
         deg_to_rad(b.heading_deg)});
  }
  const double half = 0.5 * street.road_width;
  for (const GroundPlacement& ground : streets) {
    add_ground_strip(static_, renderer, street, ground, -half, half, id_of(FacadeClass::road), 0,
                     hash64(spec.seed, kRoad));
    if (street.pavement_width > 0.0) {
      const std::uint64_t seed = hash64(spec.seed, kPavement);
      add_ground_strip(static_, renderer, street, ground, half, half + street.pavement_width,
                       id_of(FacadeClass::pavement), 1, seed);
      add_ground_strip(static_, renderer, street, ground, -half - street.pavement_width, -half,
                       id_of(FacadeClass::pavement), -1, seed);
    }
  }
  for (const FacadeSpec& facade : spec.facades) {
    const Placement p = stand_upright(facade.position, facade.facing_deg, facade.width, facade.photo.colour.size());
    static_.meshes.push_back(render::make_textured_quad(p.top_left, p.right, p.down,
                                                        renderer.add_colour_texture(facade.photo.colour),
                                                        renderer.add_label_texture(facade.photo.labels)));
  }
  const cv::Mat panorama = sky_panorama(2048, 1024, spec.sky, hash64(spec.seed, kSky));
  static_.sky =
      render::Sky{renderer.add_colour_texture(panorama, true), Eigen::Matrix3d::Identity(), id_of(FacadeClass::sky)};
  static_.background_label = id_of(FacadeClass::sky);

  const auto upload_cut_out = [&renderer](const Photo& photo, FacadeClass keep) {
    cv::Mat colour, labels;
    cut_out(photo, id_of(keep), colour, labels);
    return CutOut{renderer.add_colour_texture(colour), renderer.add_label_texture(labels)};
  };
  for (const CarSpec& car : spec.cars) cars_.push_back(upload_cut_out(car.photo, FacadeClass::car));
  for (const VegetationSpec& v : spec.vegetation)
    vegetation_.push_back(upload_cut_out(v.photo, FacadeClass::vegetation));
}

render::Scene StreetScene::at(double t) const {
  render::Scene scene = static_;
  for (std::size_t i = 0; i < spec_.cars.size(); ++i) {
    const CarSpec& car = spec_.cars[i];
    Eigen::Vector2d position;
    if (!car_position(car, t, position)) continue;
    const Placement p =
        stand_upright({position.x(), position.y(), 0.0}, car.facing_deg, car.width, car.photo.colour.size());
    scene.meshes.push_back(render::make_textured_quad(p.top_left, p.right, p.down, cars_[i].colour, cars_[i].labels));
  }
  for (std::size_t i = 0; i < spec_.vegetation.size(); ++i) {
    const VegetationSpec& v = spec_.vegetation[i];
    const Placement p = stand_upright(v.position, v.facing_deg, v.width, v.photo.colour.size());
    render::Mesh mesh = render::make_textured_quad(p.top_left, p.right, p.down, vegetation_[i].colour,
                                                   vegetation_[i].labels, 0, 1, kVegetationRows);
    if (v.sway_amplitude > 0.0) {
      // Sideways sway growing with the square of the height above the base,
      // two incommensurate waves with seeded phases per plant.
      SeededSequence random(spec_.seed, kSway + i);
      const double phase_a = 2.0 * std::numbers::pi * random.uniform();
      const double phase_b = 2.0 * std::numbers::pi * random.uniform();
      const double w = 2.0 * std::numbers::pi * v.sway_frequency;
      const double wave = (std::sin(w * t + phase_a) + 0.35 * std::sin(2.3 * w * t + phase_b)) / 1.35;
      const Eigen::Vector3d along = p.right.normalized();
      for (int r = 0; r <= kVegetationRows; ++r) {
        const double up = 1.0 - static_cast<double>(r) / kVegetationRows;  // 1 at the top, 0 at the base
        for (int c = 0; c <= 1; ++c) mesh.vertices[r * 2 + c].p_w += v.sway_amplitude * up * up * wave * along;
      }
    }
    scene.meshes.push_back(std::move(mesh));
  }
  return scene;
}

}  // namespace facadeslam::synth
