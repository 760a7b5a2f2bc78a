// A looped sequence plays the selected frames again and again as one
// sequence: indices unique, timestamps strictly increasing with one frame
// interval across each seam, the offsets recorded so a ground truth can be
// repeated the same way.
#include "sequences/looping_source.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/trajectory/trajectory.hpp"
#include "sequences/open_sequence.hpp"
#include "tests/sequences/sequence_test_files.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;
using test::read_all;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

// Frames 0-3 at 10.0, 10.5, 11.0, 11.5 s.
void write_sequence(const test::TempDir& dir) {
  for (int i = 0; i < 4; ++i) test::write_marked_image(dir / test::numbered("rgb/", i, ".png"), i);
  test::write_text(dir / "rgb.txt", "10.0 rgb/0.png\n10.5 rgb/1.png\n11.0 rgb/2.png\n11.5 rgb/3.png\n");
}

TEST(LoopingSource, PlaysTheFramesAgainAsOneSequence) {
  test::TempDir dir;
  write_sequence(dir);
  SequenceOptions options;
  options.start = 1;  // frames 1-3, each pass
  options.loops = 3;
  auto source = open_sequence(dir.path(), options);
  EXPECT_EQ(source->size_hint(), 9u);
  EXPECT_THAT(source->description(), HasSubstr("played 3 times"));
  const auto frames = read_all(*source);
  ASSERT_EQ(frames.size(), 9u);
  std::vector<std::size_t> indices;
  std::vector<int> marks;
  for (const Frame& f : frames) {
    indices.push_back(f.index);
    marks.push_back(test::mark_of(f.colour));
  }
  EXPECT_THAT(indices, ElementsAre(1, 2, 3, 5, 6, 7, 9, 10, 11));
  EXPECT_THAT(marks, ElementsAre(1, 2, 3, 1, 2, 3, 1, 2, 3));
  // Pass 0 spans 10.5-11.5 s with 0.5 s frames: each pass starts 1.5 s later.
  EXPECT_DOUBLE_EQ(frames[2].timestamp, 11.5);
  EXPECT_DOUBLE_EQ(frames[3].timestamp, 12.0);
  EXPECT_DOUBLE_EQ(frames[8].timestamp, 14.5);
  EXPECT_THAT(source->stats().pass_time_offsets_s, ElementsAre(0.0, 1.5, 3.0));
  EXPECT_EQ(source->stats().frames_read, 9u);
}

TEST(LoopingSource, OnePassIsThePlainReader) {
  test::TempDir dir;
  write_sequence(dir);
  auto source = open_sequence(dir.path(), {});
  EXPECT_EQ(read_all(*source).size(), 4u);
  EXPECT_TRUE(source->stats().pass_time_offsets_s.empty());
}

TEST(LoopingSource, ZeroOrAbsurdLoopsAreAnError) {
  test::TempDir dir;
  write_sequence(dir);
  SequenceOptions options;
  options.loops = 0;
  EXPECT_THAT(error_of([&] { open_sequence(dir.path(), options); }), HasSubstr("loops must be between 1 and"));
  options.loops = 2000000;
  EXPECT_THAT(error_of([&] { open_sequence(dir.path(), options); }), HasSubstr("loops must be between 1 and"));
}

TEST(RepeatTrajectory, RepeatsTheGroundTruthWithTheFramesAndStaysInTimeOrder) {
  Trajectory gt;
  for (double t : {10.0, 10.5, 11.0, 11.5, 12.0}) gt.push_back({t, Eigen::Isometry3d::Identity()});
  // Offsets of 1.5 s: the copy starting at 11.5 s would overlap the first
  // copy's 11.5 and 12.0 s, which are dropped from the second copy.
  const Trajectory repeated = repeat_trajectory(gt, {0.0, 1.5});
  std::vector<double> times;
  for (const StampedPose& p : repeated) times.push_back(p.timestamp);
  EXPECT_THAT(times, ElementsAre(10.0, 10.5, 11.0, 11.5, 12.0, 12.5, 13.0, 13.5));
  EXPECT_EQ(repeat_trajectory(gt, {}).size(), gt.size());
}

}  // namespace
}  // namespace facadeslam
