// Depth-prior points of a keyframe taken while the camera turns: on the
// rendered plane, with the keyframe's measured points from an epipolar search.
#include "mapmaker/depth_prior_points.hpp"

#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "core/map/map.hpp"
#include "mapmaker/epipolar_search.hpp"
#include "tests/support/plane_keyframe.hpp"
#include "tests/support/rendered_plane.hpp"

namespace facadeslam {
namespace {

class DepthPriorPoints : public ::testing::Test {
 protected:
  std::shared_ptr<KeyFrame> add_keyframe(const SE3d& T_c_w) {
    return test::add_plane_keyframe(map_, plane_, camera_, T_c_w);
  }

  test::RenderedPlane plane_ = test::make_plane(3);
  Camera camera_ = test::test_camera();
  Map map_;
};

TEST_F(DepthPriorPoints, NothingWithoutMeasuredPointsToTakeTheDepthFrom) {
  auto kf = add_keyframe(SE3d());
  EXPECT_TRUE(depth_prior_points(map_, camera_, kf).points.empty());
}

TEST_F(DepthPriorPoints, PointsTakeTheDepthOfTheirMeasuredNeighboursAndKeepAway) {
  auto first = add_keyframe(SE3d());
  auto second = add_keyframe(test::view_pose(plane_, plane_.plane_depth, 0.0, 0.0, 0.15, 0.0));
  // Measured points in the second keyframe, only at level 0 and on the left
  // half of the image, as if the right half had just come into view.
  NewPoints found = epipolar_new_points(map_, camera_, second, first, EpipolarSearchOptions{});
  std::set<MapPoint::Id> dropped;
  for (const auto& p : found.points)
    if (p->source().level != 0 || p->source().pixel_level0.x() >= camera_.width() / 2.0) dropped.insert(p->id());
  std::erase_if(found.observations, [&](const Observation& o) { return dropped.count(o.point) > 0; });
  std::erase_if(found.points, [&](const auto& p) { return dropped.count(p->id()) > 0; });
  const std::vector<std::shared_ptr<MapPoint>> measured = found.points;
  ASSERT_GT(measured.size(), 20u);
  map_.add(found);

  const DepthPriorOptions options;
  const NewPoints made = depth_prior_points(map_, camera_, second, options);
  map_.add(made);
  const auto& points = made.points;
  ASSERT_FALSE(points.empty());
  int right_half = 0;
  for (const auto& p : points) {
    // Source and only measurement in the keyframe.
    EXPECT_EQ(p->source().keyframe_id, second->id());
    EXPECT_TRUE(second->measurements().at(p->id()).from_source);
    EXPECT_EQ(first->measurements().count(p->id()), 0u);
    // Projects back onto its corner: the depth is along the corner's ray.
    const Eigen::Vector2d px = camera_.project(second->T_c_w() * p->position());
    EXPECT_LT((px - p->source().pixel_level0).norm(), 1e-6);
    // The plane is fronto-parallel, so the neighbours' depth is the truth.
    EXPECT_NEAR((second->T_c_w() * p->position()).z(), plane_.plane_depth, 0.05);
    right_half += p->source().pixel_level0.x() >= camera_.width() / 2.0;
    // Away from the measured points of its own level.
    const int level = p->source().level;
    for (const auto& q : measured) {
      if (q->source().level != level) continue;
      EXPECT_GE((ImagePyramid::level0_to_level(q->source().pixel_level0, level) -
                 ImagePyramid::level0_to_level(p->source().pixel_level0, level))
                    .norm(),
                options.min_distance_to_measurement - 1e-9);
    }
  }
  // The unmapped half is where they go.
  EXPECT_GT(right_half, static_cast<int>(points.size()) / 2);
  // No more than asked per level.
  for (int level = 0; level < kPyramidLevels; ++level) {
    int n = 0;
    for (const auto& p : points) n += p->source().level == level;
    EXPECT_LE(n, options.max_points_per_level[static_cast<std::size_t>(level)]) << "level " << level;
  }
}

}  // namespace
}  // namespace facadeslam
