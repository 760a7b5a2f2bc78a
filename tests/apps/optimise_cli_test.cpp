// `facadeslam optimise` end to end on a tiny synthetic LabelMeFacade-layout
// dataset the test writes (8 training images: 6 to train on, 2 validation):
// a tiny GA (6 genomes x 3 generations) gives the same result whatever the
// number of worker threads, a run killed after a generation and resumed ends
// exactly as the uninterrupted one, and bad input fails before any work
// with one line. The time term is the cost model's, so it takes part: and
// configs/optimise.yaml itself, scaled down, gives byte-identical results on
// one and two threads and resumed (the MPI twin: optimise_mpi_test.cpp).
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "semantics/text.hpp"
#include "tests/apps/cli_run.hpp"
#include "tests/apps/optimise_test_config.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using semantics::cat;
using ::testing::HasSubstr;

class OptimiseCli : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(scratch());
    semantics::test_util::write_synthetic_dataset(data(), 8, 1);
    write(config(), "population: 6\ngenerations: 3\nmax_samples: 2000\nmax_trees: 8\nmax_depth: 8\nstep: 9\n");
  }
  static void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }
  fs::path data() const { return dir_ / "data"; }
  fs::path scratch() const { return dir_ / "scratch"; }
  fs::path config() const { return dir_ / "tiny.yaml"; }
  // The last checkpoint's GA state (genomes, objectives, generator, history;
  // the cache beside it also holds each evaluation's wall-clock seconds).
  static nlohmann::json ga_state(const fs::path& run) {
    return nlohmann::json::parse(test::read_file_text(run / "generation-002.json")).at("ga");
  }
  test::CliResult optimise(const fs::path& out, const std::string& more = "") {
    return test::run_cli(
        FACADESLAM_BINARY,
        cat("-q optimise --dataset ", test::shell_quoted(data().string()), " --out ", test::shell_quoted(out.string()),
            " --config ", test::shell_quoted(config().string()), " --seed 4 --no-model ", more),
        scratch());
  }
  test::TempDir dir_;
};

TEST_F(OptimiseCli, ThreadedRunsGiveTheSameResultWhateverTheWorkers) {
  const test::CliResult one = optimise(dir_ / "one", "--workers 1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const test::CliResult two = optimise(dir_ / "two", "--workers 2");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  for (const char* file : {"best.genome", "fitness.json", "split.json"})
    EXPECT_EQ(test::read_file_text(dir_ / "one" / file), test::read_file_text(dir_ / "two" / file)) << file;
  EXPECT_EQ(ga_state(dir_ / "one"), ga_state(dir_ / "two"));
  for (const char* file : {"best.json", "fitness.png", "generation-000.json", "generation-001.json"})
    EXPECT_TRUE(fs::exists(dir_ / "one" / file)) << file;
  EXPECT_EQ(test::read_file_text(dir_ / "one" / "best.genome").size(), 212u);  // 211 bits and a newline
  EXPECT_THAT(test::read_file_text(dir_ / "one" / "fitness.json"), HasSubstr("\"best_fitness\""));
}

TEST_F(OptimiseCli, AResumedRunEndsExactlyAsTheUninterruptedOne) {
  ASSERT_EQ(optimise(dir_ / "whole").exit_code, 0);
  ASSERT_EQ(optimise(dir_ / "killed").exit_code, 0);
  // As if killed after generation 1: its last checkpoint and every result gone.
  for (const char* file : {"generation-002.json", "best.genome", "best.json", "fitness.json", "fitness.png"})
    fs::remove(dir_ / "killed" / file);
  const test::CliResult resumed = optimise(dir_ / "killed", "--resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  for (const char* file : {"best.genome", "fitness.json"})
    EXPECT_EQ(test::read_file_text(dir_ / "whole" / file), test::read_file_text(dir_ / "killed" / file)) << file;
  EXPECT_EQ(ga_state(dir_ / "whole"), ga_state(dir_ / "killed"));
}

// best.json's evaluation without its wall-clock `*seconds` fields (where
// the time went, not part of any result).
nlohmann::json best_evaluation(const fs::path& run) {
  nlohmann::json e = nlohmann::json::parse(test::read_file_text(run / "best.json")).at("evaluation");
  for (auto it = e.begin(); it != e.end();) it = it.key().find("seconds") != std::string::npos ? e.erase(it) : ++it;
  return e;
}

// Issue 42: with the shipped settings (the time term weighted) two runs of
// the same seed agree byte for byte on one thread, on two, and killed after
// a generation and resumed. fitness.json holds no timing; best.json's
// `*seconds` are wall clock, so its evaluation is compared without them.
TEST_F(OptimiseCli, TheShippedConfigGivesTheSameResultOnOneOrTwoThreadsAndResumed) {
  write(config(), test::scaled_down_shipped_config());
  const test::CliResult one = optimise(dir_ / "one", "--workers 1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const test::CliResult two = optimise(dir_ / "two", "--workers 2");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  ASSERT_EQ(optimise(dir_ / "killed", "--workers 2").exit_code, 0);
  for (const char* file : {"generation-002.json", "best.genome", "best.json", "fitness.json", "fitness.png"})
    fs::remove(dir_ / "killed" / file);
  const test::CliResult resumed = optimise(dir_ / "killed", "--resume --workers 1");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  for (const char* run : {"two", "killed"}) {
    for (const char* file : {"best.genome", "fitness.json", "split.json"})
      EXPECT_EQ(test::read_file_text(dir_ / "one" / file), test::read_file_text(dir_ / run / file))
          << run << " " << file;
    EXPECT_EQ(ga_state(dir_ / "one"), ga_state(dir_ / run)) << run;
    EXPECT_EQ(best_evaluation(dir_ / "one"), best_evaluation(dir_ / run)) << run;
  }
  // The time term took part: the winner's modelled ratio is in its evaluation.
  EXPECT_GT(best_evaluation(dir_ / "one").at("time_ratio").get<double>(), 0.0);
}

TEST_F(OptimiseCli, BadInputFailsBeforeAnyWorkWithOneLine) {
  ASSERT_EQ(optimise(dir_ / "run").exit_code, 0);
  // An existing run without --resume: untouched.
  const std::string before = test::read_file_text(dir_ / "run" / "fitness.json");
  test::CliResult r = optimise(dir_ / "run");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("--resume"));
  EXPECT_EQ(test::read_file_text(dir_ / "run" / "fitness.json"), before);
  // --resume with other settings.
  write(config(), "population: 7\ngenerations: 3\n");
  r = optimise(dir_ / "run", "--resume");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("other settings"));
  // A corrupt checkpoint.
  write(dir_ / "run" / "generation-002.json", "{ not json");
  r = optimise(dir_ / "run", "--resume");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("generation-002.json"));
  // --resume where there is nothing to resume; a dataset without train.txt; an unknown config key.
  r = optimise(dir_ / "fresh", "--resume");
  EXPECT_THAT(r.err, HasSubstr("no generation-NNN.json"));
  fs::remove(data() / "train.txt");
  r = optimise(dir_ / "fresh2");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("train.txt"));
  write(config(), "populaton: 6\n");
  r = optimise(dir_ / "fresh3");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("populaton"));
  for (const test::CliResult* c : {&r}) EXPECT_EQ(std::count(c->err.begin(), c->err.end(), '\n'), 1) << c->err;
}

}  // namespace
}  // namespace facadeslam
