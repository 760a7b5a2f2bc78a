#pragma once
// `facadeslam optimise`: the genetic algorithm driven generation by
// generation over a run folder.
//
// RUN_DIR holds split.json (the train / validation images of train.txt),
// generation-NNN.json after every generation (the GA's state, the fitness
// cache by genome and the run's settings; written atomically), and at the
// end best.genome, best.json, fitness.json, fitness.png and best.fsmodel.
// --resume continues from the newest generation file and ends exactly as an
// uninterrupted run would: the cache restores every evaluation made.
//
// Evaluation goes through an EvaluateBatch: worker threads here (the
// results are placed by index, so neither the number of workers nor the
// order they finish changes a generation), MPI ranks in a cluster build.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "semantics/descriptor/genome.hpp"
#include "semantics/optimiser/fitness.hpp"
#include "semantics/optimiser/ga_options.hpp"
#include "semantics/optimiser/genetic_algorithm.hpp"

namespace facadeslam::semantics {

struct OptimiseOptions {
  std::filesystem::path dataset;
  std::filesystem::path out;
  GaOptions ga;
  std::uint64_t seed = 1;
  int workers = 1;
  bool resume = false;
  bool train_best_model = true;                      // best.fsmodel (a forest on the whole of train.txt)
  std::vector<Genome> seeds{Genome::thesis_best()};  // put into the first generation
};

// Evaluates `genomes` (distinct, not in the cache) and returns one
// evaluation per genome, in the same order.
using EvaluateBatch = std::function<std::vector<GenomeEvaluation>(const std::vector<Genome>&)>;

// Evaluations over `workers` threads, each taking the next genome in turn.
std::vector<GenomeEvaluation> evaluate_in_threads(const FitnessEvaluator& evaluator, const std::vector<Genome>& genomes,
                                                  int workers);

struct OptimiseResult {
  GenerationSummary best;  // over all generations
  GenomeEvaluation best_evaluation;
  int generations = 0;
  std::size_t evaluations = 0;  // fitness evaluations made in this process
  std::size_t cache_hits = 0;
  double seconds = 0, evaluation_seconds = 0;
  // Stopped by Ctrl-C / SIGTERM after a generation's checkpoint: no final
  // outputs; --resume continues.
  bool interrupted = false;
  // Summed over this process's evaluations (threads overlap: the sums can
  // exceed evaluation_seconds): where an evaluation's time goes.
  double describe_seconds = 0, train_seconds = 0, validate_seconds = 0, invariance_seconds = 0;
};

// Validates the options and the run folder before any work (a dataset
// without train.txt, an existing run without --resume, a checkpoint of
// other settings: Error naming the file or option), then runs.
OptimiseResult run_optimisation(const OptimiseOptions& options, const EvaluateBatch& evaluate = {});

}  // namespace facadeslam::semantics
