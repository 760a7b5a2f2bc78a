#pragma once
// Synthetic bundle adjustment problems for tests and benchmarks: a camera
// driving along a street (world x) looking sideways at a facade (world +z,
// camera axes x right, y down, z forward), with points on the facade plane
// plus some relief (balconies, window recesses), and exact observations.
// Helpers then perturb the estimate, add pixel noise or gross outliers.
// Everything is deterministic for a given seed.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"
#include "mapmaker/ba/ba_problem.hpp"

namespace facadeslam {

struct StreetSceneOptions {
  int keyframes = 8;
  double spacing = 1.0;           // distance between consecutive camera centres along x (m)
  double facade_distance = 8.0;   // from the cameras to the facade plane (m)
  double relief = 0.5;            // points lie within +-relief of the plane (m)
  int points = 1000;              // drawn over the facade span the cameras see
  double rotation_jitter = 0.05;  // random rotation of each camera (rad)
  double height_jitter = 0.1;     // random height change of each camera (m)
  int levels = 1;                 // observations get random pyramid levels in [0, levels)
  unsigned seed = 1;
};

struct StreetScene {
  BaProblem problem;                      // exact: every observation is the true projection
  std::vector<SE3d> true_T_c_w;           // per keyframe
  std::vector<Eigen::Vector3d> true_p_w;  // per point
};

// Keyframe i has id i, point j has id j; no block is fixed. Points seen by
// fewer than two keyframes are dropped, so `points` is an upper bound. Only
// projections inside the image (2 px border) in front of the camera count.
// Throws Error for keyframes < 2, points < 1, levels < 1 or non-positive
// distances.
StreetScene make_street_scene(const StreetSceneOptions& options, const Camera& camera);

// Moves every free keyframe by a rotation of `rotation_rad` about a random
// axis and a translation of `translation_m` in a random direction (left
// update), and every free point by `point_m` in a random direction.
void perturb_free_blocks(BaProblem& problem, double rotation_rad, double translation_m, double point_m, unsigned seed);

// Adds Gaussian noise of sigma_px * 2^level to each observation's pixel (per axis).
void add_pixel_noise(BaProblem& problem, double sigma_px, unsigned seed);

// Moves a `fraction` of the observations, chosen at random, by `offset_px`
// (level-0 pixels) in a random direction; returns their indices, ascending.
std::vector<std::size_t> add_gross_outliers(BaProblem& problem, double fraction, double offset_px, unsigned seed);

}  // namespace facadeslam
