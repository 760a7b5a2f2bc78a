#pragma once
// The ground truth of a replayed sequence (`replay --gt`), in either format:
//  - TUM: the file's poses with their own timestamps;
//  - KITTI: no times in the file; line i is the pose of frame i of the whole
//    sequence (Frame::index, counted before --start/--stride/--limit), and
//    takes the time that frame has as the sequence reader gives it (its
//    rgb.txt line, the folder's times file), so that both associate with the
//    estimate by time alike.
#include <cstddef>
#include <filesystem>

#include "core/trajectory/trajectory.hpp"
#include "core/trajectory/trajectory_io.hpp"

namespace facadeslam {

class SequenceGroundTruth {
 public:
  // Reads the file (read_trajectory's errors); fewer than 2 poses is an Error.
  explicit SequenceGroundTruth(const std::filesystem::path& path);

  TrajectoryFormat format() const { return format_; }
  // KITTI: Error naming the file unless it has a pose for every frame up to
  // `last_index`, so that a short file fails before the run. TUM: nothing to
  // check (its poses pair by time).
  void require_frames_up_to(std::size_t last_index) const;
  // A frame as it is read, once per frame of the sequence (a looped replay's
  // later passes repeat the ground truth: repeat_trajectory). KITTI: its pose
  // joins trajectory() at `timestamp`, or Error as require_frames_up_to.
  void add_frame(std::size_t index, double timestamp);
  // TUM: the file's trajectory. KITTI: the poses of the frames added, at
  // their frames' times.
  const Trajectory& trajectory() const { return format_ == TrajectoryFormat::kitti ? stamped_ : poses_; }

 private:
  std::filesystem::path path_;
  TrajectoryFormat format_;
  Trajectory poses_;    // as read (KITTI: pose i at time i)
  Trajectory stamped_;  // KITTI: the frames' poses at the frames' times
};

}  // namespace facadeslam
