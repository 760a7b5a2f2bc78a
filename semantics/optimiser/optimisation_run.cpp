#include "semantics/optimiser/optimisation_run.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string_view>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "core/plot/line_plot.hpp"
#include "core/util/atomic_write.hpp"
#include "core/util/json.hpp"
#include "core/util/error.hpp"
#include "core/util/path_checks.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/progress.hpp"
#include "core/util/stopwatch.hpp"
#include "semantics/descriptor/genome_io.hpp"
#include "semantics/evaluation/model_training.hpp"
#include "semantics/forest/forest_model.hpp"

namespace facadeslam::semantics {
namespace fs = std::filesystem;

namespace {

constexpr int kRunVersion = 1;

// What a run's results depend on: a checkpoint is resumed only with the same.
nlohmann::json settings_json(const OptimiseOptions& o) {
  const GaOptions& g = o.ga;
  nlohmann::json seeds = nlohmann::json::array();
  for (const Genome& s : o.seeds) seeds.push_back(s.to_string());
  nlohmann::json settings = {{"dataset", fs::absolute(o.dataset).lexically_normal().string()},
                             {"seed", o.seed},
                             {"population", g.population},
                             {"generations", g.generations},
                             {"selection", to_string(g.selection)},
                             {"tournament_size", g.tournament_size},
                             {"crossover", to_string(g.crossover)},
                             {"crossover_probability", g.crossover_probability},
                             {"bit_flip_probability", g.bit_flip_probability},
                             {"interchange_probability", g.interchange_probability},
                             {"reverse_probability", g.reverse_probability},
                             {"elites", g.elites},
                             {"scaling_multiple", g.scaling_multiple},
                             {"plateau_generations", g.plateau_generations},
                             {"plateau_tolerance", g.plateau_tolerance},
                             {"validation_share", g.validation_share},
                             {"max_train_images", g.max_train_images},
                             {"max_validation_images", g.max_validation_images},
                             {"max_samples", g.max_samples},
                             {"step", g.step},
                             {"max_trees", g.max_trees},
                             {"max_depth", g.max_depth},
                             {"fitness",
                              {{"overall", g.weights.overall},
                               {"average", g.weights.average},
                               {"invariance", g.weights.invariance},
                               {"time", g.weights.time},
                               {"target_time_ratio", g.weights.target_time_ratio},
                               {"size", g.weights.size}}},
                             {"cost_model", to_json(g.cost_model)},
                             {"seeds", seeds}};
  // Only when set, so that the checkpoints of runs before the key existed still resume.
  if (g.folds > 1) settings["folds"] = g.folds;
  if (g.weights.invariance > 0) settings["invariance_images"] = g.invariance_images;
  return settings;
}

fs::path checkpoint_path(const fs::path& out, int generation) {
  char name[32];
  std::snprintf(name, sizeof name, "generation-%03d.json", generation);
  return out / name;
}

// The generation number of a checkpoint's file name, or -1.
int checkpoint_number(const std::string& name) {
  constexpr std::string_view prefix = "generation-", suffix = ".json";
  if (name.size() < prefix.size() + 3 + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return -1;
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  if (digits.empty() || digits.size() > 9 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return -1;
  return std::stoi(digits);
}

// The newest generation-NNN.json in `out`, or empty.
fs::path newest_checkpoint(const fs::path& out) {
  fs::path newest;
  int newest_n = -1;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(out, ec))
    if (const int n = checkpoint_number(entry.path().filename().string()); n > newest_n) {
      newest_n = n;
      newest = entry.path();
    }
  return newest;
}

nlohmann::json read_json_file(const fs::path& path) {
  std::ifstream in(path);
  if (!in) fail_file(path, "a readable JSON file");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    fail_file(path, std::string("valid JSON (") + e.what() + ")");
  }
}

void save_fitness_plot(const fs::path& path, const std::vector<GenerationSummary>& history) {
  plot::LinePlot p(1000, 700);
  p.set_title("Genetic optimiser: objective per generation");
  p.set_x_label("generation");
  p.set_y_label("objective (higher is better)");
  std::vector<double> x, best, mean, worst;
  for (const GenerationSummary& s : history) {
    x.push_back(s.generation);
    best.push_back(s.best);
    mean.push_back(s.mean);
    worst.push_back(s.worst);
  }
  // Generations count from 0: no axis room before the first.
  p.set_x_range(0.0, std::max(1.0, x.empty() ? 1.0 : x.back()));
  plot::SeriesStyle style;
  style.markers = true;
  p.add_series("best", x, best, style);
  p.add_series("mean", x, mean, style);
  p.add_series("worst", x, worst, style);
  p.save_png(path);
}

}  // namespace

std::vector<GenomeEvaluation> evaluate_in_threads(const FitnessEvaluator& evaluator, const std::vector<Genome>& genomes,
                                                  int workers) {
  std::vector<GenomeEvaluation> out(genomes.size());
  std::atomic<std::size_t> next{0};
  std::vector<std::string> errors(genomes.size());
  const auto work = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < genomes.size();) {
      try {
        out[i] = evaluator.evaluate(genomes[i]);
      } catch (const std::exception& e) {
        errors[i] = e.what();
      }
    }
  };
  const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(std::max(1, workers)), genomes.size());
  std::vector<std::thread> threads;
  for (std::size_t t = 1; t < n; ++t) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  for (std::size_t i = 0; i < errors.size(); ++i)
    if (!errors[i].empty()) throw Error("fitness evaluation of genome " + std::to_string(i) + ": " + errors[i]);
  return out;
}

OptimiseResult run_optimisation(const OptimiseOptions& options, const EvaluateBatch& evaluate_batch) {
  const Stopwatch total;
  // Everything that can fail cheaply, before the long work.
  if (options.workers < 1) throw Error("optimise: --workers must be at least 1");
  const nlohmann::json settings = settings_json(options);
  const fs::path newest = path_exists(options.out) ? newest_checkpoint(options.out) : fs::path();
  if (!options.resume && !newest.empty())
    throw Error(options.out.string() + ": holds a run already (" + newest.filename().string() +
                "); pass --resume to continue it, or choose another --out");
  if (options.resume && newest.empty())
    throw Error(options.out.string() + ": no generation-NNN.json to resume from (start without --resume)");
  nlohmann::json checkpoint;
  if (options.resume) {
    checkpoint = read_json_file(newest);
    if (!checkpoint.contains("settings") || checkpoint["settings"] != settings)
      throw Error(newest.string() +
                  ": written with other settings (config, seed, dataset or seeds) than this "
                  "run's; resume with the run's own");
  }
  const FitnessSplit split = split_train_list(options.dataset, options.ga, options.seed);
  const FitnessEvaluator evaluator(split, options.ga, options.seed);
  std::error_code ec;
  fs::create_directories(options.out, ec);
  if (ec || !fs::is_directory(options.out))
    throw Error(options.out.string() + ": cannot create the run folder (" + ec.message() + ")");
  write_json(options.out / "split.json", to_json(split));

  GeneticAlgorithm ga = options.resume ? GeneticAlgorithm::from_json(checkpoint.at("ga"), options.ga, newest.string())
                                       : GeneticAlgorithm(options.ga, options.seed, options.seeds);
  std::map<std::string, GenomeEvaluation> cache;
  if (options.resume) {
    try {
      for (const auto& [genome, evaluation] : checkpoint.at("cache").items())
        cache.emplace(genome, evaluation_from_json(evaluation));
    } catch (const nlohmann::json::exception& e) {
      fail_file(newest, std::string("a fitness cache of evaluations (") + e.what() + ")");
    }
    spdlog::info("optimise: resuming {} at generation {} ({} cached evaluations)", newest.string(), ga.generation(),
                 cache.size());
  }
  const EvaluateBatch evaluate =
      evaluate_batch ? evaluate_batch : EvaluateBatch([&](const std::vector<Genome>& genomes) {
        return evaluate_in_threads(evaluator, genomes, options.workers);
      });

  OptimiseResult result;
  // Ctrl-C / SIGTERM: stop after the generation being evaluated, once its
  // checkpoint is written (--resume continues from it).
  const InterruptGuard interrupts;
  Progress progress("optimise", static_cast<std::size_t>(options.ga.generations));
  progress.update(ga.history().size());
  while (!ga.finished()) {
    std::vector<Genome> fresh;
    for (const Genome& g : ga.population()) {
      const std::string key = g.to_string();
      if (cache.count(key) || std::any_of(fresh.begin(), fresh.end(), [&](const Genome& f) { return f == g; })) {
        ++result.cache_hits;
        continue;
      }
      fresh.push_back(g);
    }
    const Stopwatch evaluating;
    const std::vector<GenomeEvaluation> evaluations = evaluate(fresh);
    result.evaluation_seconds += evaluating.elapsed_s();
    result.evaluations += fresh.size();
    for (std::size_t i = 0; i < fresh.size(); ++i) {
      cache[fresh[i].to_string()] = evaluations[i];
      result.describe_seconds += evaluations[i].describe_seconds;
      result.train_seconds += evaluations[i].train_seconds;
      result.validate_seconds += evaluations[i].validate_seconds;
      result.invariance_seconds += evaluations[i].invariance_seconds;
    }
    std::vector<double> objectives;
    for (const Genome& g : ga.population()) objectives.push_back(cache.at(g.to_string()).objective);
    ga.set_objectives(std::move(objectives));
    const GenerationSummary s = ga.summary();
    ga.advance();
    nlohmann::json state{{"version", kRunVersion}, {"settings", settings}, {"ga", ga.to_json()}};
    auto& cached = state["cache"] = nlohmann::json::object();
    for (const auto& [genome, evaluation] : cache) cached[genome] = to_json(evaluation);
    write_json(checkpoint_path(options.out, s.generation), state);
    spdlog::info("optimise: generation {}: best {:.4f} mean {:.4f} worst {:.4f} ({} evaluated, {:.1f} s)", s.generation,
                 s.best, s.mean, s.worst, fresh.size(), evaluating.elapsed_s());
    progress.update(ga.history().size(), "best " + std::to_string(s.best));
    if (interrupt_requested() && !ga.finished()) {
      result.interrupted = true;
      result.generations = static_cast<int>(ga.history().size());
      result.seconds = total.elapsed_s();
      return result;
    }
  }
  progress.finish();

  // The best genome of the whole run (elitism keeps it to the last generation).
  const auto& history = ga.history();
  const auto best =
      std::max_element(history.begin(), history.end(),
                       [](const GenerationSummary& a, const GenerationSummary& b) { return a.best < b.best; });
  result.best = *best;
  result.best_evaluation = cache.at(best->best_genome.to_string());
  result.generations = static_cast<int>(history.size());

  write_text_atomically(options.out / "best.genome", result.best.best_genome.to_string() + "\n");
  nlohmann::json best_json = nlohmann::json::parse(genome_to_json(result.best.best_genome).dump());
  best_json["genome"] = result.best.best_genome.to_string();
  best_json["generation"] = result.best.generation;
  best_json["evaluation"] = to_json(result.best_evaluation);
  write_json(options.out / "best.json", best_json);
  nlohmann::json fitness{{"generations", nlohmann::json::array()}};
  for (const GenerationSummary& s : history)
    fitness["generations"].push_back({{"generation", s.generation},
                                      {"best_fitness", s.best},
                                      {"mean_fitness", s.mean},
                                      {"worst_fitness", s.worst},
                                      {"best_genome", s.best_genome.to_string()}});
  write_json(options.out / "fitness.json", fitness);
  save_fitness_plot(options.out / "fitness.png", history);
  if (options.train_best_model) {
    TrainingOptions training;
    training.datasets = {options.dataset};
    training.genome = result.best.best_genome;
    training.step = options.ga.step;
    training.balance = true;
    training.max_samples = options.ga.max_samples;
    training.seed = options.seed;
    const TrainingRun run = train_model(training);
    save_forest_model(options.out / "best.fsmodel", run.model);
  }
  result.seconds = total.elapsed_s();
  return result;
}

}  // namespace facadeslam::semantics
