#pragma once
// The on-disk layout of a synthetic sequence (TUM RGB-D style, so that
// `facadeslam replay DIR` and TUM tools read it):
//
//   rgb/000000.png      colour, 8-bit BGR PNG
//   label/000000.png    labels as LabelMeFacade colours (labels.txt)
//   depth/000000.png    z-depth, 16-bit PNG, millimetres, 0 = none
//   rgb.txt             "timestamp rgb/000000.png" per frame
//   depth.txt           "timestamp depth/000000.png" per frame
//   groundtruth.txt     TUM "timestamp tx ty tz qx qy qz qw", camera -> world,
//                       the same timestamps as rgb.txt, character for character
//   camera.yaml         the camera (configs/camera format)
//   labels.txt          the class table
//   scene.yaml          a byte-for-byte copy of the scene file
//   synth.json          what was rendered (frames, seed, options, renderer)
//
// Every file is written atomically. Frames left over from an earlier, longer
// run in the same folder (index >= frame count) are removed by finish(), so
// the folder never lists or holds frames of two different runs.
#include <filesystem>
#include <string>

#include "core/trajectory/trajectory.hpp"
#include "core/util/json.hpp"
#include "sequences/synth/frame_synthesizer.hpp"

namespace facadeslam::synth {

// "%.9f": the timestamp text shared by rgb.txt, depth.txt and groundtruth.txt.
std::string timestamp_text(double seconds);
// "000042.png"
std::string frame_file_name(int index);
// The index of a frame file name ("000042.png" -> 42), -1 for any other name.
int frame_index(const std::string& file_name);

class SequenceWriter {
 public:
  SequenceWriter(std::filesystem::path folder, const SceneSpec& spec);

  // Writes the three PNGs of a frame and remembers its pose and timestamp.
  void write(const SynthFrame& frame);
  // Writes the lists, ground truth, camera, class table, scene copy and
  // `report` (as synth.json); removes stale frames.
  void finish(const Json& report);

  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path folder_;
  const SceneSpec& spec_;
  Trajectory trajectory_;
  int written_ = 0;
};

}  // namespace facadeslam::synth
