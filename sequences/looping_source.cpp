#include "sequences/looping_source.hpp"

#include "core/util/error.hpp"

namespace facadeslam {

LoopingSource::LoopingSource(Opener open, std::size_t passes) : open_(std::move(open)), passes_(passes) {
  if (passes_ == 0) throw Error("sequence options: loops must be at least 1 (got 0)");
  current_ = open_();
  finished_passes_.pass_time_offsets_s = {0.0};
}

std::optional<Frame> LoopingSource::next() {
  for (;;) {
    if (auto frame = current_->next()) {
      if (pass_ == 0) {
        if (!first_timestamp_) first_timestamp_ = frame->timestamp;
        previous_timestamp_ = last_timestamp_;
        last_timestamp_ = frame->timestamp;
        last_index_ = frame->index;
      }
      frame->index += index_offset_;
      frame->timestamp += time_offset_;
      return frame;
    }
    // Pass 0 delivered nothing: there is nothing to loop.
    if (pass_ + 1 >= passes_ || !first_timestamp_) return std::nullopt;
    const ReadStats& done = current_->stats();
    finished_passes_.frames_read += done.frames_read;
    finished_passes_.frames_skipped_corrupt += done.frames_skipped_corrupt;
    finished_passes_.corrupt_paths.insert(finished_passes_.corrupt_paths.end(), done.corrupt_paths.begin(),
                                          done.corrupt_paths.end());
    // One frame interval across the seam: pass 0's last one (a single-frame
    // sequence has none; a second then).
    const double interval = previous_timestamp_ ? *last_timestamp_ - *previous_timestamp_ : 1.0;
    ++pass_;
    index_offset_ = pass_ * (last_index_ + 1);
    time_offset_ = static_cast<double>(pass_) * (*last_timestamp_ - *first_timestamp_ + interval);
    finished_passes_.pass_time_offsets_s.push_back(time_offset_);
    current_ = open_();
  }
}

std::size_t LoopingSource::size_hint() const { return current_->size_hint() * passes_; }

const ReadStats& LoopingSource::stats() const {
  combined_ = finished_passes_;
  const ReadStats& now = current_->stats();
  combined_.frames_read += now.frames_read;
  combined_.frames_skipped_corrupt += now.frames_skipped_corrupt;
  combined_.corrupt_paths.insert(combined_.corrupt_paths.end(), now.corrupt_paths.begin(), now.corrupt_paths.end());
  return combined_;
}

std::string LoopingSource::description() const {
  std::string text = current_->description();
  text += ", played ";
  text += std::to_string(passes_);
  text += " times";
  return text;
}

}  // namespace facadeslam
