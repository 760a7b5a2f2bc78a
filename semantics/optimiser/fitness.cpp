#include "semantics/optimiser/fitness.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <nlohmann/json.hpp>

#include "core/map/semantic_classes.hpp"
#include "core/util/error.hpp"
#include "core/util/progress.hpp"
#include "core/util/stopwatch.hpp"
#include "semantics/evaluation/confusion_matrix.hpp"
#include "semantics/evaluation/label_evaluation.hpp"
#include "semantics/evaluation/training_set.hpp"
#include "semantics/forest/forest_params.hpp"
#include "semantics/forest/random_forest.hpp"
#include "semantics/invariance/invariance_suite.hpp"
#include "semantics/optimiser/ga_random.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

namespace {

// Keeps the first `max` entries (0: all).
void cap(std::vector<LabelledImage>& images, std::size_t max) {
  if (max > 0 && images.size() > max) images.resize(max);
}

nlohmann::json names(const std::vector<LabelledImage>& images) {
  nlohmann::json list = nlohmann::json::array();
  for (const LabelledImage& image : images) list.push_back(image.name);
  return list;
}

}  // namespace

FitnessSplit split_train_list(const std::filesystem::path& dataset, const GaOptions& options, std::uint64_t seed) {
  std::vector<LabelledImage> all = read_facade_split(dataset, "train.txt");
  // A seeded shuffle (Fisher-Yates with the GA's own draws: the same split
  // with every standard library).
  GaRandom rng(seed ^ 0x5EED5B11ULL);
  for (std::size_t i = all.size(); i > 1; --i) std::swap(all[i - 1], all[uniform_index(rng, i)]);
  FitnessSplit split;
  if (options.folds >= 2) {
    const auto k = static_cast<std::size_t>(options.folds);
    if (all.size() < k)
      throw Error(dataset.string() + ": train.txt lists " + std::to_string(all.size()) + " images, too few for " +
                  std::to_string(k) + " cross-validation folds");
    // Part f holds images f, f + k, f + 2k, ... of the shuffled list.
    for (std::size_t f = 0; f < k; ++f) {
      FitnessFold fold;
      for (std::size_t i = 0; i < all.size(); ++i) (i % k == f ? fold.validation : fold.train).push_back(all[i]);
      cap(fold.validation, options.max_validation_images);
      cap(fold.train, options.max_train_images);
      split.folds.push_back(std::move(fold));
    }
    return split;
  }
  const auto validation =
      static_cast<std::size_t>(std::lround(options.validation_share * static_cast<double>(all.size())));
  if (validation < 1 || validation >= all.size())
    throw Error(dataset.string() + ": train.txt lists " + std::to_string(all.size()) +
                " images, too few to hold out a validation share of " + std::to_string(options.validation_share) +
                " and train on the rest");
  FitnessFold fold;
  fold.validation.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(validation));
  fold.train.assign(all.begin() + static_cast<std::ptrdiff_t>(validation), all.end());
  cap(fold.validation, options.max_validation_images);
  cap(fold.train, options.max_train_images);
  split.folds.push_back(std::move(fold));
  return split;
}

nlohmann::json to_json(const FitnessSplit& split) {
  // One fold: the layout runs have always written.
  if (split.folds.size() == 1)
    return {{"train", names(split.folds[0].train)}, {"validation", names(split.folds[0].validation)}};
  nlohmann::json folds = nlohmann::json::array();
  for (const FitnessFold& fold : split.folds)
    folds.push_back({{"train", names(fold.train)}, {"validation", names(fold.validation)}});
  return {{"folds", folds}};
}

nlohmann::json to_json(const GenomeEvaluation& e) {
  return {{"valid", e.valid},
          {"overall", e.overall},
          {"average", e.average},
          {"time_ratio", e.time_ratio},
          {"values", e.values},
          {"invariance", e.invariance},
          {"objective", std::isfinite(e.objective) ? nlohmann::json(e.objective) : nlohmann::json()},
          {"seconds", e.seconds},
          {"describe_seconds", e.describe_seconds},
          {"train_seconds", e.train_seconds},
          {"validate_seconds", e.validate_seconds},
          {"invariance_seconds", e.invariance_seconds}};
}

GenomeEvaluation evaluation_from_json(const nlohmann::json& j) {
  GenomeEvaluation e;
  e.valid = j.at("valid").get<bool>();
  e.overall = j.at("overall").get<double>();
  e.average = j.at("average").get<double>();
  e.time_ratio = j.at("time_ratio").get<double>();
  e.values = j.at("values").get<int>();
  e.objective =
      j.at("objective").is_null() ? -std::numeric_limits<double>::infinity() : j.at("objective").get<double>();
  e.seconds = j.at("seconds").get<double>();
  e.describe_seconds = j.value("describe_seconds", 0.0);
  e.train_seconds = j.value("train_seconds", 0.0);
  e.validate_seconds = j.value("validate_seconds", 0.0);
  // Checkpoints from before the invariance term: not measured, 0.
  e.invariance = j.value("invariance", 0.0);
  e.invariance_seconds = j.value("invariance_seconds", 0.0);
  return e;
}

double objective_of(const GenomeEvaluation& e, const FitnessWeights& w) {
  if (!e.valid) return -std::numeric_limits<double>::infinity();
  const double slow = std::max(0.0, e.time_ratio / w.target_time_ratio - 1.0);
  return w.overall * e.overall + w.average * e.average + w.invariance * e.invariance - w.time * slow -
         w.size * e.values / 128.0;
}

double FitnessEvaluator::invariance_score(PointDescriptor& descriptor) const {
  std::vector<std::filesystem::path> images;
  for (const LabelledImage& image : split_.folds.front().validation) {
    if (images.size() >= options_.invariance_images) break;
    images.push_back(image.image);
  }
  InvarianceOptions options;
  options.step = options_.step;
  options.cases = {{InvarianceCase::rotation, {20}},
                   {InvarianceCase::resize, {0.75}},
                   {InvarianceCase::blur, {5}},
                   {InvarianceCase::temperature, {3800}}};
  const InvarianceResult result = run_invariance(images, {&descriptor}, options);
  double sum = 0.0;
  int counted = 0;
  for (const InvarianceCaseResult& c : result.cases) {
    const double rate = c.match_rate.front().front();
    if (std::isfinite(rate)) {  // NaN: no keypoint survived the change
      sum += rate;
      ++counted;
    }
  }
  return counted > 0 ? sum / counted : 0.0;
}

namespace {

std::vector<LabelledImage> every_image(const FitnessSplit& split) {
  std::vector<LabelledImage> all;
  for (const FitnessFold& fold : split.folds) {
    all.insert(all.end(), fold.train.begin(), fold.train.end());
    all.insert(all.end(), fold.validation.begin(), fold.validation.end());
  }
  return all;
}

}  // namespace

FitnessEvaluator::FitnessEvaluator(FitnessSplit split, GaOptions options, std::uint64_t seed)
    : split_(std::move(split)),
      images_(std::make_shared<const DecodedImageCache>(every_image(split_), options.image_cache_mb << 20)),
      options_(std::move(options)),
      seed_(seed) {}

GenomeEvaluation FitnessEvaluator::evaluate(const Genome& genome) const {
  const Stopwatch watch;
  const Progress::SilenceOnThisThread quiet;
  GenomeEvaluation e;
  if (genome.active_value_count() == 0) {
    e.objective = objective_of(e, options_.weights);
    return e;
  }
  const std::unique_ptr<PointDescriptor> descriptor = make_point_descriptor("modular", genome);
  e.values = descriptor->width();
  e.time_ratio = modelled_time_ratio(genome.decode(), options_.cost_model);

  TrainingSetOptions set_options;
  set_options.step = options_.step;
  set_options.balance = true;  // the rare classes (door, sky) must count in the average rate
  set_options.max_samples = options_.max_samples;
  set_options.seed = seed_;
  set_options.quiet = true;
  ForestParams params = forest_params(genome.decode());
  if (options_.max_trees > 0) params.trees = std::min(params.trees, options_.max_trees);
  if (options_.max_depth > 0) params.max_depth = std::min(params.max_depth, options_.max_depth);
  params.seed = seed_;

  // Every fold's validation keypoints go into one confusion matrix.
  ConfusionMatrix confusion(static_cast<int>(kSemanticClasses.size()));
  const LabelledImageLoader load = std::cref(*images_);
  for (const FitnessFold& fold : split_.folds) {
    Stopwatch phase;
    const TrainingSet set = build_training_set(fold.train, set_options, *descriptor, load);
    e.describe_seconds += phase.elapsed_s();
    phase.restart();
    const RandomForest forest = RandomForest::train(set.samples, set.labels, params);
    e.train_seconds += phase.elapsed_s();
    phase.restart();
    classify_labelled_images(fold.validation, options_.step, *descriptor, forest, confusion, {}, load);
    e.validate_seconds += phase.elapsed_s();
  }
  if (options_.weights.invariance > 0) {
    const Stopwatch stage;
    e.invariance = invariance_score(*descriptor);
    e.invariance_seconds = stage.elapsed_s();
  }
  e.valid = confusion.total() > 0;
  e.overall = e.valid ? confusion.overall_recognition_rate() : 0.0;
  e.average = e.valid ? confusion.average_recognition_rate() : 0.0;
  e.objective = objective_of(e, options_.weights);
  e.seconds = watch.elapsed_s();
  return e;
}

}  // namespace facadeslam::semantics
