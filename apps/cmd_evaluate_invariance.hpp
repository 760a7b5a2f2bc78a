#pragma once
// `facadeslam evaluate invariance`: how well each descriptor finds the same
// keypoint again after blur, rotation, resize, affine tilts, light intensity
// and colour changes and JPEG compression (thesis IV.5).
#include <CLI/CLI.hpp>

namespace facadeslam::apps {

// Adds the `invariance` subcommand to the `evaluate` group.
void add_evaluate_invariance_command(CLI::App& evaluate);

}  // namespace facadeslam::apps
