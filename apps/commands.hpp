#pragma once
// Each subcommand of `facadeslam` lives in its own cmd_*.cpp and registers
// itself on the top-level CLI11 app here. Handlers throw facadeslam::Error on
// bad input; main() turns that into one line on stderr and exit code 1.
#include <CLI/CLI.hpp>

namespace facadeslam::apps {

void add_evaluate_command(CLI::App& app);
void add_calibrate_command(CLI::App& app);
void add_replay_command(CLI::App& app);
void add_synth_command(CLI::App& app);
void add_train_command(CLI::App& app);
void add_optimise_command(CLI::App& app);
void add_render_map_command(CLI::App& app);
void add_config_command(CLI::App& app);

}  // namespace facadeslam::apps
