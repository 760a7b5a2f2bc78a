#include "apps/cmd_evaluate_invariance.hpp"
#include "apps/cmd_evaluate_labels.hpp"
#include "apps/cmd_evaluate_trajectory.hpp"
#include "apps/commands.hpp"

namespace facadeslam::apps {

void add_evaluate_command(CLI::App& app) {
  auto* evaluate = app.add_subcommand(
      "evaluate", "Evaluate trajectories and labels against ground truth, and descriptor invariance");
  evaluate->require_subcommand(1);
  add_evaluate_trajectory_command(*evaluate);
  add_evaluate_labels_command(*evaluate);
  add_evaluate_invariance_command(*evaluate);
}

}  // namespace facadeslam::apps
