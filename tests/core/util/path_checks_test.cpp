#include "core/util/path_checks.hpp"

#include <fstream>
#include <string>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace facadeslam
