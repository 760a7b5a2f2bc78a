#include "semantics/optimiser/ga_options.hpp"

#include <ostream>
#include <string>
#include <vector>

#include "core/config/config_node.hpp"
#include "core/config/settings_table.hpp"
#include "core/config/settings_writer.hpp"

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

namespace {

// An enum setting read and written by its names; `read_name` reads the key
// among them (ConfigNode::get_choice with the names, which says what is
// allowed when the file's value is not).
template <class Enum, class ReadName>
void add_enum(SettingsTable<GaOptions>& t, const std::string& key, Enum GaOptions::*member,
              std::initializer_list<Enum> values, ReadName read_name, const std::string& doc) {
  const std::vector<Enum> all(values);
  t.add_custom(
      [key, member, all, read_name](const ConfigNode& node, GaOptions& o) {
        const std::string chosen = read_name(node, key, to_string(o.*member));
        for (const Enum e : all)
          if (chosen == to_string(e)) o.*member = e;
      },
      [key, member, all, doc](SettingsWriter& out, const GaOptions& o) {
        std::string choices;
        for (const Enum e : all) choices += (choices.empty() ? "" : " | ") + std::string(to_string(e));
        out.value(key, to_string(o.*member), doc + ": " + choices);
      });
}

SettingsTable<FitnessWeights> fitness_settings() {
  using F = FitnessWeights;
  SettingsTable<F> t;
  const Range weight = Range::closed(0, 100);
  t.add("overall", &F::overall, "weight of the overall recognition rate on the validation keypoints", weight);
  t.add("average", &F::average, "weight of the average (per-class) recognition rate", weight);
  t.add("invariance", &F::invariance,
        "weight of the mean match rate under a 20 deg rotation, a 0.75 resize, a 5 px blur and a 3800 K illuminant "
        "(evaluate invariance's measure) on invariance_images validation images",
        weight);
  t.add("time", &F::time, "weight of being slower than the target ratio to cv::SIFT", weight);
  t.add("target_time_ratio", &F::target_time_ratio,
        "modelled extraction time / cv::SIFT's on the same keypoints (cost_model) to reach (0.1: 10x faster)",
        Range::closed(0.001, 100));
  t.add("size", &F::size, "weight of the descriptor length (per 128 values, SIFT's length)", weight);
  return t;
}

const SettingsTable<GaOptions>& ga_settings() {
  static const SettingsTable<GaOptions> table = [] {
    using G = GaOptions;
    SettingsTable<G> t;
    t.add("population", &G::population, "genomes per generation (the thesis genome is one of the first)",
          Range::closed(2, 100000));
    t.add("generations", &G::generations, "generations to run", Range::closed(1, 100000));
    add_enum(
        t, "selection", &G::selection,
        {Selection::roulette, Selection::rank, Selection::tournament, Selection::stochastic_universal},
        [](const ConfigNode& node, const std::string& key, const std::string& fallback) {
          return node.get_choice(key, {"roulette", "rank", "tournament", "stochastic_universal"}, fallback);
        },
        "how parents are drawn");
    t.add("tournament_size", &G::tournament_size, "genomes per tournament (tournament selection)",
          Range::closed(1, 1000));
    add_enum(
        t, "crossover", &G::crossover, {Crossover::one_point, Crossover::two_point, Crossover::uniform},
        [](const ConfigNode& node, const std::string& key, const std::string& fallback) {
          return node.get_choice(key, {"one_point", "two_point", "uniform"}, fallback);
        },
        "how two parents' bits are crossed");
    t.add("crossover_probability", &G::crossover_probability, "P_C: a pair of parents is crossed, else copied",
          Range::closed(0, 1));
    t.add("bit_flip_probability", &G::bit_flip_probability, "P_M: each bit of a child flips with this probability",
          Range::closed(0, 1));
    t.add("interchange_probability", &G::interchange_probability,
          "a child has two random bits swap places with this probability", Range::closed(0, 1));
    t.add("reverse_probability", &G::reverse_probability,
          "... and a random bit and its neighbour swap with this probability", Range::closed(0, 1));
    t.add("elites", &G::elites, "best genomes carried over unchanged (fewer than the population)",
          Range::closed(0, 100000));
    t.add("initial_activation_density", &G::initial_activation_density,
          "share of activation bits on in a random first-generation genome (0.5: unbiased, ~92 of 185 values; a "
          "search for a fast descriptor starts sparser, e.g. 0.05)",
          Range::closed(0.001, 1));
    t.add("scaling_multiple", &G::scaling_multiple, "linear fitness scaling: the best gets this multiple of the mean",
          Range::closed(1, 100));
    t.add("plateau_generations", &G::plateau_generations,
          "stop when the best has not improved for this many generations (0: never)", Range::closed(0, 100000));
    t.add("plateau_tolerance", &G::plateau_tolerance, "... by more than this", Range::closed(0, 1));
    t.add("validation_share", &G::validation_share,
          "share of train.txt held out to measure fitness (test.txt is never read)", Range::closed(0.01, 0.99));
    t.add("folds", &G::folds,
          ">= 2: cross-validation instead: train.txt cut into this many parts, each scored by a forest trained on "
          "the others",
          Range::closed(1, 20));
    t.add("invariance_images", &G::invariance_images,
          "validation images the invariance term is measured on (when its weight is > 0)", Range::closed(1, 1000));
    t.add("image_cache_mb", &G::image_cache_mb,
          "memory for the split's images decoded once for every evaluation, MB (~2 MB an image; 0: decode per use)",
          Range::closed(0, 1000000));
    t.add("max_train_images", &G::max_train_images,
          "training images per evaluation, first of the shuffled split (0: all)", Range::closed(0, 1000000));
    t.add("max_validation_images", &G::max_validation_images, "validation images per evaluation (0: all)",
          Range::closed(0, 1000000));
    t.add("max_samples", &G::max_samples, "training keypoints per evaluation, class-balanced draw (0: all)",
          Range::closed(0, 100000000));
    t.add("step", &G::step, "grid step of the keypoints, pixels", Range::closed(1, 1000));
    t.add("max_trees", &G::max_trees,
          "forest size cap during the search (0: the genome's); best.fsmodel uses the genome's own",
          Range::closed(0, 10000));
    t.add("max_depth", &G::max_depth, "tree depth cap during the search (0: the genome's)", Range::closed(0, 1000));
    t.add("fitness", &G::weights, fitness_settings(),
          "objective = overall*w + average*w + invariance*w - time*max(0, ratio/target - 1) - size*values/128");
    t.add("cost_model", &G::cost_model, cost_model_settings(),
          "the time term's ratio, modelled (not measured: a run's results depend on the genomes and the data "
          "only): per-image and per-keypoint costs as shares of cv::SIFT's CPU time on the bench (640x480 facade, "
          "3888 keypoints on a 9-pixel grid, SIFT's patch radius 10, one thread), from "
          "`build/bench/bench_ga_cost_model` (docs/benchmarks.md)");
    t.check([](const ConfigNode& root, const G& o) {
      if (o.elites >= o.population)
        root.fail("elites", "fewer than the population (" + std::to_string(o.population) + ")",
                  std::to_string(o.elites));
      if (o.tournament_size > o.population)
        root.fail("tournament_size", "at most the population (" + std::to_string(o.population) + ")",
                  std::to_string(o.tournament_size));
    });
    return t;
  }();
  return table;
}

}  // namespace

GaOptions load_ga_options(const std::filesystem::path& path) { return ga_settings().load(path); }

void write_ga_settings(std::ostream& out, const GaOptions& options) { ga_settings().write_yaml(out, options); }

}  // namespace facadeslam::semantics
