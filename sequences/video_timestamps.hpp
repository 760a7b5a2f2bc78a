#pragma once
// Timestamps for video frames. Decoders report a position per frame
// (CAP_PROP_POS_MSEC) that is exact when the container has timestamps, but
// some backends report 0, NaN or positions that go backwards. The position
// is used while it is sane (finite, not negative, increasing); from the first
// frame where it is not, timestamps continue from the last good one at the
// frame rate, so they remain strictly increasing either way.
#include <cstddef>

namespace facadeslam {

class VideoTimestamps {
 public:
  explicit VideoTimestamps(double fps) : fps_(fps) {}

  // Seconds for frame `index` (increasing between calls; gaps allowed) whose
  // decoder position is `position_ms`.
  double next(std::size_t index, double position_ms);
  bool using_positions() const { return positions_sane_; }

 private:
  double fps_;
  bool positions_sane_ = true;
  bool have_previous_ = false;
  double previous_ = 0.0;
  std::size_t previous_index_ = 0;
};

}  // namespace facadeslam
