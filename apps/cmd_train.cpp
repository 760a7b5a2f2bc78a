// `facadeslam train`: trains the random forest of a genome on a
// LabelMeFacade-layout dataset's train.txt and writes the model (.fsmodel)
// with a JSON summary beside it (MODEL.json).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "apps/genome_option.hpp"
#include "core/util/error.hpp"
#include "apps/output_kinds.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/json.hpp"
#include "core/util/output_policy.hpp"
#include "core/util/path_checks.hpp"
#include "semantics/evaluation/model_training.hpp"
#include "semantics/forest/forest_model.hpp"

namespace facadeslam::apps {
namespace train_command {
namespace {

struct Options {
  semantics::TrainingOptions training;
  std::string genome;  // text, file or empty (thesis genome)
  std::filesystem::path out;
  std::string keypoints = "grid";
};

std::filesystem::path summary_path(const std::filesystem::path& model) {
  std::filesystem::path p = model;
  return p.replace_filename(model.filename().string() + ".json");
}

void run(Options& o) {
  // Every input and both outputs are checked before the long work.
  o.training.genome = resolve_genome(o.genome);
  o.training.keypoints = semantics::parse_keypoint_source(o.keypoints, "--keypoints");
  std::string name = o.out.filename().string();
  if (name.size() <= 8 || name.compare(name.size() - 8, 8, ".fsmodel") != 0)
    fail_file(o.out, "expected a model file name ending in .fsmodel");
  const std::filesystem::path summary = summary_path(o.out);
  // The model and its summary replace only an earlier model and summary,
  // never an input (the genome, the dataset's lists): output_policy.hpp.
  OutputPlan plan;
  for (const std::filesystem::path& dataset : o.training.datasets) {
    plan.input(dataset / "train.txt", "--dataset's train.txt");
    plan.input(dataset / "test.txt", "--dataset's test.txt");
    plan.input_folder_read_whole(dataset / "images", "--dataset's images/");
    plan.input_folder_read_whole(dataset / "labels", "--dataset's labels/");
  }
  if (is_existing_file(o.genome)) plan.input(o.genome, "--genome");
  plan.output_file(o.out, "--out", model_file_kind());
  plan.output_file(summary, "the summary (--out's NAME.fsmodel.json)", training_summary_kind());
  plan.check();
  require_writable_output(o.out);
  require_writable_output(summary);
  semantics::training_forest_params(o.training);

  // Training keeps nothing worth writing before its end: Ctrl-C, SIGTERM and
  // SIGHUP end it at once, the previous model untouched (interrupt.hpp).
  const InterruptGuard interrupts(InterruptResponse::end_at_once);
  const semantics::TrainingRun run = semantics::train_model(o.training);
  std::uintmax_t bytes = 0;
  {
    // The model and its summary are one output: a signal while they are
    // written waits until both are in place.
    const AbortDeferral both_or_neither;
    semantics::save_forest_model(o.out, run.model);
    bytes = std::filesystem::file_size(o.out);
    write_json(summary, semantics::training_summary_json(run, o.training, o.out, bytes));
  }
  std::printf("trained %s: %zu rows from %zu images, %d trees of depth <= %d (%zu nodes) in %.1f s\n",
              run.model.descriptor.c_str(), run.set.samples, run.train_images, run.model.params.trees,
              run.model.params.max_depth, run.model.forest.nodes().size(), run.total_seconds);
  std::printf("wrote %s (%.2f MB) and %s\n", o.out.string().c_str(), static_cast<double>(bytes) / 1e6,
              summary.string().c_str());
  std::fflush(stdout);
}

}  // namespace
}  // namespace train_command

void add_train_command(CLI::App& app) {
  using namespace train_command;
  auto options = std::make_shared<Options>();
  auto& t = options->training;
  auto* cmd = app.add_subcommand(
      "train", "Train the random forest of a genome on a LabelMeFacade-style dataset's train.txt and write the model");
  cmd->add_option("--dataset", t.datasets,
                  "Dataset folder: train.txt, images/, labels/ (test.txt is never read); repeat it to train on "
                  "several datasets' train.txt together")
      ->required();
  cmd->add_option("--genome", options->genome,
                  "Modular-descriptor genome and forest settings: a genome file (0/1 text or .json) or the "
                  "211-character 0/1 string (default: the thesis' best genome)");
  auto* balance = cmd->add_flag("--balance", t.balance,
                                "Class-balanced training sample: every class sampled to the median class size");
  cmd->add_option("--balance-power", t.balance_power,
                  "With --balance: 1 = every class alike; below 1 partly, class c gets median * (n_c / median)^(1 - "
                  "P) rows (0.5: halfway between the raw proportions and balance)")
      ->check(CLI::Range(0.01, 1.0))
      ->needs(balance)
      ->capture_default_str();
  cmd->add_option("--max-samples", t.max_samples, "At most N training keypoints, drawn at random (0 = all)")
      ->check(whole_number(0, kMaxCount))
      ->capture_default_str();
  cmd->add_option("--max-train", t.max_train_images, "Use only the first N images of train.txt (0 = all)")
      ->check(whole_number(0, kMaxCount))
      ->capture_default_str();
  cmd->add_option("--step", t.step, "Grid step in pixels")->check(CLI::Range(1, 10000))->capture_default_str();
  cmd->add_option("--keypoints", options->keypoints,
                  "Training keypoints: grid (the thesis' regular grid, --step) or corners (FAST corners at full "
                  "and half resolution: where the map's points are)")
      ->check(CLI::IsMember({"grid", "corners"}))
      ->capture_default_str();
  cmd->add_option("--scales", t.scales,
                  "Scales each training photo is also seen at (comma-separated, e.g. 0.5,1,2): the sample is drawn "
                  "from all of them")
      ->delimiter(',')
      ->check(CLI::Range(0.05, 8.0))
      ->capture_default_str();
  cmd->add_flag("--also-grey", t.also_grey,
                "A colour model that also learns from each photo turned grey (it leans less on colour: CamVid's "
                "dusk drive)");
  cmd->add_flag("--grey", t.grey, "Train on the photos turned grey: a model for grey cameras (KITTI's snippet)");
  cmd->add_option("--seed", t.seed, "Seed of the training-sample draw and of the forest")
      ->check(whole_number(0, kMaxSeed))
      ->capture_default_str();
  cmd->add_option("--trees", t.trees, "Number of trees (default: the genome's)")->check(CLI::Range(1, 10000));
  cmd->add_option("--depth", t.max_depth, "Maximum tree depth (default: the genome's)")->check(CLI::Range(1, 1000));
  cmd->add_option("--out", options->out,
                  "The model file to write (NAME.fsmodel; the summary goes to NAME.fsmodel.json); replaces only an "
                  "earlier model")
      ->required()
      ->check(kNonEmptyPath);
  cmd->callback([options] { run(*options); });
}

}  // namespace facadeslam::apps
