#include "apps/cmd_evaluate_trajectory.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/output_kinds.hpp"
#include "core/trajectory/kitti_relative_error.hpp"
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
  double rate = 0.0;  // frames per second of KITTI files without a times file; 0: none given
  int rpe_delta = 1;
};

// A KITTI file carries no times of its own. Two such files pair line by
// line (the devkit's way); paired with a file that has times (TUM, or KITTI
// with a times file or --rate), it needs times too, or every pose would be
// matched by its line number against seconds.
void require_comparable_clocks(const Options& o, TrajectoryFormat gt_format, TrajectoryFormat est_format) {
  const bool gt_untimed = gt_format == TrajectoryFormat::kitti && o.gt_times.empty() && o.rate == 0.0;
  const bool est_untimed = est_format == TrajectoryFormat::kitti && o.est_times.empty() && o.rate == 0.0;
  if (gt_untimed == est_untimed) return;
  const std::string option = gt_untimed ? "--gt-times" : "--est-times";
  const std::string untimed = (gt_untimed ? o.gt : o.est).string();
  const std::string timed = (gt_untimed ? o.est : o.gt).string();
  throw CLI::ValidationError(option, untimed + " is a KITTI pose file without timestamps and " + timed +
                                         " has timestamps: pass " + option +
                                         " FILE (one time per pose, KITTI's times.txt) or --rate HZ");
}

TrajectoryFormat format_of(const std::filesystem::path& path, TrajectoryFormat format) {
  return format == TrajectoryFormat::auto_detect ? detect_trajectory_format(path) : format;
}

void print_kitti_table(const Options& o, const TrajectoryEvaluation& e, const KittiRelativeError& k) {
  std::printf("  KITTI relative error (devkit segments, on the estimate aligned with %s, scale %.6f):\n",
              o.align.c_str(), e.scale);
  if (!k.has_segments()) {
    std::printf("    %s\n", k.no_segments_reason().c_str());
    return;
  }
  std::printf("    %8s %7s %14s %18s\n", "length", "pairs", "translation", "rotation");
  for (const KittiLengthError& l : k.per_length)
    std::printf("    %6.0f m %7zu %12.4f %% %10.4f deg/100 m\n", l.length_m, l.pairs, l.translation_percent,
                l.rotation_deg_per_100m);
  std::printf("    %8s %7zu %12.4f %% %10.4f deg/100 m\n", "all", k.pairs, k.translation_percent,
              k.rotation_deg_per_100m);
}

void print_table(const Options& o, const TrajectoryEvaluation& e, const KittiRelativeError& k) {
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
  print_kitti_table(o, e, k);
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

  require_comparable_clocks(o, format_of(o.gt, format), format_of(o.est, format));
  const Trajectory gt = read_trajectory(o.gt, format, o.gt_times, o.rate);
  const Trajectory est = read_trajectory(o.est, format, o.est_times, o.rate);
  spdlog::debug("read {} ground-truth and {} estimated poses", gt.size(), est.size());
  const TrajectoryEvaluation e = evaluate_trajectory(gt, est, options);
  const KittiRelativeError k = kitti_relative_error_after_alignment(gt, est, e);
  print_table(o, e, k);

  if (!o.json.empty()) {
    Json report = to_json(e);
    Json kitti = to_json(k);
    kitti["estimate_aligned_with"] = o.align;
    report["kitti_relative"] = kitti;
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
      "trajectory",
      "ATE, RPE and KITTI's relative errors of an estimated trajectory against ground truth (TUM or KITTI files)");
  cmd->add_option("--gt", options->gt, "Ground-truth trajectory file")->required();
  cmd->add_option("--est", options->est, "Estimated trajectory file")->required();
  cmd->add_option("--align", options->align, "Alignment before measuring: sim3 (monocular) or se3")
      ->check(CLI::IsMember({"sim3", "se3"}))
      ->capture_default_str();
  cmd->add_option("--format", options->format, "File format of both files: auto (by column count), tum or kitti")
      ->check(CLI::IsMember({"auto", "tum", "kitti"}))
      ->capture_default_str();
  cmd->add_option("--gt-times", options->gt_times, "Timestamps of a KITTI ground truth, one per pose line");
  cmd->add_option("--est-times", options->est_times, "Timestamps of a KITTI estimate, one per pose line");
  cmd->add_option("--rate", options->rate,
                  "Frames per second of the KITTI files without a times file: line i at i / HZ seconds (KITTI: 10)")
      ->type_name("HZ")
      ->check(CLI::Range(1e-6, 1e6));
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
