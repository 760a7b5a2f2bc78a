#include "core/trajectory/sequence_ground_truth.hpp"

#include <string>

#include "core/util/error.hpp"

namespace facadeslam {

SequenceGroundTruth::SequenceGroundTruth(const std::filesystem::path& path)
    : path_(path), format_(detect_trajectory_format(path)), poses_(read_trajectory(path, format_)) {
  if (poses_.size() < 2)
    fail_file(path_,
              "has " + std::to_string(poses_.size()) + " pose (expected a ground-truth trajectory of at least 2)");
}

void SequenceGroundTruth::require_frames_up_to(std::size_t last_index) const {
  if (format_ != TrajectoryFormat::kitti || last_index < poses_.size()) return;
  fail_file(path_, "has " + std::to_string(poses_.size()) + " poses but the sequence has frame " +
                       std::to_string(last_index) +
                       " (counted from 0; expected a KITTI pose file with line i "
                       "for frame i of the sequence)");
}

void SequenceGroundTruth::add_frame(std::size_t index, double timestamp) {
  if (format_ != TrajectoryFormat::kitti) return;
  require_frames_up_to(index);
  stamped_.push_back({timestamp, poses_[index].T_w_c});
}

}  // namespace facadeslam
