#include "tests/sequences/synth/synth_test_scene.hpp"

#include <gtest/gtest.h>

#include "tests/support/test_support.hpp"

namespace facadeslam::test {

std::string small_scene_yaml(int frames) {
  const std::string photos = (source_dir() / "data" / "demo" / "photos").string();
  const std::string camera = (source_dir() / "configs" / "camera" / "synthetic-640x480.yaml").string();
  return "camera: " + camera + "\n" +
         "resolution: [160, 120]\n"
         "fps: 10\n"
         "frames: " +
         std::to_string(frames) + "\n" +
         "seed: 3\n"
         "noise: 2.0\n"
         "photos: " +
         photos + "\n" +
         "street:\n"
         "  road_width: 8.0\n"
         "  pavement_width: 6.0\n"
         "  start: -5\n"
         "  end: 40\n"
         "  texel: 0.04\n"
         "sky:\n"
         "  clouds: 0.3\n"
         "facades:\n"
         "  - image: images/" +
         kFacadePhotoA + ".jpg\n" + "    label: labels/" + kFacadePhotoA + ".png\n" +
         "    crop: [8, 24, 504, 472]\n"
         "    width: 12.0\n"
         "    position: [8.0, 7.0, 0.0]\n"
         "    facing: -90\n"
         "  - image: images/" +
         kFacadePhotoB + ".jpg\n" + "    label: labels/" + kFacadePhotoB + ".png\n" +
         "    width: 14.0\n"
         "    position: [8.0, -7.0, 0.0]\n"
         "    facing: 90\n"
         "start:\n"
         "  position: [0.0, 0.0, 1.6]\n"
         "  heading: 20\n"
         "trajectory:\n"
         "  - type: walk\n"
         "    duration: 1.0\n"
         "    speed: 1.0\n";
}

std::filesystem::path write_scene(const std::filesystem::path& dir, const std::string& yaml) {
  const auto path = dir / "scene.yaml";
  write_text(path, yaml);
  return path;
}

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) {
    ADD_FAILURE() << "the test scene has no '" << from << "' to replace";
    return text;
  }
  return text.replace(at, from.size(), to);
}

}  // namespace facadeslam::test
