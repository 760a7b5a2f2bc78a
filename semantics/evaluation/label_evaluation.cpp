#include "semantics/evaluation/label_evaluation.hpp"

#include <cmath>

#include <spdlog/spdlog.h>

#include "core/map/semantic_classes.hpp"
#include "core/util/error.hpp"
#include "core/util/progress.hpp"
#include "semantics/evaluation/facade_dataset.hpp"
#include "semantics/evaluation/labelled_keypoints.hpp"
#include "semantics/evaluation/model_training.hpp"
#include "semantics/forest/forest_model.hpp"
#include "semantics/forest/random_forest.hpp"
#include "semantics/point_descriptors/forest_votes.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"
#include "semantics/text.hpp"
#include "core/util/stopwatch.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kClasses = static_cast<int>(kSemanticClasses.size());

std::vector<LabelledImage> first(std::vector<LabelledImage> images, std::size_t count) {
  if (count > 0 && images.size() > count) images.resize(count);
  return images;
}

void test_forest(const std::vector<LabelledImage>& images, const LabelEvaluationOptions& options,
                 PointDescriptor& descriptor, const RandomForest& forest, LabelEvaluation& result) {
  Progress progress("testing", images.size());
  const ClassifiedImages c = classify_labelled_images(
      images, options.step, descriptor, forest, result.confusion,
      [&](std::size_t i, const LoadedLabelledImage&, const LabelledKeypoints&, double) { progress.update(i + 1); },
      load_labelled_image, options.context_scale, options.keypoints);
  result.unlabelled_keypoints += c.unlabelled;
  result.test_keypoints += c.keypoints;
  result.test_extraction_seconds += c.extraction_seconds;
  result.forest_seconds += c.forest_seconds;
}

Json metrics_json(const ClassMetrics& m) {
  Json j = Json::object();
  j["tp"] = static_cast<unsigned long long>(m.tp);
  j["fp"] = static_cast<unsigned long long>(m.fp);
  j["fn"] = static_cast<unsigned long long>(m.fn);
  j["tn"] = static_cast<unsigned long long>(m.tn);
  j["accuracy"] = m.accuracy;
  j["precision"] = m.precision;
  j["recall"] = m.recall;
  j["specificity"] = m.specificity;
  j["npv"] = m.npv;
  j["f1"] = m.f1;
  return j;
}

Json per_class_counts(const std::vector<std::size_t>& counts) {
  Json j = Json::object();
  const auto names = evaluation_class_names();
  for (std::size_t k = 0; k < counts.size() && k < names.size(); ++k)
    j[names[k]] = static_cast<unsigned long long>(counts[k]);
  return j;
}

}  // namespace

double LabelEvaluation::extraction_ms_per_image() const {
  return test_images ? 1e3 * test_extraction_seconds / static_cast<double>(test_images) : std::nan("");
}

double LabelEvaluation::forest_ms_per_image() const {
  return test_images ? 1e3 * forest_seconds / static_cast<double>(test_images) : std::nan("");
}

ClassifiedImages classify_labelled_images(const std::vector<LabelledImage>& images, int step,
                                          PointDescriptor& descriptor, const RandomForest& forest,
                                          ConfusionMatrix& confusion, const AfterImage& after_image,
                                          const LabelledImageLoader& load, double context_scale,
                                          KeypointSource keypoints) {
  ClassifiedImages out;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const LoadedLabelledImage loaded = load(images[i]);
    const LabelledKeypoints kps = keypoints == KeypointSource::corners
                                      ? labelled_keypoints(loaded.label, corner_keypoints(loaded.bgr))
                                      : labelled_keypoints(loaded.label, step);
    out.unlabelled += kps.unlabelled;
    out.keypoints += kps.points.size();
    double extraction_s = 0.0;
    if (!kps.points.empty()) {
      Stopwatch stage;
      std::vector<int> predicted;
      if (context_scale > 0.0) {
        // The worker's sum of votes at full size and at the context scale;
        // timed as a whole as extraction.
        cv::Mat shares = forest_vote_shares(descriptor, forest, loaded.bgr, kps.points, 1.0);
        shares += forest_vote_shares(descriptor, forest, loaded.bgr, kps.points, context_scale);
        extraction_s = stage.elapsed_s();
        out.extraction_seconds += extraction_s;
        for (int r = 0; r < shares.rows; ++r) {
          cv::Point best;
          cv::minMaxLoc(shares.row(r), nullptr, nullptr, nullptr, &best);
          predicted.push_back(forest.classes()[static_cast<std::size_t>(best.x)]);
        }
      } else {
        const cv::Mat rows = descriptor.compute(loaded.bgr, kps.points);
        extraction_s = stage.elapsed_s();
        out.extraction_seconds += extraction_s;
        stage.restart();
        predicted = forest.predict(rows);
        out.forest_seconds += stage.elapsed_s();
      }
      for (std::size_t k = 0; k < predicted.size(); ++k) confusion.add(kps.classes[k], predicted[k]);
    }
    if (after_image) after_image(i, loaded, kps, extraction_s);
  }
  return out;
}

std::vector<std::string> evaluation_class_names() {
  std::vector<std::string> names;
  for (const SemanticClass& c : kSemanticClasses) names.emplace_back(c.name);
  return names;
}

LabelEvaluation evaluate_labels(const LabelEvaluationOptions& options) {
  const Stopwatch start;
  TrainingOptions training;
  training.datasets = {options.dataset};
  training.descriptor = options.descriptor;
  training.genome = options.genome;
  training.step = options.step;
  training.balance = options.balance;
  training.max_train_images = options.max_train_images;
  training.max_samples = options.max_samples;
  training.seed = options.seed;
  training.grey = options.grey;
  training.keypoints = options.keypoints;
  // Everything that can be checked cheaply is checked before the long work:
  // the test list here, the rest by train_model().
  const std::vector<LabelledImage> test =
      with_views(first(read_facade_split(options.dataset, "test.txt"), options.max_test_images), {1.0}, options.grey);
  const TrainingRun run = train_model(training);

  if (!options.model_out.empty()) {
    save_forest_model(options.model_out, run.model);
    spdlog::info("wrote {}", options.model_out.string());
  }

  const std::unique_ptr<PointDescriptor> descriptor = make_point_descriptor(options.descriptor, options.genome);
  LabelEvaluation result;
  result.descriptor = std::string(descriptor->name());
  result.descriptor_width = descriptor->width();
  result.genome = options.genome;
  result.forest = run.model.params;
  result.train_images = run.train_images;
  result.test_images = test.size();
  result.train_keypoints = run.set.keypoints;
  result.train_samples = run.set.samples;
  result.train_keypoints_per_class = run.set.keypoints_per_class;
  result.train_samples_per_class = run.set.samples_per_class;
  result.unlabelled_keypoints = run.set.unlabelled_keypoints;
  result.train_extraction_seconds = run.set.extraction_seconds;
  result.training_seconds = run.training_seconds;
  result.confusion = ConfusionMatrix(kClasses);
  test_forest(test, options, *descriptor, run.model.forest, result);
  result.total_seconds = start.elapsed_s();
  return result;
}

LabelEvaluation evaluate_model(const LabelEvaluationOptions& options, const std::filesystem::path& model_file) {
  const Stopwatch start;
  if (options.step < 1) throw Error(cat("evaluate labels: the grid step must be at least 1, got ", options.step));
  const std::vector<LabelledImage> test =
      with_views(first(read_facade_split(options.dataset, "test.txt"), options.max_test_images), {1.0}, options.grey);
  const Stopwatch loading;
  const ForestModel model = load_forest_model(model_file);
  const double load_ms = 1e3 * loading.elapsed_s();
  std::unique_ptr<PointDescriptor> descriptor;
  try {
    descriptor = make_point_descriptor(model.descriptor, model.genome);
  } catch (const Error& e) {
    fail_file(model_file, cat("the model's descriptor cannot be made: ", e.what()));
  }
  check_forest_model(model_file, model,
                     {model.descriptor, descriptor->width(), model.genome, labelmefacade_class_table()});
  const ModelImages tested = options.grey ? ModelImages::grey : ModelImages::colour;
  if (model.images != ModelImages::unknown && model.images != tested)
    fail_file(model_file, cat("a model trained on ", model_images_name(model.images), " images, tested on ",
                              model_images_name(tested), " ones (", options.grey ? "drop --grey" : "add --grey", ")"));
  spdlog::info("loaded {}: {} trees, {} nodes, in {:.1f} ms", model_file.string(), model.forest.tree_count(),
               model.forest.nodes().size(), load_ms);

  LabelEvaluation result;
  result.descriptor = std::string(descriptor->name());
  result.descriptor_width = descriptor->width();
  result.genome = model.genome;
  result.forest = model.params;
  result.model = model_file;
  result.test_images = test.size();
  result.confusion = ConfusionMatrix(kClasses);
  test_forest(test, options, *descriptor, model.forest, result);
  result.total_seconds = start.elapsed_s();
  return result;
}

Json to_json(const LabelEvaluation& r, const LabelEvaluationOptions& o) {
  Json j = Json::object();
  // Training facts are unknown (null) for a model read from a file.
  const bool trained = r.model.empty();
  const auto if_trained = [trained](Json value) { return trained ? std::move(value) : Json(); };
  j["dataset"] = o.dataset.string();
  j["model"] = trained ? Json() : Json(r.model.string());
  j["descriptor"] = r.descriptor;
  j["descriptor_width"] = r.descriptor_width;
  j["genome"] = r.genome.to_string();
  j["keypoints"] = keypoint_source_name(o.keypoints);
  j["grid_step"] = o.step;
  j["grid_border"] = kDefaultGridBorder;
  j["balance"] = if_trained(o.balance);
  j["grey"] = o.grey;
  j["context_scale"] = o.context_scale;
  j["max_samples"] = if_trained(static_cast<unsigned long long>(o.max_samples));
  j["seed"] = static_cast<unsigned long long>(r.forest.seed);
  Json forest = Json::object();
  forest["trees"] = r.forest.trees;
  forest["max_depth"] = r.forest.max_depth;
  forest["split_variables"] = r.forest.split_variables;
  forest["min_sample_count"] = r.forest.min_sample_count;
  j["forest"] = std::move(forest);
  j["train_images"] = if_trained(static_cast<unsigned long long>(r.train_images));
  j["test_images"] = static_cast<unsigned long long>(r.test_images);
  j["train_keypoints"] = if_trained(static_cast<unsigned long long>(r.train_keypoints));
  j["train_samples"] = if_trained(static_cast<unsigned long long>(r.train_samples));
  j["test_keypoints"] = static_cast<unsigned long long>(r.test_keypoints);
  j["unlabelled_keypoints"] = static_cast<unsigned long long>(r.unlabelled_keypoints);
  j["train_keypoints_per_class"] = if_trained(per_class_counts(r.train_keypoints_per_class));
  j["train_samples_per_class"] = if_trained(per_class_counts(r.train_samples_per_class));

  j["overall_recognition_rate"] = r.confusion.overall_recognition_rate();
  j["average_recognition_rate"] = r.confusion.average_recognition_rate();
  const auto names = evaluation_class_names();
  Json per_class = Json::object();
  for (int k = 0; k < r.confusion.classes(); ++k) {
    Json m = metrics_json(r.confusion.metrics(k));
    m["test_keypoints"] = static_cast<unsigned long long>(r.confusion.truth_count(k));
    per_class[names[static_cast<std::size_t>(k)]] = std::move(m);
  }
  j["per_class"] = std::move(per_class);
  Json matrix = Json::object();
  Json class_list = Json::array();
  for (const auto& n : names) class_list.push_back(n);
  matrix["classes"] = std::move(class_list);
  Json rows = Json::array();
  for (int t = 0; t < r.confusion.classes(); ++t) {
    Json row = Json::array();
    for (int p = 0; p < r.confusion.classes(); ++p)
      row.push_back(static_cast<unsigned long long>(r.confusion.at(t, p)));
    rows.push_back(std::move(row));
  }
  matrix["rows_true_columns_predicted"] = std::move(rows);
  j["confusion_matrix"] = std::move(matrix);

  j["extraction_ms_per_image"] = r.extraction_ms_per_image();
  j["extraction_us_per_keypoint"] =
      r.test_keypoints ? 1e6 * r.test_extraction_seconds / static_cast<double>(r.test_keypoints) : std::nan("");
  j["forest_ms_per_image"] = r.forest_ms_per_image();
  j["forest_us_per_keypoint"] =
      r.test_keypoints ? 1e6 * r.forest_seconds / static_cast<double>(r.test_keypoints) : std::nan("");
  j["train_extraction_seconds"] = if_trained(r.train_extraction_seconds);
  j["training_seconds"] = if_trained(r.training_seconds);
  j["total_seconds"] = r.total_seconds;
  return j;
}

}  // namespace facadeslam::semantics
