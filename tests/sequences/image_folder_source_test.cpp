#include "sequences/image_folder_source.hpp"

#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/util/error.hpp"
#include "tests/sequences/sequence_test_files.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using test::read_all;
using ::testing::AllOf;
using ::testing::HasSubstr;

// Ten images image0.png .. image9.png, each marked with 10 * its number.
void write_ten(const test::TempDir& dir) {
  for (int i = 0; i < 10; ++i) test::write_marked_image(dir / test::numbered("image", i, ".png"), 10 * i);
}

TEST(ImageFolderSource, ReadsImagesInNaturalOrderWithTimestampsFromFps) {
  test::TempDir dir;
  test::write_marked_image(dir / "frame10.png", 100);
  test::write_marked_image(dir / "frame2.png", 20);
  test::write_marked_image(dir / "frame1.png", 10);
  test::write_marked_image(dir / "frame3.PNG", 30);    // extension case does not matter
  test::write_text(dir / "notes.md", "not an image");  // ignored
  test::write_garbage(dir / ".frame0.png");            // hidden: ignored

  SequenceOptions options;
  options.fps = 10.0;
  ImageFolderSource source(dir.path(), options);
  EXPECT_EQ(source.size_hint(), 4u);
  EXPECT_THAT(source.description(), HasSubstr("4 images"));

  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 4u);
  const std::vector<int> marks = {10, 20, 30, 100};
  const std::vector<std::string> names = {"frame1.png", "frame2.png", "frame3.PNG", "frame10.png"};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(frames[i].index, i);
    EXPECT_DOUBLE_EQ(frames[i].timestamp, static_cast<double>(i) / 10.0);
    EXPECT_EQ(test::mark_of(frames[i].colour), marks[i]);
    EXPECT_EQ(frames[i].source.filename().string(), names[i]);
    EXPECT_EQ(frames[i].colour.type(), CV_8UC3);
    EXPECT_EQ(frames[i].colour.size(), cv::Size(32, 24));
  }
  EXPECT_EQ(source.stats().frames_read, 4u);
  EXPECT_EQ(source.stats().frames_skipped_corrupt, 0u);
  EXPECT_FALSE(source.next().has_value()) << "the end stays the end";
}

TEST(ImageFolderSource, AcceptsEveryListedExtension) {
  test::TempDir dir;
  const std::vector<std::string> extensions = {"png", "jpg", "jpeg", "bmp", "tif", "tiff", "pgm", "ppm"};
  for (std::size_t i = 0; i < extensions.size(); ++i) {
    const fs::path path = dir / test::numbered("f", static_cast<long long>(i), std::string(".") + extensions[i]);
    if (extensions[i] == "pgm")
      test::write_image(path, cv::Mat(24, 32, CV_8UC1, cv::Scalar(50)));
    else
      test::write_marked_image(path, 50);
  }
  EXPECT_TRUE(has_image_extension("x.JPEG"));
  EXPECT_FALSE(has_image_extension("x.txt"));
  ImageFolderSource source(dir.path(), {});
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), extensions.size());
  for (std::size_t i = 0; i < frames.size(); ++i)
    EXPECT_EQ(frames[i].source.extension().string(), std::string(".") + extensions[i]);
}

TEST(ImageFolderSource, TimesTxtGivesTheTimestamps) {
  test::TempDir dir;
  for (int i = 0; i < 3; ++i) test::write_marked_image(dir / test::numbered("im", i, ".png"), i);
  test::write_text(dir / "times.txt", "# seconds\n0.5\n\n0.75 # comment\n1.25\n");
  ImageFolderSource source(dir.path(), {});
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_DOUBLE_EQ(frames[0].timestamp, 0.5);
  EXPECT_DOUBLE_EQ(frames[1].timestamp, 0.75);
  EXPECT_DOUBLE_EQ(frames[2].timestamp, 1.25);
}

TEST(ImageFolderSource, TimestampsTxtAndExplicitFileAreUsed) {
  test::TempDir dir;
  for (int i = 0; i < 2; ++i) test::write_marked_image(dir / test::numbered("im", i, ".png"), i);
  test::write_text(dir / "timestamps.txt", "3\n4\n");
  {
    ImageFolderSource source(dir.path(), {});
    const auto frames = read_all(source);
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_DOUBLE_EQ(frames[1].timestamp, 4.0);
  }
  test::write_text(dir / "elsewhere/stamps.txt", "7\n9\n");
  SequenceOptions options;
  options.timestamps_file = dir / "elsewhere/stamps.txt";
  ImageFolderSource source(dir.path(), options);
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_DOUBLE_EQ(frames[0].timestamp, 7.0);
  EXPECT_DOUBLE_EQ(frames[1].timestamp, 9.0);
}

TEST(ImageFolderSource, TimestampCountMismatchNamesTheFileAndCounts) {
  test::TempDir dir;
  for (int i = 0; i < 3; ++i) test::write_marked_image(dir / test::numbered("im", i, ".png"), i);
  test::write_text(dir / "times.txt", "0\n1\n");
  const auto message = error_of([&] { ImageFolderSource source(dir.path(), {}); });
  EXPECT_THAT(message,
              AllOf(HasSubstr((dir / "times.txt").string()), HasSubstr("2 timestamps"), HasSubstr("3 images")));
}

TEST(ImageFolderSource, NonMonotonicTimestampNamesFileAndLine) {
  test::TempDir dir;
  for (int i = 0; i < 3; ++i) test::write_marked_image(dir / test::numbered("im", i, ".png"), i);
  test::write_text(dir / "times.txt", "1.0\n# comment\n2.0\n2.0\n");
  const auto message = error_of([&] { ImageFolderSource source(dir.path(), {}); });
  EXPECT_THAT(message, AllOf(HasSubstr((dir / "times.txt").string()), HasSubstr("line 4"),
                             HasSubstr("not after the previous one")));
}

TEST(ImageFolderSource, TimestampLineThatIsNotANumberNamesFileAndLine) {
  test::TempDir dir;
  for (int i = 0; i < 2; ++i) test::write_marked_image(dir / test::numbered("im", i, ".png"), i);
  test::write_text(dir / "times.txt", "0.0\nsoon\n");
  const auto message = error_of([&] { ImageFolderSource source(dir.path(), {}); });
  EXPECT_THAT(message, AllOf(HasSubstr((dir / "times.txt").string()), HasSubstr("line 2"),
                             HasSubstr("'soon' is not a timestamp")));
  test::write_text(dir / "times.txt", "0.0\n1.0 2.0\n");
  EXPECT_THAT(error_of([&] { ImageFolderSource source(dir.path(), {}); }),
              AllOf(HasSubstr("line 2"), HasSubstr("one timestamp per line")));
}

TEST(ImageFolderSource, BothTimestampFilesIsAmbiguous) {
  test::TempDir dir;
  test::write_marked_image(dir / "a.png", 1);
  test::write_text(dir / "times.txt", "0\n");
  test::write_text(dir / "timestamps.txt", "0\n");
  EXPECT_THAT(error_of([&] { ImageFolderSource source(dir.path(), {}); }),
              AllOf(HasSubstr(dir.path().string()), HasSubstr("both times.txt and timestamps.txt")));
}

TEST(ImageFolderSource, MissingExplicitTimestampsFileNamesIt) {
  test::TempDir dir;
  test::write_marked_image(dir / "a.png", 1);
  SequenceOptions options;
  options.timestamps_file = dir / "nope.txt";
  EXPECT_THAT(error_of([&] { ImageFolderSource source(dir.path(), options); }),
              AllOf(HasSubstr((dir / "nope.txt").string()), HasSubstr("no such timestamps file")));
}

TEST(ImageFolderSource, StartStrideAndLimitSelectFrames) {
  test::TempDir dir;
  write_ten(dir);
  SequenceOptions options;
  options.start = 1;
  options.stride = 3;
  options.fps = 2.0;
  {
    ImageFolderSource source(dir.path(), options);
    EXPECT_EQ(source.size_hint(), 3u);
    const auto frames = read_all(source);
    ASSERT_EQ(frames.size(), 3u);
    const std::vector<std::size_t> expected = {1, 4, 7};
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(frames[i].index, expected[i]);
      EXPECT_EQ(test::mark_of(frames[i].colour), static_cast<int>(10 * expected[i]));
      // Timestamps keep the frame's place in the whole sequence.
      EXPECT_DOUBLE_EQ(frames[i].timestamp, static_cast<double>(expected[i]) / 2.0);
    }
  }
  options.limit = 2;
  ImageFolderSource source(dir.path(), options);
  EXPECT_EQ(source.size_hint(), 2u);
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1].index, 4u);
}

TEST(ImageFolderSource, StartPastTheEndIsAnError) {
  test::TempDir dir;
  write_ten(dir);
  SequenceOptions options;
  options.start = 10;
  EXPECT_THAT(error_of([&] { ImageFolderSource source(dir.path(), options); }),
              AllOf(HasSubstr(dir.path().string()), HasSubstr("start 10 skips all 10 images")));
}

TEST(ImageFolderSource, MissingFolderNamesIt) {
  test::TempDir dir;
  EXPECT_THAT(error_of([&] { ImageFolderSource source(dir / "absent", {}); }),
              AllOf(HasSubstr((dir / "absent").string()), HasSubstr("no such folder")));
}

TEST(ImageFolderSource, FileInsteadOfFolderNamesIt) {
  test::TempDir dir;
  test::write_marked_image(dir / "a.png", 1);
  EXPECT_THAT(error_of([&] { ImageFolderSource source(dir / "a.png", {}); }),
              AllOf(HasSubstr((dir / "a.png").string()), HasSubstr("not a folder")));
}

TEST(ImageFolderSource, FolderWithoutImagesNamesItAndTheExpectedFiles) {
  test::TempDir dir;
  test::write_text(dir / "readme.txt", "nothing here");
  EXPECT_THAT(error_of([&] { ImageFolderSource source(dir.path(), {}); }),
              AllOf(HasSubstr(dir.path().string()), HasSubstr("no images found"), HasSubstr("png, jpg")));
}

TEST(ImageFolderSource, CorruptImageStopsWithItsPath) {
  test::TempDir dir;
  test::write_marked_image(dir / "f1.png", 1);
  test::write_garbage(dir / "f2.png");
  test::write_marked_image(dir / "f3.png", 3);
  ImageFolderSource source(dir.path(), {});
  ASSERT_TRUE(source.next().has_value());
  EXPECT_THAT(error_of([&] { source.next(); }),
              AllOf(HasSubstr((dir / "f2.png").string()), HasSubstr("cannot be decoded")));
}

TEST(ImageFolderSource, CorruptImagesAreCountedAndSkippedUnderSkip) {
  test::TempDir dir;
  test::write_marked_image(dir / "f1.png", 1);
  test::write_garbage(dir / "f2.png");
  test::write_marked_image(dir / "f3.png", 3);
  test::write_garbage(dir / "f4.jpg");
  test::write_marked_image(dir / "f5.png", 5);
  SequenceOptions options;
  options.on_corrupt = CorruptPolicy::skip;
  ImageFolderSource source(dir.path(), options);
  EXPECT_EQ(source.size_hint(), 5u);
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(test::mark_of(frames[0].colour), 1);
  EXPECT_EQ(test::mark_of(frames[1].colour), 3);
  EXPECT_EQ(test::mark_of(frames[2].colour), 5);
  EXPECT_EQ(frames[1].index, 2u) << "indices keep the place in the folder";
  EXPECT_EQ(source.stats().frames_read, 3u);
  EXPECT_EQ(source.stats().frames_skipped_corrupt, 2u);
  ASSERT_EQ(source.stats().corrupt_paths.size(), 2u);
  EXPECT_EQ(source.stats().corrupt_paths[0], dir / "f2.png");
  EXPECT_EQ(source.stats().corrupt_paths[1], dir / "f4.jpg");
}

TEST(ImageFolderSource, ImageOfAnotherSizeNamesItAndBothSizes) {
  test::TempDir dir;
  test::write_marked_image(dir / "f1.png", 1, 32, 24);
  test::write_marked_image(dir / "f2.png", 2, 40, 30);
  ImageFolderSource source(dir.path(), {});
  ASSERT_TRUE(source.next().has_value());
  EXPECT_THAT(error_of([&] { source.next(); }), AllOf(HasSubstr((dir / "f2.png").string()), HasSubstr("40x30"),
                                                      HasSubstr("32x24"), HasSubstr((dir / "f1.png").string())));
}

TEST(ImageFolderSource, GreyImagesBecomeBgr) {
  test::TempDir dir;
  test::write_image(dir / "g.png", cv::Mat(24, 32, CV_8UC1, cv::Scalar(77)));
  ImageFolderSource source(dir.path(), {});
  const auto frame = source.next();
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->colour.type(), CV_8UC3);
  EXPECT_EQ(frame->colour.at<cv::Vec3b>(5, 5), cv::Vec3b(77, 77, 77));
}

TEST(ImageFolderSource, SixteenBitImagesMapTheFullRangeOntoEightBits) {
  test::TempDir dir;
  cv::Mat grey16(24, 32, CV_16UC1, cv::Scalar(65535));
  grey16(cv::Rect(0, 0, 16, 24)).setTo(cv::Scalar(128 * 257));
  test::write_image(dir / "a.png", grey16);
  test::write_image(dir / "b.png", cv::Mat(24, 32, CV_16UC3, cv::Scalar(0, 257 * 10, 65535)));
  test::write_image(dir / "c.png", cv::Mat(24, 32, CV_8UC4, cv::Scalar(1, 2, 3, 0)));  // alpha dropped
  ImageFolderSource source(dir.path(), {});
  const auto a = source.next();
  const auto b = source.next();
  const auto c = source.next();
  ASSERT_TRUE(a && b && c);
  EXPECT_EQ(a->colour.type(), CV_8UC3);
  EXPECT_EQ(a->colour.at<cv::Vec3b>(0, 0), cv::Vec3b(128, 128, 128));
  EXPECT_EQ(a->colour.at<cv::Vec3b>(0, 31), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(b->colour.type(), CV_8UC3);
  EXPECT_EQ(b->colour.at<cv::Vec3b>(3, 3), cv::Vec3b(0, 10, 255));
  EXPECT_EQ(c->colour.type(), CV_8UC3);
  EXPECT_EQ(c->colour.at<cv::Vec3b>(3, 3), cv::Vec3b(1, 2, 3));
}

TEST(ImageFolderSource, ImagesAreDecodedOnlyWhenRequested) {
  test::TempDir dir;
  test::write_marked_image(dir / "f1.png", 1);
  test::write_marked_image(dir / "f2.png", 2);
  ImageFolderSource source(dir.path(), {});
  ASSERT_TRUE(source.next().has_value());
  // Replaced after opening: a reader that had decoded ahead would return 2.
  test::write_marked_image(dir / "f2.png", 42);
  const auto second = source.next();
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(test::mark_of(second->colour), 42);
}

TEST(ImageFolderSource, ReadsTheVispCubeSequence) {
  FACADESLAM_REQUIRE_SHARED_DATA("visp-cube");
  ImageFolderSource source(test::shared_data_dir() / "visp-cube", {});
  EXPECT_EQ(source.size_hint(), 218u);
  std::size_t count = 0;
  std::string last_name;
  while (auto frame = source.next()) {
    ASSERT_EQ(frame->colour.size(), cv::Size(640, 480)) << frame->source;
    ASSERT_EQ(frame->colour.type(), CV_8UC3) << frame->source;
    ASSERT_EQ(frame->index, count);
    last_name = frame->source.filename().string();
    ++count;
  }
  EXPECT_EQ(count, 218u);
  EXPECT_EQ(last_name, "image0217.png");
  EXPECT_EQ(source.stats().frames_skipped_corrupt, 0u);
}

}  // namespace
}  // namespace facadeslam
