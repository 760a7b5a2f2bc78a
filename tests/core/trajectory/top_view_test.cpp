#include "core/trajectory/top_view.hpp"

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

Trajectory line(const Eigen::Vector3d& step, const Eigen::Vector3d& wobble) {
  Trajectory t;
  for (int i = 0; i < 20; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = i * step + ((i % 2) ? wobble : Eigen::Vector3d(-wobble));
    t.push_back({0.1 * i, pose});
  }
  return t;
}

TEST(TopView, NamedPlanes) {
  const Trajectory t = line({1, 0, 0}, {0, 0, 0});
  EXPECT_EQ(top_view_axes("xy", t), (std::array<int, 2>{0, 1}));
  EXPECT_EQ(top_view_axes("xz", t), (std::array<int, 2>{0, 2}));
  EXPECT_EQ(top_view_axes("yz", t), (std::array<int, 2>{1, 2}));
}

TEST(TopView, AutoDropsTheAxisThePathHardlyMovesAlong) {
  // z up (a street): walking along x, weaving along y, bobbing a little in z.
  EXPECT_EQ(top_view_axes("auto", line({1, 0.2, 0}, {0, 0.5, 0.01})), (std::array<int, 2>{0, 1}));
  // y down (a camera-style frame): moving in x and z at one height.
  EXPECT_EQ(top_view_axes("auto", line({0.3, 0, 1}, {0.2, 0.01, 0})), (std::array<int, 2>{0, 2}));
  // Along y and z only.
  EXPECT_EQ(top_view_axes("auto", line({0, 1, 0.5}, {0.01, 0, 0})), (std::array<int, 2>{1, 2}));
}

TEST(TopView, AutoOnAStaticOrEmptyPathIsTheXyPlane) {
  EXPECT_EQ(top_view_axes("auto", Trajectory{}), (std::array<int, 2>{0, 1}));
  EXPECT_EQ(top_view_axes("auto", line({0, 0, 0}, {0, 0, 0})), (std::array<int, 2>{0, 1}));
}

TEST(TopView, RejectsAnUnknownPlane) { EXPECT_THROW(top_view_axes("zx", Trajectory{}), Error); }

}  // namespace
}  // namespace facadeslam
