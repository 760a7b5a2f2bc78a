#include "sequences/tum_list_source.hpp"

#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "core/util/input_confinement.hpp"
#include "tests/sequences/sequence_test_files.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using test::read_all;
using ::testing::AllOf;
using ::testing::HasSubstr;

// rgb/<n>.png for n in `marks`, the i-th listed at 100 + i / 10 seconds.
void write_list(const test::TempDir& dir, const std::vector<int>& marks) {
  std::string list = "# color images\n# file: 'test'\n# timestamp filename\n";
  for (std::size_t i = 0; i < marks.size(); ++i) {
    const std::string name = test::numbered("rgb/", marks[i], ".png");
    test::write_marked_image(dir / name, marks[i]);
    list += std::to_string(100.0 + static_cast<double>(i) / 10.0) + " " + name + "\n";
  }
  test::write_text(dir / "rgb.txt", list);
}

TEST(TumListSource, ReadsListedImagesInListOrderWithTheirTimestamps) {
  test::TempDir dir;
  // The list is the authority on order, not the file names.
  write_list(dir, {20, 3, 10});
  TumListSource source(dir / "rgb.txt", {});
  EXPECT_EQ(source.size_hint(), 3u);
  EXPECT_THAT(source.description(), HasSubstr("TUM list"));
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 3u);
  const std::vector<int> marks = {20, 3, 10};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(frames[i].index, i);
    EXPECT_NEAR(frames[i].timestamp, 100.0 + static_cast<double>(i) / 10.0, 1e-9);
    EXPECT_EQ(test::mark_of(frames[i].colour), marks[i]);
    EXPECT_EQ(frames[i].source, dir / test::numbered("rgb/", marks[i], ".png"));
    EXPECT_EQ(frames[i].colour.size(), cv::Size(32, 24));
  }
  EXPECT_EQ(source.stats().frames_read, 3u);
}

TEST(TumListSource, KeepsFullTimestampPrecision) {
  test::TempDir dir;
  test::write_marked_image(dir / "rgb/a.png", 1);
  test::write_marked_image(dir / "rgb/b.png", 2);
  test::write_text(dir / "rgb.txt", "1305031102.175304 rgb/a.png\n1305031102.211214 rgb/b.png\n");
  TumListSource source(dir / "rgb.txt", {});
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_NEAR(frames[1].timestamp - frames[0].timestamp, 0.03591, 1e-6);
}

TEST(TumListSource, StartStrideAndLimitSelectFrames) {
  test::TempDir dir;
  write_list(dir, {0, 1, 2, 3, 4, 5, 6});
  SequenceOptions options;
  options.start = 2;
  options.stride = 2;
  options.limit = 2;
  TumListSource source(dir / "rgb.txt", options);
  EXPECT_EQ(source.size_hint(), 2u);
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].index, 2u);
  EXPECT_EQ(frames[1].index, 4u);
  EXPECT_EQ(test::mark_of(frames[1].colour), 4);
}

TEST(TumListSource, LineThatDoesNotParseNamesFileAndLine) {
  test::TempDir dir;
  test::write_marked_image(dir / "rgb/a.png", 1);
  test::write_text(dir / "rgb.txt", "# header\n1.0 rgb/a.png\n2.0\n");
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "rgb.txt", {}); }),
              AllOf(HasSubstr((dir / "rgb.txt").string()), HasSubstr("line 3"),
                    HasSubstr("expected 'timestamp relative/path.png'")));
}

TEST(TumListSource, TimestampThatIsNotANumberNamesFileAndLine) {
  test::TempDir dir;
  test::write_marked_image(dir / "rgb/a.png", 1);
  test::write_text(dir / "rgb.txt", "\nrgb/a.png 1.0\n");
  EXPECT_THAT(
      error_of([&] { TumListSource source(dir / "rgb.txt", {}); }),
      AllOf(HasSubstr((dir / "rgb.txt").string()), HasSubstr("line 2"), HasSubstr("'rgb/a.png' is not a timestamp")));
}

TEST(TumListSource, NonMonotonicTimestampNamesFileAndLine) {
  test::TempDir dir;
  write_list(dir, {1, 2});
  test::write_text(dir / "rgb.txt", "5.0 rgb/1.png\n4.0 rgb/2.png\n");
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "rgb.txt", {}); }),
              AllOf(HasSubstr((dir / "rgb.txt").string()), HasSubstr("line 2"),
                    HasSubstr("not after the previous one (5 on line 1)")));
}

TEST(TumListSource, MissingListedImageNamesListLineAndImage) {
  test::TempDir dir;
  write_list(dir, {1});
  test::write_text(dir / "rgb.txt", "1.0 rgb/1.png\n2.0 rgb/gone.png\n");
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "rgb.txt", {}); }),
              AllOf(HasSubstr((dir / "rgb.txt").string()), HasSubstr("line 2"),
                    HasSubstr((dir / "rgb/gone.png").string()), HasSubstr("does not exist")));
}

TEST(TumListSource, MissingImageIsAnErrorEvenUnderSkip) {
  test::TempDir dir;
  write_list(dir, {1});
  test::write_text(dir / "rgb.txt", "1.0 rgb/1.png\n2.0 rgb/gone.png\n");
  SequenceOptions options;
  options.on_corrupt = CorruptPolicy::skip;
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "rgb.txt", options); }), HasSubstr("does not exist"));
}

TEST(TumListSource, ListWithoutEntriesSaysNoImagesFound) {
  test::TempDir dir;
  test::write_text(dir / "rgb.txt", "# color images\n\n# nothing else\n");
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "rgb.txt", {}); }),
              AllOf(HasSubstr((dir / "rgb.txt").string()), HasSubstr("no images found"),
                    HasSubstr("timestamp relative/path.png")));
}

TEST(TumListSource, MissingListNamesIt) {
  test::TempDir dir;
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "rgb.txt", {}); }),
              AllOf(HasSubstr((dir / "rgb.txt").string()), HasSubstr("no such file")));
}

TEST(TumListSource, CorruptImageStopsOrIsSkippedByPolicy) {
  test::TempDir dir;
  write_list(dir, {1, 3});
  test::write_garbage(dir / "rgb/2.png");
  test::write_text(dir / "rgb.txt", "1 rgb/1.png\n2 rgb/2.png\n3 rgb/3.png\n");
  {
    TumListSource source(dir / "rgb.txt", {});
    ASSERT_TRUE(source.next().has_value());
    EXPECT_THAT(error_of([&] { source.next(); }),
                AllOf(HasSubstr((dir / "rgb/2.png").string()), HasSubstr("cannot be decoded")));
  }
  SequenceOptions options;
  options.on_corrupt = CorruptPolicy::skip;
  TumListSource source(dir / "rgb.txt", options);
  const auto frames = read_all(source);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_DOUBLE_EQ(frames[1].timestamp, 3.0);
  EXPECT_EQ(source.stats().frames_skipped_corrupt, 1u);
  ASSERT_EQ(source.stats().corrupt_paths.size(), 1u);
  EXPECT_EQ(source.stats().corrupt_paths[0], dir / "rgb/2.png");
}

TEST(TumListSource, ImageOfAnotherSizeNamesItAndBothSizes) {
  test::TempDir dir;
  test::write_marked_image(dir / "rgb/a.png", 1, 32, 24);
  test::write_marked_image(dir / "rgb/b.png", 2, 16, 12);
  test::write_text(dir / "rgb.txt", "1 rgb/a.png\n2 rgb/b.png\n");
  TumListSource source(dir / "rgb.txt", {});
  ASSERT_TRUE(source.next().has_value());
  EXPECT_THAT(error_of([&] { source.next(); }),
              AllOf(HasSubstr((dir / "rgb/b.png").string()), HasSubstr("16x12"), HasSubstr("32x24")));
}

// Issue 41: listed paths stay inside the list's folder unless allowed.
TEST(TumListSource, ListedPathsLeadingOutOfTheFolderAreRefused) {
  test::TempDir dir;
  write_list(dir, {1});
  test::write_marked_image(dir / "outside.png", 2);
  fs::create_directories(dir / "seq");
  test::write_text(dir / "seq" / "rgb.txt", "1.0 ../rgb/1.png\n2.0 ../outside.png\n");
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "seq" / "rgb.txt", {}); }),
              AllOf(HasSubstr((dir / "seq" / "rgb.txt").string() + ": line 1: '../rgb/1.png' leads outside"),
                    HasSubstr("--allow-outside-paths")));
  test::write_text(dir / "seq" / "rgb.txt", "1.0 /etc/passwd\n");
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "seq" / "rgb.txt", {}); }),
              HasSubstr("'/etc/passwd' leads outside"));
  allow_paths_outside_inputs(true);
  test::write_text(dir / "seq" / "rgb.txt", "1.0 ../rgb/1.png\n2.0 ../outside.png\n");
  TumListSource source(dir / "seq" / "rgb.txt", {});
  EXPECT_EQ(read_all(source).size(), 2u);
  allow_paths_outside_inputs(false);
}

TEST(TumListSource, AListedPathThatIsNoFileSaysWhatItIs) {
  test::TempDir dir;
  write_list(dir, {1});
  fs::create_directories(dir / "rgb" / "folder.png");
  ASSERT_EQ(::mkfifo((dir / "rgb" / "fifo.png").c_str(), 0600), 0);
  test::write_text(dir / "rgb.txt", "1.0 rgb/1.png\n2.0 rgb/fifo.png\n");
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "rgb.txt", {}); }),
              AllOf(HasSubstr("line 2"), HasSubstr("fifo.png is a FIFO (named pipe)")));
  test::write_text(dir / "rgb.txt", "1.0 rgb/1.png\n2.0 rgb/folder.png\n");
  EXPECT_THAT(error_of([&] { TumListSource source(dir / "rgb.txt", {}); }), HasSubstr("folder.png is a folder"));
}

}  // namespace
}  // namespace facadeslam
