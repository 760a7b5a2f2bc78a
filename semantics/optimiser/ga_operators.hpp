#pragma once
// The genetic operators of thesis III.8.3 on 211-bit genomes, written from
// the thesis (Goldberg's simple GA): linear fitness scaling, the four
// selections, the three crossovers and the three mutations. Pure functions
// of their inputs and the random generator.
#include <cstddef>
#include <utility>
#include <vector>

#include "semantics/descriptor/genome.hpp"
#include "semantics/optimiser/ga_options.hpp"
#include "semantics/optimiser/ga_random.hpp"

namespace facadeslam::semantics {

// Objectives (higher is better; -infinity for an invalid genome) to
// fitness for selection (Goldberg 1989, "prescale"): objectives are shifted
// so the worst valid one is 0, then mapped linearly so that the mean stays
// and the best is `multiple` x the mean, unless that would take the worst
// below 0, in which case the worst goes to 0. Invalid genomes get 0; a
// population of equal objectives gets equal fitness.
std::vector<double> scale_linearly(const std::vector<double>& objectives, double multiple);

// `count` parent indices drawn by `options.selection` from `fitness` (>= 0).
std::vector<std::size_t> select_parents(const std::vector<double>& fitness, std::size_t count, const GaOptions& options,
                                        GaRandom& rng);

// Two children of `a` and `b` by `kind` (one-point and two-point cut
// between bits 1 and N-1; uniform draws a mask).
std::pair<Genome::Bits, Genome::Bits> cross(const Genome::Bits& a, const Genome::Bits& b, Crossover kind,
                                            GaRandom& rng);

// Bit flips (each bit with bit_flip_probability), then with their
// probabilities one interchange (two random bits swap places) and one
// reversal (a random bit and the next swap places).
void mutate(Genome::Bits& bits, const GaOptions& options, GaRandom& rng);

}  // namespace facadeslam::semantics
