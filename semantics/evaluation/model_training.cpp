#include "semantics/evaluation/model_training.hpp"

#include <iterator>
#include <memory>

#include <spdlog/spdlog.h>

#include "core/map/semantic_classes.hpp"
#include "core/util/elapsed_indicator.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "semantics/forest/fsmodel_format.hpp"
#include "semantics/forest/random_forest.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

Json counts_by_class_name(const std::vector<std::size_t>& counts) {
  Json j = Json::object();
  for (std::size_t k = 0; k < counts.size() && k < kSemanticClasses.size(); ++k)
    j[std::string(kSemanticClasses[k].name)] = static_cast<unsigned long long>(counts[k]);
  return j;
}

}  // namespace

ForestParams training_forest_params(const TrainingOptions& options) {
  ForestParams params = forest_params(options.genome.decode());
  if (options.trees < 0 || options.max_depth < 0)
    throw Error(cat("training: trees and depth must be positive (0 = the genome's), got ", options.trees, " and ",
                    options.max_depth));
  if (options.trees > 0) params.trees = options.trees;
  if (options.max_depth > 0) params.max_depth = options.max_depth;
  params.seed = options.seed;
  validate(params);
  return params;
}

TrainingRun train_model(const TrainingOptions& options) {
  const Stopwatch start;
  if (options.step < 1) throw Error(cat("training: the grid step must be at least 1, got ", options.step));
  const ForestParams params = training_forest_params(options);
  if (options.datasets.empty()) throw Error("training: no dataset given");
  std::vector<LabelledImage> images;
  for (const std::filesystem::path& dataset : options.datasets) {
    std::vector<LabelledImage> split = read_facade_split(dataset, "train.txt");
    images.insert(images.end(), std::make_move_iterator(split.begin()), std::make_move_iterator(split.end()));
  }
  if (options.max_train_images > 0 && images.size() > options.max_train_images) images.resize(options.max_train_images);
  const std::size_t photos = images.size();
  if (options.also_grey && options.grey)
    throw Error("training: --also-grey adds grey views to a colour model; a grey model (--grey) has only those");
  std::vector<LabelledImage> views = with_views(images, options.scales, options.grey);
  if (options.also_grey) {
    const std::vector<LabelledImage> grey_views = with_views(images, options.scales, true);
    views.insert(views.end(), grey_views.begin(), grey_views.end());
  }
  images = std::move(views);
  const std::unique_ptr<PointDescriptor> descriptor = make_point_descriptor(options.descriptor, options.genome);

  TrainingSetOptions set_options;
  set_options.step = options.step;
  set_options.keypoints = options.keypoints;
  set_options.balance = options.balance;
  set_options.balance_power = options.balance_power;
  set_options.max_samples = options.max_samples;
  set_options.seed = options.seed;
  TrainingSet set = build_training_set(images, set_options, *descriptor);

  spdlog::info("training the forest: {} rows x {} values, {} trees of depth <= {}, {} split variables",
               set.samples.rows, set.samples.cols, params.trees, params.max_depth, params.split_variables);
  TrainingRun run;
  const Stopwatch training;
  {
    const ElapsedIndicator ticking("training the forest");  // one OpenCV call: no progress to show but the time
    run.model.forest = RandomForest::train(set.samples, set.labels, params);
  }
  run.training_seconds = training.elapsed_s();
  run.model.descriptor = std::string(descriptor->name());
  run.model.genome = options.genome;
  run.model.classes = labelmefacade_class_table();
  run.model.images = options.grey ? ModelImages::grey : ModelImages::colour;
  run.model.params = params;
  run.train_images = photos;
  run.set = std::move(set.stats);
  run.total_seconds = start.elapsed_s();
  return run;
}

Json training_summary_json(const TrainingRun& run, const TrainingOptions& options,
                           const std::filesystem::path& model_file, std::uintmax_t model_bytes) {
  Json j = Json::object();
  j["model"] = model_file.string();
  j["model_bytes"] = static_cast<unsigned long long>(model_bytes);
  j["format_version"] = kFsmodelVersion;
  // One dataset as a string (what earlier summaries hold), several as a list.
  if (options.datasets.size() == 1) {
    j["dataset"] = options.datasets.front().string();
  } else {
    Json datasets = Json::array();
    for (const std::filesystem::path& d : options.datasets) datasets.push_back(d.string());
    j["dataset"] = std::move(datasets);
  }
  j["split"] = "train.txt";
  j["descriptor"] = run.model.descriptor;
  j["descriptor_width"] = run.model.descriptor_width();
  j["genome"] = run.model.genome.to_string();
  Json forest = Json::object();
  forest["trees"] = run.model.params.trees;
  forest["max_depth"] = run.model.params.max_depth;
  forest["split_variables"] = run.model.params.split_variables;
  forest["min_sample_count"] = run.model.params.min_sample_count;
  forest["seed"] = static_cast<unsigned long long>(run.model.params.seed);
  forest["nodes"] = static_cast<unsigned long long>(run.model.forest.nodes().size());
  j["forest"] = std::move(forest);
  j["grid_step"] = options.step;
  j["keypoints"] = keypoint_source_name(options.keypoints);
  j["scales"] = options.scales;
  j["grey"] = options.grey;
  j["also_grey"] = options.also_grey;
  j["balance"] = options.balance;
  if (options.balance) j["balance_power"] = options.balance_power;
  j["max_samples"] = static_cast<unsigned long long>(options.max_samples);
  j["train_images"] = static_cast<unsigned long long>(run.train_images);
  j["train_keypoints"] = static_cast<unsigned long long>(run.set.keypoints);
  j["train_rows"] = static_cast<unsigned long long>(run.set.samples);
  j["train_keypoints_per_class"] = counts_by_class_name(run.set.keypoints_per_class);
  j["train_rows_per_class"] = counts_by_class_name(run.set.samples_per_class);
  j["unlabelled_keypoints"] = static_cast<unsigned long long>(run.set.unlabelled_keypoints);
  j["extraction_seconds"] = run.set.extraction_seconds;
  j["training_seconds"] = run.training_seconds;
  j["total_seconds"] = run.total_seconds;
  return j;
}

}  // namespace facadeslam::semantics
