#include "semantics/optimiser/genetic_algorithm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/util/error.hpp"
#include "semantics/optimiser/ga_operators.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kCheckpointVersion = 1;

Genome random_genome(GaRandom& rng, double activation_density) {
  Genome::Bits bits;
  // 0.5: one random bit per draw (the draws of runs made before the density
  // existed, so their seeds give the same runs).
  const bool unbiased = activation_density == 0.5;
  for (int i = 0; i < Genome::kBits; ++i) {
    const bool parameter = i < Genome::kParameterBits;
    const bool on =
        parameter || unbiased ? (rng() >> 63) != 0 : static_cast<double>(rng() >> 11) * 0x1.0p-53 < activation_density;
    bits.set(static_cast<std::size_t>(i), on);
  }
  return Genome(bits);
}

// Best first; ties go to the earlier genome (deterministic).
std::vector<std::size_t> ranking(const std::vector<double>& objectives) {
  std::vector<std::size_t> order(objectives.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return objectives[a] > objectives[b]; });
  return order;
}

// NaN and infinities do not survive JSON: invalid genomes are null there.
nlohmann::json objective_json(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }
double objective_from(const nlohmann::json& v) {
  return v.is_null() ? -std::numeric_limits<double>::infinity() : v.get<double>();
}

}  // namespace

GeneticAlgorithm::GeneticAlgorithm(const GaOptions& options, std::uint64_t seed, const std::vector<Genome>& seeds)
    : options_(options), rng_(seed) {
  const auto n = static_cast<std::size_t>(options_.population);
  for (std::size_t i = 0; i < std::min(n, seeds.size()); ++i) population_.push_back(seeds[i]);
  while (population_.size() < n) population_.push_back(random_genome(rng_, options_.initial_activation_density));
}

void GeneticAlgorithm::set_objectives(std::vector<double> objectives) {
  if (objectives.size() != population_.size())
    throw Error("genetic algorithm: " + std::to_string(objectives.size()) + " objectives for " +
                std::to_string(population_.size()) + " genomes");
  objectives_ = std::move(objectives);
}

GenerationSummary GeneticAlgorithm::summary() const {
  GenerationSummary s;
  s.generation = generation_;
  if (objectives_.empty()) return s;
  const auto order = ranking(objectives_);
  s.best_genome = population_[order.front()];
  s.best = objectives_[order.front()];
  double sum = 0.0;
  std::size_t valid = 0;
  s.worst = s.best;
  for (const double o : objectives_)
    if (std::isfinite(o)) {
      sum += o;
      ++valid;
      s.worst = std::min(s.worst, o);
    }
  s.mean = valid ? sum / static_cast<double>(valid) : s.best;
  return s;
}

bool GeneticAlgorithm::finished() const {
  if (static_cast<int>(history_.size()) >= options_.generations) return true;
  const auto p = static_cast<std::size_t>(options_.plateau_generations);
  if (p == 0 || history_.size() <= p) return false;
  const double before = history_[history_.size() - 1 - p].best;
  for (std::size_t i = history_.size() - p; i < history_.size(); ++i)
    if (history_[i].best > before + options_.plateau_tolerance) return false;
  return true;
}

void GeneticAlgorithm::advance() {
  if (objectives_.empty()) throw Error("genetic algorithm: advance() before the generation's objectives");
  history_.push_back(summary());
  const std::vector<double> fitness = scale_linearly(objectives_, options_.scaling_multiple);
  const auto n = static_cast<std::size_t>(options_.population);
  std::vector<Genome> next;
  next.reserve(n);
  // Elitism: the best genomes unchanged.
  const auto order = ranking(objectives_);
  for (std::size_t e = 0; e < std::min<std::size_t>(static_cast<std::size_t>(options_.elites), n); ++e)
    next.push_back(population_[order[e]]);
  // Children, two per pair of parents.
  const std::size_t children = n - next.size();
  const std::vector<std::size_t> parents = select_parents(fitness, children + (children % 2), options_, rng_);
  for (std::size_t p = 0; p + 1 < parents.size() && next.size() < n; p += 2) {
    Genome::Bits a = population_[parents[p]].bits(), b = population_[parents[p + 1]].bits();
    if (uniform01(rng_) < options_.crossover_probability) std::tie(a, b) = cross(a, b, options_.crossover, rng_);
    mutate(a, options_, rng_);
    mutate(b, options_, rng_);
    next.emplace_back(a);
    if (next.size() < n) next.emplace_back(b);
  }
  population_ = std::move(next);
  objectives_.clear();
  ++generation_;
}

nlohmann::json GeneticAlgorithm::to_json() const {
  nlohmann::json j;
  j["version"] = kCheckpointVersion;
  j["generation"] = generation_;
  std::ostringstream rng;
  rng << rng_;
  j["rng_state"] = rng.str();
  auto& genomes = j["population"] = nlohmann::json::array();
  for (const Genome& g : population_) genomes.push_back(g.to_string());
  auto& objectives = j["objectives"] = nlohmann::json::array();
  for (const double o : objectives_) objectives.push_back(objective_json(o));
  auto& history = j["history"] = nlohmann::json::array();
  for (const GenerationSummary& s : history_)
    history.push_back({{"generation", s.generation},
                       {"best_fitness", objective_json(s.best)},
                       {"mean_fitness", objective_json(s.mean)},
                       {"worst_fitness", objective_json(s.worst)},
                       {"best_genome", s.best_genome.to_string()}});
  return j;
}

GeneticAlgorithm GeneticAlgorithm::from_json(const nlohmann::json& state, const GaOptions& options,
                                             const std::string& where) {
  GeneticAlgorithm ga(options);
  try {
    if (state.at("version").get<int>() != kCheckpointVersion)
      throw Error(where + ": checkpoint version " + state.at("version").dump() + ", expected " +
                  std::to_string(kCheckpointVersion));
    ga.generation_ = state.at("generation").get<int>();
    std::istringstream rng(state.at("rng_state").get<std::string>());
    rng >> ga.rng_;
    if (!rng) throw Error(where + ": rng_state is not a generator state");
    for (const auto& g : state.at("population")) ga.population_.push_back(Genome::parse(g.get<std::string>(), where));
    for (const auto& o : state.at("objectives")) ga.objectives_.push_back(objective_from(o));
    for (const auto& h : state.at("history")) {
      GenerationSummary s;
      s.generation = h.at("generation").get<int>();
      s.best = objective_from(h.at("best_fitness"));
      s.mean = objective_from(h.at("mean_fitness"));
      s.worst = objective_from(h.at("worst_fitness"));
      s.best_genome = Genome::parse(h.at("best_genome").get<std::string>(), where);
      ga.history_.push_back(s);
    }
  } catch (const nlohmann::json::exception& e) {
    throw Error(where + ": not a genetic-algorithm checkpoint (" + e.what() + ")");
  }
  if (static_cast<int>(ga.population_.size()) != options.population)
    throw Error(where + ": a population of " + std::to_string(ga.population_.size()) + ", the config says " +
                std::to_string(options.population) + " (resume with the run's own config)");
  if (!ga.objectives_.empty() && ga.objectives_.size() != ga.population_.size())
    throw Error(where + ": " + std::to_string(ga.objectives_.size()) + " objectives for " +
                std::to_string(ga.population_.size()) + " genomes");
  return ga;
}

}  // namespace facadeslam::semantics
