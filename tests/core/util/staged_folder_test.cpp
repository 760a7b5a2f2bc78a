#include "core/util/staged_folder.hpp"

#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(StagedFolder, CommitReplacesTheOldFolderAsAWhole) {
  test::TempDir dir;
  const fs::path target = dir / "out";
  fs::create_directories(target);
  write(target / "old.txt", "old");
  write(target / "kept-name.txt", "old");
  {
    StagedFolder staged(target);
    EXPECT_NE(staged.path(), target);
    EXPECT_EQ(staged.path().parent_path(), target.parent_path());
    EXPECT_EQ(staged.staged(target / "kept-name.txt"), staged.path() / "kept-name.txt");
    EXPECT_EQ(staged.staged(dir / "elsewhere.txt"), dir / "elsewhere.txt");
    EXPECT_TRUE(staged.contains(target / "a" / "b.txt"));
    EXPECT_FALSE(staged.contains(dir / "outside.txt"));
    write(staged.path() / "kept-name.txt", "new");
    write(staged.path() / "new.txt", "new");
    // Until the commit the target is the old run's, untouched.
    EXPECT_EQ(read(target / "kept-name.txt"), "old");
    staged.commit();
  }
  EXPECT_EQ(read(target / "kept-name.txt"), "new");
  EXPECT_EQ(read(target / "new.txt"), "new");
  EXPECT_FALSE(fs::exists(target / "old.txt"));
  EXPECT_EQ(entries(dir.path()), 1u) << "no staging or old folder left beside the target";
}

TEST(StagedFolder, AFailedRunLeavesTheOldFolderAndNothingElse) {
  test::TempDir dir;
  const fs::path target = dir / "out";
  fs::create_directories(target);
  write(target / "old.txt", "old");
  try {
    StagedFolder staged(target);
    write(staged.path() / "half.txt", "half");
    throw Error("disk full");
  } catch (const Error&) {
  }
  EXPECT_EQ(read(target / "old.txt"), "old");
  EXPECT_EQ(entries(target), 1u);
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(StagedFolder, AFailedRunRemovesTheFoldersItMade) {
  test::TempDir dir;
  { StagedFolder staged(dir / "a" / "b" / "out"); }
  EXPECT_FALSE(fs::exists(dir / "a"));
  {
    StagedFolder staged(dir / "a" / "b" / "out");
    staged.commit();
  }
  EXPECT_TRUE(fs::is_directory(dir / "a" / "b" / "out"));
}

TEST(StagedFolder, AFileInTheWayIsAnError) {
  test::TempDir dir;
  write(dir / "file", "x");
  EXPECT_THROW(StagedFolder(dir / "file"), Error);
}

// A run that continues an earlier one (optimise --resume) starts from the
// target's files, and from the staging folder a killed run left when that
// one got further; the target stays as it was until the commit.
TEST(StagedFolder, ARunThatContinuesStartsFromTheTargetsFiles) {
  test::TempDir dir;
  const fs::path target = dir / "run";
  fs::create_directories(target / "sub");
  write(target / "generation-000.json", "0");
  write(target / "sub" / "a.txt", "a");
  {
    StagedFolder staged(target, {true, {}});
    EXPECT_EQ(read(staged.path() / "generation-000.json"), "0");
    EXPECT_EQ(read(staged.path() / "sub" / "a.txt"), "a");
    write(staged.path() / "generation-001.json.tmp", "1");
    fs::rename(staged.path() / "generation-001.json.tmp", staged.path() / "generation-001.json");
    EXPECT_FALSE(fs::exists(target / "generation-001.json"));
    staged.commit();
  }
  EXPECT_EQ(read(target / "generation-000.json"), "0");
  EXPECT_EQ(read(target / "generation-001.json"), "1");
}

TEST(StagedFolder, ARunThatContinuesTakesOverAKilledRunsFurtherStagingFolder) {
  test::TempDir dir;
  const fs::path target = dir / "run";
  fs::create_directories(target);
  write(target / "generation-000.json", "0");
  // The staging folder of a process that is gone (killed with SIGKILL).
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  const fs::path abandoned = dir / (".run.tmp-" + std::to_string(child));
  fs::create_directories(abandoned);
  for (const char* name : {"generation-000.json", "generation-001.json", "generation-002.json"})
    write(abandoned / name, name);
  const auto further_on = [](const fs::path& a, const fs::path& than) { return entries(a) > entries(than); };
  {
    StagedFolder staged(target, {true, further_on});
    EXPECT_TRUE(fs::exists(staged.path() / "generation-002.json"));
    EXPECT_FALSE(fs::exists(abandoned)) << "its files live on in the new staging folder";
    EXPECT_EQ(read(target / "generation-000.json"), "0") << "the target untouched until the commit";
    staged.commit();
  }
  EXPECT_EQ(entries(target), 3u);
  // A run that starts anew removes such folders instead.
  fs::create_directories(abandoned);
  { StagedFolder fresh(target); }
  EXPECT_FALSE(fs::exists(abandoned));
}

}  // namespace
}  // namespace facadeslam
