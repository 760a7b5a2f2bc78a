#pragma once
// Goldberg's simple genetic algorithm over 211-bit genomes (thesis III.8,
// Algorithm 1), as a state machine the optimiser drives one generation at a
// time: it hands out the generation's genomes, takes their objectives back
// (however and wherever they were evaluated: threads or MPI ranks), and
// breeds the next generation: elites first, then children of selected
// parents by crossover and mutation.
//
// Deterministic: one random generator, used only here and in a fixed order,
// so the same seed and objectives give the same run; the whole state
// (genomes, objectives, generator, history) round-trips through JSON, so a
// resumed run continues exactly where the checkpoint left it.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "semantics/descriptor/genome.hpp"
#include "semantics/optimiser/ga_options.hpp"
#include "semantics/optimiser/ga_random.hpp"

namespace facadeslam::semantics {

// One generation's figures (objectives: higher is better; invalid genomes
// are left out of the mean and worst).
struct GenerationSummary {
  int generation = 0;
  double best = 0, mean = 0, worst = 0;
  Genome best_genome;
};

class GeneticAlgorithm {
 public:
  // The first generation: `seeds` (the thesis genome, EDD-like genomes; at
  // most the population) and random genomes for the rest.
  GeneticAlgorithm(const GaOptions& options, std::uint64_t seed, const std::vector<Genome>& seeds = {});

  int generation() const { return generation_; }  // 0-based
  const std::vector<Genome>& population() const { return population_; }
  // The generation's objectives, set once per generation (same order as
  // population()); -infinity marks an invalid genome.
  void set_objectives(std::vector<double> objectives);
  bool evaluated() const { return !objectives_.empty(); }
  const std::vector<double>& objectives() const { return objectives_; }

  // Records the evaluated generation's summary and breeds the next one.
  void advance();
  // Past generations' summaries (the evaluated current one included once
  // advance() has run for it).
  const std::vector<GenerationSummary>& history() const { return history_; }
  // Summary of the evaluated current generation.
  GenerationSummary summary() const;
  // The generation count is reached, or the best has not improved for
  // plateau_generations (GaOptions).
  bool finished() const;

  // The whole state; from_json throws Error (naming `where`) for a
  // malformed or incompatible checkpoint.
  nlohmann::json to_json() const;
  static GeneticAlgorithm from_json(const nlohmann::json& state, const GaOptions& options, const std::string& where);

 private:
  GeneticAlgorithm(const GaOptions& options) : options_(options) {}

  GaOptions options_;
  GaRandom rng_;
  int generation_ = 0;
  std::vector<Genome> population_;
  std::vector<double> objectives_;
  std::vector<GenerationSummary> history_;
};

}  // namespace facadeslam::semantics
