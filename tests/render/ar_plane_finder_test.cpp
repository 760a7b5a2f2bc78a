// The AR view's plane finder on a synthetic street: the ground and two
// facades as noisy point samples with clutter (cars, trees: points off any
// plane), in an arbitrarily rotated and scaled world frame (a map's frame
// is its first camera's, its scale arbitrary). The dominant plane and, with
// its inliers removed, the next one must be recovered within 2 degrees.
#include <iostream>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "render/ar/plane_finder.hpp"

namespace facadeslam {
namespace {

using render::ar::Plane;

struct Street {
  std::vector<Eigen::Vector3d> points_w;
  Plane ground, left_facade, right_facade;  // true planes, in the map's frame
};

// A street along x, 12 m wide, up z, in metres; then into the map frame by
// a rotation and a scale. `ground`, `facade` and `clutter` points.
Street make_street(int ground, int facade, int clutter, double noise_m, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> along(-20.0, 20.0), across(-6.0, 6.0), up(0.0, 12.0), unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, noise_m);
  std::vector<Eigen::Vector3d> street;
  for (int i = 0; i < ground; ++i) street.emplace_back(along(random), across(random), noise(random));
  for (int i = 0; i < facade; ++i) {
    const double side = i % 2 == 0 ? 6.0 : -6.0;
    street.emplace_back(along(random), side + noise(random), up(random));
  }
  for (int i = 0; i < clutter; ++i)  // between the facades, above the road
    street.emplace_back(along(random), 0.9 * across(random), 0.2 + 3.0 * unit(random));
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
                             Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const double scale = 0.137;
  const Eigen::Vector3d offset(2.0, -1.0, 0.5);
  Street out;
  for (const Eigen::Vector3d& p : street) out.points_w.push_back(scale * (R * p) + offset);
  const auto plane = [&](const Eigen::Vector3d& normal_street, const Eigen::Vector3d& point_street) {
    Plane p;
    p.normal_w = R * normal_street;
    p.offset = -p.normal_w.dot(scale * (R * point_street) + offset);
    return p;
  };
  out.ground = plane(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero());
  out.left_facade = plane(Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, 6, 0));
  out.right_facade = plane(Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, -6, 0));
  return out;
}

std::vector<Eigen::Vector3d> without(const std::vector<Eigen::Vector3d>& points, const std::vector<std::size_t>& drop) {
  std::vector<bool> dropped(points.size(), false);
  for (const std::size_t i : drop) dropped[i] = true;
  std::vector<Eigen::Vector3d> kept;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!dropped[i]) kept.push_back(points[i]);
  return kept;
}

TEST(ArPlaneFinder, RecoversTheGroundThenAFacadeOfAStreet) {
  // More ground than facade: the ground is the dominant plane.
  const Street street = make_street(900, 700, 300, 0.03, 5);
  const auto first = render::ar::find_dominant_plane(street.points_w);
  ASSERT_TRUE(first.has_value());
  const double ground_error = render::ar::angle_between_deg(first->plane, street.ground);
  const auto second = render::ar::find_dominant_plane(without(street.points_w, first->inliers));
  ASSERT_TRUE(second.has_value());
  const double facade_error = std::min(render::ar::angle_between_deg(second->plane, street.left_facade),
                                       render::ar::angle_between_deg(second->plane, street.right_facade));
  // The facade found is one of the two, not a plane between them.
  const double facade_offset_error =
      std::min(std::abs(second->plane.offset -
                        street.left_facade.offset * second->plane.normal_w.dot(street.left_facade.normal_w)),
               std::abs(second->plane.offset -
                        street.right_facade.offset * second->plane.normal_w.dot(street.right_facade.normal_w)));
  std::cout << "[ plane ] ground " << ground_error << " deg (" << first->inliers.size() << " inliers), facade "
            << facade_error << " deg (" << second->inliers.size() << " inliers)\n";
  RecordProperty("ground_error_deg", std::to_string(ground_error));
  RecordProperty("facade_error_deg", std::to_string(facade_error));
  EXPECT_LT(ground_error, 2.0);
  EXPECT_LT(facade_error, 2.0);
  EXPECT_LT(facade_offset_error, 0.137 * 0.5);  // within half a metre of the true facade
  EXPECT_GT(first->inliers.size(), 800u);
}

TEST(ArPlaneFinder, RecoversAFacadeWhenItDominates) {
  // A street seen mostly as facade (a camera looking sideways at a wall).
  const Street street = make_street(250, 1400, 200, 0.03, 9);
  const auto fit = render::ar::find_dominant_plane(street.points_w);
  ASSERT_TRUE(fit.has_value());
  const double error = std::min(render::ar::angle_between_deg(fit->plane, street.left_facade),
                                render::ar::angle_between_deg(fit->plane, street.right_facade));
  std::cout << "[ plane ] facade-dominated street: " << error << " deg\n";
  EXPECT_LT(error, 2.0);
  EXPECT_GT(render::ar::angle_between_deg(fit->plane, street.ground), 80.0);
}

TEST(ArPlaneFinder, FindsNothingInAnEmptyOrPlanelessMap) {
  EXPECT_FALSE(render::ar::find_dominant_plane({}).has_value());
  EXPECT_FALSE(render::ar::find_dominant_plane({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).has_value());
  // A uniform cloud in a unit cube has no plane that 20 % of it lies on.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> cloud;
  for (int i = 0; i < 300; ++i) cloud.emplace_back(unit(random), unit(random), unit(random));
  render::ar::PlaneFinderOptions options;
  options.min_inliers = 60;  // a 1 % slab of a unit cube holds ~3 % of the points
  EXPECT_FALSE(render::ar::find_dominant_plane(cloud, options).has_value());
}

}  // namespace
}  // namespace facadeslam
