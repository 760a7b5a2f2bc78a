#pragma once
// `facadeslam evaluate trajectory`: ATE / RPE and the KITTI benchmark's
// relative errors of an estimated trajectory against ground truth, as a
// table, a JSON report and a top-view plot.
#include <CLI/CLI.hpp>

namespace facadeslam::apps {

// Adds the `trajectory` subcommand to the `evaluate` group.
void add_evaluate_trajectory_command(CLI::App& evaluate);

}  // namespace facadeslam::apps
