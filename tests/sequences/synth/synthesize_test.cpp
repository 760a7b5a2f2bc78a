// End-to-end: scene file -> sequence folder, checked against the scene's own
// geometry (an independent CPU ray caster), the camera path and itself.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/camera/camera_yaml.hpp"
#include "core/trajectory/trajectory_io.hpp"
#include "sequences/synth/camera_path.hpp"
#include "sequences/synth/label_classes.hpp"
#include "sequences/synth/scene_loader.hpp"
#include "sequences/synth/sequence_writer.hpp"
#include "sequences/synth/street_scene.hpp"
#include "sequences/synth/synthesize.hpp"
#include "tests/render/render_test_scenes.hpp"
#include "tests/sequences/synth/synth_test_scene.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using synth::FacadeClass;
using synth::id_of;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> data_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

synth::SceneSpec load(const test::TempDir& dir, const std::string& yaml) {
  return synth::load_scene(test::write_scene(dir.path(), yaml));
}

cv::Mat read_label_ids(const fs::path& png) {
  return synth::label_ids_from_colours(cv::imread(png.string(), cv::IMREAD_COLOR), png);
}

TEST(SequenceWriter, FrameFileNamesRoundTrip) {
  EXPECT_EQ(synth::frame_file_name(42), "000042.png");
  EXPECT_EQ(synth::frame_index("000042.png"), 42);
  EXPECT_EQ(synth::frame_index(synth::frame_file_name(999999)), 999999);
  EXPECT_EQ(synth::frame_index("00042.png"), -1);
  EXPECT_EQ(synth::frame_index("0000a2.png"), -1);
  EXPECT_EQ(synth::frame_index("000042.jpg"), -1);
  EXPECT_EQ(synth::timestamp_text(1.0 / 3.0), "0.333333333");
}

TEST(Synthesize, WritesTheTumStyleSequenceFolder) {
  test::TempDir dir;
  const synth::SceneSpec spec = load(dir, test::small_scene_yaml(4));
  const fs::path out = dir / "seq";
  const synth::SynthSummary summary = synth::synthesize_sequence(spec, out, {dir / "sheet.png", 3, {}});
  EXPECT_EQ(summary.frames, 4);
  EXPECT_FALSE(summary.renderer.empty());

  const auto rgb = data_lines(out / "rgb.txt");
  const auto depth = data_lines(out / "depth.txt");
  const auto gt = data_lines(out / "groundtruth.txt");
  ASSERT_EQ(rgb.size(), 4u);
  ASSERT_EQ(depth.size(), 4u);
  ASSERT_EQ(gt.size(), 4u);
  EXPECT_EQ(rgb[1], "0.100000000 rgb/000001.png");
  EXPECT_EQ(depth[3], "0.300000000 depth/000003.png");
  for (std::size_t i = 0; i < 4; ++i)  // the same timestamps, character for character
    EXPECT_EQ(gt[i].substr(0, gt[i].find(' ')), rgb[i].substr(0, rgb[i].find(' ')));

  for (int i = 0; i < 4; ++i) {
    const std::string name = synth::frame_file_name(i);
    const cv::Mat colour = cv::imread((out / "rgb" / name).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat labels = cv::imread((out / "label" / name).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat depth_mm = cv::imread((out / "depth" / name).string(), cv::IMREAD_UNCHANGED);
    EXPECT_EQ(colour.type(), CV_8UC3);
    EXPECT_EQ(colour.size(), cv::Size(160, 120));
    EXPECT_EQ(labels.type(), CV_8UC3);
    EXPECT_EQ(depth_mm.type(), CV_16UC1);
    EXPECT_NO_THROW(synth::label_ids_from_colours(labels, name));  // only class colours
  }
  const Camera camera = load_camera(out / "camera.yaml");
  EXPECT_EQ(camera.width(), 160);
  EXPECT_DOUBLE_EQ(camera.fx(), spec.camera.fx());
  EXPECT_DOUBLE_EQ(camera.cx(), spec.camera.cx());
  EXPECT_EQ(read_bytes(out / "labels.txt"), synth::class_table_text());
  EXPECT_EQ(read_bytes(out / "scene.yaml"), read_bytes(spec.path));
  EXPECT_THAT(read_bytes(out / "synth.json"), ::testing::HasSubstr("\"frames\": 4"));
  const cv::Mat sheet = cv::imread((dir / "sheet.png").string());
  EXPECT_GT(sheet.cols, 3 * 200);
}

TEST(Synthesize, GroundTruthIsTheCameraPath) {
  test::TempDir dir;
  std::string yaml = test::small_scene_yaml(10);
  yaml += "handheld:\n  translation: 0.004\n  rotation: 0.2\n";
  const synth::SceneSpec spec = load(dir, yaml);
  synth::synthesize_sequence(spec, dir / "seq");
  const Trajectory gt = read_trajectory(dir / "seq" / "groundtruth.txt");
  const synth::CameraPath path(spec.start, spec.trajectory, spec.handheld, spec.seed);
  ASSERT_EQ(gt.size(), 10u);
  for (const StampedPose& pose : gt) {
    const Eigen::Isometry3d expected = path.T_w_c(pose.timestamp);
    EXPECT_LT((pose.T_w_c.translation() - expected.translation()).norm(), 1e-12);
    EXPECT_LT(Eigen::AngleAxisd(pose.T_w_c.linear().transpose() * expected.linear()).angle(), 1e-12);
  }
}

TEST(Synthesize, SameSeedGivesByteIdenticalFiles) {
  test::TempDir dir;
  const synth::SceneSpec spec = load(dir, test::small_scene_yaml(3));
  synth::synthesize_sequence(spec, dir / "a");
  synth::synthesize_sequence(spec, dir / "b");
  int compared = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir / "a")) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), dir / "a");
    EXPECT_EQ(read_bytes(entry.path()), read_bytes(dir / "b" / relative)) << relative;
    ++compared;
  }
  EXPECT_EQ(compared, 3 * 3 + 7);  // three PNGs per frame, seven sequence files

  synth::SceneSpec other = spec;
  other.seed = 4;
  synth::synthesize_sequence(other, dir / "c");
  EXPECT_NE(read_bytes(dir / "a" / "rgb" / "000001.png"), read_bytes(dir / "c" / "rgb" / "000001.png"));
  // The seed changes texture and noise, not geometry.
  EXPECT_EQ(read_bytes(dir / "a" / "label" / "000001.png"), read_bytes(dir / "c" / "label" / "000001.png"));
}

TEST(Synthesize, RemovesFramesLeftByALongerRun) {
  test::TempDir dir;
  synth::synthesize_sequence(load(dir, test::small_scene_yaml(6)), dir / "seq");
  synth::synthesize_sequence(load(dir, test::small_scene_yaml(2)), dir / "seq");
  for (const char* sub : {"rgb", "label", "depth"}) {
    EXPECT_TRUE(fs::exists(dir / "seq" / sub / "000001.png"));
    EXPECT_FALSE(fs::exists(dir / "seq" / sub / "000002.png")) << sub;
  }
  EXPECT_EQ(data_lines(dir / "seq" / "rgb.txt").size(), 2u);
}

// The CPU reference of a scene: facades, road and pavements as quads.
std::vector<test::ReferenceQuad> reference_quads(const synth::SceneSpec& spec) {
  std::vector<test::ReferenceQuad> quads;
  const synth::StreetSpec& s = spec.street;
  const double half = 0.5 * s.road_width, length = s.end - s.start;
  quads.push_back({{s.start, half, 0}, {length, 0, 0}, {0, -s.road_width, 0}, {}, id_of(FacadeClass::road)});
  quads.push_back({{s.start, half + s.pavement_width, 0},
                   {length, 0, 0},
                   {0, -s.pavement_width, 0},
                   {},
                   id_of(FacadeClass::pavement)});
  quads.push_back({{s.start, -half, 0}, {length, 0, 0}, {0, -s.pavement_width, 0}, {}, id_of(FacadeClass::pavement)});
  for (const auto& f : spec.facades) {
    const synth::Placement p = synth::stand_upright(f.position, f.facing_deg, f.width, f.photo.colour.size());
    quads.push_back({p.top_left, p.right, p.down, f.photo.labels, 0});
  }
  return quads;
}

struct Agreement {
  long interior = 0, agreeing = 0, depth_checked = 0;
  double worst_depth_mm = 0.0;
};

Agreement compare_first_frame(const test::TempDir& dir, const std::string& yaml) {
  const synth::SceneSpec spec = load(dir, yaml);
  synth::synthesize_sequence(spec, dir / "seq");
  const cv::Mat labels = read_label_ids(dir / "seq" / "label" / "000000.png");
  const cv::Mat depth = cv::imread((dir / "seq" / "depth" / "000000.png").string(), cv::IMREAD_UNCHANGED);
  const auto quads = reference_quads(spec);
  const Eigen::Isometry3d T_w_c = synth::CameraPath(spec.start, spec.trajectory, spec.handheld, spec.seed).T_w_c(0.0);
  const int w = spec.camera.width(), h = spec.camera.height();
  cv::Mat ref(h, w, CV_8UC1), quad(h, w, CV_32SC1), z(h, w, CV_64FC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const test::ReferenceHit hit = test::cast_ray(quads, spec.camera, T_w_c, x, y);
      ref.at<std::uint8_t>(y, x) = hit.quad >= 0 ? hit.label : id_of(FacadeClass::sky);
      quad.at<int>(y, x) = hit.quad;
      z.at<double>(y, x) = hit.z;
    }
  Agreement a;
  for (int y = 2; y < h - 2; ++y)
    for (int x = 2; x < w - 2; ++x) {
      bool interior = true;
      for (int dy = -2; dy <= 2 && interior; ++dy)
        for (int dx = -2; dx <= 2 && interior; ++dx)
          interior = ref.at<std::uint8_t>(y + dy, x + dx) == ref.at<std::uint8_t>(y, x) &&
                     quad.at<int>(y + dy, x + dx) == quad.at<int>(y, x);
      if (!interior) continue;
      ++a.interior;
      if (labels.at<std::uint8_t>(y, x) == ref.at<std::uint8_t>(y, x)) ++a.agreeing;
      const double expected_mm = z.at<double>(y, x) * 1000.0;
      if (quad.at<int>(y, x) >= 0 && expected_mm < 60000.0) {
        ++a.depth_checked;
        a.worst_depth_mm = std::max(a.worst_depth_mm, std::abs(depth.at<std::uint16_t>(y, x) - expected_mm));
      }
    }
  return a;
}

// The scene's street is a whole number of texels across, so the rendered
// ground strips coincide with the reference quads.
std::string full_size_scene() { return test::replace_once(test::small_scene_yaml(1), "resolution: [160, 120]\n", ""); }

TEST(Synthesize, LabelsAgreeWithTheSourceLabelMapsUnderTheSameProjection) {
  test::TempDir dir;
  const Agreement a = compare_first_frame(dir, full_size_scene());
  const double share = double(a.agreeing) / a.interior;
  std::cout << "[ labels ] synth pinhole 640x480: " << 100.0 * share << " % of " << a.interior
            << " pixels away from edges agree with the source label maps; worst depth error " << a.worst_depth_mm
            << " mm over " << a.depth_checked << " pixels\n";
  EXPECT_GT(a.interior, 640 * 480 / 2);
  EXPECT_GE(share, 0.995);
  EXPECT_LE(a.worst_depth_mm, 1.0);  // half a millimetre of rounding, plus float error
}

TEST(Synthesize, LabelsAgreeThroughADistortedCamera) {
  test::TempDir dir;
  test::write_text(dir / "distorted.yaml",
                   "model: pinhole\nwidth: 640\nheight: 480\nfx: 480\nfy: 481\ncx: 322.5\ncy: 236.3\n"
                   "distortion: [-0.25, 0.07, 0.001, -0.001, 0]\n");
  const std::string camera = (test::source_dir() / "configs" / "camera" / "synthetic-640x480.yaml").string();
  const std::string yaml = test::replace_once(full_size_scene(), "camera: " + camera, "camera: distorted.yaml");
  const Agreement a = compare_first_frame(dir, yaml);
  const double share = double(a.agreeing) / a.interior;
  std::cout << "[ labels ] synth distorted 640x480: " << 100.0 * share << " % of " << a.interior
            << " pixels away from edges agree\n";
  EXPECT_GE(share, 0.995);
}

// A still camera watching a car cross and a tree sway.
std::string moving_objects_scene() {
  std::string yaml =
      test::replace_once(test::small_scene_yaml(6), "  - type: walk\n    duration: 1.0\n    speed: 1.0\n",
                         "  - type: pan\n    duration: 1.0\n    distance: 0\n");
  yaml += "cars:\n  - image: images/" + std::string(test::kCarPhoto) + ".jpg\n" + "    label: labels/" +
          test::kCarPhoto + ".png\n" +
          "    crop: [39, 386, 324, 95]\n    width: 4.2\n    from: [12, -2]\n    to: [12, 2]\n"
          "    facing: 180\n    speed: 8\n    start: 0.0\n"
          "vegetation:\n  - image: images/" +
          test::kTreePhoto + ".jpg\n" + "    label: labels/" + test::kTreePhoto + ".png\n" +
          "    crop: [324, 79, 187, 280]\n    width: 3\n    position: [9, 4.5, 0]\n    facing: -110\n"
          "    sway:\n      amplitude: 0.6\n      frequency: 1.3\n";
  return test::replace_once(yaml, "  heading: 20", "  heading: 5");
}

TEST(Synthesize, MovingObjectsAppearInTheLabelImages) {
  test::TempDir dir;
  synth::synthesize_sequence(load(dir, moving_objects_scene()), dir / "seq");
  const cv::Mat first = read_label_ids(dir / "seq" / "label" / "000000.png");
  const cv::Mat later = read_label_ids(dir / "seq" / "label" / "000003.png");
  const int car = id_of(FacadeClass::car), vegetation = id_of(FacadeClass::vegetation);
  EXPECT_GT(cv::countNonZero(first == car), 50);
  EXPECT_GT(cv::countNonZero(later == car), 50);
  EXPECT_GT(cv::countNonZero(first == vegetation), 50);
  // Where the two frames differ, a car or the tree is involved: the static
  // street is identical (the camera does not move).
  int changed = 0;
  for (int y = 0; y < first.rows; ++y)
    for (int x = 0; x < first.cols; ++x) {
      const int a = first.at<std::uint8_t>(y, x), b = later.at<std::uint8_t>(y, x);
      if (a == b) continue;
      ++changed;
      EXPECT_TRUE(a == car || b == car || a == vegetation || b == vegetation) << "pixel " << x << ", " << y;
    }
  EXPECT_GT(changed, 50);
  // The car moved across the view: its centre of mass shifted sideways.
  const cv::Moments m0 = cv::moments(first == car, true), m3 = cv::moments(later == car, true);
  EXPECT_GT(std::abs(m0.m10 / m0.m00 - m3.m10 / m3.m00), 5.0);
}

TEST(Synthesize, MotionBlurSmoothsColourButLabelsStayAtTheTimestamp) {
  test::TempDir dir;
  std::string yaml = test::replace_once(test::small_scene_yaml(3), "noise: 2.0", "noise: 0");
  yaml = test::replace_once(yaml, "    speed: 1.0\n", "    speed: 4.0\n    ease: false\n");
  synth::synthesize_sequence(load(dir, yaml), dir / "sharp");
  for (const char* samples : {"3", "4"}) {  // odd: middle sub-frame; even: an extra render
    SCOPED_TRACE(samples);
    const fs::path out = dir / (std::string("blur") + samples);
    synth::synthesize_sequence(load(dir, yaml + "motion_blur:\n  samples: " + samples + "\n  shutter: 1.0\n"), out);
    EXPECT_EQ(read_bytes(dir / "sharp" / "label" / "000001.png"), read_bytes(out / "label" / "000001.png"));
    EXPECT_EQ(read_bytes(dir / "sharp" / "depth" / "000001.png"), read_bytes(out / "depth" / "000001.png"));
    const auto detail = [](const fs::path& png) {
      cv::Mat grey, laplacian;
      cv::cvtColor(cv::imread(png.string()), grey, cv::COLOR_BGR2GRAY);
      cv::Laplacian(grey, laplacian, CV_32F);
      cv::Scalar mean, sigma;
      cv::meanStdDev(laplacian, mean, sigma);
      return sigma[0];
    };
    EXPECT_LT(detail(out / "rgb" / "000001.png"), 0.95 * detail(dir / "sharp" / "rgb" / "000001.png"));
  }
}

TEST(Synthesize, LightingScalesShiftsAndTintsTheColours) {
  test::TempDir dir;
  const std::string yaml = test::replace_once(test::small_scene_yaml(2), "noise: 2.0", "noise: 0");
  synth::synthesize_sequence(load(dir, yaml), dir / "plain");
  synth::synthesize_sequence(load(dir, yaml + "lighting:\n  - time: 0\n    scale: 0.5\n    shift: 10\n"), dir / "dim");
  synth::synthesize_sequence(load(dir, yaml + "lighting:\n  - time: 0\n    temperature: 3500\n"), dir / "warm");
  const cv::Mat plain = cv::imread((dir / "plain" / "rgb" / "000001.png").string());
  const cv::Mat dim = cv::imread((dir / "dim" / "rgb" / "000001.png").string());
  const cv::Mat warm = cv::imread((dir / "warm" / "rgb" / "000001.png").string());
  cv::Mat expected;
  plain.convertTo(expected, CV_32FC3, 0.5, 10.0);
  cv::Mat got;
  dim.convertTo(got, CV_32FC3);
  EXPECT_LE(cv::norm(got, expected, cv::NORM_INF), 1.0);  // both rounded once
  const cv::Scalar p = cv::mean(plain), w = cv::mean(warm);
  EXPECT_GT(w[2] / p[2], 1.1);  // red up
  EXPECT_LT(w[0] / p[0], 0.8);  // blue down
  EXPECT_EQ(read_bytes(dir / "plain" / "label" / "000001.png"), read_bytes(dir / "warm" / "label" / "000001.png"));
}

}  // namespace
}  // namespace facadeslam
