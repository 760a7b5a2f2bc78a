// The GA's cost model (semantics/optimiser/cost_model.hpp): what a genome
// asks for is what it pays (planes once per image, moments once per channel
// at the highest order, singular values by the highest one wanted), patches
// scale with their side, the shipped configs carry the code's calibration,
// and the config block is read like the other keys.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "semantics/descriptor/genome.hpp"
#include "semantics/descriptor/genome_io.hpp"
#include "semantics/optimiser/cost_model.hpp"
#include "semantics/optimiser/fitness.hpp"
#include "semantics/optimiser/ga_options.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

namespace fs = std::filesystem;

DescriptorParams with(std::initializer_list<const char*> names, int radius = 10) {
  DescriptorParams p = Genome::thesis_best().decode();
  p.gaussian_kernel = 1;
  p.colour_space = ColourSpace::rgb;
  p.patch_radius = radius;
  p.activation.reset();
  for (const char* name : names) p.activation.set(static_cast<std::size_t>(*value_index(name)));
  return p;
}

TEST(CostModel, EachPartIsPaidOnceForWhatTheGenomeAsks) {
  const CostModel m;
  const auto values = [&](int n) { return n * m.per_value; };
  EXPECT_EQ(modelled_time_ratio(with({}), m), 0.0);
  // Position reads no plane.
  EXPECT_DOUBLE_EQ(modelled_time_ratio(with({"x_norm", "y_norm"}), m), m.position + values(2));
  // One channel's mean and sigma: its plane once, one strip.
  const double rgb = m.colour_space[0];
  const double one = m.equalise + rgb + m.colour_plane + m.position + m.statistics_plane;
  EXPECT_DOUBLE_EQ(modelled_time_ratio(with({"mean_c0"}), m), one + values(1));
  EXPECT_DOUBLE_EQ(modelled_time_ratio(with({"mean_c0", "std_c0"}), m), one + values(2));
  EXPECT_DOUBLE_EQ(modelled_time_ratio(with({"mean_c0", "mean_c1"}), m),
                   one + m.colour_plane + m.statistics_plane + values(2));
  // Moments of one channel: the highest order, once, whichever module asks.
  const double order5 = m.equalise + rgb + m.colour_plane + m.position + m.moments[3];
  EXPECT_DOUBLE_EQ(modelled_time_ratio(with({"eta50_c1"}), m), order5 + values(1));
  EXPECT_DOUBLE_EQ(modelled_time_ratio(with({"eta50_c1", "eta20_c1"}), m), order5 + values(2));
  EXPECT_DOUBLE_EQ(modelled_time_ratio(with({"eta50_c1", "hu1_c1", "hu2_c1"}), m), order5 + 2 * m.hu + values(3));
  // Singular values: the highest wanted.
  EXPECT_DOUBLE_EQ(modelled_time_ratio(with({"sv3_c2", "sv1_c2"}), m),
                   m.equalise + rgb + m.colour_plane + m.position + m.singular_values[2] + values(2));
  // Blur and colour space are per image.
  DescriptorParams blurred = with({"mean_c0"});
  blurred.gaussian_kernel = 7;
  blurred.colour_space = ColourSpace::lab;
  EXPECT_DOUBLE_EQ(modelled_time_ratio(blurred, m), one - rgb + values(1) + 7 * m.blur_per_tap + m.colour_space[1]);
}

TEST(CostModel, PatchesScaleWithTheirSideAndSiftWithItsOwn) {
  CostModel m;
  m.sift[0] = 0.5;  // radius 3
  const CostBreakdown at10 = modelled_cost(with({"sv3_c0"}, 10), m);
  const CostBreakdown at3 = modelled_cost(with({"sv3_c0"}, 3), m);
  EXPECT_DOUBLE_EQ(at3.per_image, at10.per_image);
  const double walk = m.position + m.per_value;  // neither grows with the patch
  EXPECT_NEAR(at3.per_keypoint - walk, (at10.per_keypoint - walk) * std::pow(7.0 / 21.0, m.singular_values_exponent),
              1e-12);
  EXPECT_DOUBLE_EQ(at3.ratio, (at3.per_image + at3.per_keypoint) / 0.5);
}

TEST(CostModel, MoreValuesNeverCostLessAndTheShippedGenomeIsFasterThanTheThesisOne) {
  const CostModel m;
  const DescriptorParams thesis = Genome::thesis_best().decode();
  for (int v = 0; v < kValueCount; ++v) {
    DescriptorParams more = thesis;
    more.activation.set(static_cast<std::size_t>(v));
    EXPECT_GE(modelled_time_ratio(more, m), modelled_time_ratio(thesis, m)) << value_name(v);
  }
  const Genome shipped = load_genome(test::source_dir() / "models" / "default.genome");
  EXPECT_LT(modelled_time_ratio(shipped.decode(), m), modelled_time_ratio(thesis, m));
}

// The shipped GA settings carry the code's calibration (a recalibration
// updates both), and the block is checked like every other key.
TEST(CostModel, ShippedConfigsHoldTheCalibrationAndTheBlockIsChecked) {
  int configs = 0;
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "configs")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("optimise", 0) != 0 || entry.path().extension() != ".yaml") continue;
    EXPECT_EQ(to_json(load_ga_options(entry.path()).cost_model), to_json(CostModel{})) << name;
    ++configs;
  }
  EXPECT_GE(configs, 5);
  test::TempDir dir;
  const auto error = [&](const std::string& yaml) {
    test::write_text(dir / "ga.yaml", yaml);
    return test::error_of([&] { load_ga_options(dir / "ga.yaml"); });
  };
  EXPECT_NE(error("cost_model:\n  colour_plan: 0.1\n").find("cost_model.colour_plan"), std::string::npos);
  EXPECT_NE(error("cost_model:\n  hu: -1\n").find("cost_model.hu"), std::string::npos);
  EXPECT_NE(error("cost_model:\n  moments: [1, 2]\n").find("cost_model.moments"), std::string::npos);
  EXPECT_NE(error("cost_model:\n  sift: [1, 1, 1, 0, 1, 1, 1, 1]\n").find("cost_model.sift"), std::string::npos);
  // The measured time term's setting is gone with it.
  EXPECT_NE(error("timing_images: 8\n").find("timing_images"), std::string::npos);
  test::write_text(dir / "ga.yaml", "cost_model:\n  hu: 0.5\n  moments: [1, 2, 3, 4]\n");
  const CostModel read = load_ga_options(dir / "ga.yaml").cost_model;
  EXPECT_EQ(read.hu, 0.5);
  EXPECT_EQ(read.moments[3], 4.0);
  EXPECT_EQ(read.affine, CostModel{}.affine);
}

// The evaluation's time ratio is the model's: the same for the same genome
// whenever it is evaluated.
TEST(CostModel, TheFitnessTimeTermIsTheModelled) {
  test::TempDir dir;
  test_util::write_synthetic_dataset(dir.path(), 6, 1);
  GaOptions options;
  options.validation_share = 0.34;
  options.max_samples = 500;
  options.max_trees = 4;
  options.max_depth = 4;
  options.weights.invariance = 0.0;
  options.cost_model.position = 0.25;
  const FitnessEvaluator evaluator(split_train_list(dir.path(), options, 3), options, 3);
  const Genome genome = Genome::thesis_best();
  const GenomeEvaluation a = evaluator.evaluate(genome);
  EXPECT_EQ(a.time_ratio, modelled_time_ratio(genome.decode(), options.cost_model));
  EXPECT_EQ(a.objective, evaluator.evaluate(genome).objective);
  EXPECT_EQ(a.objective, objective_of(a, options.weights));
  EXPECT_EQ(evaluation_from_json(to_json(a)).time_ratio, a.time_ratio);
}

}  // namespace
}  // namespace facadeslam::semantics
