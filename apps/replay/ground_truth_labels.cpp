#include "apps/replay/ground_truth_labels.hpp"

#include "core/util/error.hpp"
#include "core/util/path_checks.hpp"
#include "semantics/evaluation/label_image.hpp"
#include "sequences/synth/label_classes.hpp"

namespace facadeslam::apps {

namespace fs = std::filesystem;

fs::path find_ground_truth_labels(const fs::path& sequence, const fs::path& given) {
  if (!given.empty()) {
    if (!is_existing_folder(given))
      fail_file(given, "--gt-labels expects a folder of label PNGs named like the frames");
    return given;
  }
  const fs::path folder = is_existing_folder(sequence) ? sequence : sequence.parent_path();
  const fs::path beside = folder / "label";
  return is_existing_folder(beside) && path_exists(folder / "labels.txt") ? beside : fs::path();
}

namespace {

// A frame's label image: the same file name (synthetic sequences: PNG frames
// and PNG labels), else its stem with .png (a JPEG frame beside a PNG label,
// LabelMeFacade's and CamVid's layout: labels are never lossy).
fs::path label_file_for(const fs::path& folder, const fs::path& frame_name) {
  const fs::path same = folder / frame_name;
  if (is_readable_file(same)) return same;
  fs::path png = same;
  png.replace_extension(".png");
  return is_readable_file(png) ? png : same;
}

}  // namespace

GroundTruthLabelFiles::GroundTruthLabelFiles(fs::path folder) : folder_(std::move(folder)) {}

void GroundTruthLabelFiles::add(const Frame& frame) {
  if (frame.source.empty())
    fail_file(folder_, "ground-truth labels need frames read from image files (a video's frames have no names)");
  const bool first = names_.empty();
  const std::string name = frame.source.filename().string();
  const auto [it, added] = name_ids_.emplace(name, static_cast<std::uint32_t>(names_.size()));
  if (added) names_.push_back(name);
  if (name_of_frame_.size() <= frame.index) name_of_frame_.resize(frame.index + 1, 0);
  name_of_frame_[frame.index] = it->second + 1;
  if (first) {
    frame_size_ = frame.colour.size();
    class_ids(frame.index);
  }
}

void GroundTruthLabelFiles::require_files_for(const std::vector<fs::path>& frame_files) const {
  for (const fs::path& frame : frame_files) {
    const fs::path label = label_file_for(folder_, frame.filename());
    if (!is_readable_file(label))
      fail_file(label, "the ground-truth label image of frame " + frame.filename().string() + " " +
                           describe_path(label) +
                           " (--gt-labels: a label PNG named like each frame, or its name with .png)");
  }
}

cv::Mat GroundTruthLabelFiles::class_ids(std::size_t frame_index) const {
  if (frame_index >= name_of_frame_.size() || name_of_frame_[frame_index] == 0)
    fail_file(folder_, "ground-truth labels: frame " + std::to_string(frame_index) + " was not read");
  const fs::path path = label_file_for(folder_, names_[name_of_frame_[frame_index] - 1]);
  const cv::Mat colours = semantics::read_label_image(path);
  if (colours.size() != frame_size_)
    fail_file(path, "label image is " + std::to_string(colours.cols) + "x" + std::to_string(colours.rows) +
                        ", the frame is " + std::to_string(frame_size_.width) + "x" +
                        std::to_string(frame_size_.height));
  return synth::label_ids_from_colours(colours, path);
}

}  // namespace facadeslam::apps
