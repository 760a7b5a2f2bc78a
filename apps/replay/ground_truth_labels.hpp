#pragma once
// Ground-truth label images for a replay (`--gt-labels DIR`, or the `label/`
// folder a synthetic sequence has beside its rgb.txt): one LabelMeFacade-
// coloured PNG per frame, named like the frame's colour image. They give
// report.json its label accuracy (semantics/evaluation/map_label_accuracy.hpp).
#include <cstddef>
#include <filesystem>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <opencv2/core.hpp>

#include "core/image/frame.hpp"

namespace facadeslam::apps {

// The folder to use: `given` if not empty (it must be a folder), else
// `label/` beside the sequence when it has one, else empty.
std::filesystem::path find_ground_truth_labels(const std::filesystem::path& sequence,
                                               const std::filesystem::path& given);

class GroundTruthLabelFiles {
 public:
  explicit GroundTruthLabelFiles(std::filesystem::path folder);

  // Notes where frame `frame.index`'s labels are. The first frame's label
  // image is read at once, so a folder that does not fit the sequence fails
  // before the work rather than after it.
  void add(const Frame& frame);

  // Every frame file's label image is there (a file of the frame's name in
  // the folder), checked before the run: a folder missing a later frame's
  // label fails now, not at that frame. Error naming the first one missing.
  void require_files_for(const std::vector<std::filesystem::path>& frame_files) const;

  // Class ids (CV_8UC1) of a frame added before. Throws Error naming the file
  // when it is missing, not a label image, or not the frame's size.
  cv::Mat class_ids(std::size_t frame_index) const;

 private:
  std::filesystem::path folder_;
  // Frame index -> 1 + the index of its file name in names_ (0: not read).
  // Four bytes a frame, and each name once: a looped soak replay plays the
  // same files thousands of times.
  std::vector<std::uint32_t> name_of_frame_;
  std::vector<std::string> names_;
  std::unordered_map<std::string, std::uint32_t> name_ids_;
  cv::Size frame_size_;
};

}  // namespace facadeslam::apps
