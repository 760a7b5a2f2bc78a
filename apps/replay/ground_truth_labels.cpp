#include "apps/replay/ground_truth_labels.hpp"

#include "core/util/error.hpp"
#include "semantics/evaluation/label_image.hpp"
#include "sequences/synth/label_classes.hpp"

namespace facadeslam::apps {

namespace fs = std::filesystem;

fs::path find_ground_truth_labels(const fs::path& sequence, const fs::path& given) {
  if (!given.empty()) {
    if (!fs::is_directory(given)) fail_file(given, "--gt-labels expects a folder of label PNGs named like the frames");
    return given;
  }
  const fs::path folder = fs::is_directory(sequence) ? sequence : sequence.parent_path();
  const fs::path beside = folder / "label";
  return fs::is_directory(beside) && fs::exists(folder / "labels.txt") ? beside : fs::path();
}

GroundTruthLabelFiles::GroundTruthLabelFiles(fs::path folder) : folder_(std::move(folder)) {}

void GroundTruthLabelFiles::add(const Frame& frame) {
  if (frame.source.empty()) throw Error("ground-truth labels need frames read from image files");
  const bool first = files_.empty();
  files_[frame.index] = folder_ / frame.source.filename();
  if (first) {
    frame_size_ = frame.colour.size();
    class_ids(frame.index);
  }
}

cv::Mat GroundTruthLabelFiles::class_ids(std::size_t frame_index) const {
  const auto it = files_.find(frame_index);
  if (it == files_.end()) throw Error("ground-truth labels: frame " + std::to_string(frame_index) + " was not read");
  const fs::path& path = it->second;
  const cv::Mat colours = semantics::read_label_image(path);
  if (colours.size() != frame_size_)
    fail_file(path, "label image is " + std::to_string(colours.cols) + "x" + std::to_string(colours.rows) +
                        ", the frame is " + std::to_string(frame_size_.width) + "x" + std::to_string(frame_size_.height));
  return synth::label_ids_from_colours(colours, path);
}

}  // namespace facadeslam::apps
