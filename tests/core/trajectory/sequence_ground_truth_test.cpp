#include "core/trajectory/sequence_ground_truth.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// Three KITTI poses 1 m apart along z.
constexpr const char* kThreeKittiPoses =
    "1 0 0 0 0 1 0 0 0 0 1 0\n"
    "1 0 0 0 0 1 0 0 0 0 1 1\n"
    "1 0 0 0 0 1 0 0 0 0 1 2\n";

TEST(SequenceGroundTruth, KittiLinesTakeTheirFramesTimes) {
  test::TempDir dir;
  test::write_text(dir / "poses.txt", kThreeKittiPoses);
  SequenceGroundTruth gt(dir / "poses.txt");
  EXPECT_EQ(gt.format(), TrajectoryFormat::kitti);
  EXPECT_TRUE(gt.trajectory().empty());  // no frame read yet
  // --start 0 --stride 2: frames 0 and 2, at the times their sequence gives them.
  gt.add_frame(0, 1305031102.175304);
  gt.add_frame(2, 1305031102.243211);
  const Trajectory& t = gt.trajectory();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].timestamp, 1305031102.175304);
  EXPECT_EQ(t[1].timestamp, 1305031102.243211);
  EXPECT_EQ(t[0].T_w_c.translation().z(), 0.0);
  EXPECT_EQ(t[1].T_w_c.translation().z(), 2.0);  // line 3 for frame 2
}

TEST(SequenceGroundTruth, KittiFileShorterThanTheSequenceIsAnError) {
  test::TempDir dir;
  test::write_text(dir / "poses.txt", kThreeKittiPoses);
  SequenceGroundTruth gt(dir / "poses.txt");
  EXPECT_NO_THROW(gt.require_frames_up_to(2));
  EXPECT_THAT(error_of([&] { gt.require_frames_up_to(3); }),
              AllOf(StartsWith((dir / "poses.txt").string() + ": has 3 poses but the sequence has frame 3"),
                    HasSubstr("line i for frame i")));
  EXPECT_THAT(error_of([&] { gt.add_frame(5, 0.5); }), HasSubstr("has 3 poses but the sequence has frame 5"));
}

TEST(SequenceGroundTruth, TumIsTheFileAsItIs) {
  test::TempDir dir;
  test::write_text(dir / "gt.txt", "10.0 0 0 0 0 0 0 1\n10.1 0 0 1 0 0 0 1\n");
  SequenceGroundTruth gt(dir / "gt.txt");
  EXPECT_EQ(gt.format(), TrajectoryFormat::tum);
  EXPECT_NO_THROW(gt.require_frames_up_to(1000));  // TUM poses pair by time, not by line
  gt.add_frame(7, 55.0);
  ASSERT_EQ(gt.trajectory().size(), 2u);
  EXPECT_EQ(gt.trajectory()[1].timestamp, 10.1);
}

TEST(SequenceGroundTruth, OnePoseIsAnError) {
  test::TempDir dir;
  test::write_text(dir / "one.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_THAT(
      error_of([&] { SequenceGroundTruth gt(dir / "one.txt"); }),
      StartsWith((dir / "one.txt").string() + ": has 1 pose (expected a ground-truth trajectory of at least 2)"));
}

}  // namespace
}  // namespace facadeslam
