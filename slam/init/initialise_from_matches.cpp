#include "slam/init/initialise_from_matches.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/LU>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <fmt/format.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <spdlog/spdlog.h>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/median.hpp"
#include "slam/init/essential_refinement.hpp"
#include "slam/init/homography_refinement.hpp"
#include "slam/init/model_scoring.hpp"
#include "slam/init/two_view_triangulation.hpp"

namespace facadeslam {
namespace {

// Refine, re-score, refine again while the inliers change: two or three
// rounds settle in practice.
constexpr int kMaxRefinementRounds = 3;

TwoViewResult& fail(TwoViewResult& result, InitStatus status, std::string reason) {
  result.status = status;
  result.reason = std::move(reason);
  spdlog::debug("two-view initialisation: {} ({})", to_string(status), result.reason);
  return result;
}

Eigen::Matrix3d to_eigen3(const cv::Mat& m) {
  Eigen::Matrix3d e;
  cv::cv2eigen(m, e);
  return e;
}

// |t|/d of a homography in normalised coordinates, H = R + t n^T / d: up to
// scale its singular values are 1 +- about |t|/d, so their spread measures the
// translation against the plane distance (0 for a pure rotation).
double homography_translation(const Eigen::Matrix3d& H_normalised) {
  const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(H_normalised).singularValues();
  if (!(s(1) > 0.0)) return 0.0;
  return (s(0) - s(2)) / s(1);
}

struct Hypothesis {
  SE3d T_c1_c0;
  PoseEvaluation evaluation;
};

// Best first: most good points, then the smaller total reprojection error.
void rank(std::vector<Hypothesis>& hypotheses) {
  std::stable_sort(hypotheses.begin(), hypotheses.end(), [](const Hypothesis& a, const Hypothesis& b) {
    if (a.evaluation.good_count() != b.evaluation.good_count())
      return a.evaluation.good_count() > b.evaluation.good_count();
    return a.evaluation.good_reprojection_error_sum < b.evaluation.good_reprojection_error_sum;
  });
}

std::vector<SE3d> homography_poses(const Eigen::Matrix3d& H_normalised) {
  cv::Mat H_cv, K_cv = cv::Mat::eye(3, 3, CV_64F);
  cv::eigen2cv(H_normalised, H_cv);
  std::vector<cv::Mat> rotations, translations, normals;
  cv::decomposeHomographyMat(H_cv, K_cv, rotations, translations, normals);
  std::vector<SE3d> poses;
  for (std::size_t i = 0; i < rotations.size(); ++i) {
    Eigen::Vector3d t;
    cv::cv2eigen(translations[i], t);
    poses.emplace_back(to_eigen3(rotations[i]), t);
  }
  return poses;
}

std::vector<SE3d> essential_poses(const Eigen::Matrix3d& E) {
  cv::Mat E_cv, R1, R2, t_cv;
  cv::eigen2cv(E, E_cv);
  cv::decomposeEssentialMat(E_cv, R1, R2, t_cv);
  Eigen::Vector3d t;
  cv::cv2eigen(t_cv, t);
  const Eigen::Matrix3d Ra = to_eigen3(R1), Rb = to_eigen3(R2);
  return {SE3d(Ra, t), SE3d(Ra, -t), SE3d(Rb, t), SE3d(Rb, -t)};
}

std::vector<int> indices_of(const std::vector<bool>& mask) {
  std::vector<int> indices;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) indices.push_back(static_cast<int>(i));
  return indices;
}

}  // namespace

TwoViewResult initialise_from_matches(const Camera& camera, const std::vector<Eigen::Vector2d>& pixels0,
                                      const std::vector<Eigen::Vector2d>& pixels1, const TwoViewOptions& options) {
  validate(options);
  if (pixels0.size() != pixels1.size())
    throw Error(fmt::format("two-view initialiser: {} reference pixels but {} current pixels (one pair per match)",
                            pixels0.size(), pixels1.size()));
  for (std::size_t i = 0; i < pixels0.size(); ++i)
    if (!pixels0[i].allFinite() || !pixels1[i].allFinite())
      throw Error(fmt::format("two-view initialiser: match {} has a non-finite pixel", i));

  TwoViewResult result;
  const std::size_t n = pixels0.size();
  result.matches = static_cast<int>(n);
  if (result.matches < options.min_tracks)
    return fail(result, InitStatus::too_few_tracks,
                fmt::format("{} matches, fewer than min_tracks = {}", n, options.min_tracks));

  // 1. Enough image motion to be worth a try?
  std::vector<double> motion(n);
  for (std::size_t i = 0; i < n; ++i) motion[i] = (pixels1[i] - pixels0[i]).norm();
  result.median_image_motion_px = median(motion);
  const double diagonal = std::hypot(static_cast<double>(camera.width()), static_cast<double>(camera.height()));
  const double min_motion = options.min_image_motion_fraction * diagonal;
  if (result.median_image_motion_px < min_motion)
    return fail(result, InitStatus::need_more_parallax,
                fmt::format("median image motion {:.1f} px < {:.1f} px", result.median_image_motion_px, min_motion));

  // 2. Rays and ideal pixels.
  TwoViewMatches matches{pixels0, pixels1, {}, {}};
  matches.rays0.reserve(n);
  matches.rays1.reserve(n);
  const Eigen::Matrix3d K = camera.pinhole_matrix();
  const Eigen::Matrix3d K_inv = K.inverse();
  std::vector<Eigen::Vector2d> ideal0(n), ideal1(n);
  std::vector<cv::Point2d> cv0(n), cv1(n);
  for (std::size_t i = 0; i < n; ++i) {
    matches.rays0.push_back(camera.unproject(pixels0[i]));
    matches.rays1.push_back(camera.unproject(pixels1[i]));
    ideal0[i] = (K * matches.rays0[i]).hnormalized();
    ideal1[i] = (K * matches.rays1[i]).hnormalized();
    cv0[i] = {ideal0[i].x(), ideal0[i].y()};
    cv1[i] = {ideal1[i].x(), ideal1[i].y()};
  }

  // 3. Both models on the same matches. OpenCV's RANSAC seeds its own RNG
  // with a constant, so the result is reproducible.
  const double sigma = options.match_sigma_px;
  const cv::Mat H_cv = cv::findHomography(cv0, cv1, cv::RANSAC, std::sqrt(kChiSquare95TwoDof) * sigma, cv::noArray(),
                                          options.ransac_max_iterations, options.ransac_confidence);
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  ModelScore h_score;
  h_score.inliers.assign(n, false);
  if (!H_cv.empty()) {
    H = to_eigen3(H_cv);
    h_score = score_homography(H, ideal0, ideal1, sigma);
  }
  cv::Mat K_cv;
  cv::eigen2cv(K, K_cv);
  const cv::Mat E_cv = cv::findEssentialMat(cv0, cv1, K_cv, cv::RANSAC, options.ransac_confidence,
                                            std::sqrt(kChiSquare95OneDof) * sigma, options.ransac_max_iterations);
  // With few matches OpenCV may return several stacked 3x3 solutions.
  Eigen::Matrix3d E = Eigen::Matrix3d::Zero();
  ModelScore e_score;
  e_score.inliers.assign(n, false);
  for (int row = 0; row + 3 <= E_cv.rows; row += 3) {
    const Eigen::Matrix3d E_candidate = to_eigen3(E_cv.rowRange(row, row + 3));
    ModelScore s = score_fundamental(K_inv.transpose() * E_candidate * K_inv, ideal0, ideal1, sigma);
    if (s.score > e_score.score) {
      e_score = std::move(s);
      E = E_candidate;
    }
  }
  result.score_homography = h_score.score;
  result.score_essential = e_score.score;
  result.inliers_homography = h_score.inlier_count;
  result.inliers_essential = e_score.inlier_count;
  if (h_score.score + e_score.score <= 0.0)
    return fail(result, InitStatus::degenerate, "neither a homography nor an essential matrix fits the matches");
  result.homography_ratio = h_score.score / (h_score.score + e_score.score);

  // 3b. H in normalised coordinates, polished on the symmetric transfer error of
  // its inliers (OpenCV refines the one-sided error only), re-scored, and
  // polished again while the inliers grow. On synthetic facades with 0.3 px
  // noise this roughly halves the worst rotation and translation-direction
  // errors of its decomposition.
  const double focal = std::sqrt(camera.fx() * camera.fy());
  Eigen::Matrix3d H_normalised = K_inv * H * K;
  ModelScore h_support = h_score;
  if (h_support.inlier_count >= 8) {
    std::vector<Eigen::Vector2d> normalised0(n), normalised1(n);
    for (std::size_t i = 0; i < n; ++i) {
      normalised0[i] = matches.rays0[i].hnormalized();
      normalised1[i] = matches.rays1[i].hnormalized();
    }
    for (int round = 0; round < kMaxRefinementRounds; ++round) {
      H_normalised = refine_homography(H_normalised, normalised0, normalised1, indices_of(h_support.inliers),
                                       std::sqrt(kChiSquare95TwoDof) * sigma / focal);
      ModelScore rescored = score_homography(K * H_normalised * K_inv, ideal0, ideal1, sigma);
      const bool grew = rescored.inlier_count > h_support.inlier_count;
      if (rescored.inlier_count >= 8) h_support = std::move(rescored);
      if (!grew) break;
    }
  }

  // 3c. Pure rotation: every match obeys a homography that is a rotation.
  // The essential matrix is then undetermined (any translation fits), so
  // this is tested on the homography, whatever the ratio says.
  if (h_score.inlier_count > 0 && h_score.inlier_count >= 0.9 * e_score.inlier_count) {
    const double t_over_d = homography_translation(H_normalised);
    if (t_over_d < options.pure_rotation_max_translation)
      return fail(result, InitStatus::degenerate,
                  fmt::format("pure rotation: the homography explains the matches with |t|/d = {:.4f} < {:.4f} "
                              "(the camera turned but hardly moved)",
                              t_over_d, options.pure_rotation_max_translation));
  }

  // 4. The model and its pose hypotheses.
  result.model =
      result.homography_ratio > options.homography_ratio_threshold ? TwoViewModel::homography : TwoViewModel::essential;
  const bool use_h = result.model == TwoViewModel::homography;
  std::vector<bool> model_inliers = use_h ? h_support.inliers : e_score.inliers;
  const std::vector<int> inliers = indices_of(model_inliers);
  const std::vector<SE3d> poses = use_h ? homography_poses(H_normalised) : essential_poses(E);
  const PointCheckOptions checks{options.max_reprojection_error_px, deg_to_rad(options.min_point_parallax_deg)};
  std::vector<Hypothesis> hypotheses;
  for (const SE3d& pose : poses) hypotheses.push_back({pose, evaluate_pose(camera, pose, matches, inliers, checks)});
  if (hypotheses.empty())
    return fail(result, InitStatus::degenerate,
                fmt::format("the {} has no pose decomposition", to_string(result.model)));
  rank(hypotheses);
  const Hypothesis& best = hypotheses.front();
  result.median_parallax_deg = rad_to_deg(best.evaluation.median_parallax_rad());
  if (result.median_parallax_deg < options.min_median_parallax_deg)
    return fail(result, InitStatus::degenerate,
                fmt::format("{}: median parallax {:.2f} deg < {:.2f} deg", to_string(result.model),
                            result.median_parallax_deg, options.min_median_parallax_deg));
  if (best.evaluation.good_count() < options.min_points)
    return fail(result, InitStatus::degenerate,
                fmt::format("{}: only {} of {} inliers triangulate well (need {})", to_string(result.model),
                            best.evaluation.good_count(), inliers.size(), options.min_points));
  if (hypotheses.size() > 1 &&
      hypotheses[1].evaluation.good_count() > options.ambiguity_ratio * best.evaluation.good_count())
    return fail(result, InitStatus::degenerate,
                fmt::format("{}: ambiguous pose, two hypotheses triangulate {} and {} points", to_string(result.model),
                            best.evaluation.good_count(), hypotheses[1].evaluation.good_count()));

  // 5. An essential matrix from RANSAC is the best minimal sample: refine its
  // pose on the Sampson distances of its support, which starts as the
  // winner's consistent inliers and then becomes every match within the
  // epipolar cut-off of the refined pose, until it stops changing (a poor
  // sample may have left good matches out). A homography's pose is kept as
  // decomposed: H was already polished on all its inliers, and for a plane
  // the epipolar cost is nearly flat along the bas-relief direction (a
  // rotation traded for a translation), where the homography, which also
  // uses the planarity, is the better-conditioned model (measured: Sampson
  // refinement made facade poses worse, not better).
  SE3d T_c1_c0 = best.T_c1_c0;
  if (!use_h) {
    const EssentialRefinementOptions refinement{focal, std::sqrt(kChiSquare95OneDof) * sigma, 20};
    std::vector<int> support = best.evaluation.consistent;
    for (int round = 0; round < kMaxRefinementRounds; ++round) {
      T_c1_c0 = refine_relative_pose(T_c1_c0, matches.rays0, matches.rays1, support, refinement);
      ModelScore rescored =
          score_fundamental(K_inv.transpose() * essential_from_pose(T_c1_c0) * K_inv, ideal0, ideal1, sigma);
      std::vector<int> new_support = indices_of(rescored.inliers);
      model_inliers = std::move(rescored.inliers);
      if (new_support == support) break;
      support = std::move(new_support);
    }
  }

  // 6. Every match under the final pose.
  std::vector<int> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = static_cast<int>(i);
  PoseEvaluation final_eval = evaluate_pose(camera, T_c1_c0, matches, all, checks);
  result.median_parallax_deg = rad_to_deg(final_eval.median_parallax_rad());
  int good_inliers = 0;
  int inlier_count = 0;
  for (const bool inlier : model_inliers) inlier_count += inlier ? 1 : 0;
  for (int i : final_eval.good) good_inliers += model_inliers[static_cast<std::size_t>(i)] ? 1 : 0;
  const double good_fraction = inlier_count == 0 ? 0.0 : static_cast<double>(good_inliers) / inlier_count;
  if (result.median_parallax_deg < options.min_median_parallax_deg)
    return fail(result, InitStatus::degenerate,
                fmt::format("{}: median parallax {:.2f} deg < {:.2f} deg after refinement", to_string(result.model),
                            result.median_parallax_deg, options.min_median_parallax_deg));
  if (final_eval.good_count() < options.min_points)
    return fail(result, InitStatus::degenerate,
                fmt::format("{}: only {} points triangulate well (need {})", to_string(result.model),
                            final_eval.good_count(), options.min_points));
  if (good_fraction < options.min_triangulated_fraction)
    return fail(
        result, InitStatus::degenerate,
        fmt::format("{}: only {:.0f}% of the {} inliers triangulate well (need {:.0f}%)", to_string(result.model),
                    100.0 * good_fraction, inlier_count, 100.0 * options.min_triangulated_fraction));

  // Scale: median depth 1 in the first camera.
  std::vector<double> depths;
  depths.reserve(final_eval.good_points_c0.size());
  for (const Eigen::Vector3d& p : final_eval.good_points_c0) depths.push_back(p.z());
  const double scale = 1.0 / median(depths);
  result.T_c1_c0 = SE3d(T_c1_c0.so3(), T_c1_c0.translation() * scale);
  for (std::size_t k = 0; k < final_eval.good.size(); ++k) {
    const auto i = static_cast<std::size_t>(final_eval.good[k]);
    result.points_c0.push_back(final_eval.good_points_c0[k] * scale);
    result.pixels0.push_back(pixels0[i]);
    result.pixels1.push_back(pixels1[i]);
    result.match_indices.push_back(final_eval.good[k]);
  }
  result.status = InitStatus::success;
  spdlog::debug(
      "two-view initialisation: success with the {} (R_H {:.2f}, inliers H {} E {}), {} points, median parallax "
      "{:.2f} deg",
      to_string(result.model), result.homography_ratio, result.inliers_homography, result.inliers_essential,
      result.points_c0.size(), result.median_parallax_deg);
  return result;
}

}  // namespace facadeslam
