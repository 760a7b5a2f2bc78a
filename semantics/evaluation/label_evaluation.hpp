#pragma once
// The labelling evaluation of thesis IV.5 on a LabelMeFacade-layout
// dataset: grid keypoints on every image, ground truth from the colour
// labels, a random forest trained on the training images' descriptors and
// tested on the test images' (`facadeslam evaluate labels`), or a trained
// model file tested on the test images alone (`evaluate labels --model`).
//
// Keypoints whose label colour is no class colour are skipped and counted
// (unlabelled_keypoints); every descriptor sees exactly the same keypoints.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/util/json.hpp"
#include "semantics/descriptor/genome.hpp"
#include "semantics/evaluation/confusion_matrix.hpp"
#include "semantics/evaluation/corner_keypoints.hpp"
#include "semantics/evaluation/facade_dataset.hpp"
#include "semantics/evaluation/grid_keypoints.hpp"
#include "semantics/evaluation/labelled_keypoints.hpp"
#include "semantics/forest/forest_params.hpp"

namespace facadeslam::semantics {

class PointDescriptor;
class RandomForest;

struct LabelEvaluationOptions {
  std::filesystem::path dataset;
  std::string descriptor = "modular";  // a kPointDescriptorNames entry
  Genome genome = Genome::thesis_best();
  int step = kDefaultGridStep;
  bool balance = false;              // training_sample.hpp
  std::size_t max_train_images = 0;  // first N of train.txt; 0 = all
  std::size_t max_test_images = 0;   // first N of test.txt; 0 = all
  std::size_t max_samples = 0;       // training keypoints cap; 0 = all
  std::uint64_t seed = 1;            // training-sample draw and forest
  std::filesystem::path model_out;   // save the trained forest here when set
  bool grey = false;                 // train and test on the photos turned grey (a grey camera's model)
  // > 0: each test keypoint is classified by the votes at full size plus
  // those in the image shrunk to this scale, as the semantic worker does
  // (configs/semantics.yaml context_scale); 0 = full size only.
  double context_scale = 0.0;
  // Where the keypoints are, in training and test: the thesis' grid (`step`)
  // or FAST corners, where the tracker makes its map points.
  KeypointSource keypoints = KeypointSource::grid;
};

struct LabelEvaluation {
  std::string descriptor;
  int descriptor_width = 0;
  Genome genome;
  ForestParams forest;
  // Empty when the forest was trained in this run; the model file tested
  // otherwise (then the training counts below are unknown: null in JSON).
  std::filesystem::path model;
  std::size_t train_images = 0, test_images = 0;
  std::size_t train_keypoints = 0;  // labelled grid keypoints of the training images
  std::size_t train_samples = 0;    // rows the forest was trained on
  std::vector<std::size_t> train_keypoints_per_class, train_samples_per_class;
  std::size_t test_keypoints = 0;        // labelled grid keypoints of the test images
  std::size_t unlabelled_keypoints = 0;  // skipped (colour of no class), train + test
  ConfusionMatrix confusion{1};
  double train_extraction_seconds = 0, training_seconds = 0;
  double test_extraction_seconds = 0, forest_seconds = 0, total_seconds = 0;

  double extraction_ms_per_image() const;  // test images, all their keypoints
  double forest_ms_per_image() const;
};

// Runs the whole evaluation. Bad input (missing folder or list, an image
// without label, a label of another size, an unknown descriptor, ...) is an
// Error naming the file; checked before the long work starts where possible.
// Shows a progress bar on a terminal (core/util/progress.hpp).
LabelEvaluation evaluate_labels(const LabelEvaluationOptions& options);

// Tests the model file `model` on test.txt without training: its own
// descriptor, genome and forest; `options` gives the dataset, the grid
// step and max_test_images (the training options are not used). A model
// whose class table is not LabelMeFacade's, or whose descriptor width is
// not what its descriptor computes today, is an Error naming the file.
LabelEvaluation evaluate_model(const LabelEvaluationOptions& options, const std::filesystem::path& model);

// The report: options, counts, overall and average recognition rate,
// ("model": the model file, or null when trained in the run)
// per-class tp fp fn tn accuracy precision recall specificity npv f1,
// the confusion matrix and the timings.
Json to_json(const LabelEvaluation& result, const LabelEvaluationOptions& options);

// The test loop shared by `evaluate labels` and the optimiser's fitness:
// each image's keypoints (the grid of `step`, or its FAST corners) described, classified by `forest` and
// counted in `confusion`. `after_image(index, loaded, keypoints,
// extraction_seconds)`, if given, is called for every image once it is
// counted (keypoints may be empty): progress, or timing a peer descriptor on
// the same keypoints.
struct ClassifiedImages {
  std::size_t keypoints = 0, unlabelled = 0;
  double extraction_seconds = 0, forest_seconds = 0;
};
using AfterImage = std::function<void(std::size_t index, const LoadedLabelledImage& loaded,
                                      const LabelledKeypoints& keypoints, double extraction_seconds)>;
ClassifiedImages classify_labelled_images(const std::vector<LabelledImage>& images, int step,
                                          PointDescriptor& descriptor, const RandomForest& forest,
                                          ConfusionMatrix& confusion, const AfterImage& after_image = {},
                                          const LabelledImageLoader& load = load_labelled_image,
                                          double context_scale = 0.0, KeypointSource keypoints = KeypointSource::grid);

// Class names in id order (LabelMeFacade's nine).
std::vector<std::string> evaluation_class_names();

}  // namespace facadeslam::semantics
