#include "slam/initialiser.hpp"

#include <algorithm>

#include <spdlog/spdlog.h>

namespace facadeslam {

Initialiser::Initialiser(const Camera& camera, const TwoViewOptions& options, MapMaker& map_maker)
    : two_view_(camera, options), map_maker_(map_maker) {}

void Initialiser::restart(const Frame& frame, const char* why) {
  if (reference_) spdlog::debug("frame {}: initialisation restarts ({})", frame.index, why);
  reference_ = frame;
  two_view_.reset(frame.pyramid->level(0).image, frame.pyramid->level(0).corners, frame.timestamp);
}

std::optional<StartPose> Initialiser::add_frame(const Frame& frame) {
  if (!reference_) {
    restart(frame, "first frame");
    return std::nullopt;
  }
  const InitStatus status = two_view_.add_frame(frame.pyramid->level(0).image);
  if (status == InitStatus::too_few_tracks) {
    restart(frame, two_view_.last_attempt().reason.c_str());
    return std::nullopt;
  }
  if (status != InitStatus::success) return std::nullopt;

  const TwoViewResult& result = two_view_.result();
  const auto T_c_w = map_maker_.initialise({*reference_, frame, result.T_c1_c0, result.points_c0, result.pixels0,
                                            result.pixels1, result.median_parallax_deg, to_string(result.model)});
  if (!T_c_w) {
    restart(frame, "the map maker discarded the initial map");
    return std::nullopt;
  }
  // The reference is the first keyframe, at the origin: T_c_w is the motion
  // over the frames tracked since it.
  const int frames = std::max(1, two_view_.frames_since_reset());
  return StartPose{*T_c_w, T_c_w->log() / frames, reference_->index, reference_->timestamp};
}

}  // namespace facadeslam
