#include "mapmaker/map_ba.hpp"

#include <map>

#include "mapmaker/point_geometry.hpp"

namespace facadeslam {

MapBaReport adjust_map(Map& map, const Camera& camera, const BundleAdjuster& adjuster,
                       std::optional<KeyFrame::Id> newest, const LocalBaOptions& selection_options,
                       const PointWeight& weight_of) {
  MapBaReport report;
  const auto keyframes = map.keyframes();
  if (keyframes.size() < 2) return report;

  // Which keyframes and points take part.
  std::vector<KeyFrameCentre> centres;
  std::vector<ObservationRef> refs;
  // Poses and measurements: written only by the map maker, which runs this.
  for (const auto& kf : keyframes) centres.push_back({kf->id(), kf->centre_w()});
  for (const auto& kf : keyframes)
    for (const auto& [point_id, m] : kf->measurements()) refs.push_back({kf->id(), point_id});
  const BaSelection selection = newest ? local_ba_selection(centres, refs, *newest, selection_options)
                                       : global_ba_selection(centres, refs);

  // Copy into the problem.
  BaProblem problem;
  std::map<KeyFrame::Id, std::size_t> kf_index;
  std::map<MapPoint::Id, std::size_t> point_index;
  std::vector<std::shared_ptr<KeyFrame>> kf_of;
  std::vector<std::shared_ptr<MapPoint>> point_of;
  map.read([&](const MapView& view) {
    for (const auto& kf : keyframes) {
      const bool is_free = selection.free_keyframes.count(kf->id()) > 0;
      if (!is_free && !selection.fixed_keyframes.count(kf->id())) continue;
      kf_index[kf->id()] = problem.keyframes.size();
      problem.keyframes.push_back({kf->id(), kf->T_c_w(), !is_free});
      kf_of.push_back(kf);
    }
    for (const MapPoint::Id id : selection.free_points) {
      const auto p = view.point(id);
      if (!p || p->is_bad()) continue;
      point_index[id] = problem.points.size();
      problem.points.push_back({id, p->position(), false});
      point_of.push_back(p);
    }
  });
  std::vector<std::pair<KeyFrame*, MapPoint::Id>> obs_of;
  for (const auto& kf : kf_of)
    for (const auto& [point_id, m] : kf->measurements()) {
      const auto pi = point_index.find(point_id);
      if (pi == point_index.end()) continue;
      const double weight = weight_of ? weight_of(*point_of[pi->second]) : 1.0;
      if (!(weight > 0.0)) continue;  // left out
      problem.observations.push_back({kf_index.at(kf->id()), pi->second, m.pixel, m.level, weight});
      obs_of.emplace_back(kf.get(), point_id);
    }
  if (!newest && problem.keyframes.size() >= 2) {
    // Global: fix the first keyframe; keep the scale by anchoring the second's distance.
    problem.keyframes.front().fixed = true;
    for (std::size_t i = 1; i < problem.keyframes.size(); ++i)
      if (!problem.keyframes[i].fixed &&
          (problem.keyframes[i].T_c_w.inverse().translation() - problem.keyframes[0].T_c_w.inverse().translation())
                  .norm() > 1e-9) {
        problem.scale_anchor = BaScaleAnchor{i, 0};
        break;
      }
  }
  report.keyframes = problem.keyframes.size();
  report.points = problem.points.size();
  report.observations = problem.observations.size();
  if (problem.points.empty() || problem.observations.empty()) return report;
  if (std::none_of(problem.keyframes.begin(), problem.keyframes.end(), [](const BaKeyFrame& k) { return k.fixed; }))
    problem.keyframes.front().fixed = true;

  report.ba = adjuster.solve(problem, camera);
  // An aborted solve still leaves the last accepted iterate in `problem`
  // (never worse than the input, bundle_adjuster.hpp): publish it, so the
  // iterations done before a new keyframe interrupted a global BA are kept.
  // Only a solve aborted before its first iteration has nothing to publish.
  if (report.ba.aborted && report.ba.iterations == 0) return report;

  // Publish the results in one short exclusive section: outlier measurements
  // (never a point's source measurement) leave their keyframes, the poses
  // and points move.
  map.update([&](MapEditor& edit) {
    for (const std::size_t o : report.ba.outliers) {
      auto& [kf, point_id] = obs_of[o];
      const auto it = kf->measurements().find(point_id);
      if (it != kf->measurements().end() && !it->second.from_source) {
        edit.erase_measurement(*kf, point_id);
        ++report.outliers_removed;
      }
    }
    for (std::size_t i = 0; i < problem.keyframes.size(); ++i)
      if (!problem.keyframes[i].fixed) edit.set_pose(*kf_of[i], problem.keyframes[i].T_c_w);
    for (std::size_t i = 0; i < problem.points.size(); ++i) {
      const auto& p = point_of[i];
      const auto source_kf = edit.keyframe(p->source().keyframe_id);
      if (!source_kf) continue;
      edit.set_geometry(*p, source_geometry(camera, source_kf->T_c_w(), p->source(), problem.points[i].p_w));
      if (p->view().keyframe_id == p->source().keyframe_id) continue;
      if (const auto view_kf = edit.keyframe(p->view().keyframe_id))
        edit.set_view(*p, p->view(), source_geometry(camera, view_kf->T_c_w(), p->view(), problem.points[i].p_w));
    }
  });
  return report;
}

}  // namespace facadeslam
