#include "semantics/optimiser/ga_options.hpp"

#include "core/config/config_node.hpp"

namespace facadeslam::semantics {

const char* to_string(Selection s) {
  switch (s) {
    case Selection::roulette: return "roulette";
    case Selection::rank: return "rank";
    case Selection::tournament: return "tournament";
    case Selection::stochastic_universal: return "stochastic_universal";
  }
  return "?";
}

const char* to_string(Crossover c) {
  switch (c) {
    case Crossover::one_point: return "one_point";
    case Crossover::two_point: return "two_point";
    case Crossover::uniform: return "uniform";
  }
  return "?";
}

GaOptions load_ga_options(const std::filesystem::path& path) {
  GaOptions o;
  const ConfigNode root = ConfigNode::load_file(path);
  o.population = root.get_int("population", Range::closed(2, 100000), o.population);
  o.generations = root.get_int("generations", Range::closed(1, 100000), o.generations);
  const std::string selection =
      root.get_choice("selection", {"roulette", "rank", "tournament", "stochastic_universal"}, to_string(o.selection));
  o.selection = selection == "roulette"     ? Selection::roulette
                : selection == "rank"       ? Selection::rank
                : selection == "tournament" ? Selection::tournament
                                            : Selection::stochastic_universal;
  o.tournament_size = root.get_int("tournament_size", Range::closed(1, 1000), o.tournament_size);
  const std::string crossover =
      root.get_choice("crossover", {"one_point", "two_point", "uniform"}, to_string(o.crossover));
  o.crossover = crossover == "one_point"   ? Crossover::one_point
                : crossover == "two_point" ? Crossover::two_point
                                           : Crossover::uniform;
  o.crossover_probability = root.get_double("crossover_probability", Range::closed(0, 1), o.crossover_probability);
  o.bit_flip_probability = root.get_double("bit_flip_probability", Range::closed(0, 1), o.bit_flip_probability);
  o.interchange_probability =
      root.get_double("interchange_probability", Range::closed(0, 1), o.interchange_probability);
  o.reverse_probability = root.get_double("reverse_probability", Range::closed(0, 1), o.reverse_probability);
  o.elites = root.get_int("elites", Range::closed(0, 100000), o.elites);
  o.initial_activation_density =
      root.get_double("initial_activation_density", Range::closed(0.001, 1), o.initial_activation_density);
  o.scaling_multiple = root.get_double("scaling_multiple", Range::closed(1, 100), o.scaling_multiple);
  o.plateau_generations = root.get_int("plateau_generations", Range::closed(0, 100000), o.plateau_generations);
  o.plateau_tolerance = root.get_double("plateau_tolerance", Range::closed(0, 1), o.plateau_tolerance);
  o.validation_share = root.get_double("validation_share", Range::closed(0.01, 0.99), o.validation_share);
  o.folds = root.get_int("folds", Range::closed(1, 20), o.folds);
  o.image_cache_mb = static_cast<std::size_t>(
      root.get_int("image_cache_mb", Range::closed(0, 1000000), static_cast<int>(o.image_cache_mb)));
  o.invariance_images = static_cast<std::size_t>(
      root.get_int("invariance_images", Range::closed(1, 1000), static_cast<int>(o.invariance_images)));
  o.max_train_images = static_cast<std::size_t>(root.get_int("max_train_images", Range::closed(0, 1000000), 0));
  o.max_validation_images =
      static_cast<std::size_t>(root.get_int("max_validation_images", Range::closed(0, 1000000), 0));
  o.max_samples = static_cast<std::size_t>(root.get_int("max_samples", Range::closed(0, 100000000), 0));
  o.step = root.get_int("step", Range::closed(1, 1000), o.step);
  o.max_trees = root.get_int("max_trees", Range::closed(0, 10000), o.max_trees);
  o.max_depth = root.get_int("max_depth", Range::closed(0, 1000), o.max_depth);
  if (const auto w = root.optional_child("fitness")) {
    FitnessWeights& f = o.weights;
    f.overall = w->get_double("overall", Range::closed(0, 100), f.overall);
    f.average = w->get_double("average", Range::closed(0, 100), f.average);
    f.invariance = w->get_double("invariance", Range::closed(0, 100), f.invariance);
    f.time = w->get_double("time", Range::closed(0, 100), f.time);
    f.target_time_ratio = w->get_double("target_time_ratio", Range::closed(0.001, 100), f.target_time_ratio);
    f.size = w->get_double("size", Range::closed(0, 100), f.size);
    w->finish();
  }
  if (const auto c = root.optional_child("cost_model")) read_cost_model(*c, o.cost_model);
  root.finish();
  if (o.elites >= o.population)
    root.fail("elites", "fewer than the population (" + std::to_string(o.population) + ")", std::to_string(o.elites));
  if (o.tournament_size > o.population)
    root.fail("tournament_size", "at most the population (" + std::to_string(o.population) + ")",
              std::to_string(o.tournament_size));
  return o;
}

}  // namespace facadeslam::semantics
