#include "sequences/video_timestamps.hpp"

#include <cmath>

namespace facadeslam {

double VideoTimestamps::next(std::size_t index, double position_ms) {
  double t = position_ms / 1000.0;
  if (positions_sane_) positions_sane_ = std::isfinite(t) && t >= 0.0 && (!have_previous_ || t > previous_);
  if (!positions_sane_) {
    t = have_previous_ ? previous_ + static_cast<double>(index - previous_index_) / fps_
                       : static_cast<double>(index) / fps_;
  }
  have_previous_ = true;
  previous_ = t;
  previous_index_ = index;
  return t;
}

}  // namespace facadeslam
