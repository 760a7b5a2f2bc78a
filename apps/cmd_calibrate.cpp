// `facadeslam calibrate`: chessboard images -> camera YAML (+ coverage and
// residual PNG, optional JSON report). The work is in calib/; this file
// only maps options onto a CalibrationRequest and writes the outputs.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "apps/output_kinds.hpp"
#include "calib/calibrate.hpp"
#include "calib/calibration_report.hpp"
#include "calib/residual_plot.hpp"
#include "core/util/error.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/output_policy.hpp"
#include "core/util/json.hpp"

namespace facadeslam::apps {
// Named, so that a unity build can hold every command's Options and run().
namespace calibrate_command {
namespace {

struct Options {
  std::filesystem::path images, out, plot, json;
  std::string board = "9x6";
  double square = 0.025;
  std::string model = "pinhole";
  bool fix_aspect = false;
  bool fix_k3 = false;
  double max_edge_width = calib::QualityThresholds{}.max_edge_width_px;
  double duplicate_fraction = calib::QualityThresholds{}.duplicate_fraction;
};

// camera.yaml -> camera_coverage.png beside it.
std::filesystem::path default_plot_path(const std::filesystem::path& out) {
  std::filesystem::path plot = out;
  plot.replace_filename(out.stem().string() + "_coverage.png");
  return plot;
}

void run(const Options& o) {
  calib::CalibrationRequest request;
  request.images = o.images;
  request.board = calib::parse_board_size(o.board, o.square);
  request.model = calib::parse_model_kind(o.model);
  request.fit.fix_aspect = o.fix_aspect;
  request.fit.fix_k3 = o.fix_k3;
  request.quality.max_edge_width_px = o.max_edge_width;
  request.quality.duplicate_fraction = o.duplicate_fraction;

  // Every output can be written before the images are read; the plot is
  // written before the camera file, so that a failed plot leaves no
  // camera.yaml behind. Each replaces only a file of its kind calibrate
  // wrote, none lies among the images (it would be read as one next time).
  if (o.out.extension() != ".yaml")
    fail_file(o.out,
              "--out: expected a camera file name ending in .yaml (the plot goes beside it as "
              "NAME_coverage.png)");
  const std::filesystem::path plot = o.plot.empty() ? default_plot_path(o.out) : o.plot;
  OutputPlan plan;
  plan.input_folder_read_whole(o.images, "--images");
  plan.output_file(o.out, "--out", calibrated_camera_kind());
  plan.output_file(plot, o.plot.empty() ? "the coverage plot (beside --out)" : "--plot", png_picture_kind());
  plan.output_file(o.json, "--json", calibration_report_kind());
  plan.check();
  require_writable_output(o.out);
  require_writable_output(plot);
  if (!o.json.empty()) require_writable_output(o.json);

  // Ctrl-C, SIGTERM, SIGHUP end the run at once: nothing is written before
  // the end, and a file being written is removed (core/util/interrupt.hpp).
  const InterruptGuard interrupts(InterruptResponse::end_at_once);
  const calib::CalibrationRun run = calib::run_calibration(request);
  std::fputs(calib::format_report(run).c_str(), stdout);
  std::fflush(stdout);

  calib::save_residual_plot(plot, run.views, run.result, run.coverage);
  calib::write_camera_file(o.out, run);
  std::printf("wrote %s\nwrote %s\n", o.out.string().c_str(), plot.string().c_str());
  if (!o.json.empty()) {
    Json report = calib::report_json(run);
    report["camera_file"] = o.out.string();
    report["plot"] = plot.string();
    write_json(o.json, report);
    std::printf("wrote %s\n", o.json.string().c_str());
  }
}

// CLI11 validator: "" when `text` is a valid WxH board size, else the reason.
std::string check_board_size(const std::string& text) {
  try {
    calib::parse_board_size(text, 1.0);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

// CLI11's PositiveNumber prints the whole double range in its message.
std::string check_positive_length(const std::string& text) {
  double value = 0.0;
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(value) || value <= 0.0) return "'" + text + "': expected a number > 0";
  return {};
}

}  // namespace
}  // namespace calibrate_command

void add_calibrate_command(CLI::App& app) {
  using namespace calibrate_command;
  auto options = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "calibrate",
      "Calibrate a camera from chessboard images: writes a camera YAML, a coverage/residual PNG and a report");
  cmd->add_option("--images", options->images,
                  "Folder of chessboard images (.png/.jpg/.jpeg/.bmp, same size; at least " +
                      std::to_string(calib::kMinimumViews) + " usable, 10-20 varied views recommended)")
      ->required();
  cmd->add_option("--out", options->out,
                  "Camera YAML to write, NAME.yaml (the format of configs/camera/*.yaml); replaces only a camera file "
                  "calibrate wrote")
      ->required()
      ->check(kNonEmptyPath);
  cmd->add_option("--board", options->board, "Inner corners per row x per column, WxH (a 10 x 7 squares board is 9x6)")
      ->check(CLI::Validator(check_board_size, "WxH", "board size"))
      ->capture_default_str();
  cmd->add_option("--square", options->square,
                  "Side of one square in metres (scales the board poses only; intrinsics do not depend on it)")
      ->check(CLI::Validator(check_positive_length, "METRES", "square size"))
      ->capture_default_str();
  cmd->add_option("--model", options->model, "Camera model: pinhole (OpenCV radial-tangential) or atan (PTAM FOV)")
      ->check(CLI::IsMember({"pinhole", "atan"}))
      ->capture_default_str();
  cmd->add_flag("--fix-aspect", options->fix_aspect, "Fit one focal length, fx = fy (OpenCV's CALIB_FIX_ASPECT_RATIO)");
  cmd->add_flag("--fix-k3", options->fix_k3, "Pinhole: keep k3 = 0 (for few or central views)");
  cmd->add_option("--max-blur", options->max_edge_width,
                  "Reject views whose board edges are wider than this many pixels (10-90 % rise)")
      ->check(CLI::Validator(check_positive_length, "PIXELS", "edge width"))
      ->capture_default_str();
  cmd->add_option("--duplicate-fraction", options->duplicate_fraction,
                  "Reject a view whose corners lie within this fraction of the image diagonal of an accepted view's")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--plot", options->plot, "Coverage/residual PNG to write (default: <out>_coverage.png beside --out)")
      ->check(kNonEmptyPath);
  cmd->add_option("--json", options->json, "Write the full report to this JSON file")->check(kNonEmptyPath);
  cmd->callback([options] { run(*options); });
}

}  // namespace facadeslam::apps
