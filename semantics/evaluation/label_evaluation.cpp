#include "semantics/evaluation/label_evaluation.hpp"

#include <cmath>

#include <spdlog/spdlog.h>

#include "core/map/semantic_classes.hpp"
#include "core/util/error.hpp"
#include "core/util/progress.hpp"
#include "semantics/evaluation/facade_dataset.hpp"
#include "semantics/evaluation/label_image.hpp"
#include "semantics/evaluation/training_sample.hpp"
#include "semantics/forest/forest_model.hpp"
#include "semantics/forest/random_forest.hpp"
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

// The labelled grid keypoints of one image (unknown colours dropped).
struct LabelledKeypoints {
  std::vector<cv::Point2f> points;
  std::vector<std::uint8_t> classes;
  std::size_t unlabelled = 0;
};

LabelledKeypoints labelled_keypoints(const cv::Mat& label, int step) {
  LabelledKeypoints out;
  const std::vector<cv::Point2f> grid = grid_keypoints(label.size(), step);
  const std::vector<std::uint8_t> classes = classes_at(label, grid);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    if (classes[k] == kUnknownClass) {
      ++out.unlabelled;
      continue;
    }
    out.points.push_back(grid[k]);
    out.classes.push_back(classes[k]);
  }
  return out;
}

// Pass 1 over the training images: labels only (photos are read for the
// size check). Pass 2 describes the chosen keypoints.
struct TrainingSet {
  cv::Mat samples;
  std::vector<int> labels;
};

TrainingSet build_training_set(const std::vector<LabelledImage>& images, const LabelEvaluationOptions& options,
                               PointDescriptor& descriptor, LabelEvaluation& result) {
  std::vector<std::vector<cv::Point2f>> points(images.size());
  std::vector<SampleCandidate> candidates;
  result.train_keypoints_per_class.assign(kClasses, 0);
  {
    Progress progress("reading training labels", images.size());
    for (std::size_t i = 0; i < images.size(); ++i) {
      const LoadedLabelledImage loaded = load_labelled_image(images[i]);
      LabelledKeypoints kps = labelled_keypoints(loaded.label, options.step);
      result.unlabelled_keypoints += kps.unlabelled;
      for (std::size_t k = 0; k < kps.points.size(); ++k) {
        candidates.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k), kps.classes[k]});
        ++result.train_keypoints_per_class[kps.classes[k]];
      }
      points[i] = std::move(kps.points);
      progress.update(i + 1);
    }
  }
  result.train_keypoints = candidates.size();
  if (candidates.empty()) throw Error("evaluate labels: the training images have no labelled grid keypoint");

  SampleOptions sample_options;
  sample_options.balance = options.balance;
  sample_options.max_samples = options.max_samples;
  sample_options.seed = options.seed;
  const std::vector<SampleCandidate> sample = choose_training_sample(candidates, kClasses, sample_options);
  result.train_samples = sample.size();
  result.train_samples_per_class.assign(kClasses, 0);
  for (const SampleCandidate& c : sample) ++result.train_samples_per_class[c.class_id];
  spdlog::info("training sample: {} of {} labelled keypoints{}", sample.size(), candidates.size(),
               options.balance ? " (class-balanced)" : "");

  TrainingSet set;
  set.samples.create(static_cast<int>(sample.size()), descriptor.width(), CV_32F);
  set.labels.reserve(sample.size());
  Progress progress("describing training images", images.size());
  const Stopwatch start;
  std::size_t row = 0;
  while (row < sample.size()) {
    // The chosen keypoints of one image (sorted, possibly repeated).
    const std::uint32_t image = sample[row].image;
    std::size_t end = row;
    std::vector<cv::Point2f> unique;
    std::vector<int> unique_index;  // per chosen row, its row in `unique`
    while (end < sample.size() && sample[end].image == image) {
      if (end == row || sample[end].keypoint != sample[end - 1].keypoint)
        unique.push_back(points[image][sample[end].keypoint]);
      unique_index.push_back(static_cast<int>(unique.size()) - 1);
      ++end;
    }
    const cv::Mat bgr = load_labelled_image(images[image]).bgr;
    const Stopwatch described;
    const cv::Mat rows = descriptor.compute(bgr, unique);
    result.train_extraction_seconds += described.elapsed_s();
    for (std::size_t r = row; r < end; ++r) {
      rows.row(unique_index[r - row]).copyTo(set.samples.row(static_cast<int>(r)));
      set.labels.push_back(sample[r].class_id);
    }
    row = end;
    progress.update(image + 1);
  }
  progress.finish();
  spdlog::debug("described the training sample in {:.1f} s", start.elapsed_s());
  return set;
}

void test_forest(const std::vector<LabelledImage>& images, const LabelEvaluationOptions& options,
                 PointDescriptor& descriptor, const RandomForest& forest, LabelEvaluation& result) {
  Progress progress("testing", images.size());
  for (std::size_t i = 0; i < images.size(); ++i) {
    const LoadedLabelledImage loaded = load_labelled_image(images[i]);
    const LabelledKeypoints kps = labelled_keypoints(loaded.label, options.step);
    result.unlabelled_keypoints += kps.unlabelled;
    result.test_keypoints += kps.points.size();
    if (!kps.points.empty()) {
      Stopwatch stage;
      const cv::Mat rows = descriptor.compute(loaded.bgr, kps.points);
      result.test_extraction_seconds += stage.elapsed_s();
      stage.restart();
      const std::vector<int> predicted = forest.predict(rows);
      result.forest_seconds += stage.elapsed_s();
      for (std::size_t k = 0; k < predicted.size(); ++k) result.confusion.add(kps.classes[k], predicted[k]);
    }
    progress.update(i + 1);
  }
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
  for (std::size_t k = 0; k < counts.size() && k < names.size(); ++k) j[names[k]] = static_cast<unsigned long long>(counts[k]);
  return j;
}

}  // namespace

double LabelEvaluation::extraction_ms_per_image() const {
  return test_images ? 1e3 * test_extraction_seconds / static_cast<double>(test_images) : std::nan("");
}

double LabelEvaluation::forest_ms_per_image() const {
  return test_images ? 1e3 * forest_seconds / static_cast<double>(test_images) : std::nan("");
}

std::vector<std::string> evaluation_class_names() {
  std::vector<std::string> names;
  for (const SemanticClass& c : kSemanticClasses) names.emplace_back(c.name);
  return names;
}

LabelEvaluation evaluate_labels(const LabelEvaluationOptions& options) {
  const Stopwatch start;
  if (options.step < 1) throw Error(cat("evaluate labels: the grid step must be at least 1, got ", options.step));
  // Everything that can be checked cheaply is checked before the long work.
  const std::vector<LabelledImage> train = first(read_facade_split(options.dataset, "train.txt"), options.max_train_images);
  const std::vector<LabelledImage> test = first(read_facade_split(options.dataset, "test.txt"), options.max_test_images);
  const std::unique_ptr<PointDescriptor> descriptor = make_point_descriptor(options.descriptor, options.genome);

  LabelEvaluation result;
  result.descriptor = std::string(descriptor->name());
  result.descriptor_width = descriptor->width();
  result.forest = forest_params(options.genome.decode());
  result.forest.seed = options.seed;
  result.train_images = train.size();
  result.test_images = test.size();
  result.confusion = ConfusionMatrix(kClasses);

  const TrainingSet set = build_training_set(train, options, *descriptor, result);
  spdlog::info("training the forest: {} rows x {} values, {} trees of depth <= {}, {} split variables",
               set.samples.rows, set.samples.cols, result.forest.trees, result.forest.max_depth,
               result.forest.split_variables);
  const Stopwatch training;
  const RandomForest forest = RandomForest::train(set.samples, set.labels, result.forest);
  result.training_seconds = training.elapsed_s();

  if (!options.model_out.empty()) {
    ForestModel model;
    model.descriptor = result.descriptor;
    model.genome = options.genome;
    model.classes = labelmefacade_class_table();
    model.forest = forest;
    save_forest_model(options.model_out, model);
    spdlog::info("wrote {}", options.model_out.string());
  }

  test_forest(test, options, *descriptor, forest, result);
  result.total_seconds = start.elapsed_s();
  return result;
}

Json to_json(const LabelEvaluation& r, const LabelEvaluationOptions& o) {
  Json j = Json::object();
  j["dataset"] = o.dataset.string();
  j["descriptor"] = r.descriptor;
  j["descriptor_width"] = r.descriptor_width;
  j["genome"] = o.genome.to_string();
  j["grid_step"] = o.step;
  j["grid_border"] = kDefaultGridBorder;
  j["balance"] = o.balance;
  j["max_samples"] = static_cast<unsigned long long>(o.max_samples);
  j["seed"] = static_cast<unsigned long long>(o.seed);
  Json forest = Json::object();
  forest["trees"] = r.forest.trees;
  forest["max_depth"] = r.forest.max_depth;
  forest["split_variables"] = r.forest.split_variables;
  forest["min_sample_count"] = r.forest.min_sample_count;
  j["forest"] = std::move(forest);
  j["train_images"] = static_cast<unsigned long long>(r.train_images);
  j["test_images"] = static_cast<unsigned long long>(r.test_images);
  j["train_keypoints"] = static_cast<unsigned long long>(r.train_keypoints);
  j["train_samples"] = static_cast<unsigned long long>(r.train_samples);
  j["test_keypoints"] = static_cast<unsigned long long>(r.test_keypoints);
  j["unlabelled_keypoints"] = static_cast<unsigned long long>(r.unlabelled_keypoints);
  j["train_keypoints_per_class"] = per_class_counts(r.train_keypoints_per_class);
  j["train_samples_per_class"] = per_class_counts(r.train_samples_per_class);

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
    for (int p = 0; p < r.confusion.classes(); ++p) row.push_back(static_cast<unsigned long long>(r.confusion.at(t, p)));
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
  j["train_extraction_seconds"] = r.train_extraction_seconds;
  j["training_seconds"] = r.training_seconds;
  j["total_seconds"] = r.total_seconds;
  return j;
}

}  // namespace facadeslam::semantics
