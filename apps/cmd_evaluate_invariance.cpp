#include "apps/cmd_evaluate_invariance.hpp"

#include <array>
#include <cctype>
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
#include "semantics/invariance/image_list.hpp"
#include "semantics/invariance/invariance_plot.hpp"
#include "semantics/invariance/invariance_report.hpp"
#include "semantics/invariance/invariance_suite.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::apps {
// Named, so that a unity build can hold every command's Options and run().
namespace invariance_command {
namespace {

namespace fs = std::filesystem;
using semantics::kInvarianceCases;

constexpr std::size_t kCaseCount = kInvarianceCases.size();

struct Options {
  std::vector<std::string> images;
  std::size_t max_images = 0;
  std::vector<std::string> descriptors{"all"};
  std::string genome;
  int step = semantics::kDefaultInvarianceStep;
  int margin = semantics::kDefaultInvarianceMargin;
  std::vector<std::string> cases{"all"};
  std::array<std::vector<double>, kCaseCount> values;  // per case; empty = defaults
  fs::path json, plot, plot_dir;
};

std::string option_name(std::string_view case_name) {
  std::string name = "--";
  return name.append(case_name);
}

// "--<option>: <message>" for a bad option value: a bad command line (exit code 2).
[[noreturn]] void fail_option(const std::string& option, const std::string& message) { fail_usage(option, message); }

std::vector<semantics::InvarianceCaseRun> chosen_cases(const Options& o) {
  std::array<bool, kCaseCount> chosen{};
  for (const std::string& name : o.cases) {
    if (name == "all") {
      chosen.fill(true);
      continue;
    }
    try {
      const semantics::InvarianceCase id = semantics::case_by_name(name);
      for (std::size_t k = 0; k < kCaseCount; ++k) chosen[k] = chosen[k] || kInvarianceCases[k].id == id;
    } catch (const Error& e) {
      fail_option("--cases", e.what());
    }
  }
  std::vector<semantics::InvarianceCaseRun> runs;
  for (std::size_t k = 0; k < kCaseCount; ++k) {
    const auto& info = kInvarianceCases[k];
    if (!chosen[k]) {
      if (!o.values[k].empty()) fail_option(option_name(info.name), "values given for a case that --cases leaves out");
      continue;
    }
    semantics::InvarianceCaseRun run{info.id,
                                     o.values[k].empty() ? semantics::default_case_values(info.id) : o.values[k]};
    try {
      semantics::check_case_values(run.id, run.values);
    } catch (const Error& e) {
      // The message starts with the case name, which is the option's name.
      std::string text = "--";
      throw CLI::ValidationError(text.append(e.what()));
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

void run(const Options& o) {
  // Everything cheap is checked before the long run.
  const semantics::Genome genome = resolve_genome(o.genome);
  if (o.step < 1) fail_option("--step", "expected a grid step of at least 1 pixel");
  if (o.margin < 0) fail_option("--margin", "expected a margin of at least 0 pixels");
  semantics::InvarianceOptions options;
  options.step = o.step;
  options.margin = o.margin;
  options.cases = chosen_cases(o);
  std::string plot_extension = o.plot.extension().string();
  for (char& c : plot_extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!o.plot.empty() && plot_extension != ".png")
    fail_file(o.plot, "expected a file name ending in .png for the plot");
  // Every output location, before the long run: each replaces only a file
  // of its kind this program wrote and none is an input (output_policy.hpp).
  OutputPlan plan;
  for (const std::string& input : o.images) {
    if (is_existing_folder(input))
      plan.input_folder_read_whole(input, "--images");
    else
      plan.input(input, "--images");
  }
  if (is_existing_file(o.genome)) plan.input(o.genome, "--genome");
  plan.output_file(o.json, "--json", invariance_report_kind());
  plan.output_file(o.plot, "--plot", png_picture_kind());
  if (!o.plot_dir.empty())
    for (const semantics::InvarianceCaseRun& run : options.cases)
      plan.output_file(o.plot_dir / ("invariance-" + std::string(semantics::case_info(run.id).name) + ".png"),
                       "--plot-dir", png_picture_kind());
  plan.check();
  if (!o.plot.empty()) require_writable_output(o.plot);
  if (!o.json.empty()) require_writable_output(o.json);
  if (!o.plot_dir.empty()) require_creatable_folder(o.plot_dir);
  // Nothing is written before the end: Ctrl-C, SIGTERM and SIGHUP end the
  // run at once (a file being written is removed: core/util/interrupt.hpp).
  const InterruptGuard interrupts(InterruptResponse::end_at_once);

  std::vector<std::unique_ptr<semantics::PointDescriptor>> owned;
  for (const std::string& name : semantics::expand_descriptor_names(o.descriptors)) {
    try {
      owned.push_back(semantics::make_point_descriptor(name, genome));
    } catch (const Error& e) {
      fail_option("--descriptor", e.what());
    }
  }
  std::vector<semantics::PointDescriptor*> descriptors;
  for (const auto& d : owned) descriptors.push_back(d.get());
  const std::vector<fs::path> inputs(o.images.begin(), o.images.end());
  const std::vector<fs::path> images = semantics::list_images(inputs, o.max_images);

  const semantics::InvarianceResult result = semantics::run_invariance(images, descriptors, options);
  std::fputs(semantics::invariance_table(result).c_str(), stdout);
  std::fflush(stdout);
  if (!o.json.empty()) {
    Json report = semantics::to_json(result);
    report["genome"] = genome.to_string();
    write_json(o.json, report);
    spdlog::info("wrote {}", o.json.string());
  }
  if (!o.plot.empty()) {
    semantics::save_invariance_figure(o.plot, result);
    spdlog::info("wrote {}", o.plot.string());
  }
  if (!o.plot_dir.empty())
    for (const fs::path& written : semantics::save_case_plots(o.plot_dir, result))
      spdlog::info("wrote {}", written.string());
}

}  // namespace
}  // namespace invariance_command

void add_evaluate_invariance_command(CLI::App& evaluate) {
  using namespace invariance_command;
  auto options = std::make_shared<Options>();
  auto* cmd = evaluate.add_subcommand(
      "invariance",
      "Match rate of each descriptor between images and changed copies of them (blur, rotation, resize, affine tilts, "
      "light intensity scale and shift, illuminant colour, JPEG)");
  cmd->add_option("--images", options->images,
                  "Image files, folders of images, or .txt lists (one image per line; LabelMeFacade names are looked "
                  "up as images/NAME.jpg beside the list)")
      ->required();
  cmd->add_option("--max-images", options->max_images, "Use only the first N images (0 = all)")
      ->check(whole_number(0, kMaxCount))
      ->capture_default_str();
  std::vector<std::string> names(std::begin(semantics::kPointDescriptorNames),
                                 std::end(semantics::kPointDescriptorNames));
  names.emplace_back("all");
  cmd->add_option("--descriptor", options->descriptors, "Descriptors to compare (comma-separated or repeated), or all")
      ->delimiter(',')
      ->check(CLI::IsMember(names))
      ->capture_default_str();
  cmd->add_option("--genome", options->genome,
                  "Modular-descriptor genome: a genome file (0/1 text or .json) or the 211-character 0/1 string "
                  "(default: the thesis' best genome); also sets the SIFT patch size");
  cmd->add_option("--step", options->step, "Grid step of the reference keypoints in pixels")
      ->check(whole_number(1, 10000))
      ->capture_default_str();
  cmd->add_option("--margin", options->margin,
                  "Pixels around each keypoint that must show the image in both the original and the changed copy")
      ->check(whole_number(0, 10000))
      ->capture_default_str();
  std::string case_list;
  for (const auto& info : kInvarianceCases) case_list.append(case_list.empty() ? "" : ", ").append(info.name);
  cmd->add_option("--cases", options->cases, std::string("Cases to run (comma-separated) or all: ").append(case_list))
      ->delimiter(',')
      ->capture_default_str();
  for (std::size_t k = 0; k < kCaseCount; ++k) {
    const auto& info = kInvarianceCases[k];
    std::string defaults;
    for (const double v : semantics::default_case_values(info.id)) {
      char text[32];
      std::snprintf(text, sizeof text, "%g", v);
      defaults.append(defaults.empty() ? "" : ",").append(text);
    }
    std::string help = std::string(info.title);
    help.append(": values of the ").append(info.parameter).append(" (default ").append(defaults);
    help.append("; negative values as --").append(info.name).append("=-10,0,10)");
    cmd->add_option(option_name(info.name), options->values[k], help)->delimiter(',');
  }
  cmd->add_option("--json", options->json, "Write the report (every case's values and match rates) to this JSON file")
      ->check(kNonEmptyPath);
  cmd->add_option("--plot", options->plot, "Write all cases as panels of one PNG")->check(kNonEmptyPath);
  cmd->add_option("--plot-dir", options->plot_dir, "Write one PNG per case, DIR/invariance-<case>.png")
      ->check(kNonEmptyPath);
  cmd->callback([options] { run(*options); });
}

}  // namespace facadeslam::apps
