#include "core/map/label_policy.hpp"

#include <memory>

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

constexpr std::uint8_t kCar = 2, kVegetation = 7, kBuilding = 1;

std::unique_ptr<MapPoint> point_voted(std::uint8_t label, float share) {
  auto point = std::make_unique<MapPoint>(1, PatchSource{}, PointGeometry{});
  ClassVotes votes{};
  votes[label] = share;
  votes[kBuilding] += 1.f - share;
  point->set_votes(votes);
  return point;
}

LabelPolicy shipped_like() {
  return {.unreliable = {.classes = ClassSet{(1u << kCar) | (1u << kVegetation)}, .min_confidence = 0.5f},
          .moving = {.classes = ClassSet{1u << kCar}, .min_confidence = 0.5f, .regions = true},
          .unreliable_weight = 0.1};
}

TEST(LabelPolicy, WeighsUnreliableDownAndLeavesMovingOutOfTrackingAndBa) {
  const LabelPolicy policy = shipped_like();
  ASSERT_TRUE(policy.leaves_points_out());
  const auto tree_point = point_voted(kVegetation, 0.8f), car_point = point_voted(kCar, 0.9f);
  const auto wall_point = point_voted(kBuilding, 1.f), unsure_tree_point = point_voted(kVegetation, 0.4f);
  const MapPoint &tree = *tree_point, &car = *car_point, &wall = *wall_point, &unsure_tree = *unsure_tree_point;
  EXPECT_EQ(policy.tracking_weight(tree), 0.1);
  EXPECT_EQ(policy.ba_weight(tree), 1.0) << "a still tree is good structure for bundle adjustment";
  EXPECT_EQ(policy.tracking_weight(car), 0.0);
  EXPECT_EQ(policy.ba_weight(car), 0.0);
  EXPECT_TRUE(policy.left_out(car));
  EXPECT_EQ(policy.tracking_weight(wall), 1.0);
  EXPECT_EQ(policy.tracking_weight(unsure_tree), 1.0) << "below the minimum confidence the label is not used";
  const MapPoint unlabelled(2, PatchSource{}, PointGeometry{});
  EXPECT_EQ(policy.tracking_weight(unlabelled), 1.0);
}

TEST(LabelPolicy, APointInAMovingRegionIsLeftOutWhateverItsLabel) {
  LabelPolicy policy = shipped_like();
  const auto wall_point = point_voted(kBuilding, 1.f);
  MapPoint& wall = *wall_point;
  wall.add_region_view(true);
  EXPECT_TRUE(policy.left_out(wall));
  policy.moving.regions = false;
  EXPECT_FALSE(policy.left_out(wall));
}

TEST(LabelPolicy, WithoutClassesLabelsAreIgnored) {
  const LabelPolicy none;
  EXPECT_FALSE(none.leaves_points_out());
  const auto car_point = point_voted(kCar, 1.f);
  const MapPoint& car = *car_point;
  EXPECT_EQ(none.tracking_weight(car), 1.0);
  EXPECT_EQ(none.ba_weight(car), 1.0);
}

}  // namespace
}  // namespace facadeslam
