#pragma once
// A genome's fitness (issue 18, thesis IV.4): a forest trained with the
// genome's descriptor and forest fields on the training part of train.txt,
// tested on a validation part carved from train.txt by the run's seed, or
// cross-validated over parts of it (test.txt is never seen), and the
// genome's extraction time as a ratio to cv::SIFT's on the same keypoints,
// modelled from what the genome computes (cost_model.hpp) rather than
// measured: an evaluation is a function of the genome, the split and the
// seed, so runs with the same seed agree whatever the threads, ranks or load.
//
// With a weight on it, a small invariance term: the genome's match rate
// (`evaluate invariance`'s measure) under a rotation of 20 degrees, a resize
// to 0.75, a 5-pixel Gaussian blur and a 3800 K illuminant, on the first
// validation images: the changes a facade undergoes between keyframes.
//
// evaluate() is const and thread-safe: workers call it in parallel.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "semantics/descriptor/genome.hpp"
#include "semantics/evaluation/facade_dataset.hpp"
#include "semantics/optimiser/ga_options.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

// One way of scoring a genome: a forest trained on `train`, tested on `validation`.
struct FitnessFold {
  std::vector<LabelledImage> train, validation;
};
// train.txt split by the seed: `validation_share` of it held out (one fold),
// or, with GaOptions::folds >= 2, cut into that many parts, each the
// validation of one fold and training data of the others.
struct FitnessSplit {
  std::vector<FitnessFold> folds;
};
// Throws Error naming the dataset when train.txt is missing or too small to
// leave images on both sides.
FitnessSplit split_train_list(const std::filesystem::path& dataset, const GaOptions& options, std::uint64_t seed);
nlohmann::json to_json(const FitnessSplit& split);

struct GenomeEvaluation {
  bool valid = false;               // a genome without an active value describes nothing
  double overall = 0, average = 0;  // recognition rates on the validation keypoints
  double time_ratio = 0;            // modelled extraction time / cv::SIFT's on the same keypoints (cost_model.hpp)
  double invariance = 0;            // mean match rate under the invariance cases (0 unless weighted)
  int values = 0;                   // descriptor length
  double objective = 0;             // FitnessWeights applied (-infinity when invalid)
  // Wall time: where an evaluation's time went (never part of the objective).
  double seconds = 0;             // the evaluation, of which:
  double describe_seconds = 0;    // reading the training images and describing the sample
  double train_seconds = 0;       // training the forest
  double validate_seconds = 0;    // describing and classifying the validation keypoints
  double invariance_seconds = 0;  // the invariance cases
};
nlohmann::json to_json(const GenomeEvaluation& e);
GenomeEvaluation evaluation_from_json(const nlohmann::json& j);  // throws nlohmann::json::exception

// The objective of an evaluation's figures (ga_options.hpp, FitnessWeights).
double objective_of(const GenomeEvaluation& e, const FitnessWeights& weights);

class FitnessEvaluator {
 public:
  FitnessEvaluator(FitnessSplit split, GaOptions options, std::uint64_t seed);
  GenomeEvaluation evaluate(const Genome& genome) const;
  const FitnessSplit& split() const { return split_; }

 private:
  double invariance_score(PointDescriptor& descriptor) const;

  FitnessSplit split_;
  // The split's images decoded once (read-only: shared by the worker threads).
  std::shared_ptr<const DecodedImageCache> images_;
  GaOptions options_;
  std::uint64_t seed_;
};

}  // namespace facadeslam::semantics
