#include "apps/cmd_evaluate_labels.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/genome_option.hpp"
#include "core/util/error.hpp"
#include "apps/output_kinds.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/json.hpp"
#include "core/util/output_policy.hpp"
#include "core/util/path_checks.hpp"
#include "semantics/evaluation/confusion_plot.hpp"
#include "semantics/evaluation/label_comparison.hpp"
#include "semantics/evaluation/label_evaluation.hpp"
#include "semantics/forest/forest_model.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::apps {
// Named, so that a unity build can hold every command's Options and run().
namespace labels_command {
namespace {

using semantics::Genome;

struct Options {
  semantics::LabelEvaluationOptions evaluation;
  std::vector<std::string> descriptors{"modular"};  // several: one run each, same keypoints and forest settings
  std::string genome;                               // text, file or empty (thesis genome)
  std::filesystem::path json, confusion;
  std::filesystem::path model;  // test this model file instead of training
  std::string keypoints = "grid";
};

std::string percent(double v) {
  if (!std::isfinite(v)) return "   -  ";
  char text[32];
  std::snprintf(text, sizeof text, "%6.2f", 100.0 * v);
  return text;
}

void print_summary(const semantics::LabelEvaluation& r) {
  if (r.model.empty())
    std::printf(
        "label evaluation: %s (%d values), %zu training / %zu test images, %zu training rows, %zu test keypoints\n",
        r.descriptor.c_str(), r.descriptor_width, r.train_images, r.test_images, r.train_samples, r.test_keypoints);
  else
    std::printf(
        "label evaluation of %s: %s (%d values), %d trees of depth <= %d, %zu test images, %zu test keypoints\n",
        r.model.string().c_str(), r.descriptor.c_str(), r.descriptor_width, r.forest.trees, r.forest.max_depth,
        r.test_images, r.test_keypoints);
  std::printf("  overall recognition rate  %s %%\n", percent(r.confusion.overall_recognition_rate()).c_str());
  std::printf("  average recognition rate  %s %%\n", percent(r.confusion.average_recognition_rate()).c_str());
  std::printf("  %-12s %8s %9s %8s %10s\n", "class", "recall", "precision", "f1", "keypoints");
  const auto names = semantics::evaluation_class_names();
  for (int k = 0; k < r.confusion.classes(); ++k) {
    const semantics::ClassMetrics m = r.confusion.metrics(k);
    std::printf("  %-12s %8s %9s %8s %10llu\n", names[static_cast<std::size_t>(k)].c_str(), percent(m.recall).c_str(),
                percent(m.precision).c_str(), percent(m.f1).c_str(),
                static_cast<unsigned long long>(r.confusion.truth_count(k)));
  }
  if (r.model.empty())
    std::printf("  extraction %.1f ms/image, forest %.1f ms/image, training %.1f s, total %.1f s\n",
                r.extraction_ms_per_image(), r.forest_ms_per_image(), r.training_seconds, r.total_seconds);
  else
    std::printf("  extraction %.1f ms/image, forest %.1f ms/image, total %.1f s\n", r.extraction_ms_per_image(),
                r.forest_ms_per_image(), r.total_seconds);
  std::fflush(stdout);
}

// With several descriptors each gets its own confusion PNG: NAME_<descriptor>.png.
std::filesystem::path confusion_path(const Options& o, const std::string& descriptor, bool several) {
  if (!several) return o.confusion;
  std::filesystem::path p = o.confusion;
  return p.replace_filename(o.confusion.stem().string() + "_" + descriptor + ".png");
}

void save_confusion(const std::filesystem::path& path, const semantics::LabelEvaluation& result) {
  char title[200];
  std::snprintf(title, sizeof title, "%s: overall %.1f %%, average %.1f %% (%zu test images)",
                result.descriptor.c_str(), 100.0 * result.confusion.overall_recognition_rate(),
                100.0 * result.confusion.average_recognition_rate(), result.test_images);
  semantics::save_confusion_matrix_png(path, result.confusion, semantics::evaluation_class_names(), title);
  spdlog::info("wrote {}", path.string());
}

void write_report(const Options& o, const Json& report) {
  write_json(o.json, report);
  spdlog::info("wrote {}", o.json.string());
}

// --model: the model's own descriptor, genome and forest on test.txt.
void run_model(const Options& o) {
  const semantics::LabelEvaluation result = semantics::evaluate_model(o.evaluation, o.model);
  print_summary(result);
  if (!o.confusion.empty()) save_confusion(o.confusion, result);
  if (!o.json.empty()) write_report(o, semantics::to_json(result, o.evaluation));
}

void run(Options& o) {
  o.evaluation.keypoints = semantics::parse_keypoint_source(o.keypoints, "--keypoints");
  // Output names and locations are checked now, not after an hour of
  // training: every output can be written (so that --model-out is not
  // written when --confusion or --json would fail after it).
  if (!o.confusion.empty() && o.confusion.extension() != ".png")
    fail_file(o.confusion, "expected a file name ending in .png for the confusion matrix");
  const std::vector<std::string> descriptors =
      o.model.empty() ? semantics::expand_descriptor_names(o.descriptors) : std::vector<std::string>{};
  const bool several = descriptors.size() > 1;
  // Each output replaces only a file of its kind this program wrote, and
  // none is an input (`--json DATASET/test.txt`): output_policy.hpp.
  OutputPlan plan;
  for (const char* list : {"train.txt", "test.txt"})
    plan.input(o.evaluation.dataset / list, "--dataset's " + std::string(list));
  plan.input_folder_read_whole(o.evaluation.dataset / "images", "--dataset's images/");
  plan.input_folder_read_whole(o.evaluation.dataset / "labels", "--dataset's labels/");
  plan.input(o.model, "--model");
  if (is_existing_file(o.genome)) plan.input(o.genome, "--genome");
  plan.output_file(o.json, "--json", label_evaluation_kind());
  if (!o.confusion.empty() && o.model.empty())
    for (const std::string& name : descriptors)
      plan.output_file(confusion_path(o, name, several), "--confusion", png_picture_kind());
  else
    plan.output_file(o.confusion, "--confusion", png_picture_kind());
  plan.output_file(o.evaluation.model_out, "--model-out", model_out_kind());
  plan.check();
  if (!o.json.empty()) require_writable_output(o.json);
  // Nothing is written before the end: Ctrl-C, SIGTERM and SIGHUP end the
  // run at once (a file being written is removed: core/util/interrupt.hpp).
  const InterruptGuard interrupts(InterruptResponse::end_at_once);
  if (!o.model.empty()) {
    if (!o.confusion.empty()) require_writable_output(o.confusion);
    run_model(o);
    return;
  }
  o.evaluation.genome = resolve_genome(o.genome);
  if (!o.confusion.empty())
    for (const std::string& name : descriptors) require_writable_output(confusion_path(o, name, several));
  if (!o.evaluation.model_out.empty()) {
    semantics::require_model_file_name(o.evaluation.model_out);
    if (several) throw Error("--model-out: a model file holds one descriptor's forest; give one --descriptor");
    require_writable_output(o.evaluation.model_out);
  }
  std::vector<semantics::LabelEvaluation> results;
  Json reports = Json::array();
  for (const std::string& name : descriptors) {
    o.evaluation.descriptor = name;
    results.push_back(semantics::evaluate_labels(o.evaluation));
    print_summary(results.back());
    if (several) reports.push_back(semantics::to_json(results.back(), o.evaluation));
  }
  if (several) std::printf("\n%s", semantics::comparison_table(results).c_str());
  // The outputs together at the end: a signal while they are written waits
  // for them, one before leaves the earlier ones as they were.
  const AbortDeferral all_outputs;
  if (!o.confusion.empty())
    for (std::size_t i = 0; i < descriptors.size(); ++i)
      save_confusion(confusion_path(o, descriptors[i], several), results[i]);
  if (!o.json.empty()) {
    Json report = several ? Json::object() : semantics::to_json(results.front(), o.evaluation);
    if (several) {
      report["comparison"] = semantics::comparison_json(results);
      report["runs"] = std::move(reports);
    }
    write_report(o, report);
  }
}

}  // namespace
}  // namespace labels_command

void add_evaluate_labels_command(CLI::App& evaluate) {
  using namespace labels_command;
  auto options = std::make_shared<Options>();
  auto& e = options->evaluation;
  auto* cmd = evaluate.add_subcommand(
      "labels",
      "Train a random forest on a LabelMeFacade-style dataset's train.txt and report keypoint labelling on test.txt");
  cmd->add_option("--dataset", e.dataset, "Dataset folder: train.txt, test.txt, images/, labels/")->required();
  std::vector<std::string> names(std::begin(semantics::kPointDescriptorNames),
                                 std::end(semantics::kPointDescriptorNames));
  names.emplace_back("all");
  auto* descriptor_option =
      cmd->add_option(
             "--descriptor", options->descriptors,
             "Descriptors to evaluate (comma-separated or repeated), or all: one run each on the same keypoints "
             "and training sample with the same forest settings, then a comparison table; with several, the "
             "JSON holds {comparison, runs} and --confusion NAME.png becomes NAME_<descriptor>.png")
          ->delimiter(',')
          ->check(CLI::IsMember(names))
          ->capture_default_str();
  auto* genome_option = cmd->add_option(
      "--genome", options->genome,
      "Modular-descriptor genome and forest settings: a genome file (0/1 text or .json) or the 211-character "
      "0/1 string (default: the thesis' best genome)");
  cmd->add_option("--step", e.step, "Grid step in pixels")->check(CLI::Range(1, 10000))->capture_default_str();
  cmd->add_flag("--grey", e.grey,
                "Train and test on the photos turned grey (three equal channels, as a grey camera's frames reach "
                "the semantic worker): the figures of a grey model");
  cmd->add_option("--keypoints", options->keypoints,
                  "Keypoints trained and tested on: grid (the thesis' regular grid, --step) or corners (FAST "
                  "corners at full and half resolution: where the map's points are)")
      ->check(CLI::IsMember({"grid", "corners"}))
      ->capture_default_str();
  cmd->add_option("--context-scale", e.context_scale,
                  "Also classify each keypoint in the image shrunk to this scale and add the votes, as the semantic "
                  "worker does (configs/semantics.yaml context_scale, 0.25); 0 = full size only")
      ->check(CLI::Range(0.0, 0.9))
      ->capture_default_str();
  auto* balance_option =
      cmd->add_flag("--balance", e.balance,
                    "Class-balanced training sample: every class sampled to the median class size (rare classes "
                    "oversampled, common ones subsampled)");
  auto* max_train_option =
      cmd->add_option("--max-train", e.max_train_images, "Use only the first N images of train.txt (0 = all)")
          ->check(whole_number(0, kMaxCount))
          ->capture_default_str();
  cmd->add_option("--max-test", e.max_test_images, "Use only the first N images of test.txt (0 = all)")
      ->check(whole_number(0, kMaxCount))
      ->capture_default_str();
  auto* max_samples_option =
      cmd->add_option("--max-samples", e.max_samples, "At most N training keypoints, drawn at random (0 = all)")
          ->check(whole_number(0, kMaxCount))
          ->capture_default_str();
  auto* seed_option = cmd->add_option("--seed", e.seed, "Seed of the training-sample draw and of the forest")
                          ->check(whole_number(0, kMaxSeed))
                          ->capture_default_str();
  cmd->add_option("--json", options->json, "Write the report to this JSON file")->check(kNonEmptyPath);
  cmd->add_option("--confusion", options->confusion, "Write the confusion matrix to this PNG")->check(kNonEmptyPath);
  auto* model_out_option =
      cmd->add_option("--model-out", e.model_out,
                      "Save the trained forest (model.fsmodel, or model.yml.gz for OpenCV's own format)")
          ->check(kNonEmptyPath);
  // A model file fixes the descriptor, genome and forest: the training
  // options would be silently ignored, so they are refused.
  cmd->add_option("--model", options->model,
                  "Test this trained model (.fsmodel from `facadeslam train`) on test.txt instead of training one")
      ->excludes(descriptor_option)
      ->excludes(genome_option)
      ->excludes(balance_option)
      ->excludes(max_train_option)
      ->excludes(max_samples_option)
      ->excludes(seed_option)
      ->excludes(model_out_option);
  cmd->callback([options] { run(*options); });
}

}  // namespace facadeslam::apps
