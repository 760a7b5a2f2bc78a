#include "sequences/synth/sequence_writer.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "core/camera/camera_yaml.hpp"
#include "core/plot/png_file.hpp"
#include "core/trajectory/trajectory_io.hpp"
#include "core/util/atomic_write.hpp"
#include "core/util/error.hpp"
#include "sequences/synth/label_classes.hpp"

namespace facadeslam::synth {
namespace {

namespace fs = std::filesystem;

const char* const kFrameFolders[] = {"rgb", "label", "depth"};

// zlib level 1 makes 16-bit depth PNGs about 5x smaller than OpenCV's
// default settings (smooth surfaces compress well), in less time; colour
// images with pixel noise do best with the default.
const std::vector<int> kDepthPng = {cv::IMWRITE_PNG_COMPRESSION, 1};
const std::vector<int> kColourPng = {};  // OpenCV's default settings

std::string list_text(const SceneSpec& spec, int frames, const std::string& folder, const std::string& what) {
  std::ostringstream out;
  out << "# " << what << " of a facadeslam synthetic sequence (scene " << spec.path.filename().string() << ")\n"
      << "# timestamp filename\n";
  for (int i = 0; i < frames; ++i)
    out << timestamp_text(i / spec.fps) << " " << folder << "/" << frame_file_name(i) << "\n";
  return out.str();
}

}  // namespace

std::string timestamp_text(double seconds) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.9f", seconds);
  return buffer;
}

int frame_index(const std::string& file_name) {
  if (file_name.size() != 10 || file_name.substr(6) != ".png") return -1;
  int index = 0;
  for (int i = 0; i < 6; ++i) {
    if (file_name[i] < '0' || file_name[i] > '9') return -1;
    index = index * 10 + (file_name[i] - '0');
  }
  return index;
}

std::string frame_file_name(int index) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%06d.png", index);
  return buffer;
}

SequenceWriter::SequenceWriter(fs::path folder, const SceneSpec& spec) : folder_(std::move(folder)), spec_(spec) {
  std::error_code ec;
  for (const char* sub : kFrameFolders) {
    fs::create_directories(folder_ / sub, ec);
    if (ec) fail_file(folder_ / sub, "cannot create the output folder (" + ec.message() + ")");
  }
}

void SequenceWriter::write(const SynthFrame& frame) {
  if (frame.index != written_)
    throw Error("synth: frames must be written in order (expected frame " + std::to_string(written_) + ", got " +
                std::to_string(frame.index) + ")");
  const std::string name = frame_file_name(frame.index);
  plot::save_png(folder_ / "rgb" / name, frame.colour, kColourPng);
  plot::save_png(folder_ / "label" / name, colours_from_label_ids(frame.labels), kColourPng);
  plot::save_png(folder_ / "depth" / name, frame.depth_mm, kDepthPng);
  trajectory_.push_back({frame.timestamp, frame.T_w_c});
  ++written_;
}

void SequenceWriter::finish(const Json& report) {
  write_text_atomically(folder_ / "rgb.txt", list_text(spec_, written_, "rgb", "colour images"));
  write_text_atomically(folder_ / "depth.txt", list_text(spec_, written_, "depth", "depth images (16-bit, mm)"));
  write_tum_trajectory(folder_ / "groundtruth.txt", trajectory_);
  save_camera(folder_ / "camera.yaml", spec_.camera,
              "The camera of the synthetic sequence rendered from " + spec_.path.filename().string());
  write_text_atomically(folder_ / "labels.txt", class_table_text());
  std::ifstream scene(spec_.path, std::ios::binary);
  if (!scene) fail_file(spec_.path, "cannot read the scene file to copy it");
  std::ostringstream text;
  text << scene.rdbuf();
  write_text_atomically(folder_ / "scene.yaml", text.str());
  write_json(folder_ / "synth.json", report);

  // Stale frames of an earlier, longer run.
  for (const char* sub : kFrameFolders)
    for (const auto& entry : fs::directory_iterator(folder_ / sub)) {
      const int index = frame_index(entry.path().filename().string());
      if (index >= written_) fs::remove(entry.path());
    }
}

}  // namespace facadeslam::synth
