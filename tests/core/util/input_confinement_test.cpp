// Paths named inside input files stay inside the file's folder unless the
// user allows otherwise (--allow-outside-paths).
#include "core/util/input_confinement.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using ::testing::AllOf;
using ::testing::HasSubstr;

struct AllowedForTheTest {
  explicit AllowedForTheTest(bool allowed) { allow_paths_outside_inputs(allowed); }
  ~AllowedForTheTest() { allow_paths_outside_inputs(false); }
};

TEST(InputConfinement, PathsLeadingOutOfTheFolderAreRefused) {
  test::TempDir dir;
  fs::create_directories(dir / "seq" / "rgb");
  fs::create_directory_symlink("/etc", dir / "seq" / "etc-link");
  EXPECT_FALSE(paths_outside_inputs_allowed());
  EXPECT_TRUE(path_confined(dir / "seq" / "rgb" / "1.png", dir / "seq"));
  EXPECT_TRUE(path_confined(dir / "seq" / "rgb" / ".." / "2.png", dir / "seq"));
  EXPECT_FALSE(path_confined("/etc/passwd", dir / "seq"));
  EXPECT_FALSE(path_confined(dir / "seq" / ".." / ".." / "x.png", dir / "seq"));
  EXPECT_FALSE(path_confined(dir / "seq" / "etc-link" / "passwd", dir / "seq")) << "out through a link";
  EXPECT_THAT(
      error_of([&] { require_confined("/etc/passwd", dir / "seq", dir / "seq" / "rgb.txt", 4, "/etc/passwd"); }),
      AllOf(HasSubstr((dir / "seq" / "rgb.txt").string() + ": line 4: '/etc/passwd' leads outside"),
            HasSubstr("--allow-outside-paths")));
}

TEST(InputConfinement, TheUserMayAllowThem) {
  const AllowedForTheTest allowed(true);
  EXPECT_TRUE(path_confined("/etc/passwd", "/tmp"));
  EXPECT_NO_THROW(require_confined("/etc/passwd", "/tmp", "/tmp/rgb.txt", 1, "/etc/passwd"));
}

}  // namespace
}  // namespace facadeslam
