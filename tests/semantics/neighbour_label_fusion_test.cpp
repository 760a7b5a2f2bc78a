// Labels fused over map neighbours: a stray label on a wall is outvoted, a
// separate object keeps its own, the points' votes stay their own, and the
// grid's nearest neighbours are the exact ones (against brute force). And the
// geometric cue: a point two keyframes measure at a finite depth is not sky.
#include "semantics/worker/neighbour_label_fusion.hpp"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace facadeslam::semantics {
namespace {

constexpr std::size_t kBuilding = 1, kCar = 2, kSky = 6, kVegetation = 7;

MapLabelOptions neighbours(int k) { return {.neighbours = k, .sky_only_at_infinity = true}; }

ClassVotes votes_of(std::size_t winner, float share, std::size_t runner_up) {
  ClassVotes v{};
  v[winner] = share;
  v[runner_up] = 1.f - share;
  return v;
}

class NeighbourFusionTest : public ::testing::Test {
 protected:
  std::shared_ptr<MapPoint> add(const Eigen::Vector3d& p, const ClassVotes& votes) {
    PointGeometry geometry;
    geometry.p_w = p;
    auto point = std::make_shared<MapPoint>(map.new_point_id(), PatchSource{}, geometry);
    point->set_votes(votes);
    points.push_back(point);
    return point;
  }
  void publish() { map.add({}, points); }

  Map map;
  std::vector<std::shared_ptr<MapPoint>> points;
};

TEST_F(NeighbourFusionTest, AStrayLabelOnAWallIsOutvotedAndASeparateObjectKeepsItsOwn) {
  std::shared_ptr<MapPoint> stray;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      const Eigen::Vector3d p(0.1 * i, 0.0, 0.1 * j);
      if (i == 5 && j == 5)
        stray = add(p, votes_of(kVegetation, 0.6f, kBuilding));
      else
        add(p, votes_of(kBuilding, 0.7f, kVegetation));
    }
  std::vector<std::shared_ptr<MapPoint>> car;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) car.push_back(add({50.0 + 0.1 * i, 3.0, 0.1 * j}, votes_of(kCar, 0.55f, kBuilding)));
  const auto unlabelled = add({0.45, 0.0, 0.45}, ClassVotes{});
  const auto far_off = add({1e12, -1e12, 5.0}, votes_of(kCar, 0.9f, kBuilding));  // a point at infinity's coordinates
  publish();

  EXPECT_EQ(fuse_labels_with_neighbours(map, neighbours(15)), points.size() - 1);  // all but the unlabelled one
  EXPECT_EQ(stray->label().label, kBuilding);
  EXPECT_EQ(stray->votes(), votes_of(kVegetation, 0.6f, kBuilding)) << "its own votes are kept";
  for (const auto& p : car) EXPECT_EQ(p->label().label, kCar);
  EXPECT_EQ(unlabelled->label().label, kUnlabelled);
  EXPECT_NE(far_off->label().label, kUnlabelled);

  // No neighbours: every point's own votes again.
  fuse_labels_with_neighbours(map, neighbours(0));
  EXPECT_EQ(stray->label(), (SemanticLabel{static_cast<std::uint8_t>(kVegetation), 0.6f}));
}

TEST_F(NeighbourFusionTest, BadPointsNeitherVoteNorGetLabels) {
  for (int i = 0; i < 20; ++i) add({0.1 * i, 0.0, 0.0}, votes_of(kBuilding, 0.8f, kCar));
  const auto middle = add({1.0, 0.01, 0.0}, votes_of(kCar, 0.9f, kBuilding));
  std::vector<std::shared_ptr<MapPoint>> bad_cars;
  for (int i = 0; i < 40; ++i) bad_cars.push_back(add({1.0 + 0.001 * i, 0.02, 0.0}, votes_of(kCar, 0.9f, kBuilding)));
  publish();
  map.update([&](MapEditor& editor) {
    for (const auto& p : bad_cars) editor.mark_bad(*p);
  });
  fuse_labels_with_neighbours(map, neighbours(5));
  EXPECT_EQ(middle->label().label, kBuilding) << "the 40 bad car points next to it must not count";
  EXPECT_EQ(bad_cars.front()->label().label, kCar) << "a bad point keeps what it had";
}

// The label each point should get, by brute force over all points.
std::vector<std::uint8_t> brute_force_labels(const std::vector<std::shared_ptr<MapPoint>>& points, std::size_t k) {
  std::vector<std::uint8_t> labels;
  for (const auto& p : points) {
    std::vector<std::pair<double, std::size_t>> d;
    for (std::size_t j = 0; j < points.size(); ++j)
      d.emplace_back((points[j]->position() - p->position()).squaredNorm(), j);
    std::sort(d.begin(), d.end());
    ClassVotes sum{};
    for (std::size_t m = 0; m <= k; ++m) {
      const ClassVotes v = points[d[m].second]->votes();
      float total = 0.f;
      for (const float x : v) total += x;
      for (std::size_t c = 0; c < v.size(); ++c) sum[c] += v[c] / total;
    }
    labels.push_back(label_from_votes(sum).label);
  }
  return labels;
}

TEST_F(NeighbourFusionTest, TheGridFindsTheExactNearestNeighbours) {
  // A street-like cloud: two walls, a road and scattered trees, random votes.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 600; ++i) {
    const double kind = unit(random);
    const double x = 20.0 * unit(random);
    const double a = unit(random);
    const double b = unit(random);
    Eigen::Vector3d p = kind < 0.35  ? Eigen::Vector3d(x, 4.0, 6.0 * a)
                        : kind < 0.7 ? Eigen::Vector3d(x, -4.0, 6.0 * a)
                        : kind < 0.9 ? Eigen::Vector3d(x, 8.0 * a - 4.0, 0.0)
                                     : Eigen::Vector3d(x, 6.0 * a - 3.0, 5.0 * b);
    ClassVotes votes{};
    for (float& v : votes) v = static_cast<float>(unit(random));
    add(p, votes);
  }
  publish();
  for (const int k : {1, 7, 15, 40}) {
    fuse_labels_with_neighbours(map, neighbours(k));
    const auto expected = brute_force_labels(points, static_cast<std::size_t>(k));
    for (std::size_t i = 0; i < points.size(); ++i)
      ASSERT_EQ(points[i]->label().label, expected[i]) << "point " << i << ", " << k << " neighbours";
  }
}

// Two keyframes 1 m apart looking down +z, scene depth 5 m; points in front
// of them, measured by one or both.
class SkyCueTest : public ::testing::Test {
 protected:
  SkyCueTest() {
    const cv::Mat colour(120, 160, CV_8UC3, cv::Scalar(90, 120, 150));
    const auto pyramid = std::make_shared<const ImagePyramid>(colour);
    for (int k = 0; k < 2; ++k) {
      const SE3d T_c_w(SO3d(), Eigen::Vector3d(-1.0 * k, 0.0, 0.0));
      keyframes.push_back(std::make_shared<KeyFrame>(
          map.new_keyframe_id(), Frame{static_cast<std::size_t>(k), 0.1 * k, colour, {}, pyramid}, T_c_w));
    }
  }
  // A point at `depth` along the first keyframe's axis, mostly sky by its
  // votes, measured by the first keyframe and, if `both`, the second.
  std::shared_ptr<MapPoint> add(double depth, bool both, const ClassVotes& votes = votes_of(kSky, 0.6f, kBuilding)) {
    PointGeometry geometry;
    geometry.p_w = Eigen::Vector3d(0.0, 0.0, depth);
    auto point =
        std::make_shared<MapPoint>(map.new_point_id(), PatchSource{keyframes[0]->id(), nullptr, 0, {80, 60}}, geometry);
    point->set_votes(votes);
    points.push_back(point);
    observations.push_back({keyframes[0], point->id(), {0, {80.0, 60.0}, true}});
    if (both) observations.push_back({keyframes[1], point->id(), {0, {90.0, 60.0}, false}});
    return point;
  }
  void publish() {
    map.add(keyframes, points, observations);
    map.update([&](MapEditor& editor) {
      for (const auto& kf : keyframes) editor.set_depth_stats(*kf, 5.0, 1.0);
    });
  }

  Map map;
  std::vector<std::shared_ptr<KeyFrame>> keyframes;
  std::vector<std::shared_ptr<MapPoint>> points;
  std::vector<Observation> observations;
};

TEST_F(SkyCueTest, APointTwoKeyframesMeasureAtAFiniteDepthIsNotSky) {
  const auto triangulated = add(5.0, true);
  const auto depth_prior = add(5.0, false);
  const auto far_away = add(5.0 * kFarDepthRatio * 1.5, true);
  const auto only_sky = add(5.0, true, votes_of(kSky, 1.0f, kBuilding));
  publish();
  fuse_labels_with_neighbours(map, neighbours(0));
  EXPECT_EQ(triangulated->label().label, kBuilding);
  EXPECT_FLOAT_EQ(triangulated->label().confidence, 1.f) << "building is all of the evidence left";
  EXPECT_EQ(triangulated->own_label().label, kSky) << "the tracker's label is the point's own votes'";
  EXPECT_EQ(depth_prior->label().label, kSky) << "only its source measures it: its depth is a prior";
  EXPECT_EQ(far_away->label().label, kSky) << "bundle adjustment pushed it to infinity";
  EXPECT_EQ(only_sky->label().label, kSky) << "no other class to give it";

  fuse_labels_with_neighbours(map, {.neighbours = 0, .sky_only_at_infinity = false});
  EXPECT_EQ(triangulated->label().label, kSky);
}

}  // namespace
}  // namespace facadeslam::semantics
