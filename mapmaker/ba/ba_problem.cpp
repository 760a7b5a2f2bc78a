#include "mapmaker/ba/ba_problem.hpp"

#include <cmath>
#include <string>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

[[noreturn]] void fail_problem(const std::string& what) { throw Error("bundle adjustment: " + what); }

bool finite_pose(const SE3d& pose) {
  return pose.unit_quaternion().coeffs().allFinite() && pose.translation().allFinite();
}

void validate_scale_anchor(const BaProblem& problem, const BaScaleAnchor& anchor) {
  const std::size_t n = problem.keyframes.size();
  if (anchor.keyframe >= n || anchor.reference >= n)
    fail_problem("the scale anchor names keyframe index " + std::to_string(anchor.keyframe) + " and reference " +
                 std::to_string(anchor.reference) + ", expected indices below the " + std::to_string(n) + " keyframes");
  if (anchor.keyframe == anchor.reference)
    fail_problem("the scale anchor's keyframe and reference must be two different keyframes");
  const BaKeyFrame& reference = problem.keyframes[anchor.reference];
  const BaKeyFrame& keyframe = problem.keyframes[anchor.keyframe];
  if (!reference.fixed)
    fail_problem("the scale anchor's reference keyframe (index " + std::to_string(anchor.reference) +
                 ") must be fixed");
  if (keyframe.fixed)
    fail_problem("the scale anchor's keyframe (index " + std::to_string(anchor.keyframe) +
                 ") must be free: a fixed keyframe already fixes the scale");
  const double distance = (keyframe.T_c_w.inverse().translation() - reference.T_c_w.inverse().translation()).norm();
  if (!(distance > 1e-9))
    fail_problem("the scale anchor's keyframes have the same camera centre: their distance cannot fix the scale");
}

void validate_ground(const BaProblem& problem) {
  for (std::size_t i = 0; i < problem.ground.size(); ++i) {
    const BaGroundObservation& g = problem.ground[i];
    const std::string name = "ground observation " + std::to_string(i);
    if (g.keyframe >= problem.keyframes.size() || g.point >= problem.points.size())
      fail_problem(name + " refers to keyframe index " + std::to_string(g.keyframe) + " and point index " +
                   std::to_string(g.point) + ", expected below " + std::to_string(problem.keyframes.size()) + " and " +
                   std::to_string(problem.points.size()));
    if (!g.normal_c.allFinite() || std::abs(g.normal_c.norm() - 1.0) > 1e-6)
      fail_problem(name + " has a normal that is not a unit vector");
    for (const double value : {g.height, g.sigma, g.weight})
      if (!(std::isfinite(value) && value > 0.0))
        fail_problem(name + " has a height, sigma or weight that is not finite and > 0");
  }
}

}  // namespace

void validate_ba_problem(const BaProblem& problem) {
  for (std::size_t i = 0; i < problem.keyframes.size(); ++i)
    if (!finite_pose(problem.keyframes[i].T_c_w))
      fail_problem("keyframe " + std::to_string(i) + " (id " + std::to_string(problem.keyframes[i].id) +
                   ") has a non-finite pose");
  for (std::size_t i = 0; i < problem.points.size(); ++i)
    if (!problem.points[i].p_w.allFinite())
      fail_problem("point " + std::to_string(i) + " (id " + std::to_string(problem.points[i].id) +
                   ") has a non-finite position");

  bool any_fixed_block = false;
  for (std::size_t i = 0; i < problem.observations.size(); ++i) {
    const BaObservation& obs = problem.observations[i];
    const std::string name = "observation " + std::to_string(i);
    if (obs.keyframe >= problem.keyframes.size())
      fail_problem(name + " refers to keyframe index " + std::to_string(obs.keyframe) + ", expected below " +
                   std::to_string(problem.keyframes.size()));
    if (obs.point >= problem.points.size())
      fail_problem(name + " refers to point index " + std::to_string(obs.point) + ", expected below " +
                   std::to_string(problem.points.size()));
    if (!obs.pixel.allFinite()) fail_problem(name + " has a non-finite pixel");
    if (obs.level < 0 || obs.level > kMaxBaLevel)
      fail_problem(name + " has pyramid level " + std::to_string(obs.level) + ", expected 0.." +
                   std::to_string(kMaxBaLevel));
    if (!(obs.weight > 0.0 && obs.weight <= 1.0))
      fail_problem(name + " has weight " + std::to_string(obs.weight) + ", expected in (0, 1]");
    any_fixed_block = any_fixed_block || problem.keyframes[obs.keyframe].fixed || problem.points[obs.point].fixed;
  }
  // Without a single fixed block the whole map can slide, turn and scale
  // freely: a caller's mistake, not something to paper over here.
  if (!problem.observations.empty() && !any_fixed_block)
    fail_problem(
        "no keyframe or point taking part is fixed: fix at least one keyframe (normally the map's "
        "first) to remove the gauge freedom");
  validate_ground(problem);
  if (problem.scale_anchor) validate_scale_anchor(problem, *problem.scale_anchor);
}

}  // namespace facadeslam
