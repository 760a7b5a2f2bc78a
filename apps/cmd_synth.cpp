// `facadeslam synth`: render a synthetic street sequence (colour, labels,
// depth, ground-truth trajectory) from a scene file.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "apps/output_kinds.hpp"
#include "core/util/error.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/output_policy.hpp"
#include "core/util/progress.hpp"
#include "core/util/staged_folder.hpp"
#include "sequences/synth/scene_loader.hpp"
#include "sequences/synth/synthesize.hpp"

namespace facadeslam::apps {
// Named, so that a unity build can hold every command's Options and run().
namespace synth_command {
namespace {

struct SynthCliOptions {
  std::filesystem::path scene, out, contact_sheet;
  std::optional<int> frames, seed;
  std::optional<double> fps, noise;
  std::string resolution;
  int sheet_frames = 6;
};

// Thrown from the progress callback after Ctrl-C: the frame loop stops.
struct Interrupted {};

void run(const SynthCliOptions& o) {
  // The command line first (exit code 2), then the scene and the output
  // locations, all before the first frame.
  std::optional<std::pair<int, int>> resolution;
  if (!o.resolution.empty()) {
    try {
      resolution = parse_image_size(o.resolution, "--resolution");
    } catch (const Error& e) {
      throw CLI::ValidationError(e.what());
    }
  }
  require_readable_file(o.scene, "a scene YAML file (see configs/scenes/)");
  // --out replaces only an earlier synth output, never the scene's own
  // folder or photos; the contact sheet only a picture (output_policy.hpp).
  OutputPlan plan;
  plan.input(o.scene, "--scene");
  plan.output_folder(o.out, "--out", synth_folder_layout());
  plan.output_file(o.contact_sheet, "--contact-sheet", png_picture_kind());
  plan.check();
  synth::SceneSpec spec = synth::load_scene(o.scene);
  // Command-line overrides, each checked as the scene file's keys are.
  if (o.frames) spec.frames = *o.frames;
  if (o.fps) spec.fps = *o.fps;
  if (o.seed) spec.seed = static_cast<std::uint64_t>(*o.seed);
  if (o.noise) spec.noise_sigma = *o.noise;
  if (resolution) spec.camera = spec.camera.resized(resolution->first, resolution->second);
  if (o.frames || o.fps) synth::check_trajectory_covers_frames(spec, "--frames/--fps");

  // The sequence is rendered into a staging folder beside --out and moved
  // into place at the end: a failed or interrupted run leaves the previous
  // sequence as it was, never frames of two runs (core/util/staged_folder.hpp).
  // The scene's camera and photos, known once it is read, are inputs too.
  plan.input(spec.camera_file, "the scene's camera");
  plan.input(spec.photo_root, "the scene's photos");
  plan.check();
  StagedFolder staged(o.out);
  if (!o.contact_sheet.empty() && !staged.contains(o.contact_sheet)) require_writable_output(o.contact_sheet);

  spdlog::info("synth: rendering {} frames of {} ({}x{}) into {}", spec.frames, o.scene.string(), spec.camera.width(),
               spec.camera.height(), o.out.string());
  Progress progress("synth", static_cast<std::size_t>(spec.frames));
  synth::SynthOptions options;
  options.contact_sheet = staged.staged(o.contact_sheet);
  options.contact_sheet_frames = o.sheet_frames;
  const InterruptGuard interrupts;
  options.progress = [&progress](int done) {
    if (interrupt_requested()) throw Interrupted{};
    progress.update(static_cast<std::size_t>(done));
  };
  synth::SynthSummary summary;
  try {
    summary = synth::synthesize_sequence(spec, staged.path(), options);
  } catch (const Interrupted&) {
    progress.finish();
    std::fprintf(stderr, "facadeslam: synth interrupted: %s left as it was\n", o.out.string().c_str());
    throw CLI::RuntimeError(interrupt_exit_code());
  }
  staged.commit();
  progress.finish();
  std::printf("synth: %d frames in %.1f s (%.1f frames/s, %s) -> %s\n", summary.frames, summary.seconds,
              summary.frames / summary.seconds, summary.renderer.c_str(), o.out.string().c_str());
  if (!o.contact_sheet.empty()) std::printf("synth: contact sheet -> %s\n", o.contact_sheet.string().c_str());
  std::fflush(stdout);
}

}  // namespace
}  // namespace synth_command

void add_synth_command(CLI::App& app) {
  using namespace synth_command;
  auto o = std::make_shared<SynthCliOptions>();
  auto* cmd = app.add_subcommand(
      "synth", "Render a synthetic street sequence from real facade photos: colour, labels, depth, ground truth");
  cmd->add_option("--scene", o->scene, "Scene YAML file (configs/scenes/*.yaml)")->required();
  cmd->add_option("--out", o->out,
                  "Output folder (replaced as a whole at the end: a new or empty folder, or an earlier synth output)")
      ->required()
      ->check(kNonEmptyPath);
  cmd->add_option("--frames", o->frames, "Number of frames (overrides the scene's `frames`)")
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--fps", o->fps, "Frames per second (overrides the scene's `fps`)")->check(CLI::Range(0.1, 1000.0));
  cmd->add_option("--seed", o->seed, "Random seed (overrides the scene's `seed`); same seed, same bytes")
      ->check(CLI::Range(0, 2147483647));
  cmd->add_option("--noise", o->noise, "Pixel noise sigma in 8-bit units (overrides the scene's `noise`)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--resolution", o->resolution,
                  "Image size WIDTHxHEIGHT (default: the scene's; the camera is rescaled)");
  cmd->add_option("--contact-sheet", o->contact_sheet, "Also write a contact sheet PNG of a few frames and labels")
      ->check(kNonEmptyPath);
  cmd->add_option("--sheet-frames", o->sheet_frames, "Frames on the contact sheet")
      ->check(CLI::Range(1, 32))
      ->capture_default_str();
  cmd->callback([o] { run(*o); });
}

}  // namespace facadeslam::apps
