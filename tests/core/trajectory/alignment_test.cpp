#include "core/trajectory/alignment.hpp"

#include <random>

#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "tests/core/trajectory/synthetic_trajectories.hpp"

namespace facadeslam {
namespace {

std::vector<Eigen::Vector3d> random_points(std::size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  std::vector<Eigen::Vector3d> points;
  for (std::size_t i = 0; i < count; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  return points;
}

std::vector<Eigen::Vector3d> apply(const std::vector<Eigen::Vector3d>& points, double s, const Eigen::Matrix3d& R,
                                   const Eigen::Vector3d& t) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& p : points) out.push_back(s * R * p + t);
  return out;
}

TEST(UmeyamaAlignment, RecoversAKnownSimilarityExactly) {
  const auto source = random_points(20, 1);
  const Eigen::Matrix3d R = test::some_rotation();
  const Eigen::Vector3d t(1.0, -2.0, 0.5);
  const auto target = apply(source, 2.5, R, t);

  const auto a = umeyama_alignment(source, target, true);
  EXPECT_NEAR(a.scale, 2.5, 1e-12);
  EXPECT_LT((a.R - R).norm(), 1e-12);
  EXPECT_LT((a.t - t).norm(), 1e-12);
  for (std::size_t i = 0; i < source.size(); ++i) EXPECT_LT((a.apply(source[i]) - target[i]).norm(), 1e-12);
}

TEST(UmeyamaAlignment, WithoutScaleKeepsScaleOneAndFindsTheRigidMotion) {
  const auto source = random_points(10, 2);
  const Eigen::Matrix3d R = test::some_rotation();
  const Eigen::Vector3d t(0.0, 3.0, -1.0);
  const auto a = umeyama_alignment(source, apply(source, 1.0, R, t), false);
  EXPECT_EQ(a.scale, 1.0);
  EXPECT_LT((a.R - R).norm(), 1e-12);
  EXPECT_LT((a.t - t).norm(), 1e-12);

  // On scaled data the rigid fit still returns scale 1 (and a rotation).
  const auto b = umeyama_alignment(source, apply(source, 3.0, R, t), false);
  EXPECT_EQ(b.scale, 1.0);
  EXPECT_LT((b.R - R).norm(), 1e-9);
}

TEST(UmeyamaAlignment, MirroredDataStillGivesAProperRotation) {
  const auto source = random_points(15, 3);
  std::vector<Eigen::Vector3d> mirrored;
  for (const auto& p : source) mirrored.emplace_back(p.x(), p.y(), -p.z());
  const auto a = umeyama_alignment(source, mirrored, true);
  EXPECT_NEAR(a.R.determinant(), 1.0, 1e-12);
  EXPECT_LT((a.R.transpose() * a.R - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

TEST(UmeyamaAlignment, CoplanarPointsAreEnough) {
  const std::vector<Eigen::Vector3d> source{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {3, 1, 0}};
  const Eigen::Matrix3d R = test::some_rotation();
  const Eigen::Vector3d t(0.5, 0.5, 0.5);
  const auto a = umeyama_alignment(source, apply(source, 0.5, R, t), true);
  EXPECT_NEAR(a.scale, 0.5, 1e-12);
  EXPECT_LT((a.R - R).norm(), 1e-12);
  EXPECT_LT((a.t - t).norm(), 1e-12);
}

TEST(UmeyamaAlignment, FewerThanThreePairsIsAnError) {
  const std::vector<Eigen::Vector3d> two{{0, 0, 0}, {1, 0, 0}};
  try {
    umeyama_alignment(two, two, true);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("at least 3"), std::string::npos) << e.what();
  }
}

TEST(UmeyamaAlignment, CollinearPointsAreAnError) {
  const std::vector<Eigen::Vector3d> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {5, 5, 5}};
  const auto target = apply(line, 1.0, test::some_rotation(), Eigen::Vector3d(1, 2, 3));
  try {
    umeyama_alignment(line, target, true);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("one line"), std::string::npos) << e.what();
  }
  // Collinear on the ground-truth side only is just as undetermined.
  EXPECT_THROW(umeyama_alignment(random_points(4, 4), line, false), Error);
}

TEST(UmeyamaAlignment, IdenticalPointsAreAnError) {
  const std::vector<Eigen::Vector3d> same(5, Eigen::Vector3d(1, 2, 3));
  EXPECT_THROW(umeyama_alignment(same, same, true), Error);
}

TEST(UmeyamaAlignment, DifferentSizesAreAnError) {
  EXPECT_THROW(umeyama_alignment(random_points(4, 5), random_points(5, 5), true), Error);
}

}  // namespace
}  // namespace facadeslam
