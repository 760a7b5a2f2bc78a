#include "mapmaker/epipolar_search.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

#include "core/util/angles.hpp"
#include "mapmaker/new_point_candidates.hpp"
#include "mapmaker/point_geometry.hpp"
#include "core/patch/patch_search.hpp"
#include "core/patch/patch_warp.hpp"

namespace facadeslam {

std::optional<Eigen::Vector3d> triangulate_rays(const SE3d& T_a_w, const Eigen::Vector3d& ray_a, const SE3d& T_b_w,
                                                const Eigen::Vector3d& ray_b) {
  Eigen::Matrix4d A;
  const Eigen::Matrix<double, 3, 4> Pa = T_a_w.matrix3x4(), Pb = T_b_w.matrix3x4();
  A.row(0) = ray_a.x() * Pa.row(2) - ray_a.z() * Pa.row(0);
  A.row(1) = ray_a.y() * Pa.row(2) - ray_a.z() * Pa.row(1);
  A.row(2) = ray_b.x() * Pb.row(2) - ray_b.z() * Pb.row(0);
  A.row(3) = ray_b.y() * Pb.row(2) - ray_b.z() * Pb.row(1);
  const Eigen::JacobiSVD<Eigen::Matrix4d> svd(A, Eigen::ComputeFullV);
  const Eigen::Vector4d X = svd.matrixV().col(3);
  if (std::abs(X.w()) < 1e-12) return std::nullopt;
  const Eigen::Vector3d p_w = X.head<3>() / X.w();
  if ((T_a_w * p_w).z() <= 0 || (T_b_w * p_w).z() <= 0) return std::nullopt;
  return p_w;
}

namespace {

double point_line_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           double* along) {
  const Eigen::Vector2d d = b - a;
  const double len2 = std::max(d.squaredNorm(), 1e-12);
  const double t = std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
  if (along) *along = t;
  return (a + t * d - p).norm();
}

}  // namespace

NewPoints epipolar_new_points(Map& map, const Camera& camera, const std::shared_ptr<KeyFrame>& newest_kf,
                              const std::shared_ptr<KeyFrame>& other_kf, const EpipolarSearchOptions& options,
                              EpipolarSearchStats* stats) {
  // The map maker, the only writer of poses and depth statistics, reads them
  // without the map's lock.
  const KeyFrame& newest = *newest_kf;
  const KeyFrame& other = *other_kf;
  const SE3d T_new_w = newest.T_c_w();
  const SE3d T_other_w = other.T_c_w();
  const double mean_depth = newest.mean_depth();
  const double depth_sigma = newest.depth_sigma();
  const SE3d T_other_new = T_other_w * T_new_w.inverse();
  const double depth_min =
      std::max(options.min_depth_fraction * mean_depth, mean_depth - options.depth_range_sigmas * depth_sigma);
  const double depth_max = std::max(mean_depth + options.depth_range_sigmas * std::max(depth_sigma, 0.25 * mean_depth),
                                    options.min_far_depth_factor * mean_depth);

  NewPoints created;
  EpipolarSearchStats local;
  const float max_zmssd = 64.f * options.max_zmssd_per_pixel;
  patch::SearchOptions refine_options;

  for (int level = 0; level < kPyramidLevels; ++level) {
    const double scale = static_cast<double>(1 << level);
    NewPointCandidates candidates(newest, level, options.min_distance_to_measurement);
    int tried = 0;
    for (const Corner& c : candidates.corners()) {
      if (tried >= options.max_candidates_per_level[static_cast<std::size_t>(level)]) break;
      const Eigen::Vector2d at(c.x, c.y);
      if (candidates.near_taken(at)) continue;
      ++tried;
      ++local.candidates;

      // The patch as the other keyframe sees it. Warped (options.warp_templates):
      // as if the point lay at the new keyframe's mean depth on a plane facing
      // it, which is what forward motion needs (a car at 10 Hz scales patches
      // by 1.3-1.5 between keyframes three frames apart); the warp also picks
      // the level of the other keyframe to search. Otherwise PTAM's identity
      // warp at the same level.
      const Eigen::Vector2d pixel0 = ImagePyramid::level_to_level0(at, level);
      const PatchSource source{newest.id(), newest.pyramid(), level, pixel0};
      const Eigen::Vector3d ray = camera.unproject(pixel0);
      Eigen::Matrix2d warp = Eigen::Matrix2d::Identity() * scale;
      if (options.warp_templates) {
        const Eigen::Vector3d p_w = T_new_w.inverse() * (ray * mean_depth);
        const Eigen::Vector3d p_other = T_other_w * p_w;
        if (p_other.z() <= 1e-6) continue;
        warp = patch::patch_warp(p_other, T_other_w.rotation_matrix(), source_geometry(camera, T_new_w, source, p_w),
                                 camera);
      }
      const patch::PatchTemplate tpl = patch::make_patch_template(source, warp, {});
      if (!tpl.valid() || (!options.warp_templates && tpl.search_level != level)) continue;
      const int other_level_index = tpl.search_level;
      const auto& other_level = other.pyramid()->level(other_level_index);

      // The depth range's segment of the epipolar line in the other keyframe.
      const Eigen::Vector3d near_p = T_other_new * (ray * depth_min);
      const Eigen::Vector3d far_p = T_other_new * (ray * depth_max);
      if (near_p.z() <= 1e-6 || far_p.z() <= 1e-6) continue;
      const Eigen::Vector2d seg_a = ImagePyramid::level0_to_level(camera.project(near_p), other_level_index);
      const Eigen::Vector2d seg_b = ImagePyramid::level0_to_level(camera.project(far_p), other_level_index);

      float best = max_zmssd;
      Eigen::Vector2i best_corner(-1, -1);
      const double lo_y = std::min(seg_a.y(), seg_b.y()) - options.max_line_distance;
      const double hi_y = std::max(seg_a.y(), seg_b.y()) + options.max_line_distance;
      const auto& oc = other_level.corners;  // sorted by row
      auto it = std::lower_bound(oc.begin(), oc.end(), lo_y, [](const Corner& k, double y) { return k.y < y; });
      for (; it != oc.end() && it->y <= hi_y; ++it) {
        const Eigen::Vector2d q(it->x, it->y);
        if (point_line_distance(q, seg_a, seg_b, nullptr) > options.max_line_distance) continue;
        const float score = patch::zmssd_at(tpl, other_level.image, it->x, it->y);
        if (score < best) {
          best = score;
          best_corner = {it->x, it->y};
        }
      }
      if (options.dense_line_search) {
        // Every pixel along the segment too: under a scale change the other
        // keyframe's FAST corners are not where the patch's corner is.
        const double length = (seg_b - seg_a).norm();
        const int steps = static_cast<int>(std::min(length, 2000.0));
        for (int k = 0; k <= steps; ++k) {
          const Eigen::Vector2d q = steps == 0 ? seg_a : seg_a + (seg_b - seg_a) * (static_cast<double>(k) / steps);
          const int x = static_cast<int>(std::lround(q.x())), y = static_cast<int>(std::lround(q.y()));
          const float score = patch::zmssd_at(tpl, other_level.image, x, y);
          if (score < best) {
            best = score;
            best_corner = {x, y};
          }
        }
      }
      if (best_corner.x() < 0) continue;
      ++local.matched;

      const auto refined = patch::refine_subpixel(tpl, other_level.image, best_corner.cast<double>(), refine_options);
      if (!refined.converged) continue;
      const Eigen::Vector2d other_pixel0 = ImagePyramid::level_to_level0(refined.pixel, other_level_index);
      const double other_scale = static_cast<double>(1 << other_level_index);
      const Eigen::Vector3d other_ray = camera.unproject(other_pixel0);

      const auto p_w = triangulate_rays(T_new_w, ray, T_other_w, other_ray);
      if (!p_w) continue;
      const Eigen::Vector3d in_new = T_new_w * *p_w, in_other = T_other_w * *p_w;
      const double err_new = (camera.project(in_new) - pixel0).norm() / scale;
      const double err_other = (camera.project(in_other) - other_pixel0).norm() / other_scale;
      if (err_new > options.max_reprojection_px || err_other > options.max_reprojection_px) continue;
      const Eigen::Vector3d to_new = T_new_w.inverse().translation() - *p_w;
      const Eigen::Vector3d to_other = T_other_w.inverse().translation() - *p_w;
      const double parallax_deg =
          rad_to_deg(std::acos(std::clamp(to_new.normalized().dot(to_other.normalized()), -1.0, 1.0)));
      // A level-L match is only good to ~2^L level-0 pixels, so its depth
      // needs 2^L times the parallax of a level-0 point to be as certain.
      if (parallax_deg < options.min_parallax_deg * scale) continue;

      auto point =
          std::make_shared<MapPoint>(map.new_point_id(), source, source_geometry(camera, T_new_w, source, *p_w));
      // Recorded when the points are published (Map::add). A level's
      // candidates look at measurements of their own and the next coarser
      // level only, so the later levels' searches do not miss them.
      created.observations.push_back({newest_kf, point->id(), {level, pixel0, true}});
      created.observations.push_back({other_kf, point->id(), {other_level_index, other_pixel0, false}});
      candidates.take(at);
      created.points.push_back(std::move(point));
      ++local.triangulated;
      ++local.triangulated_per_level[static_cast<std::size_t>(level)];
    }
  }
  if (stats) *stats = local;
  return created;
}

}  // namespace facadeslam
