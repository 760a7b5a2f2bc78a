#pragma once
// The synthetic street, as read from a scene file (configs/scenes/*.yaml,
// format documented there and in sequences/synth/scene_loader.hpp). Every
// photo is already loaded, cropped and converted to class ids.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera/camera.hpp"

namespace facadeslam::synth {

// A photo and its label map, cropped to the region the scene uses.
struct Photo {
  std::filesystem::path image_path;
  std::filesystem::path label_path;
  cv::Rect crop;   // in the original photo
  cv::Mat colour;  // CV_8UC3 BGR, cropped
  cv::Mat labels;  // CV_8UC1 class ids (label_classes.hpp), cropped
};

// A facade: a photo on a vertical rectangle. Its height follows from the
// crop's aspect ratio.
struct FacadeSpec {
  Photo photo;
  double width = 10.0;                                 // metres
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // bottom centre, metres
  double facing_deg = 0.0;                             // azimuth of the outward normal (0 = +x, 90 = +y)
};

// A further street of the same cross-section as `street` (a scene that
// turns corners): its axis runs from `origin` for `length` metres along the
// azimuth `heading`. Where streets meet, start the branch at the other
// street's outer edge: overlapping ground quads would fight over pixels.
struct StreetBranch {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // metres
  double heading_deg = 0.0;                          // azimuth of the axis (0 = +x, 90 = +y)
  double length = 50.0;                              // metres
};

// The ground: a road along the x axis centred on y = 0, pavements either side.
struct StreetSpec {
  double road_width = 8.0;       // metres
  double pavement_width = 10.0;  // metres, each side, from the road edge outwards
  double start = -20.0;          // x range covered, metres
  double end = 100.0;
  double texel = 0.02;                 // metres per texel of the procedural textures
  std::vector<StreetBranch> branches;  // the scene's `streets:` list
};

struct SkySpec {
  cv::Vec3d zenith_rgb{70, 120, 200};
  cv::Vec3d horizon_rgb{190, 210, 230};
  double clouds = 0.4;  // cloud cover, 0..1
};

// The camera's starting pose: position and viewing direction.
struct StartSpec {
  Eigen::Vector3d position{0.0, 0.0, 1.6};
  double heading_deg = 0.0;  // azimuth of the optical axis (0 = +x, 90 = +y, to the left)
  double pitch_deg = 0.0;    // up positive
  double roll_deg = 0.0;     // about the optical axis, clockwise as seen by the camera positive
};

enum class SegmentType { pan, walk, arc, rotate, shake };

// One piece of the trajectory; only the fields of its type are used.
struct SegmentSpec {
  SegmentType type = SegmentType::walk;
  double duration = 1.0;       // seconds
  bool ease = true;            // start and end at rest (smooth), else constant rate
  double distance = 0.0;       // pan: metres to the right (negative: left)
  double speed = 1.4;          // walk: metres per second
  double direction_deg = 0.0;  // walk: direction of travel relative to the heading (90 = left)
  double bob = 0.0;            // walk: vertical head-bob amplitude, metres
  double radius = 10.0;        // arc: metres
  double angle_deg = 0.0;      // arc: heading change (positive: turn left)
  double yaw_deg = 0.0;        // rotate: heading change (positive: left)
  double pitch_deg = 0.0;      // rotate: pitch change (positive: up)
  double translation = 0.0;    // shake: amplitude, metres
  double rotation_deg = 0.0;   // shake: amplitude, degrees
  double frequency = 2.0;      // shake: Hz
};

// Smooth random jitter over the whole trajectory (a hand-held camera).
struct JitterSpec {
  double translation = 0.0;   // amplitude, metres
  double rotation_deg = 0.0;  // amplitude, degrees
  double frequency = 1.5;     // Hz
};

struct MotionBlurSpec {
  int samples = 1;       // sub-frames averaged per frame (1 = no blur)
  double shutter = 0.0;  // exposure as a fraction of the frame interval
};

// Illumination at a time (the diagonal model of docs/design.md / thesis III.4.3).
struct LightingKey {
  double time = 0.0;            // seconds
  double scale = 1.0;           // intensity scale a
  double shift = 0.0;           // intensity shift o1, 8-bit units
  double temperature = 6500.0;  // illuminant colour temperature, kelvin (6500 = neutral)
};

// A car cut out of a photo (its car-labelled pixels), driving from `from` to
// `to` on the ground.
struct CarSpec {
  Photo photo;
  double width = 4.0;  // metres
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  double facing_deg = 0.0;
  double start = 0.0;   // seconds: when it is at `from`
  double speed = 5.0;   // metres per second; 0: parked at `from`
  double period = 0.0;  // seconds between repeated passes (0: once)
};

// Vegetation cut out of a photo (its vegetation-labelled pixels), swaying.
struct VegetationSpec {
  Photo photo;
  double width = 3.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double facing_deg = 0.0;
  double sway_amplitude = 0.0;  // metres at the top
  double sway_frequency = 0.5;  // Hz
};

struct SceneSpec {
  std::filesystem::path path;         // the scene file
  std::filesystem::path camera_file;  // the camera YAML it names (empty: built in)
  std::filesystem::path photo_root;   // the folder its photos are in
  Camera camera{640, 480, PinholeRadTan{500, 500, 319.5, 239.5}};
  double fps = 30.0;
  int frames = 1;
  std::uint64_t seed = 0;
  double noise_sigma = 0.0;  // pixel noise, 8-bit units
  double anisotropy = 1.0;   // texture filtering (render::RendererSettings::anisotropy)
  StreetSpec street;
  SkySpec sky;
  std::vector<FacadeSpec> facades;
  StartSpec start;
  std::vector<SegmentSpec> trajectory;
  JitterSpec handheld;
  MotionBlurSpec motion_blur;
  std::vector<LightingKey> lighting;  // empty: neutral throughout
  std::vector<CarSpec> cars;
  std::vector<VegetationSpec> vegetation;

  double trajectory_duration() const;
  // Time of the last frame, (frames - 1) / fps.
  double last_frame_time() const { return (frames - 1) / fps; }
};

}  // namespace facadeslam::synth
