#include "core/trajectory/association.hpp"

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

Trajectory at_times(const std::vector<double>& times) {
  Trajectory trajectory;
  for (const double t : times) trajectory.push_back({t, Eigen::Isometry3d::Identity()});
  return trajectory;
}

TEST(AssociateByTime, EqualTimestampsPairOneToOne) {
  const auto gt = at_times({0.0, 1.0, 2.0});
  const auto pairs = associate_by_time(gt, gt);
  ASSERT_EQ(pairs.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(pairs[i].gt_index, i);
    EXPECT_EQ(pairs[i].est_index, i);
  }
}

TEST(AssociateByTime, TakesTheNearestGroundTruthPose) {
  const auto gt = at_times({10.000, 10.008, 10.020});
  const auto est = at_times({10.005});
  const auto pairs = associate_by_time(gt, est);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].gt_index, 1u);  // 3 ms away, against 5 ms for the first
}

TEST(AssociateByTime, EachGroundTruthPoseIsUsedOnce) {
  // Both estimates are nearest to gt 0; the closer one gets it, the other
  // falls back to the next pose within reach or stays unpaired.
  const auto gt = at_times({5.000, 5.030});
  const auto est = at_times({4.996, 5.003});
  const auto pairs = associate_by_time(gt, est);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].gt_index, 0u);
  EXPECT_EQ(pairs[0].est_index, 1u);

  const auto gt2 = at_times({4.990, 5.000});
  const auto pairs2 = associate_by_time(gt2, est);
  ASSERT_EQ(pairs2.size(), 2u);
  EXPECT_EQ(pairs2[0].est_index, 0u);
  EXPECT_EQ(pairs2[0].gt_index, 0u);
  EXPECT_EQ(pairs2[1].est_index, 1u);
  EXPECT_EQ(pairs2[1].gt_index, 1u);
}

TEST(AssociateByTime, LimitIsInclusiveDespiteDoubleRounding) {
  // 4-decimal ground truth against 6-decimal estimates, exactly 10 ms apart
  // in the files; as doubles near 1.3e9 the difference is off by up to 0.2 µs.
  const auto gt = at_times({1305031098.6659, 1305031099.6659});
  const auto est = at_times({1305031098.675900, 1305031099.655900});
  EXPECT_EQ(associate_by_time(gt, est, 0.01).size(), 2u);
  EXPECT_EQ(associate_by_time(gt, est, 0.0099).size(), 0u);
  const auto late = at_times({1305031098.676200});  // 10.3 ms
  EXPECT_EQ(associate_by_time(gt, late, 0.01).size(), 0u);
}

TEST(AssociateByTime, RepeatedGroundTruthStampPrefersTheFirst) {
  const auto gt = at_times({1.5694, 1.5760, 1.5760, 1.5794});
  const auto pairs = associate_by_time(gt, at_times({1.5761}), 0.01);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].gt_index, 1u);
}

TEST(AssociateByTime, PairsAreInEstimateOrder) {
  const auto gt = at_times({0.0, 0.1, 0.2, 0.3, 0.4});
  const auto est = at_times({0.101, 0.198, 0.304});
  const auto pairs = associate_by_time(gt, est);
  ASSERT_EQ(pairs.size(), 3u);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    EXPECT_EQ(pairs[i].est_index, i);
    EXPECT_EQ(pairs[i].gt_index, i + 1);
  }
}

TEST(AssociateByTime, NoOverlapGivesNoPairs) {
  EXPECT_TRUE(associate_by_time(at_times({0.0, 1.0}), at_times({100.0, 101.0})).empty());
  EXPECT_TRUE(associate_by_time(at_times({}), at_times({1.0})).empty());
  EXPECT_TRUE(associate_by_time(at_times({1.0}), at_times({})).empty());
}

TEST(AssociateByTime, BadMaximumIsAnError) {
  const auto gt = at_times({0.0});
  EXPECT_THROW(associate_by_time(gt, gt, -0.01), Error);
  EXPECT_THROW(associate_by_time(gt, gt, std::numeric_limits<double>::quiet_NaN()), Error);
}

}  // namespace
}  // namespace facadeslam
