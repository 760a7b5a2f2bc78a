// Issue 18's scale-out check: configs/optimise.yaml scaled down to a tiny GA
// (4 genomes x 2 generations on a tiny synthetic dataset; the shipped
// fitness weights and cost model) under `mpirun -np 3 --oversubscribe` (rank
// 0 runs the GA, ranks 1-2 evaluate) gives byte for byte the threaded run's
// best genome and fitness per generation. Needs a build with MPI and mpirun
// on the PATH; skips with a message otherwise. Labelled regression: the
// sanitizer pass does not run the MPI runtime.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "semantics/text.hpp"
#include "tests/apps/cli_run.hpp"
#include "tests/apps/optimise_test_config.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using semantics::cat;

TEST(OptimiseMpi, ThreeRanksGiveTheThreadedRunsResult) {
#ifndef FACADESLAM_MPIEXEC
  GTEST_SKIP() << "built without MPI (libopenmpi-dev): optimise runs threaded only";
#else
  test::TempDir dir;
  fs::create_directories(dir / "scratch");
  semantics::test_util::write_synthetic_dataset(dir / "data", 8, 1);
  std::ofstream(dir / "tiny.yaml") << test::scaled_down_shipped_config({{"population", "4"},
                                                                        {"generations", "2"},
                                                                        {"max_train_images", "6"},
                                                                        {"max_validation_images", "2"},
                                                                        {"max_samples", "2000"},
                                                                        {"max_trees", "8"},
                                                                        {"max_depth", "8"}});
  const auto arguments = [&](const fs::path& out) {
    return cat("-q optimise --dataset ", test::shell_quoted((dir / "data").string()), " --out ",
               test::shell_quoted(out.string()), " --config ", test::shell_quoted((dir / "tiny.yaml").string()),
               " --seed 4 --no-model");
  };
  const test::CliResult threaded =
      test::run_cli(FACADESLAM_BINARY, arguments(dir / "threaded") + " --workers 2", dir / "scratch");
  ASSERT_EQ(threaded.exit_code, 0) << threaded.err;
  // Containers often run as root, which mpirun refuses without these.
  const std::string command = cat("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ", FACADESLAM_MPIEXEC,
                                  " -np 3 --oversubscribe ", test::shell_quoted(FACADESLAM_BINARY));
  const test::CliResult mpi =
      test::run_cli("/bin/sh", "-c " + test::shell_quoted(command + " " + arguments(dir / "mpi")), dir / "scratch");
  ASSERT_EQ(mpi.exit_code, 0) << mpi.err;
  for (const char* file : {"best.genome", "fitness.json", "split.json"})
    EXPECT_EQ(test::read_file_text(dir / "threaded" / file), test::read_file_text(dir / "mpi" / file)) << file;
#endif
}

}  // namespace
}  // namespace facadeslam
