// PTAM's local/global bundle adjustment selection on hand-made maps.
#include "mapmaker/ba/ba_selection.hpp"

#include <limits>

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

using Ids = std::set<std::uint64_t>;

// Seven keyframes on the x axis: ids 10..16 at x = 0, 1, 2, 3, 4, 10, 11.
std::vector<KeyFrameCentre> line_of_keyframes() {
  std::vector<KeyFrameCentre> kfs;
  const double xs[] = {0, 1, 2, 3, 4, 10, 11};
  for (std::uint64_t i = 0; i < 7; ++i) kfs.push_back({10 + i, Eigen::Vector3d(xs[i], 0, 0)});
  return kfs;
}

TEST(LocalBaSelection, PicksNewestNeighboursTheirPointsAndTheFixedObservers) {
  const std::vector<ObservationRef> obs = {
      {16, 100}, {13, 100},  // 100: newest + keyframe 13 -> free point, 13 fixed
      {10, 101}, {11, 101},  // 101: only far keyframes -> not in the BA
      {15, 102}, {10, 102},  // 102: neighbour 15 + gauge 10 -> 10 fixed
      {14, 103},             // 103: neighbour 14 alone
      {12, 104}, {11, 104},  // 104: not in the BA
  };
  LocalBaOptions options;
  options.neighbours = 2;
  const BaSelection s = local_ba_selection(line_of_keyframes(), obs, 16, options);
  // Nearest to x = 11: 15 (d 1), then 14 (d 7).
  EXPECT_EQ(s.free_keyframes, (Ids{14, 15, 16}));
  EXPECT_EQ(s.free_points, (Ids{100, 102, 103}));
  EXPECT_EQ(s.fixed_keyframes, (Ids{10, 13}));
}

TEST(LocalBaSelection, DefaultFourNeighbours) {
  const std::vector<ObservationRef> obs = {{16, 1}, {12, 1}, {11, 1}};
  const BaSelection s = local_ba_selection(line_of_keyframes(), obs, 16);
  EXPECT_EQ(s.free_keyframes, (Ids{12, 13, 14, 15, 16}));
  EXPECT_EQ(s.fixed_keyframes, (Ids{11}));
  EXPECT_EQ(s.free_points, (Ids{1}));
}

TEST(LocalBaSelection, NeverFreesTheGaugeKeyframe) {
  // Newest 12 (x = 2): nearest are 11, 13 (d 1), then 10, 14 (d 2), 15 (d 8).
  // 10 is the gauge (smallest id) and is skipped, so 15 comes in instead.
  const std::vector<ObservationRef> obs = {{10, 1}, {12, 1}, {11, 2}, {16, 2}};
  const BaSelection s = local_ba_selection(line_of_keyframes(), obs, 12);
  EXPECT_EQ(s.free_keyframes, (Ids{11, 12, 13, 14, 15}));
  EXPECT_FALSE(s.free_keyframes.contains(10));
  EXPECT_EQ(s.fixed_keyframes, (Ids{10, 16}));
  EXPECT_EQ(s.free_points, (Ids{1, 2}));
}

TEST(LocalBaSelection, TiesAreBrokenBySmallerId) {
  const std::vector<KeyFrameCentre> kfs = {{1, Eigen::Vector3d(-5, 0, 0)},
                                           {2, Eigen::Vector3d(0, 0, 0)},
                                           {3, Eigen::Vector3d(1, 0, 0)},
                                           {4, Eigen::Vector3d(-1, 0, 0)},
                                           {5, Eigen::Vector3d(0, 1, 0)}};
  LocalBaOptions options;
  options.neighbours = 2;
  const BaSelection s = local_ba_selection(kfs, {}, 2, options);  // 3, 4, 5 all at distance 1
  EXPECT_EQ(s.free_keyframes, (Ids{2, 3, 4}));
  EXPECT_TRUE(s.fixed_keyframes.empty());
  EXPECT_TRUE(s.free_points.empty());
}

TEST(LocalBaSelection, SmallMapFreesAllButTheGauge) {
  const std::vector<KeyFrameCentre> kfs = {{0, Eigen::Vector3d(0, 0, 0)}, {1, Eigen::Vector3d(1, 0, 0)}};
  const BaSelection s = local_ba_selection(kfs, {{0, 7}, {1, 7}}, 1);
  EXPECT_EQ(s.free_keyframes, (Ids{1}));
  EXPECT_EQ(s.fixed_keyframes, (Ids{0}));
  EXPECT_EQ(s.free_points, (Ids{7}));
}

TEST(LocalBaSelection, RejectsBadInput) {
  const auto kfs = line_of_keyframes();
  EXPECT_THROW(local_ba_selection(kfs, {}, 99), Error);         // unknown newest
  EXPECT_THROW(local_ba_selection(kfs, {{42, 1}}, 16), Error);  // unknown observer
  auto duplicate = kfs;
  duplicate.push_back(kfs[2]);
  EXPECT_THROW(local_ba_selection(duplicate, {}, 16), Error);  // repeated id
  auto not_finite = kfs;
  not_finite[3].centre_w.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(local_ba_selection(not_finite, {}, 16), Error);  // NaN centre
}

TEST(GlobalBaSelection, AllFreeButTheFirst) {
  const std::vector<ObservationRef> obs = {{10, 1}, {11, 1}, {16, 2}, {15, 2}, {13, 3}};
  auto kfs = line_of_keyframes();
  std::swap(kfs[0], kfs[4]);  // order does not matter: the gauge is the smallest id
  const BaSelection s = global_ba_selection(kfs, obs);
  EXPECT_EQ(s.fixed_keyframes, (Ids{10}));
  EXPECT_EQ(s.free_keyframes, (Ids{11, 12, 13, 14, 15, 16}));
  EXPECT_EQ(s.free_points, (Ids{1, 2, 3}));
}

TEST(GlobalBaSelection, RejectsBadInput) {
  EXPECT_THROW(global_ba_selection({}, {}), Error);
  EXPECT_THROW(global_ba_selection(line_of_keyframes(), {{3, 1}}), Error);
  auto duplicate = line_of_keyframes();
  duplicate.push_back(duplicate.front());
  EXPECT_THROW(global_ba_selection(duplicate, {}), Error);
}

}  // namespace
}  // namespace facadeslam
