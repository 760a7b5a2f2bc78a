#pragma once
// Plays another reader's frames several times over (`replay --loop N`), for
// soak runs: hours of input from a short sequence. Each pass reopens the
// reader, so frames are still decoded one at a time and nothing is held.
// Pass k shifts what it delivers so the whole run stays one sequence:
//   index     + k x (last index of pass 0 + 1)      (still unique)
//   timestamp + k x (span of pass 0 + its last frame interval)
// (still strictly increasing, one frame interval across each seam). The
// offsets are in ReadStats::pass_time_offsets_s, so a ground truth can be
// repeated the same way (repeat_trajectory). The camera jumps from the last
// frame back to the first at each seam: the tracker relocalises there.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "sequences/frame_source.hpp"

namespace facadeslam {

class LoopingSource : public FrameSource {
 public:
  using Opener = std::function<std::unique_ptr<FrameSource>()>;

  // Opens the first pass at once (so a bad input fails here). `passes` >= 1.
  LoopingSource(Opener open, std::size_t passes);

  std::optional<Frame> next() override;
  std::size_t size_hint() const override;
  const ReadStats& stats() const override;
  std::string description() const override;
  // One pass's files (every pass plays the same).
  std::vector<std::filesystem::path> image_files() const override;

 private:
  Opener open_;
  std::size_t passes_;
  std::size_t pass_ = 0;
  std::unique_ptr<FrameSource> current_;
  ReadStats finished_passes_;  // stats of the passes before the current one
  mutable ReadStats combined_;
  // Pass 0's extent, learnt while it plays.
  std::optional<double> first_timestamp_, last_timestamp_, previous_timestamp_;
  std::size_t last_index_ = 0;
  std::size_t index_offset_ = 0;
  double time_offset_ = 0.0;
};

}  // namespace facadeslam
