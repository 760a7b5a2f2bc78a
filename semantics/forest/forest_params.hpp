#pragma once
// The random forest's training settings. The genome carries three of them
// (thesis IV.4.1: depth, number of trees, variables tried per split); the
// rest are fixed here so that every descriptor is trained the same way.
#include <cstdint>

#include "semantics/descriptor/descriptor_params.hpp"

namespace facadeslam::semantics {

struct ForestParams {
  int trees = 100;
  int max_depth = 35;
  // Variables drawn at random at each split; clamped to the descriptor width
  // at training time (a 2-value descriptor cannot offer 16).
  int split_variables = 16;
  // A node with fewer samples is not split (OpenCV's default). Smaller values
  // only grow deeper, larger models without changing the votes much.
  int min_sample_count = 10;
  // Seed of the bootstrap samples and split-variable draws: the same data
  // and parameters give the same forest.
  std::uint64_t seed = 1;
};

// Depth, tree count and split-variable count of a decoded genome.
ForestParams forest_params(const DescriptorParams& params);

// Throws Error naming the first field outside a sane range (trees 1..10000,
// depth 1..1000, split variables >= 1, min_sample_count >= 1).
void validate(const ForestParams& params);

}  // namespace facadeslam::semantics
