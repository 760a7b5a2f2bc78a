// `facadeslam optimise`: the genetic algorithm over the modular descriptor's
// 211-bit genome (thesis III.8, IV.4) on a LabelMeFacade-layout dataset's
// train.txt, with a validation split carved from it; results, checkpoints
// and the winner's model in the run folder (semantics/optimiser).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/core/utility.hpp>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "apps/genome_option.hpp"
#include "apps/output_kinds.hpp"
#include "core/util/error.hpp"
#include "core/util/path_checks.hpp"
#include "core/util/shipped_files.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/output_policy.hpp"
#include "core/util/staged_folder.hpp"
#include "semantics/optimiser/ga_options.hpp"
#include "semantics/optimiser/optimisation_run.hpp"
#ifdef FACADESLAM_HAVE_MPI
#include "semantics/optimiser/mpi_evaluation.hpp"
#endif

namespace facadeslam::apps {
namespace optimise_command {
namespace {

struct Options {
  semantics::OptimiseOptions run;
  std::filesystem::path config = "configs/optimise.yaml";
  bool config_given = false;
  std::optional<int> population, generations;
  std::vector<std::string> seed_genomes;  // --seed-genome, resolved in run()
  bool no_model = false;
};

void report(const Options& o, const semantics::OptimiseResult& r) {
  if (r.interrupted) {
    std::fprintf(stderr, "facadeslam: optimise interrupted after generation %d; --resume continues it\n",
                 r.generations - 1);
    throw CLI::RuntimeError(interrupt_exit_code());
  }
  std::printf("optimise: %d generations, %zu evaluations (%zu cached) in %.1f s (%.1f s evaluating)\n", r.generations,
              r.evaluations, r.cache_hits, r.seconds, r.evaluation_seconds);
  const double busy = r.describe_seconds + r.train_seconds + r.validate_seconds + r.invariance_seconds;
  if (busy > 0)
    std::printf(
        "optimise: evaluation time: %.0f %% describing the training sample, %.0f %% training forests, "
        "%.0f %% validating, %.0f %% invariance cases\n",
        100 * r.describe_seconds / busy, 100 * r.train_seconds / busy, 100 * r.validate_seconds / busy,
        100 * r.invariance_seconds / busy);
  std::printf(
      "optimise: best objective %.4f at generation %d: overall %.4f, average %.4f, "
      "%.3f x cv::SIFT's time (modelled), %d values -> %s\n",
      r.best.best, r.best.generation, r.best_evaluation.overall, r.best_evaluation.average,
      r.best_evaluation.time_ratio, r.best_evaluation.values, (o.run.out / "best.genome").string().c_str());
  std::fflush(stdout);
}

// "DIR/.NAME.tmp-PID/..." in a message -> "DIR/NAME/...".
std::string unstaged(std::string text, const std::filesystem::path& staging, const std::filesystem::path& out) {
  const std::string from = staging.string(), to = out.string();
  for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size())
    text.replace(at, from.size(), to);
  return text;
}

// The newest generation-NNN.json's number in `folder`, -1 without one.
int newest_generation(const std::filesystem::path& folder) {
  int newest = -1;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() < 19 || name.size() > 24 || name.compare(0, 11, "generation-") != 0 ||
        name.compare(name.size() - 5, 5, ".json") != 0)
      continue;
    const std::string digits = name.substr(11, name.size() - 16);
    if (digits.find_first_not_of("0123456789") == std::string::npos) newest = std::max(newest, std::stoi(digits));
  }
  return newest;
}

// A killed run's staging folder is further on than `than` (more generations).
bool further_on(const std::filesystem::path& abandoned, const std::filesystem::path& than) {
  return newest_generation(abandoned) > newest_generation(than);
}

// A run folder holding a run is continued only with --resume; --resume needs
// one (in --out, or in the staging folder a killed run left beside it).
void require_run_state(const std::filesystem::path& out, bool resume) {
  const int newest = newest_generation(out);
  if (!resume && newest >= 0)
    throw Error(out.string() + ": holds a run already (generation " + std::to_string(newest) +
                "); pass --resume to continue it, or choose another --out");
}

// The GA (the threaded run, or MPI's rank 0) writes into a staging folder
// beside --out, moved into place when it ends or stops at Ctrl-C (its
// checkpoints kept for --resume); a failed run leaves --out as it was.
// --resume starts from --out's files, or from the staging folder a killed
// run left when that one is further on.
semantics::OptimiseResult run_staged(const Options& o, const semantics::EvaluateBatch& evaluate_batch = {}) {
  StagedFolder staged(o.run.out, {o.run.resume, further_on});
  semantics::OptimiseOptions run = o.run;
  run.out = staged.path();
  try {
    const semantics::OptimiseResult result = semantics::run_optimisation(run, evaluate_batch);
    staged.commit();
    return result;
  } catch (const Error& e) {
    // Messages name --out, not the hidden staging folder.
    throw Error(unstaged(e.what(), staged.path(), o.run.out));
  }
}

#ifdef FACADESLAM_HAVE_MPI
// Under mpirun: rank 0 runs the GA and the ranks above it evaluate. A rank
// that fails ends them all (the others would wait for it forever).
// Returns rank 0's result (reported once MPI is finalised); nothing on the other ranks.
std::optional<semantics::OptimiseResult> run_under_mpi(const Options& o) {
  semantics::MpiSession mpi;
  if (mpi.size() == 1) return run_staged(o);
  try {
    if (mpi.rank() > 0) {
      const semantics::FitnessEvaluator evaluator(semantics::split_train_list(o.run.dataset, o.run.ga, o.run.seed),
                                                  o.run.ga, o.run.seed);
      semantics::serve_mpi_evaluations(evaluator);
      return std::nullopt;
    }
    const semantics::OptimiseResult r = run_staged(o, semantics::mpi_evaluate_batch(mpi.size()));
    semantics::stop_mpi_workers(mpi.size());
    return r;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "facadeslam: error (MPI rank %d): %s\n", mpi.rank(), e.what());
    std::fflush(stderr);
    semantics::MpiSession::abort(kExitError);
  }
}
#endif

void run(Options& o) {
  // OpenCV single-threaded: the evaluations are the parallel unit
  // (--workers, MPI ranks); OpenCV's threads inside each would only contend
  // with the other workers for the same cores.
  cv::setNumThreads(1);
  // The run folder can be made (or is one) before any work, and is a new
  // or empty folder or an earlier run's, never one of other files.
  if (!o.config_given) o.config = shipped_file(o.config);  // beside the executable, not the current folder
  OutputPlan plan;
  plan.input(o.run.dataset / "train.txt", "--dataset's train.txt");
  plan.input(o.run.dataset / "test.txt", "--dataset's test.txt");
  plan.input_folder_read_whole(o.run.dataset / "images", "--dataset's images/");
  plan.input_folder_read_whole(o.run.dataset / "labels", "--dataset's labels/");
  if (o.config_given || path_exists(o.config)) plan.input(o.config, "--config");
  for (const std::string& g : o.seed_genomes)
    if (is_existing_file(g)) plan.input(g, "--seed-genome");
  plan.output_folder(o.run.out, "--out", optimise_folder_layout());
  plan.check();
  require_creatable_folder(o.run.out);
  require_run_state(o.run.out, o.run.resume);
  if (o.config_given || path_exists(o.config)) o.run.ga = semantics::load_ga_options(o.config);
  if (o.population) o.run.ga.population = *o.population;
  if (o.generations) o.run.ga.generations = *o.generations;
  if (o.run.ga.elites >= o.run.ga.population)
    throw Error("optimise: --population " + std::to_string(o.run.ga.population) + " leaves no room beside " +
                std::to_string(o.run.ga.elites) + " elites (" + o.config.string() + ")");
  o.run.ga.tournament_size = std::min(o.run.ga.tournament_size, o.run.ga.population);
  o.run.train_best_model = !o.no_model;
  // Given genomes join the thesis genome in the first generation (a run
  // continued from an earlier run's winner, EDD-like genomes).
  for (const std::string& g : o.seed_genomes) {
    semantics::Genome genome = resolve_genome(g, "--seed-genome");
    if (std::find(o.run.seeds.begin(), o.run.seeds.end(), genome) == o.run.seeds.end())
      o.run.seeds.push_back(std::move(genome));
  }
  if (o.run.seeds.size() > static_cast<std::size_t>(o.run.ga.population))
    throw CLI::ValidationError("--seed-genome", std::to_string(o.run.seeds.size()) +
                                                    " seed genomes (with the thesis "
                                                    "genome) do not fit a population of " +
                                                    std::to_string(o.run.ga.population));
#ifdef FACADESLAM_HAVE_MPI
  if (semantics::launched_by_mpi()) {
    if (const auto r = run_under_mpi(o)) report(o, *r);
    return;
  }
#endif
  report(o, run_staged(o));
}

}  // namespace
}  // namespace optimise_command

void add_optimise_command(CLI::App& app) {
  using namespace optimise_command;
  auto options = std::make_shared<Options>();
  auto& r = options->run;
  auto* cmd = app.add_subcommand(
      "optimise", "Genetic algorithm over the descriptor genome on a dataset's train.txt (validation split from it)");
  cmd->add_option("--dataset", r.dataset, "Dataset folder: train.txt, images/, labels/ (test.txt is never read)")
      ->required();
  cmd->add_option("--out", r.out,
                  "Run folder: checkpoints, best.genome, best.json, fitness.json/.png, best.fsmodel (a new or empty "
                  "folder, or an earlier run's; replaced as a whole when the run ends)")
      ->required()
      ->check(kNonEmptyPath);
  cmd->add_option("--population", options->population, "Genomes per generation (default: the config's, 30)")
      ->check(CLI::Range(2, 100000));
  cmd->add_option("--generations", options->generations, "Generations (default: the config's, 20)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--seed", r.seed, "Seed of the first generation, the operators and the validation split")
      ->check(whole_number(0, kMaxSeed))
      ->capture_default_str();
  cmd->add_option("--workers", r.workers, "Fitness evaluations in parallel (threads)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  cmd->add_flag("--resume", r.resume, "Continue the run in --out from its newest generation-NNN.json");
  cmd->add_option("--config", options->config, "GA settings YAML (default: the shipped configs/optimise.yaml)")
      ->each([options](const std::string&) { options->config_given = true; });
  cmd->add_option("--seed-genome", options->seed_genomes,
                  "A genome (file or 0/1 string) for the first generation beside the thesis genome; repeatable");
  cmd->add_flag("--no-model", options->no_model, "Do not train best.fsmodel at the end");
  cmd->callback([options] { run(*options); });
}

}  // namespace facadeslam::apps
