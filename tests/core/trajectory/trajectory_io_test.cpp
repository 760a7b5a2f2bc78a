#include "core/trajectory/trajectory_io.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "tests/core/trajectory/synthetic_trajectories.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;

using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(TrajectoryIo, TumRoundTripKeepsFullPrecision) {
  test::TempDir dir;
  const auto original = test::helix(50);
  write_tum_trajectory(dir / "out" / "traj.txt", original);
  const auto read = read_trajectory(dir / "out" / "traj.txt");
  ASSERT_EQ(read.size(), original.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_NEAR(read[i].timestamp, original[i].timestamp, 1e-6);  // ulp near 1.3e9 s is 0.24 µs
    EXPECT_LT((read[i].T_w_c.matrix() - original[i].T_w_c.matrix()).norm(), 1e-13);
  }
  // No temporary file is left beside the output.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir / "out"), {}), 1);
}

TEST(TrajectoryIo, TumTimestampsAreWrittenWithNineDecimals) {
  test::TempDir dir;
  const Trajectory t{{1.123456789, Eigen::Isometry3d::Identity()}, {2.5, Eigen::Isometry3d::Identity()}};
  write_tum_trajectory(dir / "t.txt", t);
  const auto read = read_trajectory(dir / "t.txt");
  EXPECT_DOUBLE_EQ(read[0].timestamp, 1.123456789);
  EXPECT_DOUBLE_EQ(read[1].timestamp, 2.5);
}

TEST(TrajectoryIo, TumSkipsCommentsAndBlankLinesAndNormalisesQuaternions) {
  test::TempDir dir;
  test::write_text(dir / "t.txt",
                   "# ground truth\n"
                   "\n"
                   "1.0 1 2 3 0 0 0 2   # a comment after the numbers\n"
                   "   \t\n"
                   "2.0 4 5 6 0 0 1 1\r\n");
  const auto t = read_trajectory(dir / "t.txt", TrajectoryFormat::tum);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].timestamp, 1.0);
  EXPECT_EQ(t[0].T_w_c.translation(), Eigen::Vector3d(1, 2, 3));
  EXPECT_LT((t[0].T_w_c.linear() - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  const Eigen::Matrix3d yaw90 = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_LT((t[1].T_w_c.linear() - yaw90).norm(), 1e-15);
}

TEST(TrajectoryIo, KittiUsesLineIndexOrTimesFile) {
  test::TempDir dir;
  test::write_text(dir / "k.txt",
                   "1 0 0 0.5 0 1 0 0 0 0 1 0\n"
                   "0 -1 0 1 1 0 0 2 0 0 1 3\n");
  const auto by_index = read_trajectory(dir / "k.txt");  // 12 columns: KITTI
  ASSERT_EQ(by_index.size(), 2u);
  EXPECT_EQ(by_index[0].timestamp, 0.0);
  EXPECT_EQ(by_index[1].timestamp, 1.0);
  EXPECT_EQ(by_index[0].T_w_c.translation(), Eigen::Vector3d(0.5, 0, 0));
  EXPECT_EQ(by_index[1].T_w_c.translation(), Eigen::Vector3d(1, 2, 3));
  const Eigen::Matrix3d yaw90 = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_LT((by_index[1].T_w_c.linear() - yaw90).norm(), 1e-15);

  test::write_text(dir / "times.txt", "0.000000e+00\n1.037359e-01\n");
  const auto timed = read_trajectory(dir / "k.txt", TrajectoryFormat::kitti, dir / "times.txt");
  EXPECT_EQ(timed[1].timestamp, 1.037359e-01);
}

TEST(TrajectoryIo, KittiWithoutTimesFileTakesARate) {
  test::TempDir dir;
  test::write_text(dir / "k.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n1 0 0 2 0 1 0 0 0 0 1 0\n");
  const auto at_10_hz = read_trajectory(dir / "k.txt", TrajectoryFormat::auto_detect, {}, 10.0);
  ASSERT_EQ(at_10_hz.size(), 3u);
  EXPECT_DOUBLE_EQ(at_10_hz[1].timestamp, 0.1);
  EXPECT_DOUBLE_EQ(at_10_hz[2].timestamp, 0.2);
  // A times file wins over the rate.
  test::write_text(dir / "times.txt", "5.0\n5.5\n6.0\n");
  EXPECT_EQ(read_trajectory(dir / "k.txt", TrajectoryFormat::kitti, dir / "times.txt", 10.0)[2].timestamp, 6.0);
  EXPECT_THAT(error_of([&] { read_trajectory(dir / "k.txt", TrajectoryFormat::kitti, {}, -10.0); }),
              HasSubstr("expected a positive number of frames per second"));
}

TEST(TrajectoryIo, DetectsTheFormatByTheColumnCount) {
  test::TempDir dir;
  test::write_text(dir / "k.txt", "# KITTI\n1 0 0 0 0 1 0 0 0 0 1 0\n");
  test::write_text(dir / "t.txt", "0.5 0 0 0 0 0 0 1\n");
  test::write_text(dir / "x.txt", "\n1 2 3\n");
  EXPECT_EQ(detect_trajectory_format(dir / "k.txt"), TrajectoryFormat::kitti);
  EXPECT_EQ(detect_trajectory_format(dir / "t.txt"), TrajectoryFormat::tum);
  EXPECT_THAT(error_of([&] { detect_trajectory_format(dir / "x.txt"); }),
              StartsWith((dir / "x.txt").string() + ":2: cannot tell the trajectory format"));
}

TEST(TrajectoryIo, KittiRotationsAreSnappedToOrthonormal) {
  test::TempDir dir;
  // 7 significant digits, as KITTI files print them.
  test::write_text(dir / "k.txt",
                   "9.999978e-01 5.272628e-04 -2.066935e-03 -4.690294e-02 -5.296506e-04 "
                   "9.999992e-01 -1.154865e-03 -2.839928e-02 2.066324e-03 1.155958e-03 "
                   "9.999971e-01 8.586941e-01\n");
  const auto t = read_trajectory(dir / "k.txt");
  const Eigen::Matrix3d R = t[0].T_w_c.linear();
  EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_NEAR(R(0, 1), 5.272628e-04, 1e-6);
}

TEST(TrajectoryIo, ParsesFormatNames) {
  EXPECT_EQ(parse_trajectory_format("auto"), TrajectoryFormat::auto_detect);
  EXPECT_EQ(parse_trajectory_format("tum"), TrajectoryFormat::tum);
  EXPECT_EQ(parse_trajectory_format("kitti"), TrajectoryFormat::kitti);
  EXPECT_THAT(error_of([] { parse_trajectory_format("euroc"); }), HasSubstr("'euroc'"));
}

// --- bad input: one test per case, each checking the message names the place.

class TrajectoryIoBadInput : public ::testing::Test {
 protected:
  std::string read_error(const std::string& content, TrajectoryFormat format = TrajectoryFormat::auto_detect) {
    test::write_text(dir_ / "t.txt", content);
    return error_of([&] { read_trajectory(dir_ / "t.txt", format); });
  }
  std::string file() const { return (dir_ / "t.txt").string(); }
  test::TempDir dir_;
};

TEST_F(TrajectoryIoBadInput, MissingFile) {
  EXPECT_THAT(error_of([&] { read_trajectory(dir_ / "nope.txt"); }),
              AllOf(StartsWith((dir_ / "nope.txt").string() + ": "), HasSubstr("no such file")));
}

TEST_F(TrajectoryIoBadInput, EmptyFile) {
  EXPECT_THAT(read_error(""), AllOf(StartsWith(file() + ": "), HasSubstr("no poses")));
}

TEST_F(TrajectoryIoBadInput, OnlyComments) {
  EXPECT_THAT(read_error("# timestamp tx ty tz qx qy qz qw\n\n"), HasSubstr("no poses"));
}

// Issue 20: no ATE from a file whose time stands still, and a line
// repeated word for word counts once.
TEST_F(TrajectoryIoBadInput, AllEqualTimestampsAreRejected) {
  EXPECT_THAT(read_error("5 0 0 0 0 0 0 1\n5 1 0 0 0 0 0 1\n5 2 0 0 0 0 0 1\n"),
              AllOf(StartsWith(file() + ": "), HasSubstr("all 3 timestamps are equal")));
}

TEST_F(TrajectoryIoBadInput, ARepeatedLineIsReadOnce) {
  test::write_text(dir_ / "t.txt", "1 0 0 0 0 0 0 1\n2 1 0 0 0 0 0 1\n2 1 0 0 0 0 0 1\n3 2 0 0 0 0 0 1\n");
  EXPECT_EQ(read_trajectory(dir_ / "t.txt").size(), 3u);
  // Equal stamps with different poses stay (TUM ground truth rounds to 0.1 ms).
  test::write_text(dir_ / "t.txt", "1 0 0 0 0 0 0 1\n2 1 0 0 0 0 0 1\n2 1.5 0 0 0 0 0 1\n");
  EXPECT_EQ(read_trajectory(dir_ / "t.txt").size(), 3u);
}

TEST_F(TrajectoryIoBadInput, ShortLine) {
  EXPECT_EQ(read_error("1 0 0 0 0 0 0 1\n2 0 0 0 0 0 1\n"),
            file() + ":2: expected 8 numbers (timestamp tx ty tz qx qy qz qw), got 7");
}

TEST_F(TrajectoryIoBadInput, LongLineInTum) {
  EXPECT_THAT(read_error("1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1 9\n"), StartsWith(file() + ":2: expected 8 numbers"));
}

TEST_F(TrajectoryIoBadInput, NotANumber) {
  EXPECT_EQ(read_error("# header\n1 0 0 0 0 0 x 1\n"),
            file() + ":2: expected 8 numbers (timestamp tx ty tz qx qy qz qw); 'x' is not a finite number");
}

TEST_F(TrajectoryIoBadInput, TrailingGarbageInANumber) {
  EXPECT_THAT(read_error("1 0 0 0 0 0 0 1.0abc\n"), HasSubstr(":1: expected 8 numbers"));
}

TEST_F(TrajectoryIoBadInput, NonFiniteNumber) {
  EXPECT_THAT(read_error("1 0 nan 0 0 0 0 1\n"),
              AllOf(StartsWith(file() + ":1: expected 8 numbers"), HasSubstr("'nan'")));
  EXPECT_THAT(read_error("1 inf 0 0 0 0 0 1\n"), HasSubstr("'inf' is not a finite number"));
}

TEST_F(TrajectoryIoBadInput, DecreasingTimestamps) {
  EXPECT_THAT(read_error("2 0 0 0 0 0 0 1\n3 0 0 0 0 0 0 1\n2.5 0 0 0 0 0 0 1\n"),
              AllOf(StartsWith(file() + ":3: "), HasSubstr("smaller than the previous")));
}

// Not bad input: TUM ground truth rounds to 0.1 ms and repeats a stamp now and then.
TEST(TrajectoryIo, RepeatedTimestampIsKept) {
  test::TempDir dir;
  test::write_text(dir / "t.txt", "1.5760 0 0 0 0 0 0 1\n1.5760 1 0 0 0 0 0 1\n1.5794 2 0 0 0 0 0 1\n");
  const auto t = read_trajectory(dir / "t.txt");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].timestamp, t[1].timestamp);
}

TEST_F(TrajectoryIoBadInput, ZeroQuaternion) {
  EXPECT_THAT(read_error("1 0 0 0 0 0 0 0\n"), AllOf(StartsWith(file() + ":1: "), HasSubstr("zero length")));
}

TEST_F(TrajectoryIoBadInput, UnknownColumnCount) {
  EXPECT_THAT(read_error("1 2 3 4\n"),
              AllOf(StartsWith(file() + ":1: "), HasSubstr("8 numbers per line (TUM) or 12 (KITTI), got 4")));
}

TEST_F(TrajectoryIoBadInput, KittiFileReadAsTum) {
  EXPECT_THAT(read_error("1 0 0 0 0 1 0 0 0 0 1 0\n", TrajectoryFormat::tum), HasSubstr(":1: expected 8 numbers"));
}

TEST_F(TrajectoryIoBadInput, TumFileReadAsKitti) {
  EXPECT_THAT(read_error("1 0 0 0 0 0 0 1\n", TrajectoryFormat::kitti), HasSubstr(":1: expected 12 numbers"));
}

TEST_F(TrajectoryIoBadInput, KittiBlockNotARotation) {
  EXPECT_THAT(read_error("2 0 0 0 0 1 0 0 0 0 1 0\n"), AllOf(StartsWith(file() + ":1: "), HasSubstr("not a rotation")));
  EXPECT_THAT(read_error("-1 0 0 0 0 1 0 0 0 0 1 0\n"), HasSubstr("not a rotation"));  // a reflection
}

TEST_F(TrajectoryIoBadInput, TimesFileWithWrongCount) {
  test::write_text(dir_ / "k.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n");
  test::write_text(dir_ / "times.txt", "0.0\n");
  EXPECT_THAT(error_of([&] { read_trajectory(dir_ / "k.txt", TrajectoryFormat::auto_detect, dir_ / "times.txt"); }),
              AllOf(StartsWith((dir_ / "times.txt").string() + ": "), HasSubstr("has 1 timestamps")));
}

TEST_F(TrajectoryIoBadInput, TimesFileNotIncreasing) {
  test::write_text(dir_ / "k.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n");
  test::write_text(dir_ / "times.txt", "0.5\n0.4\n");
  EXPECT_THAT(error_of([&] { read_trajectory(dir_ / "k.txt", TrajectoryFormat::kitti, dir_ / "times.txt"); }),
              StartsWith((dir_ / "times.txt").string() + ":2: timestamp"));
}

TEST_F(TrajectoryIoBadInput, TimesFileWithBadLine) {
  test::write_text(dir_ / "k.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
  test::write_text(dir_ / "times.txt", "0.5 0.6\n");
  EXPECT_THAT(error_of([&] { read_trajectory(dir_ / "k.txt", TrajectoryFormat::kitti, dir_ / "times.txt"); }),
              StartsWith((dir_ / "times.txt").string() + ":1: expected 1 number"));
}

TEST_F(TrajectoryIoBadInput, MissingTimesFile) {
  test::write_text(dir_ / "k.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_THAT(error_of([&] { read_trajectory(dir_ / "k.txt", TrajectoryFormat::kitti, dir_ / "none.txt"); }),
              AllOf(StartsWith((dir_ / "none.txt").string() + ": "), HasSubstr("no such file")));
}

TEST_F(TrajectoryIoBadInput, TimesFileForATumTrajectory) {
  test::write_text(dir_ / "times.txt", "0.5\n");
  test::write_text(dir_ / "t.txt", "1 0 0 0 0 0 0 1\n");
  EXPECT_THAT(error_of([&] { read_trajectory(dir_ / "t.txt", TrajectoryFormat::auto_detect, dir_ / "times.txt"); }),
              HasSubstr("only to KITTI"));
}

TEST_F(TrajectoryIoBadInput, UnwritableOutput) {
  test::write_text(dir_ / "file", "x");
  EXPECT_THROW(write_tum_trajectory(dir_ / "file" / "t.txt", test::helix(3)), Error);
}

}  // namespace
}  // namespace facadeslam
