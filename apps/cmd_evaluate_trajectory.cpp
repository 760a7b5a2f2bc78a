#include "apps/cmd_evaluate_trajectory.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/output_kinds.hpp"
#include "core/trajectory/metrics.hpp"
#include "core/trajectory/top_view.hpp"
#include "core/trajectory/trajectory_io.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/json.hpp"
#include "core/util/output_policy.hpp"

namespace facadeslam::apps {
// Named, so that a unity build can hold every command's Options and run().
namespace trajectory_command {
namespace {

struct Options {
  std::filesystem::path gt, est, gt_times, est_times, json, plot;
  std::string align = "sim3";
  std::string format = "auto";
  std::string plane = "auto";
  double max_dt = kDefaultMaxTimeDifference;
  int rpe_delta = 1;
};

void print_table(const Options& o, const TrajectoryEvaluation& e) {
  std::printf("trajectory evaluation: %s vs %s\n", o.est.string().c_str(), o.gt.string().c_str());
  std::printf("  %-22s %zu (|dt| <= %g s)\n", "pairs", e.pairs, o.max_dt);
  std::printf("  %-22s %s\n", "alignment", o.align.c_str());
  std::printf("  %-22s %.6f\n", "scale", e.scale);
  std::printf("  %-22s %.6f m  (%.3f %% of the path)\n", "ATE RMSE", e.ate_rmse_m, e.ate_percent_of_path);
  std::printf("  %-22s %.6f m\n", "ATE mean", e.ate_mean_m);
  std::printf("  %-22s %.6f m\n", "ATE median", e.ate_median_m);
  std::printf("  %-22s %.6f m\n", "ATE max", e.ate_max_m);
  std::printf("  %-22s %.6f m  (poses %d apart)\n", "RPE translation RMSE", e.rpe_trans_rmse_m, o.rpe_delta);
  std::printf("  %-22s %.6f deg\n", "RPE rotation RMSE", e.rpe_rot_rmse_deg);
  std::printf("  %-22s %.6f m\n", "path length (gt)", e.path_length_m);
  std::fflush(stdout);
}

void run(const Options& o) {
  const TrajectoryFormat format = parse_trajectory_format(o.format);
  EvaluationOptions options;
  options.alignment = parse_alignment_mode(o.align);
  options.max_dt = o.max_dt;
  options.rpe_delta = static_cast<std::size_t>(o.rpe_delta);

  // The outputs replace only an earlier evaluation's files, never an input.
  OutputPlan plan;
  plan.input(o.gt, "--gt");
  plan.input(o.est, "--est");
  plan.input(o.gt_times, "--gt-times");
  plan.input(o.est_times, "--est-times");
  plan.output_file(o.json, "--json", trajectory_evaluation_kind());
  plan.output_file(o.plot, "--plot", png_picture_kind());
  plan.check();
  require_readable_if_present(o.gt, "a trajectory file");
  require_readable_if_present(o.est, "a trajectory file");
  require_readable_if_present(o.gt_times, "a timestamps file");
  require_readable_if_present(o.est_times, "a timestamps file");
  if (!o.json.empty()) require_writable_output(o.json);
  if (!o.plot.empty()) require_writable_output(o.plot);
  const InterruptGuard interrupts(InterruptResponse::end_at_once);

  const Trajectory gt = read_trajectory(o.gt, format, o.gt_times);
  const Trajectory est = read_trajectory(o.est, format, o.est_times);
  spdlog::debug("read {} ground-truth and {} estimated poses", gt.size(), est.size());
  const TrajectoryEvaluation e = evaluate_trajectory(gt, est, options);
  print_table(o, e);

  if (!o.json.empty()) {
    Json report = to_json(e);
    report["alignment"] = o.align;
    report["max_dt"] = o.max_dt;
    report["rpe_delta"] = o.rpe_delta;
    report["gt"] = o.gt.string();
    report["est"] = o.est.string();
    write_json(o.json, report);
    spdlog::info("wrote {}", o.json.string());
  }
  if (!o.plot.empty()) {
    save_top_view_png(o.plot, gt, e, o.plane, o.align, o.max_dt);
    spdlog::info("wrote {}", o.plot.string());
  }
}

}  // namespace
}  // namespace trajectory_command

void add_evaluate_trajectory_command(CLI::App& evaluate) {
  using namespace trajectory_command;
  auto options = std::make_shared<Options>();
  auto* cmd = evaluate.add_subcommand(
      "trajectory", "ATE and RPE of an estimated trajectory against ground truth (TUM or KITTI files)");
  cmd->add_option("--gt", options->gt, "Ground-truth trajectory file")->required();
  cmd->add_option("--est", options->est, "Estimated trajectory file")->required();
  cmd->add_option("--align", options->align, "Alignment before measuring: sim3 (monocular) or se3")
      ->check(CLI::IsMember({"sim3", "se3"}))
      ->capture_default_str();
  cmd->add_option("--format", options->format, "File format of both files: auto (by column count), tum or kitti")
      ->check(CLI::IsMember({"auto", "tum", "kitti"}))
      ->capture_default_str();
  cmd->add_option("--gt-times", options->gt_times, "Timestamps of a KITTI ground truth, one per line");
  cmd->add_option("--est-times", options->est_times, "Timestamps of a KITTI estimate, one per line");
  cmd->add_option("--max-dt", options->max_dt, "Largest time difference of an associated pose pair, seconds")
      ->check(CLI::Range(0.0, 3600.0))
      ->capture_default_str();
  cmd->add_option("--rpe-delta", options->rpe_delta, "RPE over pose pairs this many associated poses apart")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  cmd->add_option("--json", options->json, "Write the figures to this JSON file")->check(kNonEmptyPath);
  cmd->add_option("--plot", options->plot, "Write a top view of both trajectories to this PNG")->check(kNonEmptyPath);
  cmd->add_option("--plane", options->plane,
                  "World plane of the top view: auto (the two axes the ground truth spreads along most), xy, xz or yz")
      ->check(CLI::IsMember({"auto", "xy", "xz", "yz"}))
      ->capture_default_str();
  cmd->callback([options] { run(*options); });
}

}  // namespace facadeslam::apps
