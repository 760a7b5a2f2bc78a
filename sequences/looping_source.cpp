#include "sequences/looping_source.hpp"

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

// Adds a pass's counts and corrupt files to the run's.
void add_pass(ReadStats& run, const ReadStats& pass) {
  run.frames_read += pass.frames_read;
  run.frames_skipped_corrupt += pass.frames_skipped_corrupt;
  run.corrupt_paths.insert(run.corrupt_paths.end(), pass.corrupt_paths.begin(), pass.corrupt_paths.end());
}

}  // namespace

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
    add_pass(finished_passes_, current_->stats());
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
  add_pass(combined_, current_->stats());
  return combined_;
}

std::string LoopingSource::description() const {
  std::string text = current_->description();
  text += ", played ";
  text += std::to_string(passes_);
  text += " times";
  return text;
}

std::vector<std::filesystem::path> LoopingSource::image_files() const {
  return current_ ? current_->image_files() : std::vector<std::filesystem::path>{};
}

}  // namespace facadeslam
