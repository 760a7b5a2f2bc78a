#include "sequences/open_sequence.hpp"

#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/sequences/sequence_test_files.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using test::read_all;
using ::testing::AllOf;
using ::testing::HasSubstr;

TEST(OpenSequence, MissingPathSaysWhatWasExpected) {
  test::TempDir dir;
  const fs::path absent = dir / "nothing";
  EXPECT_EQ(error_of([&] { open_sequence(absent, {}); }),
            absent.string() +
                ": no such file or folder (expected an image folder, a TUM rgb.txt list or a "
                "video file)");
}

TEST(OpenSequence, PicksTheReaderFromThePath) {
  test::TempDir dir;
  test::write_marked_image(dir / "images/a.png", 1);
  test::write_marked_image(dir / "tum/rgb/a.png", 2);
  test::write_text(dir / "tum/rgb.txt", "1.0 rgb/a.png\n");
  test::write_text(dir / "list.txt", "1.0 images/a.png\n");
  test::write_garbage(dir / "clip.mp4");
  EXPECT_EQ(detect_sequence_kind(dir / "images"), SequenceKind::image_folder);
  EXPECT_EQ(detect_sequence_kind(dir / "tum"), SequenceKind::tum_list);
  EXPECT_EQ(detect_sequence_kind(dir / "list.txt"), SequenceKind::tum_list);
  EXPECT_EQ(detect_sequence_kind(dir / "clip.mp4"), SequenceKind::video);
}

TEST(OpenSequence, OpensEachKindAndAppliesOptions) {
  test::TempDir dir;
  for (int i = 0; i < 4; ++i) test::write_marked_image(dir / test::numbered("tum/rgb/", i, ".png"), i);
  test::write_text(dir / "tum/rgb.txt", "10 rgb/0.png\n11 rgb/1.png\n12 rgb/2.png\n13 rgb/3.png\n");
  SequenceOptions options;
  options.start = 1;
  options.stride = 2;

  auto folder = open_sequence(dir / "tum/rgb", options);
  EXPECT_THAT(folder->description(), HasSubstr("image folder"));
  auto folder_frames = read_all(*folder);
  ASSERT_EQ(folder_frames.size(), 2u);
  EXPECT_EQ(test::mark_of(folder_frames[1].colour), 3);
  EXPECT_DOUBLE_EQ(folder_frames[1].timestamp, 3.0 / 30.0);

  auto list = open_sequence(dir / "tum", options);
  EXPECT_THAT(list->description(), HasSubstr("TUM list"));
  auto list_frames = read_all(*list);
  ASSERT_EQ(list_frames.size(), 2u);
  EXPECT_DOUBLE_EQ(list_frames[0].timestamp, 11.0);
  EXPECT_DOUBLE_EQ(list_frames[1].timestamp, 13.0);
}

TEST(OpenSequence, GarbageVideoIsAnErrorNamingIt) {
  test::TempDir dir;
  test::write_garbage(dir / "clip.mp4");
  EXPECT_THAT(error_of([&] { open_sequence(dir / "clip.mp4", {}); }), HasSubstr((dir / "clip.mp4").string()));
}

TEST(OpenSequence, TimestampsFileForAListIsAnError) {
  test::TempDir dir;
  test::write_marked_image(dir / "rgb/a.png", 1);
  test::write_text(dir / "rgb.txt", "1.0 rgb/a.png\n");
  test::write_text(dir / "stamps.txt", "1.0\n");
  SequenceOptions options;
  options.timestamps_file = dir / "stamps.txt";
  EXPECT_THAT(error_of([&] { open_sequence(dir.path(), options); }),
              AllOf(HasSubstr((dir / "stamps.txt").string()), HasSubstr("applies only to an image folder")));
}

TEST(OpenSequence, InvalidOptionsAreAnError) {
  test::TempDir dir;
  test::write_marked_image(dir / "a.png", 1);
  SequenceOptions options;
  options.stride = 0;
  EXPECT_THAT(error_of([&] { open_sequence(dir.path(), options); }), HasSubstr("stride"));
}

}  // namespace
}  // namespace facadeslam
