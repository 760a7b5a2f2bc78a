#pragma once
// Every setting of the genetic optimiser (thesis III.8 and IV.4), loaded from
// a YAML file such as configs/optimise.yaml (`optimise`'s default: these
// defaults with the search's sizes scaled down). Defaults follow the
// issue: 30 genomes x 20 generations, tournament selection, two-point
// crossover, bit-flip / interchange / reverse mutation, two elites, linear
// fitness scaling.
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>

#include "semantics/optimiser/cost_model.hpp"

namespace facadeslam::semantics {

enum class Selection { roulette, rank, tournament, stochastic_universal };
enum class Crossover { one_point, two_point, uniform };

const char* to_string(Selection s);
const char* to_string(Crossover c);

// How a genome's evaluation becomes its objective (higher is better):
//   overall * w_overall + average * w_average + invariance * w_invariance
//   - w_time * max(0, time_ratio / target_time_ratio - 1)
//   - w_size * values / 128
// where time_ratio is the genome's extraction time over cv::SIFT's on the
// same keypoints (0.1: ten times faster) as the cost model puts it
// (cost_model.hpp: calibrated on the bench, not measured during the run) and
// values its descriptor length.
struct FitnessWeights {
  double overall = 0.5;
  double average = 0.5;
  // The mean match rate under a few image changes (rotation, resize, blur,
  // illuminant colour: fitness.hpp) on `invariance_images` validation images.
  double invariance = 0.05;
  double time = 0.1;
  double target_time_ratio = 0.1;
  double size = 0.02;

  friend bool operator==(const FitnessWeights&, const FitnessWeights&) = default;
};

struct GaOptions {
  int population = 30;
  int generations = 20;
  Selection selection = Selection::tournament;
  int tournament_size = 3;
  Crossover crossover = Crossover::two_point;
  double crossover_probability = 0.9;    // P_C: a pair is crossed, else copied
  double bit_flip_probability = 0.01;    // P_M per bit
  double interchange_probability = 0.1;  // per child: two random bits swap places
  double reverse_probability = 0.1;      // per child: a bit and its neighbour swap
  int elites = 2;                        // best genomes copied unchanged
  // Share of the activation bits set in a random first-generation genome
  // (the parameter fields are always uniform). 0.5 is an unbiased draw with
  // ~92 of 185 values on; a fast descriptor has a few, which bit flips at
  // P_M = 0.01 reach only after many generations, so a search for speed
  // starts sparse.
  double initial_activation_density = 0.5;
  // Linear scaling (Goldberg): the best scaled fitness is this multiple of
  // the mean, the mean is kept, nothing goes below zero.
  double scaling_multiple = 2.0;
  // Stop early when the best objective has not improved by more than
  // `plateau_tolerance` for this many generations (0: never).
  int plateau_generations = 0;
  double plateau_tolerance = 1e-4;
  // Share of train.txt's images held out for validation (never test.txt).
  double validation_share = 0.25;
  // Cross-validation: with folds >= 2, train.txt is cut into that many parts
  // and a genome is scored on each part by a forest trained on the others
  // (one confusion matrix over all), instead of on one held-out share. The
  // score is then measured on every training image, not a quarter of them:
  // with ~25 validation images a genome's rate moves by ~1 point with the
  // draw, and the GA's best is the one the draw favoured most.
  int folds = 1;
  // Validation images the invariance term is measured on (when its weight is > 0).
  std::size_t invariance_images = 2;
  // Memory for the split's images decoded once and shared by every
  // evaluation (facade_dataset.hpp, DecodedImageCache), MB; 0: decode per use.
  std::size_t image_cache_mb = 2048;
  // Images and keypoints per fitness evaluation (0: all).
  std::size_t max_train_images = 0, max_validation_images = 0, max_samples = 0;
  int step = 9;  // grid step of the keypoints
  // Forest size cap during the search (0: the genome's own), to keep an
  // evaluation affordable; the winner's model is trained at its own size.
  int max_trees = 0, max_depth = 0;
  FitnessWeights weights;
  // The time term's per-module costs (the `cost_model:` block).
  CostModel cost_model;

  friend bool operator==(const GaOptions&, const GaOptions&) = default;
};

// Throws Error naming the file and key for unknown keys and bad values.
GaOptions load_ga_options(const std::filesystem::path& path);
// Every setting with what it means, as YAML load_ga_options reads back
// (`facadeslam config --dump optimise`; configs/optimise.yaml is its own dump).
void write_ga_settings(std::ostream& out, const GaOptions& options);

}  // namespace facadeslam::semantics
