#include "sequences/synth/scene_loader.hpp"

#include <cctype>
#include <cmath>
#include <initializer_list>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "core/camera/camera_yaml.hpp"
#include "core/config/config_node.hpp"
#include "core/util/error.hpp"
#include "core/util/input_confinement.hpp"
#include "core/util/path_checks.hpp"
#include "sequences/synth/label_classes.hpp"

namespace facadeslam::synth {
namespace {

namespace fs = std::filesystem;

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string size_text(const cv::Mat& m) { return std::to_string(m.cols) + "x" + std::to_string(m.rows); }

Eigen::Vector3d vector3(const ConfigNode& node, const std::string& key) {
  const auto v = node.get_doubles(key, 3);
  return {v[0], v[1], v[2]};
}

Eigen::Vector2d vector2(const ConfigNode& node, const std::string& key) {
  const auto v = node.get_doubles(key, 2);
  return {v[0], v[1]};
}

// An optional [r, g, b] colour (0-255).
cv::Vec3d colour(const ConfigNode& node, const std::string& key, const cv::Vec3d& fallback) {
  if (!node.has(key)) return fallback;
  const auto v = node.get_doubles(key, 3, Range::closed(0, 255));
  return {v[0], v[1], v[2]};
}

// A scene's photos stay inside its `photos` folder and are image files
// (input_confinement.hpp): a scene from elsewhere must not make synth open
// /etc/passwd or climb out with ../../... The `photos` folder and the
// `camera` file themselves are the scene's named resources and may lie
// anywhere (the shipped street scenes take their photos from the shared
// data beside the project), but the camera must be a YAML file.
constexpr const char* kOutsidePaths = "pass --allow-outside-paths to read it";

bool has_extension(const fs::path& path, std::initializer_list<const char*> extensions) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* e : extensions)
    if (extension == e) return true;
  return false;
}

// An existing image file under `root`, named by `key` of `node`.
fs::path existing_file(const ConfigNode& node, const std::string& key, const fs::path& root) {
  const std::string relative = node.get_string(key);
  const fs::path path = root / relative;
  if (!path_confined(path, root))
    node.fail(key, std::string("a path inside the photos folder ") + root.string() + " (" + kOutsidePaths + ")",
              relative);
  if (!paths_outside_inputs_allowed() &&
      !has_extension(path, {".jpg", ".jpeg", ".png", ".bmp", ".tif", ".tiff", ".ppm", ".pgm"}))
    node.fail(
        key,
        std::string("an image file (.jpg, .jpeg, .png, .bmp, .tif, .tiff, .ppm, .pgm; ") + kOutsidePaths + " anyway)",
        relative);
  if (!is_readable_file(path))
    node.fail(key, "an existing file (looked for " + path.string() + ", which " + describe_path(path) + ")", relative);
  return path;
}

Photo load_photo(const ConfigNode& node, const fs::path& photo_root) {
  Photo photo;
  photo.image_path = existing_file(node, "image", photo_root);
  photo.label_path = existing_file(node, "label", photo_root);
  const cv::Mat image = cv::imread(photo.image_path.string(), cv::IMREAD_COLOR);
  if (image.empty()) node.fail("image", "an image file OpenCV can read (PNG, JPEG, ...)", photo.image_path.string());
  const cv::Mat label_colours = cv::imread(photo.label_path.string(), cv::IMREAD_COLOR);
  if (label_colours.empty()) node.fail("label", "a label map OpenCV can read (PNG)", photo.label_path.string());
  if (label_colours.size() != image.size())
    node.fail("label", "a label map of the image's size " + size_text(image), size_text(label_colours));
  photo.crop = cv::Rect(0, 0, image.cols, image.rows);
  if (node.has("crop")) {
    const auto c = node.get_doubles("crop", 4, Range::closed(0, 1e5));
    const std::string expected =
        "[x, y, width, height] in whole pixels, at least 8x8, inside the " + size_text(image) + " photo";
    for (double v : c)
      if (v != std::floor(v)) node.fail("crop", expected, number(v));
    const cv::Rect crop(static_cast<int>(c[0]), static_cast<int>(c[1]), static_cast<int>(c[2]), static_cast<int>(c[3]));
    if (crop.width < 8 || crop.height < 8 || crop.x < 0 || crop.y < 0 || crop.x + crop.width > image.cols ||
        crop.y + crop.height > image.rows)
      node.fail("crop", expected,
                "[" + number(c[0]) + ", " + number(c[1]) + ", " + number(c[2]) + ", " + number(c[3]) + "]");
    photo.crop = crop;
  }
  photo.colour = image(photo.crop).clone();
  photo.labels = label_ids_from_colours(label_colours(photo.crop), photo.label_path);
  return photo;
}

// A cut-out object must show some of its class inside its crop.
void require_class(const ConfigNode& node, const Photo& photo, FacadeClass cls) {
  if (cv::countNonZero(photo.labels == id_of(cls)) == 0)
    node.fail("label", "a label map with " + std::string(class_info(cls).name) + " pixels inside the crop",
              photo.label_path.string());
}

StreetSpec read_street(const ConfigNode& node) {
  StreetSpec s;
  s.road_width = node.get_double("road_width", Range::positive(200));
  s.pavement_width = node.get_double("pavement_width", Range::non_negative(500));
  s.start = node.get_double("start", Range::closed(-1e5, 1e5));
  s.end = node.get_double("end", Range::closed(-1e5, 1e5));
  s.texel = node.get_double("texel", Range::closed(0.002, 1.0), s.texel);
  node.finish();
  if (s.end <= s.start) node.fail("end", "a number > start (" + number(s.start) + ")", number(s.end));
  // Across the street each strip is one texture; along it, textures are tiled.
  constexpr double kMaxTexels = 16384;
  if (s.road_width / s.texel > kMaxTexels)
    node.fail("road_width", "at most " + number(kMaxTexels) + " texels across (road_width / texel)",
              number(s.road_width));
  if (s.pavement_width / s.texel > kMaxTexels)
    node.fail("pavement_width", "at most " + number(kMaxTexels) + " texels across (pavement_width / texel)",
              number(s.pavement_width));
  return s;
}

StreetBranch read_branch(const ConfigNode& node) {
  StreetBranch b;
  b.origin = vector2(node, "origin");
  b.heading_deg = node.get_double("heading", Range::closed(-360, 360));
  b.length = node.get_double("length", Range::positive(1e5));
  node.finish();
  return b;
}

SkySpec read_sky(const ConfigNode& node) {
  SkySpec s;
  s.zenith_rgb = colour(node, "zenith", s.zenith_rgb);
  s.horizon_rgb = colour(node, "horizon", s.horizon_rgb);
  s.clouds = node.get_double("clouds", Range::closed(0, 1), s.clouds);
  node.finish();
  return s;
}

FacadeSpec read_facade(const ConfigNode& node, const fs::path& photo_root) {
  FacadeSpec f;
  f.photo = load_photo(node, photo_root);
  f.width = node.get_double("width", Range::positive(1000));
  f.position = vector3(node, "position");
  f.facing_deg = node.get_double("facing", Range::closed(-360, 360));
  node.finish();
  return f;
}

StartSpec read_start(const ConfigNode& node) {
  StartSpec s;
  s.position = vector3(node, "position");
  s.heading_deg = node.get_double("heading", Range::closed(-360, 360));
  s.pitch_deg = node.get_double("pitch", Range::closed(-89, 89), 0.0);
  s.roll_deg = node.get_double("roll", Range::closed(-180, 180), 0.0);
  node.finish();
  return s;
}

SegmentSpec read_segment(const ConfigNode& node) {
  SegmentSpec s;
  const std::string type = node.get_choice("type", {"pan", "walk", "arc", "rotate", "shake"});
  s.duration = node.get_double("duration", Range::positive(1e5));
  s.ease = node.get_bool("ease", true);
  if (type == "pan") {
    s.type = SegmentType::pan;
    s.distance = node.get_double("distance", Range::closed(-1000, 1000));
  } else if (type == "walk") {
    s.type = SegmentType::walk;
    s.speed = node.get_double("speed", Range::non_negative(50));
    s.direction_deg = node.get_double("direction", Range::closed(-360, 360), 0.0);
    s.bob = node.get_double("bob", Range::non_negative(1), 0.0);
  } else if (type == "arc") {
    s.type = SegmentType::arc;
    s.radius = node.get_double("radius", Range::positive(1e4));
    s.angle_deg = node.get_double("angle", Range::closed(-720, 720));
  } else if (type == "rotate") {
    s.type = SegmentType::rotate;
    s.yaw_deg = node.get_double("yaw", Range::closed(-720, 720), 0.0);
    s.pitch_deg = node.get_double("pitch", Range::closed(-89, 89), 0.0);
  } else {
    s.type = SegmentType::shake;
    s.translation = node.get_double("translation", Range::non_negative(1));
    s.rotation_deg = node.get_double("rotation", Range::non_negative(45));
    s.frequency = node.get_double("frequency", Range::positive(50), s.frequency);
  }
  node.finish();
  return s;
}

JitterSpec read_jitter(const ConfigNode& node) {
  JitterSpec j;
  j.translation = node.get_double("translation", Range::non_negative(1));
  j.rotation_deg = node.get_double("rotation", Range::non_negative(45));
  j.frequency = node.get_double("frequency", Range::positive(50), j.frequency);
  node.finish();
  return j;
}

MotionBlurSpec read_motion_blur(const ConfigNode& node) {
  MotionBlurSpec m;
  m.samples = node.get_int("samples", Range::closed(1, 64));
  m.shutter = node.get_double("shutter", Range::closed(0, 1));
  node.finish();
  return m;
}

LightingKey read_lighting_key(const ConfigNode& node) {
  LightingKey k;
  k.time = node.get_double("time", Range::non_negative(1e6));
  k.scale = node.get_double("scale", Range::positive(100), k.scale);
  k.shift = node.get_double("shift", Range::closed(-255, 255), k.shift);
  k.temperature = node.get_double("temperature", Range::closed(1000, 40000), k.temperature);
  node.finish();
  return k;
}

CarSpec read_car(const ConfigNode& node, const fs::path& photo_root) {
  CarSpec c;
  c.photo = load_photo(node, photo_root);
  require_class(node, c.photo, FacadeClass::car);
  c.width = node.get_double("width", Range::positive(100));
  c.from = vector2(node, "from");
  c.facing_deg = node.get_double("facing", Range::closed(-360, 360));
  c.start = node.get_double("start", Range::closed(-1e6, 1e6), 0.0);
  // Speed 0: a parked car, standing at `from` the whole run (no `to`).
  c.speed = node.get_double("speed", Range::closed(0, 200));
  c.to = c.speed > 0.0 ? vector2(node, "to") : c.from;
  c.period = node.get_double("period", Range::non_negative(1e6), 0.0);
  node.finish();
  if (c.speed > 0.0 && (c.to - c.from).norm() < 1e-6) node.fail("to", "a point other than `from`");
  if (c.speed > 0.0 && c.period > 0.0 && c.period < (c.to - c.from).norm() / c.speed)
    node.fail("period",
              "0 (once) or at least the time one pass takes (" + number((c.to - c.from).norm() / c.speed) + " s)",
              number(c.period));
  return c;
}

VegetationSpec read_vegetation(const ConfigNode& node, const fs::path& photo_root) {
  VegetationSpec v;
  v.photo = load_photo(node, photo_root);
  require_class(node, v.photo, FacadeClass::vegetation);
  v.width = node.get_double("width", Range::positive(100));
  v.position = vector3(node, "position");
  v.facing_deg = node.get_double("facing", Range::closed(-360, 360));
  if (const auto sway = node.optional_child("sway")) {
    v.sway_amplitude = sway->get_double("amplitude", Range::non_negative(10));
    v.sway_frequency = sway->get_double("frequency", Range::positive(20));
    sway->finish();
  }
  node.finish();
  return v;
}

}  // namespace

void check_trajectory_covers_frames(const SceneSpec& scene, const std::string& what) {
  const double needed = scene.last_frame_time();
  const double total = scene.trajectory_duration();
  if (total + 1e-9 < needed)
    throw Error(what + ": the trajectory lasts " + number(total) + " s but the last of " +
                std::to_string(scene.frames) + " frames at " + number(scene.fps) + " fps is at " + number(needed) +
                " s; lengthen the segments or render fewer frames");
}

SceneSpec load_scene(const fs::path& path) {
  const ConfigNode root = ConfigNode::load_file(path);
  SceneSpec scene;
  scene.path = path;
  const fs::path folder = path.parent_path();

  const std::string camera_file = root.get_string("camera");
  if (!paths_outside_inputs_allowed() && !has_extension(camera_file, {".yaml", ".yml"}))
    root.fail("camera", std::string("a camera YAML file (.yaml or .yml; ") + kOutsidePaths + " anyway)", camera_file);
  if (!is_existing_file(folder / camera_file))
    root.fail("camera", "an existing camera YAML file, relative to the scene file (looked for " +
                            (folder / camera_file).string() + ")");
  scene.camera = load_camera(folder / camera_file);
  scene.camera_file = folder / camera_file;
  if (root.has("resolution")) {
    const auto r = root.get_doubles("resolution", 2, Range::closed(16, 8192));
    if (r[0] != std::floor(r[0]) || r[1] != std::floor(r[1]))
      root.fail("resolution", "[width, height] in whole pixels", number(r[0]) + ", " + number(r[1]));
    scene.camera = scene.camera.resized(static_cast<int>(r[0]), static_cast<int>(r[1]));
  }
  scene.fps = root.get_double("fps", Range::closed(0.1, 1000));
  scene.frames = root.get_int("frames", Range::closed(1, 1000000));
  scene.seed = static_cast<std::uint64_t>(root.get_int("seed", Range::closed(0, 2147483647)));
  scene.noise_sigma = root.get_double("noise", Range::closed(0, 100), 0.0);
  scene.anisotropy = root.get_double("anisotropy", Range::closed(1, 16), 1.0);
  const fs::path photo_root = folder / root.get_string("photos", ".");
  scene.photo_root = photo_root;
  std::error_code ec;
  if (!fs::is_directory(photo_root, ec))
    root.fail("photos", "an existing folder, relative to the scene file (looked for " + photo_root.string() + ")",
              root.get_string("photos", "."));

  scene.street = read_street(root.child("street"));
  for (const ConfigNode& item : root.get_mappings("streets")) scene.street.branches.push_back(read_branch(item));
  if (const auto sky = root.optional_child("sky")) scene.sky = read_sky(*sky);

  const std::vector<ConfigNode> facades = root.get_mappings("facades");
  if (facades.empty()) root.fail("facades", "a list of at least one facade");
  for (const ConfigNode& item : facades) scene.facades.push_back(read_facade(item, photo_root));

  scene.start = read_start(root.child("start"));
  const std::vector<ConfigNode> segments = root.get_mappings("trajectory");
  if (segments.empty()) root.fail("trajectory", "a list of at least one segment");
  for (const ConfigNode& item : segments) scene.trajectory.push_back(read_segment(item));
  if (const auto handheld = root.optional_child("handheld")) scene.handheld = read_jitter(*handheld);
  if (const auto blur = root.optional_child("motion_blur")) scene.motion_blur = read_motion_blur(*blur);

  for (const ConfigNode& item : root.get_mappings("lighting")) {
    const LightingKey key = read_lighting_key(item);
    if (!scene.lighting.empty() && key.time <= scene.lighting.back().time)
      item.fail("time", "a time after the previous key's (" + number(scene.lighting.back().time) + " s)",
                number(key.time));
    scene.lighting.push_back(key);
  }
  for (const ConfigNode& item : root.get_mappings("cars")) scene.cars.push_back(read_car(item, photo_root));
  for (const ConfigNode& item : root.get_mappings("vegetation"))
    scene.vegetation.push_back(read_vegetation(item, photo_root));
  root.finish();

  check_trajectory_covers_frames(scene, path.string() + ": key 'trajectory'");
  return scene;
}

}  // namespace facadeslam::synth
