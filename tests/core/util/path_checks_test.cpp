#include "core/util/path_checks.hpp"

#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

TEST(PathChecks, TellFilesFromFoldersAndMissingPaths) {
  test::TempDir dir;
  const auto file = dir.path() / "a.txt";
  std::ofstream(file) << "x";
  EXPECT_TRUE(path_exists(file));
  EXPECT_TRUE(is_existing_file(file));
  EXPECT_FALSE(is_existing_folder(file));
  EXPECT_TRUE(is_existing_folder(dir.path()));
  EXPECT_FALSE(is_existing_file(dir.path()));
  EXPECT_FALSE(path_exists(dir.path() / "missing"));
  EXPECT_FALSE(is_existing_file(file / "below_a_file"));  // ENOTDIR on the way
}

// std::filesystem's plain overloads throw here (ENAMETOOLONG); found by
// fuzz_scene_yaml through a scene's camera key.
TEST(PathChecks, ANameTooLongIsAbsentNotAnException) {
  const std::filesystem::path too_long = std::filesystem::temp_directory_path() / std::string(300, 'n');
  EXPECT_FALSE(path_exists(too_long));
  EXPECT_FALSE(is_existing_file(too_long));
  EXPECT_FALSE(is_existing_folder(too_long));
}

// Messages say what is there, not "does not exist" for all of it.
TEST(PathChecks, DescribeWhatIsThere) {
  test::TempDir dir;
  const auto file = dir.path() / "a.txt";
  std::ofstream(file) << "x";
  const auto fifo = dir.path() / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::filesystem::create_symlink(dir.path() / "gone", dir.path() / "dangling");
  EXPECT_EQ(describe_path(file), "is a file");
  EXPECT_EQ(describe_path(dir.path()), "is a folder");
  EXPECT_EQ(describe_path(fifo), "is a FIFO (named pipe)");
  EXPECT_EQ(describe_path("/dev/null"), "is a character device");
  EXPECT_EQ(describe_path(dir.path() / "missing"), "does not exist");
  EXPECT_EQ(describe_path(dir.path() / "dangling"), "is a symbolic link to nothing");
  EXPECT_TRUE(is_readable_file(file));
  EXPECT_FALSE(is_readable_file(fifo));
  EXPECT_FALSE(is_readable_file(dir.path()));
  if (::geteuid() != 0) {  // root reads everything
    std::filesystem::permissions(file, std::filesystem::perms::none);
    EXPECT_EQ(describe_path(file), "is a file that cannot be read (Permission denied)");
    EXPECT_FALSE(is_readable_file(file));
  }
}

}  // namespace
}  // namespace facadeslam
