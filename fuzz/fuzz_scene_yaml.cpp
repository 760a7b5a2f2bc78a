// The synthetic scene reader (`synth --scene`): nested lists of facades,
// trajectory segments, lighting keys, cars and trees, each checked against
// the others (crops inside their photos, keys in time order, a trajectory
// that lasts the sequence) and resolved against files beside the scene.
//
// The input is written as scene.yaml in a scratch folder that also holds a
// small camera file and a 64x48 photo with its label map, so that paths in
// the input can resolve. Before libFuzzer reads the corpus the target seeds
// it with a scene naming every key the reader knows (paths relative to that
// folder), so that mutations start from a real structure; the bad-input
// corpus (tests/bad_input/scene_yaml/) adds the ways scenes go wrong.
#include <fstream>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fuzz/fuzz_input.hpp"
#include "sequences/synth/scene_loader.hpp"

namespace {

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

// What the input's relative paths can name: camera.yaml, photo.png, label.png.
void write_scene_neighbours(const std::filesystem::path& folder) {
  write_text(folder / "camera.yaml",
             "model: pinhole\nwidth: 64\nheight: 48\nfx: 50\nfy: 50\ncx: 31.5\ncy: 23.5\n"
             "distortion: [0, 0, 0, 0, 0]\n");
  cv::Mat photo(48, 64, CV_8UC3, cv::Scalar(90, 120, 150));
  cv::rectangle(photo, cv::Rect(10, 8, 12, 16), cv::Scalar(30, 30, 30), cv::FILLED);
  cv::Mat label(48, 64, CV_8UC3, cv::Scalar(0, 0, 128));                               // building (BGR of 128,0,0)
  cv::rectangle(label, cv::Rect(10, 8, 12, 16), cv::Scalar(128, 0, 0), cv::FILLED);    // window
  cv::rectangle(label, cv::Rect(2, 30, 38, 16), cv::Scalar(128, 0, 128), cv::FILLED);  // car
  cv::rectangle(label, cv::Rect(44, 28, 16, 18), cv::Scalar(0, 128, 0), cv::FILLED);   // vegetation
  cv::imwrite((folder / "photo.png").string(), photo);
  cv::imwrite((folder / "label.png").string(), label);
}

constexpr const char* kSeedScene = R"(camera: camera.yaml
resolution: [32, 24]
fps: 10
frames: 12
seed: 3
noise: 1.0
anisotropy: 2
photos: .
street: {road_width: 8, pavement_width: 4, start: -5, end: 20, texel: 0.05}
streets:
  - {origin: [20, 8], heading: 90, length: 10}
sky: {zenith: [70, 120, 200], horizon: [185, 205, 228], clouds: 0.4}
facades:
  - {image: photo.png, label: label.png, crop: [0, 0, 64, 48], width: 6, position: [2, 6, 0], facing: -90}
  - {image: photo.png, label: label.png, width: 4, position: [8, -6, 0], facing: 90}
start: {position: [0, 0, 1.6], heading: 10, pitch: 2, roll: 0}
trajectory:
  - {type: pan, duration: 0.2, distance: 0.1}
  - {type: walk, duration: 0.2, speed: 1.0, direction: -10, bob: 0.01, ease: false}
  - {type: arc, duration: 0.2, radius: 5, angle: 20}
  - {type: rotate, duration: 0.2, yaw: 10, pitch: 2}
  - {type: shake, duration: 0.4, translation: 0.01, rotation: 0.5, frequency: 2}
handheld: {translation: 0.002, rotation: 0.1, frequency: 1.5}
motion_blur: {samples: 3, shutter: 0.5}
lighting:
  - {time: 0, scale: 1.0, shift: 0, temperature: 6500}
  - {time: 1, scale: 0.8, shift: 5, temperature: 5000}
cars:
  - {image: photo.png, label: label.png, crop: [0, 24, 64, 24], width: 4, from: [0, 2], to: [10, 2], facing: -90, start: 0.1, speed: 1.0, period: 0}
vegetation:
  - {image: photo.png, label: label.png, width: 2, position: [4, 4, 0], facing: -90, sway: {amplitude: 0.2, frequency: 0.5}}
)";

}  // namespace

// The corpus folders are the command line's arguments that are not options.
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  write_scene_neighbours(facadeslam::fuzz::scratch_folder());
  for (int i = 1; i < *argc; ++i) {
    const std::filesystem::path folder = (*argv)[i];
    if ((*argv)[i][0] == '-' || !std::filesystem::is_directory(folder)) continue;
    write_text(folder / "every_key.yaml", kSeedScene);
    break;
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace facadeslam;
  const auto path = fuzz::write_input("scene.yaml", data, size);
  fuzz::expect_clean_rejection([&] { (void)synth::load_scene(path); });
  return 0;
}
