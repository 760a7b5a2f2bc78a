#pragma once
// Training a forest model on a LabelMeFacade-layout dataset's train.txt
// (never test.txt): `facadeslam train`, and the training half of
// `evaluate labels`.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/util/json.hpp"
#include "semantics/descriptor/genome.hpp"
#include "semantics/evaluation/facade_dataset.hpp"
#include "semantics/evaluation/grid_keypoints.hpp"
#include "semantics/evaluation/training_set.hpp"
#include "semantics/forest/forest_model.hpp"

namespace facadeslam::semantics {

struct TrainingOptions {
  // One or more datasets: the training photos are every one's train.txt
  // together (a street model from CamVid's driving frames and
  // LabelMeFacade's facades; the class table is the same).
  std::vector<std::filesystem::path> datasets;
  std::string descriptor = "modular";  // a kPointDescriptorNames entry
  Genome genome = Genome::thesis_best();
  int step = kDefaultGridStep;
  KeypointSource keypoints = KeypointSource::grid;  // grid (the thesis') or FAST corners (the map's)
  bool balance = false;
  double balance_power = 1.0;        // with balance: 1 = fully, (0, 1) partly (training_sample.hpp)
  std::size_t max_train_images = 0;  // first N of train.txt; 0 = all
  std::size_t max_samples = 0;       // training keypoints cap; 0 = all
  std::uint64_t seed = 1;            // training-sample draw and forest
  // Views of each training photo (with_views): the sample is drawn from all
  // of them. Scales other than 1 teach the forest the sizes a camera sees
  // facades at; grey trains a model for grey cameras.
  std::vector<double> scales{1.0};
  bool grey = false;
  // Each photo in colour and also turned grey (a colour model that leans
  // less on hue: on CamVid's dusk test drive the colour of a hedge or a
  // wall misleads a forest that only learnt daylight colours).
  bool also_grey = false;
  // Forest size overrides (0 = the genome's): the shipped model trades a
  // smaller forest for a file that fits in the repository.
  int trees = 0, max_depth = 0;
};

// The genome's forest settings with the overrides and the seed applied.
// Throws Error for out-of-range values.
ForestParams training_forest_params(const TrainingOptions& options);

struct TrainingRun {
  ForestModel model;  // LabelMeFacade's class table
  std::size_t train_images = 0;
  TrainingSetStats set;
  double training_seconds = 0;  // the forest alone
  double total_seconds = 0;     // reading, describing and training
};

// Checks what can be checked cheaply (the step, the forest settings, the
// descriptor, every file train.txt lists) before the long work, then trains.
// Errors name the file or option and what was expected.
TrainingRun train_model(const TrainingOptions& options);

// The summary written beside a model (`MODEL.json`): dataset, descriptor,
// genome, forest settings, sample options, training rows and per-class
// counts, seconds, and the model file's name and size in bytes.
Json training_summary_json(const TrainingRun& run, const TrainingOptions& options,
                           const std::filesystem::path& model_file, std::uintmax_t model_bytes);

}  // namespace facadeslam::semantics
