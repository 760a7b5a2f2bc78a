#include "core/util/atomic_write.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count_entries(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicWrite, WritesAndCreatesParentFolder) {
  test::TempDir dir;
  const auto target = dir / "sub/out.txt";
  write_text_atomically(target, "hello\n");
  EXPECT_EQ(read_all(target), "hello\n");
  EXPECT_EQ(count_entries(target.parent_path()), 1u) << "temporary file left behind";
}

TEST(AtomicWrite, FailedWriterLeavesOldFileAndNoTemporary) {
  test::TempDir dir;
  const auto target = dir / "out.txt";
  write_text_atomically(target, "old");
  EXPECT_THROW(write_atomically(target,
                                [](std::ostream& out) {
                                  out << "half";
                                  throw Error("writer failed");
                                }),
               Error);
  EXPECT_EQ(read_all(target), "old");
  EXPECT_EQ(count_entries(dir.path()), 1u);
}

TEST(AtomicWrite, FileWriterThatCreatesNothingIsAnError) {
  test::TempDir dir;
  EXPECT_THROW(write_file_atomically(dir / "x.png", [](const std::filesystem::path&) {}), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(AtomicWrite, TemporaryKeepsExtension) {
  test::TempDir dir;
  std::filesystem::path seen;
  write_file_atomically(dir / "image.png", [&](const std::filesystem::path& tmp) {
    seen = tmp;
    std::ofstream(tmp) << "x";
  });
  EXPECT_EQ(seen.extension(), ".png");
  EXPECT_EQ(seen.parent_path(), dir.path());
}

}  // namespace
}  // namespace facadeslam
