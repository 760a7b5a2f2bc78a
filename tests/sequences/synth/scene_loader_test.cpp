#include <filesystem>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/util/error.hpp"
#include "sequences/synth/label_classes.hpp"
#include "sequences/synth/scene_loader.hpp"
#include "tests/sequences/synth/synth_test_scene.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using synth::load_scene;
using ::testing::HasSubstr;

TEST(SceneLoader, ReadsEveryPartOfAScene) {
  test::TempDir dir;
  std::string yaml = test::small_scene_yaml(7);
  yaml +=
      "handheld:\n  translation: 0.002\n  rotation: 0.1\n"
      "motion_blur:\n  samples: 3\n  shutter: 0.5\n"
      "lighting:\n  - time: 0\n  - time: 0.5\n    scale: 0.8\n    shift: -5\n    temperature: 4000\n"
      "cars:\n  - image: images/" +
      std::string(test::kCarPhoto) + ".jpg\n" + "    label: labels/" + test::kCarPhoto + ".png\n" +
      "    crop: [39, 386, 324, 95]\n    width: 4.2\n    from: [20, -2]\n    to: [-5, -2]\n"
      "    facing: 90\n    speed: 6\n    start: 0.2\n"
      "vegetation:\n  - image: images/" +
      test::kTreePhoto + ".jpg\n" + "    label: labels/" + test::kTreePhoto + ".png\n" +
      "    crop: [324, 79, 187, 280]\n    width: 3\n    position: [6, 5, 0]\n    facing: -90\n"
      "    sway:\n      amplitude: 0.2\n      frequency: 0.5\n";
  const synth::SceneSpec s = load_scene(test::write_scene(dir.path(), yaml));
  EXPECT_EQ(s.camera.width(), 160);
  EXPECT_EQ(s.camera.height(), 120);
  EXPECT_DOUBLE_EQ(s.camera.fx(), 125.0);  // 500 at 640 px wide, rescaled
  EXPECT_EQ(s.frames, 7);
  EXPECT_EQ(s.seed, 3u);
  EXPECT_DOUBLE_EQ(s.noise_sigma, 2.0);
  ASSERT_EQ(s.facades.size(), 2u);
  EXPECT_EQ(s.facades[0].photo.crop, cv::Rect(8, 24, 504, 472));
  EXPECT_EQ(s.facades[0].photo.colour.size(), cv::Size(504, 472));
  EXPECT_EQ(s.facades[0].photo.labels.size(), cv::Size(504, 472));
  EXPECT_EQ(s.facades[1].photo.crop, cv::Rect(0, 0, 683, 512));  // no crop: the whole photo
  EXPECT_DOUBLE_EQ(s.facades[1].facing_deg, 90.0);
  EXPECT_DOUBLE_EQ(s.sky.clouds, 0.3);
  ASSERT_EQ(s.trajectory.size(), 1u);
  EXPECT_EQ(s.trajectory[0].type, synth::SegmentType::walk);
  EXPECT_DOUBLE_EQ(s.handheld.translation, 0.002);
  EXPECT_EQ(s.motion_blur.samples, 3);
  ASSERT_EQ(s.lighting.size(), 2u);
  EXPECT_DOUBLE_EQ(s.lighting[1].temperature, 4000.0);
  EXPECT_DOUBLE_EQ(s.lighting[0].scale, 1.0);  // defaults
  ASSERT_EQ(s.cars.size(), 1u);
  EXPECT_GT(cv::countNonZero(s.cars[0].photo.labels == synth::id_of(synth::FacadeClass::car)), 1000);
  ASSERT_EQ(s.vegetation.size(), 1u);
  EXPECT_DOUBLE_EQ(s.vegetation[0].sway_amplitude, 0.2);
}

TEST(SceneLoader, LoadsTheShippedDemoScene) {
  const synth::SceneSpec s = load_scene("configs/scenes/demo.yaml");
  EXPECT_EQ(s.frames, 150);
  EXPECT_EQ(s.camera.width(), 640);
  EXPECT_EQ(s.camera.height(), 480);
  EXPECT_GE(s.trajectory_duration(), s.last_frame_time());
  EXPECT_EQ(s.trajectory.front().type, synth::SegmentType::pan);  // monocular initialisation first
}

TEST(SceneLoader, LoadsTheShippedStreetScenes) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  const std::vector<std::pair<std::string, int>> scenes = {
      {"street-walk", 600}, {"street-pan", 300}, {"street-lighting", 300}, {"street-dynamic", 300}};
  for (const auto& [name, frames] : scenes) {
    SCOPED_TRACE(name);
    const synth::SceneSpec s = load_scene("configs/scenes/" + name + ".yaml");
    EXPECT_EQ(s.frames, frames);
    EXPECT_GE(s.facades.size(), 8u);
  }
  EXPECT_GE(load_scene("configs/scenes/street-lighting.yaml").lighting.size(), 2u);
  const synth::SceneSpec dynamic = load_scene("configs/scenes/street-dynamic.yaml");
  EXPECT_FALSE(dynamic.cars.empty());
  EXPECT_FALSE(dynamic.vegetation.empty());
}

// One broken scene per case: the message must name the scene file, the key
// and what was expected.
struct BadScene {
  std::string name;
  std::string from, to;               // textual mutation of the valid scene
  std::vector<std::string> expected;  // substrings of the message
};

std::vector<BadScene> bad_scenes() {
  const std::string photo_a = test::kFacadePhotoA;
  return {
      {"missing_texture",
       "images/" + photo_a + ".jpg",
       "images/no-such-photo.jpg",
       {"facades[0].image", "existing file", "no-such-photo.jpg"}},
      {"missing_label_map",
       "labels/" + photo_a + ".png",
       "labels/no-such-map.png",
       {"facades[0].label", "existing file"}},
      {"unknown_top_level_key", "fps: 10", "fps: 10\nframs: 3", {"'frams'", "unknown key"}},
      {"unknown_facade_key",
       "    width: 14.0",
       "    width: 14.0\n    colour: red",
       {"facades[1].colour", "unknown key"}},
      {"missing_required_key", "    width: 14.0\n", "", {"facades[1].width", "required key is missing"}},
      {"wrong_type", "fps: 10", "fps: fast", {"'fps'", "expected a number"}},
      {"out_of_range", "    width: 12.0", "    width: -3", {"facades[0].width", "(0, 1000]", "-3"}},
      {"crop_outside_photo",
       "crop: [8, 24, 504, 472]",
       "crop: [8, 24, 900, 472]",
       {"facades[0].crop", "inside the 512x512 photo"}},
      {"fractional_crop", "crop: [8, 24, 504, 472]", "crop: [8.5, 24, 504, 472]", {"facades[0].crop", "whole pixels"}},
      {"label_map_of_another_size",
       "labels/" + photo_a + ".png",
       "labels/" + std::string(test::kFacadePhotoB) + ".png",
       {"facades[0].label", "image's size 512x512", "683x512"}},
      {"trajectory_too_short", "frames: 4", "frames: 40", {"'trajectory'", "lasts 1 s", "3.9 s"}},
      {"unknown_segment_type", "  - type: walk", "  - type: jog", {"trajectory[0].type", "'pan'", "jog"}},
      {"key_of_another_segment_type",
       "    speed: 1.0",
       "    speed: 1.0\n    distance: 2",
       {"trajectory[0].distance", "unknown key"}},
      {"facades_not_a_list", "facades:\n", "facades: 3\nunused:\n", {"'facades'", "a list of mappings"}},
      {"street_end_before_start", "  end: 40", "  end: -10", {"street.end", "> start"}},
      {"missing_camera", "camera: ", "camera: /no/such/camera.yaml\n#", {"'camera'", "existing camera YAML"}},
      {"missing_photo_folder", "photos: ", "photos: /no/such/folder\n#", {"'photos'", "existing folder"}},
      {"bad_resolution", "resolution: [160, 120]", "resolution: [160.5, 120]", {"'resolution'", "whole pixels"}},
      {"pitch_out_of_range", "  heading: 20", "  heading: 20\n  pitch: 95", {"start.pitch", "[-89, 89]"}},
  };
}

class BadSceneFile : public ::testing::TestWithParam<int> {};

TEST_P(BadSceneFile, FailsWithOneMessageNamingFileAndKey) {
  const BadScene c = bad_scenes()[GetParam()];
  test::TempDir dir;
  const auto path = test::write_scene(dir.path(), test::replace_once(test::small_scene_yaml(), c.from, c.to));
  try {
    load_scene(path);
    FAIL() << c.name << ": no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_THAT(message, ::testing::StartsWith(path.string() + ": ")) << c.name;
    for (const auto& part : c.expected) EXPECT_THAT(message, HasSubstr(part)) << c.name;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, BadSceneFile, ::testing::Range(0, static_cast<int>(bad_scenes().size())),
                         [](const ::testing::TestParamInfo<int>& info) { return bad_scenes()[info.param].name; });

TEST(SceneLoader, RejectsLightingKeysOutOfTimeOrder) {
  test::TempDir dir;
  const std::string yaml = test::small_scene_yaml() + "lighting:\n  - time: 0.5\n  - time: 0.2\n";
  EXPECT_THAT([&] { load_scene(test::write_scene(dir.path(), yaml)); },
              ::testing::ThrowsMessage<Error>(HasSubstr("lighting[1].time")));
}

TEST(SceneLoader, RejectsACarPhotoWithoutCarPixels) {
  test::TempDir dir;
  const std::string photo = test::kFacadePhotoA;
  const std::string yaml = test::small_scene_yaml() + "cars:\n  - image: images/" + photo + ".jpg\n" +
                           "    label: labels/" + photo +
                           ".png\n    crop: [8, 24, 100, 100]\n    width: 4\n"
                           "    from: [0, 0]\n    to: [5, 0]\n    facing: 90\n    speed: 5\n";
  EXPECT_THAT([&] { load_scene(test::write_scene(dir.path(), yaml)); },
              ::testing::ThrowsMessage<Error>(HasSubstr("cars[0].label': expected a label map with car pixels")));
}

TEST(SceneLoader, RejectsALabelMapWithAColourNoClassUses) {
  test::TempDir dir;
  cv::Mat image(64, 64, CV_8UC3, cv::Scalar(90, 100, 110)), labels(64, 64, CV_8UC3, cv::Scalar(0, 0, 128));
  labels.at<cv::Vec3b>(5, 7) = {12, 34, 56};
  std::filesystem::create_directories(dir.path() / "images");
  std::filesystem::create_directories(dir.path() / "labels");
  ASSERT_TRUE(cv::imwrite((dir.path() / "images" / "wall.png").string(), image));
  ASSERT_TRUE(cv::imwrite((dir.path() / "labels" / "wall.png").string(), labels));
  std::string yaml = test::small_scene_yaml();
  yaml = test::replace_once(yaml, "images/" + std::string(test::kFacadePhotoA) + ".jpg", "images/wall.png");
  yaml = test::replace_once(yaml, "labels/" + std::string(test::kFacadePhotoA) + ".png", "labels/wall.png");
  yaml = test::replace_once(yaml, "crop: [8, 24, 504, 472]", "crop: [0, 0, 64, 64]");
  const std::string folder = (test::source_dir() / "data" / "demo" / "photos").string();
  yaml = test::replace_once(yaml, "photos: " + folder, "photos: " + dir.path().string());
  yaml = test::replace_once(yaml, "images/" + std::string(test::kFacadePhotoB) + ".jpg", "images/wall.png");
  yaml = test::replace_once(yaml, "labels/" + std::string(test::kFacadePhotoB) + ".png", "labels/wall.png");
  EXPECT_THAT([&] { load_scene(test::write_scene(dir.path(), yaml)); },
              ::testing::ThrowsMessage<Error>(
                  ::testing::AllOf(HasSubstr("wall.png"), HasSubstr("pixel (7, 5) has colour (56, 34, 12)"))));
}

}  // namespace
}  // namespace facadeslam
