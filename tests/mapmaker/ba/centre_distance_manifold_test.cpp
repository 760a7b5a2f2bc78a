// The scale-anchor manifold: Ceres' invariants, and the distance it keeps.
#include "mapmaker/ba/centre_distance_manifold.hpp"

#include <random>

#include <ceres/manifold_test_utils.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/lie/manifolds.hpp"
#include "core/util/error.hpp"

namespace facadeslam {
namespace {

using Vector = Eigen::VectorXd;
// The matchers EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD names unqualified.
using ceres::HasCorrectMinusJacobianAt;
using ceres::HasCorrectPlusJacobianAt;
using ceres::HasCorrectRightMultiplyByPlusJacobianAt;
using ceres::MinusPlusIsIdentityAt;
using ceres::MinusPlusJacobianIsIdentityAt;
using ceres::PlusMinusIsIdentityAt;
using ceres::XMinusXIsZeroAt;
using ceres::XPlusZeroIsXAt;

struct Case {
  Eigen::Vector3d anchor;
  Vector x;  // a pose whose centre lies on the sphere
  double radius;
};

Case random_case(std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d anchor, offset;  // << draws in order (a call's arguments would not)
  anchor << normal(rng), normal(rng), normal(rng);
  offset << normal(rng), normal(rng), normal(rng);
  const Eigen::Vector3d centre = anchor + offset * 2.0;
  SE3d::Tangent xi;
  for (int i = 0; i < 6; ++i) xi(i) = normal(rng);
  const SO3d r = SE3d::exp(xi).so3();
  Case c{anchor, Vector(kSe3ParamSize), (centre - anchor).norm()};
  se3_to_params(SE3d(r, -(r * centre)), c.x.data());
  return c;
}

Eigen::Vector3d centre_of(const Vector& params) {
  const SE3d pose = se3_from_params(params.data());
  return pose.inverse().translation();
}

TEST(CentreDistanceManifold, SatisfiesCeresInvariants) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0.0, 0.3);
  for (int k = 0; k < 20; ++k) {
    const Case c = random_case(rng);
    const auto manifold_ptr = make_centre_distance_manifold(c.anchor, c.radius);
    const ceres::Manifold& manifold = *manifold_ptr;
    Vector delta(5), other(5);
    for (int i = 0; i < 5; ++i) {
      delta(i) = normal(rng);
      other(i) = normal(rng);
    }
    Vector y(kSe3ParamSize);
    ASSERT_TRUE(manifold.Plus(c.x.data(), other.data(), y.data()));
    constexpr double tolerance = 1e-8;
    EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD(manifold, c.x, delta, y, tolerance);
  }
}

TEST(CentreDistanceManifold, PlusKeepsTheDistanceAndUpdatesRotationOnTheLeft) {
  std::mt19937 rng(6);
  const Case c = random_case(rng);
  const auto manifold = make_centre_distance_manifold(c.anchor, c.radius);
  Vector delta(5);
  delta << 0.7, -0.4, 0.2, -0.1, 0.3;
  Vector y(kSe3ParamSize);
  ASSERT_TRUE(manifold->Plus(c.x.data(), delta.data(), y.data()));
  EXPECT_NEAR((centre_of(y) - c.anchor).norm(), c.radius, 1e-12 * c.radius);
  EXPECT_GT((centre_of(y) - centre_of(c.x)).norm(), 0.1);  // the centre did move
  const SO3d expected = SO3d::exp(delta.tail<3>()) * se3_from_params(c.x.data()).so3();
  EXPECT_LT((se3_from_params(y.data()).so3() * expected.inverse()).log().norm(), 1e-12);
}

TEST(CentreDistanceManifold, RejectsBadSpheres) {
  EXPECT_THROW(make_centre_distance_manifold(Eigen::Vector3d::Zero(), 0.0), Error);
  EXPECT_THROW(make_centre_distance_manifold(Eigen::Vector3d::Zero(), -1.0), Error);
  EXPECT_THROW(make_centre_distance_manifold(Eigen::Vector3d(std::nan(""), 0, 0), 1.0), Error);
}

}  // namespace
}  // namespace facadeslam
