#include "slam/relative_trajectory.hpp"

#include <unordered_map>

namespace facadeslam {

void RelativeTrajectory::add(std::size_t frame_index, double timestamp, const SE3d& T_c_w, KeyFrame::Id reference,
                             const SE3d& T_ref_w) {
  frames_.push_back({frame_index, timestamp, reference, T_c_w * T_ref_w.inverse(), T_c_w});
}

void RelativeTrajectory::add_online(std::size_t frame_index, double timestamp, const SE3d& T_c_w) {
  frames_.push_back({frame_index, timestamp, std::nullopt, SE3d(), T_c_w});
}

Trajectory RelativeTrajectory::online() const {
  Trajectory out;
  out.reserve(frames_.size());
  for (const RelativeFramePose& f : frames_) out.push_back({f.timestamp, f.T_c_w.inverse().isometry()});
  return out;
}

RelativeTrajectory::Recomposed RelativeTrajectory::recompose(
    const std::vector<KeyFrameSnapshot>& keyframes, const std::map<KeyFrame::Id, CulledKeyFrame>& culled) const {
  std::unordered_map<KeyFrame::Id, const SE3d*> T_ref_w;
  for (const KeyFrameSnapshot& kf : keyframes) T_ref_w.emplace(kf.keyframe->id(), &kf.T_c_w);
  Recomposed out;
  out.trajectory.reserve(frames_.size());
  for (const RelativeFramePose& f : frames_) {
    if (!f.reference) {
      out.trajectory.push_back({f.timestamp, f.T_c_w.inverse().isometry()});
      continue;
    }
    // A culled reference: on to its parent, carrying the relative pose, as
    // often as it takes (a parent may have been culled in turn). Each link
    // points to a keyframe that was in the map when its child went, and a
    // culled keyframe never comes back, so the chain ends.
    KeyFrame::Id reference = *f.reference;
    SE3d T_c_ref = f.T_c_ref;
    auto it = T_ref_w.find(reference);
    for (auto link = culled.find(reference); it == T_ref_w.end() && link != culled.end();
         link = culled.find(reference)) {
      T_c_ref = T_c_ref * link->second.T_culled_parent;
      reference = link->second.parent;
      it = T_ref_w.find(reference);
      out.culled_references += it != T_ref_w.end();
    }
    if (it == T_ref_w.end()) {
      ++out.fallbacks;
      out.trajectory.push_back({f.timestamp, f.T_c_w.inverse().isometry()});
      continue;
    }
    const SE3d T_c_w = T_c_ref * *it->second;
    out.trajectory.push_back({f.timestamp, T_c_w.inverse().isometry()});
  }
  return out;
}

}  // namespace facadeslam
