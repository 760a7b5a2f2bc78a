#include "mapmaker/map_ba.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <unordered_map>

#include "core/util/error.hpp"
#include "mapmaker/point_geometry.hpp"
#include "core/util/assert.hpp"

namespace facadeslam {

MapBaReport adjust_map(Map& map, const Camera& camera, const BundleAdjuster& adjuster,
                       std::optional<KeyFrame::Id> newest, const LocalBaOptions& selection_options,
                       const PointWeight& weight_of, GroundGauge* ground) {
  MapBaReport report;
  const auto keyframes = map.keyframes();
  if (keyframes.size() < 2) return report;

  // Each point's weight, read once (the semantic worker relabels points
  // while we work): the selection, the problem and the outlier test must
  // agree on which points take part.
  std::unordered_map<MapPoint::Id, double> weight;
  map.read([&](const MapView& view) {
    for (const auto& kf : keyframes)
      for (const auto& [point_id, m] : kf->measurements()) {
        if (weight.contains(point_id)) continue;
        const auto p = view.point(point_id);
        const double w = p && weight_of ? weight_of(*p) : 1.0;
        FACADESLAM_ASSERT(w >= 0.0 && w <= 1.0, "a point's bundle adjustment weight is in [0, 1]");
        weight.emplace(point_id, w);
      }
  });

  // Which keyframes and points take part. Points of weight 0 are left out
  // before the selection, so that every fixed keyframe it picks shares a
  // measured point with the free ones.
  std::vector<KeyFrameCentre> centres;
  centres.reserve(keyframes.size());
  std::vector<ObservationRef> refs;
  // Poses and measurements: written only by the map maker, which runs this.
  for (const auto& kf : keyframes) centres.push_back({kf->id(), kf->centre_w()});
  for (const auto& kf : keyframes)
    for (const auto& [point_id, m] : kf->measurements())
      if (weight.at(point_id) > 0.0) refs.push_back({kf->id(), point_id});
  if (refs.empty()) return report;
  const BaSelection selection =
      newest ? local_ba_selection(centres, refs, *newest, selection_options) : global_ba_selection(centres, refs);

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
  std::vector<bool> observed(problem.keyframes.size(), false);
  for (const auto& kf : kf_of)
    for (const auto& [point_id, m] : kf->measurements()) {
      const auto pi = point_index.find(point_id);
      if (pi == point_index.end()) continue;
      const std::size_t k = kf_index.at(kf->id());
      problem.observations.push_back({k, pi->second, m.pixel, m.level, weight.at(point_id)});
      obs_of.emplace_back(kf.get(), point_id);
      observed[k] = true;
    }
  report.keyframes = problem.keyframes.size();
  report.points = problem.points.size();
  report.observations = problem.observations.size();
  if (problem.points.empty() || problem.observations.empty()) return report;
  // The gauge is fixed among the keyframes that measure something (a
  // keyframe without a measurement in the problem fixes nothing).
  const std::size_t first_observed =
      static_cast<std::size_t>(std::find(observed.begin(), observed.end(), true) - observed.begin());
  if (!newest) {
    // Global: fix the first keyframe; keep the scale by anchoring the second's distance.
    problem.keyframes[first_observed].fixed = true;
    const Eigen::Vector3d first_centre = problem.keyframes[first_observed].T_c_w.inverse().translation();
    for (std::size_t i = first_observed + 1; i < problem.keyframes.size(); ++i)
      if (observed[i] && !problem.keyframes[i].fixed &&
          (problem.keyframes[i].T_c_w.inverse().translation() - first_centre).norm() > 1e-9) {
        problem.scale_anchor = BaScaleAnchor{i, first_observed};
        break;
      }
  }
  bool gauge_fixed = false;
  for (std::size_t i = 0; i < problem.keyframes.size(); ++i)
    gauge_fixed = gauge_fixed || (observed[i] && problem.keyframes[i].fixed);
  if (!gauge_fixed) problem.keyframes[first_observed].fixed = true;
  if (ground) report.ground_keyframes = ground->constrain(problem, /*fixed_too=*/!newest);

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
