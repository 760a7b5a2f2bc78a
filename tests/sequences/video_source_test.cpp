#include "sequences/video_source.hpp"

#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/videoio.hpp>

#include "tests/sequences/sequence_test_files.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using test::read_all;
using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr int kFrames = 12;
const cv::Size kSize(160, 120);
constexpr double kFps = 25.0;

// Writes kFrames MJPG frames whose brightness encodes their number (20 * i),
// coarse enough to survive JPEG. False when this OpenCV cannot write MJPG.
bool write_test_video(const fs::path& path) {
  cv::VideoWriter writer(path.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), kFps, kSize);
  if (!writer.isOpened()) return false;
  for (int i = 0; i < kFrames; ++i) writer.write(cv::Mat(kSize, CV_8UC3, cv::Scalar::all(20 * i)));
  writer.release();
  return true;
}

#define WRITE_VIDEO_OR_SKIP(path)                                                      \
  if (!write_test_video(path))                                                         \
  GTEST_SKIP() << "this OpenCV build cannot write MJPG .avi files (no videoio writer " \
                  "backend), so there is no video to read back"

TEST(VideoSource, ReadsBackEveryFrameWithSizeOrderAndIncreasingTimestamps) {
  test::TempDir dir;
  const fs::path video = dir / "clip.avi";
  WRITE_VIDEO_OR_SKIP(video);
  VideoSource source(video, {});
  EXPECT_EQ(source.frame_size(), kSize);
  EXPECT_THAT(source.description(), HasSubstr(video.string()));
  const std::size_t hint = source.size_hint();
  EXPECT_TRUE(hint == 0 || hint == static_cast<std::size_t>(kFrames)) << hint;

  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), static_cast<std::size_t>(kFrames));
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(frames[i].index, i);
    EXPECT_EQ(frames[i].colour.size(), kSize);
    EXPECT_EQ(frames[i].colour.type(), CV_8UC3);
    EXPECT_EQ(frames[i].source, video);
    EXPECT_NEAR(test::mark_of(frames[i].colour), 20 * static_cast<int>(i), 4) << "frame " << i;
    if (i > 0) {
      EXPECT_GT(frames[i].timestamp, frames[i - 1].timestamp);
    }
  }
  // Whether from the decoder's positions or from the rate, 25 fps it is.
  EXPECT_NEAR(frames.back().timestamp - frames.front().timestamp, (kFrames - 1) / kFps, 1e-3);
  EXPECT_EQ(source.stats().frames_read, static_cast<std::size_t>(kFrames));
}

TEST(VideoSource, StartStrideAndLimitSelectFrames) {
  test::TempDir dir;
  const fs::path video = dir / "clip.avi";
  WRITE_VIDEO_OR_SKIP(video);
  SequenceOptions options;
  options.start = 2;
  options.stride = 3;  // 2 5 8 11
  {
    VideoSource source(video, options);
    const auto frames = read_all(source);
    ASSERT_EQ(frames.size(), 4u);
    const std::vector<std::size_t> expected = {2, 5, 8, 11};
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(frames[i].index, expected[i]);
      EXPECT_NEAR(test::mark_of(frames[i].colour), 20 * static_cast<int>(expected[i]), 4);
      EXPECT_NEAR(frames[i].timestamp, static_cast<double>(expected[i]) / kFps, 1e-3);
    }
  }
  options.limit = 2;
  VideoSource source(video, options);
  const std::size_t hint = source.size_hint();
  EXPECT_TRUE(hint == 0 || hint == 2u) << hint;
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1].index, 5u);
}

TEST(VideoSource, FileThatIsNotAVideoNamesIt) {
  test::TempDir dir;
  test::write_garbage(dir / "broken.avi");
  EXPECT_THAT(error_of([&] { VideoSource source(dir / "broken.avi", {}); }),
              AllOf(HasSubstr((dir / "broken.avi").string()), HasSubstr("expected a video file readable by OpenCV")));
}

TEST(VideoSource, MissingFileNamesIt) {
  test::TempDir dir;
  EXPECT_THAT(error_of([&] { VideoSource source(dir / "absent.mp4", {}); }),
              AllOf(HasSubstr((dir / "absent.mp4").string()), HasSubstr("no such file")));
}

}  // namespace
}  // namespace facadeslam
