#pragma once
// `facadeslam evaluate labels`: train a random forest on LabelMeFacade-style
// training images and report how well it labels the test images' grid
// keypoints, for the modular descriptor or a baseline.
#include <CLI/CLI.hpp>

namespace facadeslam::apps {

// Adds the `labels` subcommand to the `evaluate` group.
void add_evaluate_labels_command(CLI::App& evaluate);

}  // namespace facadeslam::apps
