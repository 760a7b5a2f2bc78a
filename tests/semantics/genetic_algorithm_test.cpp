// The genetic optimiser's core (semantics/optimiser): the operators do what
// thesis III.8.3 says, scaling keeps the mean and bounds the best, the GA is
// deterministic and climbs a known objective, and a checkpoint resumes a
// run exactly.
#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <cmath>
#include <limits>
#include <numeric>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/util/error.hpp"
#include "semantics/optimiser/ga_operators.hpp"
#include "semantics/optimiser/genetic_algorithm.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

Genome::Bits ones() { return Genome::Bits().set(); }

TEST(GaOperators, LinearScalingKeepsTheMeanAndMakesTheBestTheMultiple) {
  const std::vector<double> objectives{1.0, 1.1, 1.2, 1.3, 3.0};
  const auto f = scale_linearly(objectives, 2.0);
  // Shifted: 0 0.1 0.2 0.3 2.0, mean 0.52: best 2.0 > 2 x 0.52 -> scaled.
  const double mean = std::accumulate(f.begin(), f.end(), 0.0) / 5.0;
  EXPECT_NEAR(mean, 0.52, 1e-12);
  EXPECT_NEAR(*std::max_element(f.begin(), f.end()), 2.0 * mean, 1e-12);
  EXPECT_GE(*std::min_element(f.begin(), f.end()), 0.0);
  // Ordering kept.
  for (std::size_t i = 1; i < f.size(); ++i) EXPECT_LE(f[i - 1], f[i]);
}

TEST(GaOperators, InvalidGenomesGetZeroAndEqualObjectivesEqualChances) {
  const double bad = -std::numeric_limits<double>::infinity();
  const auto f = scale_linearly({bad, 0.5, 0.7}, 2.0);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_GT(f[2], f[1]);
  const auto same = scale_linearly({0.4, 0.4, bad}, 2.0);
  EXPECT_EQ(same[0], same[1]);
  EXPECT_GT(same[0], 0.0);
  EXPECT_EQ(same[2], 0.0);
}

TEST(GaOperators, EverySelectionFavoursTheFitAndNeverPicksAZero) {
  const std::vector<double> fitness{0.0, 1.0, 3.0};
  for (const Selection s :
       {Selection::roulette, Selection::rank, Selection::tournament, Selection::stochastic_universal}) {
    GaOptions o;
    o.selection = s;
    o.tournament_size = 2;
    GaRandom rng(7);
    const auto picks = select_parents(fitness, 3000, o, rng);
    ASSERT_EQ(picks.size(), 3000u);
    std::vector<int> count(3, 0);
    for (const auto p : picks) ++count[p];
    EXPECT_GT(count[2], count[1]) << to_string(s);
    if (s != Selection::rank && s != Selection::tournament) {
      EXPECT_EQ(count[0], 0) << to_string(s);
    }
    if (s == Selection::stochastic_universal) {
      EXPECT_EQ(count[1], 750);  // evenly spaced pointers: exactly the expected share
      EXPECT_EQ(count[2], 2250);
    }
  }
}

TEST(GaOperators, CrossoversExchangeSegmentsOrMaskedBits) {
  const Genome::Bits a = ones(), b;  // all ones x all zeros
  for (const Crossover kind : {Crossover::one_point, Crossover::two_point, Crossover::uniform}) {
    GaRandom rng(3);
    const auto [c, d] = cross(a, b, kind, rng);
    EXPECT_EQ(c ^ d, ones()) << to_string(kind);  // every bit from one parent each
    EXPECT_GT(c.count(), 0u);
    EXPECT_LT(c.count(), static_cast<std::size_t>(Genome::kBits));
    // One-point: a prefix of a then b's suffix; two-point: one run of b's bits inside.
    std::size_t runs = 0;
    for (int i = 1; i < Genome::kBits; ++i)
      runs += c[static_cast<std::size_t>(i)] != c[static_cast<std::size_t>(i - 1)];
    if (kind == Crossover::one_point) {
      EXPECT_EQ(runs, 1u);
      EXPECT_TRUE(c[0]);
    }
    if (kind == Crossover::two_point) {
      EXPECT_LE(runs, 2u);
    }
  }
}

TEST(GaOperators, MutationsFlipOrMoveBits) {
  GaOptions o;
  o.bit_flip_probability = 1.0;
  o.interchange_probability = 0.0;
  o.reverse_probability = 0.0;
  GaRandom rng(1);
  Genome::Bits bits;
  mutate(bits, o, rng);
  EXPECT_EQ(bits, ones());
  // Interchange and reversal only move bits: the count of ones stays.
  o.bit_flip_probability = 0.0;
  o.interchange_probability = 1.0;
  o.reverse_probability = 1.0;
  Genome::Bits half;
  for (std::size_t i = 0; i < half.size(); i += 2) half.set(i);
  const auto before = half.count();
  for (int k = 0; k < 50; ++k) mutate(half, o, rng);
  EXPECT_EQ(half.count(), before);
}

// Objective: the share of set bits (a known optimum: all ones).
std::vector<double> ones_share(const std::vector<Genome>& population) {
  std::vector<double> out;
  out.reserve(population.size());
  for (const Genome& g : population) out.push_back(static_cast<double>(g.bits().count()) / Genome::kBits);
  return out;
}

TEST(GeneticAlgorithm, ClimbsAKnownObjectiveAndKeepsItsElites) {
  GaOptions o;
  o.population = 20;
  o.generations = 30;
  GeneticAlgorithm ga(o, 11);
  double first_best = -1.0;
  while (true) {
    ga.set_objectives(ones_share(ga.population()));
    if (first_best < 0) first_best = ga.summary().best;
    const double best = ga.summary().best;
    ga.advance();
    // The elite is carried over unchanged.
    EXPECT_EQ(ones_share(ga.population()).front(), best);
    if (ga.finished()) break;
  }
  ASSERT_EQ(ga.history().size(), 30u);
  EXPECT_GT(ga.history().back().best, first_best + 0.1);
  for (std::size_t i = 1; i < ga.history().size(); ++i)
    EXPECT_GE(ga.history()[i].best, ga.history()[i - 1].best);  // elitism: never worse
}

// A sparse first generation: the activation bits are on at the density, the
// parameter fields stay uniform, the given seeds are kept as they are.
TEST(GeneticAlgorithm, TheFirstGenerationCanStartSparse) {
  GaOptions o;
  o.population = 40;
  o.initial_activation_density = 0.05;
  GeneticAlgorithm ga(o, 3, {Genome::thesis_best()});
  EXPECT_EQ(ga.population().front(), Genome::thesis_best());
  double activation = 0, parameter = 0;
  for (std::size_t g = 1; g < ga.population().size(); ++g) {
    const Genome::Bits& bits = ga.population()[g].bits();
    for (int i = 0; i < Genome::kBits; ++i)
      (i < Genome::kParameterBits ? parameter : activation) += bits[static_cast<std::size_t>(i)];
  }
  const double genomes = static_cast<double>(ga.population().size() - 1);
  EXPECT_NEAR(activation / (genomes * (Genome::kBits - Genome::kParameterBits)), 0.05, 0.015);
  EXPECT_NEAR(parameter / (genomes * Genome::kParameterBits), 0.5, 0.06);
}

TEST(GeneticAlgorithm, SameSeedSameRunAndACheckpointResumesExactly) {
  GaOptions o;
  o.population = 12;
  o.generations = 8;
  const auto run = [&](int stop_after, const nlohmann::json* resume_from) {
    GeneticAlgorithm ga = resume_from ? GeneticAlgorithm::from_json(*resume_from, o, "test checkpoint")
                                      : GeneticAlgorithm(o, 5, {Genome::thesis_best()});
    for (int g = 0; !ga.finished() && g < stop_after; ++g) {
      ga.set_objectives(ones_share(ga.population()));
      ga.advance();
    }
    return ga;
  };
  const GeneticAlgorithm whole = run(100, nullptr);
  EXPECT_EQ(whole.history().front().best_genome.to_string().size(), 211u);
  const GeneticAlgorithm again = run(100, nullptr);
  EXPECT_EQ(whole.to_json(), again.to_json());
  // Killed after 3 generations, its checkpoint written as text and read back.
  const nlohmann::json checkpoint = nlohmann::json::parse(run(3, nullptr).to_json().dump());
  const GeneticAlgorithm resumed = run(100, &checkpoint);
  EXPECT_EQ(resumed.to_json(), whole.to_json());
}

TEST(GeneticAlgorithm, RejectsACheckpointOfAnotherRun) {
  GaOptions o;
  o.population = 6;
  nlohmann::json state = GeneticAlgorithm(o, 1).to_json();
  GaOptions other = o;
  other.population = 8;
  EXPECT_THROW(GeneticAlgorithm::from_json(state, other, "x.json"), Error);
  state["rng_state"] = "not a state";
  EXPECT_THROW(GeneticAlgorithm::from_json(state, o, "x.json"), Error);
  EXPECT_THROW(GeneticAlgorithm::from_json(nlohmann::json::object(), o, "x.json"), Error);
}

}  // namespace
}  // namespace facadeslam::semantics

namespace facadeslam::semantics {
namespace {

// Every GA settings file the project ships loads (unknown or malformed keys
// would fail), and the variants differ from the defaults where they say so.
TEST(GaOptions, EveryShippedConfigLoads) {
  const std::filesystem::path configs = "configs";  // tests run from the project root
  int loaded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(configs)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("optimise", 0) != 0 || entry.path().extension() != ".yaml") continue;
    EXPECT_NO_THROW(load_ga_options(entry.path())) << name;
    ++loaded;
  }
  EXPECT_GE(loaded, 3);
  const GaOptions refine = load_ga_options(configs / "optimise-refine.yaml");
  EXPECT_DOUBLE_EQ(refine.weights.average, 0.6);
  EXPECT_DOUBLE_EQ(refine.weights.overall, 0.4);
}

// configs/optimise.yaml is what `facadeslam config --dump optimise --from`
// writes of it (below its own header): every key there, with what it
// means, from the one table that also reads it.
TEST(GaOptions, ShippedConfigIsItsOwnDump) {
  const std::filesystem::path shipped = "configs/optimise.yaml";
  std::ostringstream dump;
  write_ga_settings(dump, load_ga_options(shipped));
  EXPECT_NE(test::read_text(shipped).find(dump.str()), std::string::npos)
      << "configs/optimise.yaml is not its own dump: rewrite it with "
         "`facadeslam config --dump optimise --from configs/optimise.yaml` (keep its header)";
}

// Every setting written is read back to the same value, nested ones included.
TEST(GaOptions, DumpReadsBackToTheSameSettings) {
  // Every setting a value of its own, so that a key bound to a neighbour's
  // member cannot read back equal.
  GaOptions changed;
  changed.population = 17;
  changed.generations = 19;
  changed.selection = Selection::stochastic_universal;
  changed.tournament_size = 4;
  changed.crossover = Crossover::uniform;
  changed.crossover_probability = 0.81;
  changed.bit_flip_probability = 0.0125;
  changed.interchange_probability = 0.21;
  changed.reverse_probability = 0.23;
  changed.elites = 3;
  changed.initial_activation_density = 0.07;
  changed.scaling_multiple = 2.5;
  changed.plateau_generations = 6;
  changed.plateau_tolerance = 0.002;
  changed.validation_share = 0.3;
  changed.folds = 5;
  changed.invariance_images = 7;
  changed.image_cache_mb = 512;
  changed.max_train_images = 11;
  changed.max_validation_images = 13;
  changed.max_samples = 1234;
  changed.step = 8;
  changed.max_trees = 21;
  changed.max_depth = 15;
  changed.weights = {0.41, 0.42, 0.3, 0.14, 0.15, 0.016};
  double cost = 0.001;
  for (double* value :
       {&changed.cost_model.equalise, &changed.cost_model.blur_per_tap, &changed.cost_model.colour_plane,
        &changed.cost_model.angle_plane, &changed.cost_model.edge_distance, &changed.cost_model.gevers_l_plane,
        &changed.cost_model.gevers_c_plane, &changed.cost_model.geusebroek_plane, &changed.cost_model.position,
        &changed.cost_model.statistics_plane, &changed.cost_model.hu, &changed.cost_model.affine,
        &changed.cost_model.gradient_angles, &changed.cost_model.per_value, &changed.cost_model.statistics_exponent,
        &changed.cost_model.moments_exponent, &changed.cost_model.singular_values_exponent,
        &changed.cost_model.gradient_angles_exponent})
    *value = cost += 0.001;
  for (double& value : changed.cost_model.colour_space) value = cost += 0.001;
  for (double& value : changed.cost_model.moments) value = cost += 0.001;
  for (double& value : changed.cost_model.singular_values) value = cost += 0.001;
  for (double& value : changed.cost_model.sift) value = cost += 0.001;
  std::ostringstream first;
  write_ga_settings(first, changed);
  test::TempDir dir;
  test::write_text(dir / "optimise.yaml", first.str());
  EXPECT_EQ(load_ga_options(dir / "optimise.yaml"), changed);
  test::write_text(dir / "bad.yaml", "selection: best\n");
  try {
    load_ga_options(dir / "bad.yaml");
    ADD_FAILURE() << "an unknown selection was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("roulette"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace facadeslam::semantics
