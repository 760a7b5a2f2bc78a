// The optimiser's fitness: its validation split (one held-out share, or k
// cross-validation folds in which every training image is validated exactly
// once), the invariance term, and the images decoded once for all evaluations.
#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/util/error.hpp"
#include "semantics/optimiser/fitness.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

class FitnessSplitTest : public ::testing::Test {
 protected:
  void SetUp() override { test_util::write_synthetic_dataset(dir_.path(), 10, 1, {40, 30}); }
  test::TempDir dir_;
};

TEST_F(FitnessSplitTest, OneShareHeldOut) {
  GaOptions options;
  options.validation_share = 0.3;
  const FitnessSplit split = split_train_list(dir_.path(), options, 7);
  ASSERT_EQ(split.folds.size(), 1u);
  EXPECT_EQ(split.folds[0].validation.size(), 3u);
  EXPECT_EQ(split.folds[0].train.size(), 7u);
  const nlohmann::json json = to_json(split);
  EXPECT_EQ(json.at("validation").size(), 3u);  // the layout runs have always written
}

TEST_F(FitnessSplitTest, FoldsValidateEveryImageOnceAndTrainOnTheRest) {
  GaOptions options;
  options.folds = 3;
  const FitnessSplit split = split_train_list(dir_.path(), options, 7);
  ASSERT_EQ(split.folds.size(), 3u);
  std::map<std::string, int> validated;
  for (const FitnessFold& fold : split.folds) {
    EXPECT_EQ(fold.train.size() + fold.validation.size(), 10u);
    for (const LabelledImage& image : fold.validation) {
      ++validated[image.name];
      EXPECT_TRUE(std::none_of(fold.train.begin(), fold.train.end(),
                               [&](const LabelledImage& t) { return t.name == image.name; }))
          << image.name << " is in its own fold's training part";
    }
  }
  EXPECT_EQ(validated.size(), 10u);
  for (const auto& [name, count] : validated) EXPECT_EQ(count, 1) << name;
  // The seed fixes the split; another seed gives another one.
  EXPECT_EQ(to_json(split_train_list(dir_.path(), options, 7)), to_json(split));
  EXPECT_NE(to_json(split_train_list(dir_.path(), options, 8)), to_json(split));
  EXPECT_EQ(to_json(split).at("folds").size(), 3u);
}

TEST_F(FitnessSplitTest, MoreFoldsThanImagesIsAnError) {
  GaOptions options;
  options.folds = 11;
  EXPECT_THROW(split_train_list(dir_.path(), options, 7), Error);
}

}  // namespace
}  // namespace facadeslam::semantics

namespace facadeslam::semantics {
namespace {

// The invariance term: measured (a match rate in [0, 1]) only when weighted,
// deterministic, and added to the objective with its weight.
TEST(FitnessInvariance, MeasuredOnlyWhenWeightedAndAddedToTheObjective) {
  test::TempDir dir;
  test_util::write_synthetic_dataset(dir.path(), 6, 1);
  GaOptions options;
  options.validation_share = 0.34;
  options.max_samples = 500;
  options.max_trees = 4;
  options.max_depth = 4;
  options.weights.invariance = 0.0;
  const FitnessEvaluator without(split_train_list(dir.path(), options, 3), options, 3);
  const GenomeEvaluation plain = without.evaluate(Genome::thesis_best());
  EXPECT_EQ(plain.invariance, 0.0);

  options.weights.invariance = 0.5;
  const FitnessEvaluator with(split_train_list(dir.path(), options, 3), options, 3);
  const GenomeEvaluation a = with.evaluate(Genome::thesis_best());
  EXPECT_GT(a.invariance, 0.0);
  EXPECT_LE(a.invariance, 1.0);
  EXPECT_EQ(a.invariance, with.evaluate(Genome::thesis_best()).invariance);
  EXPECT_EQ(a.overall, plain.overall);  // the rest of the evaluation is unchanged
  EXPECT_NEAR(a.objective - plain.objective, 0.5 * a.invariance, 1e-12);
  // Checkpoints keep it.
  EXPECT_EQ(evaluation_from_json(to_json(a)).invariance, a.invariance);
}

}  // namespace
}  // namespace facadeslam::semantics

namespace facadeslam::semantics {
namespace {

TEST(DecodedImageCache, DecodesOnceWithinItsBudgetAndReadsTheRestFromDisk) {
  test::TempDir dir;
  test_util::write_synthetic_dataset(dir.path(), 3, 0, {40, 30});
  const std::vector<LabelledImage> images = read_facade_split(dir.path(), "train.txt");
  const std::size_t one_image = 2 * 40 * 30 * 3;  // photo and label image, 8-bit BGR
  const DecodedImageCache all(images, 10 * one_image), two(images, 2 * one_image), none(images, 0);
  EXPECT_EQ(all.images(), 3u);
  EXPECT_EQ(all.bytes(), 3 * one_image);
  EXPECT_EQ(two.images(), 2u);
  EXPECT_EQ(none.images(), 0u);
  for (const LabelledImage& entry : images) {
    const LoadedLabelledImage disk = load_labelled_image(entry);
    for (const DecodedImageCache* cache : {&all, &two, &none}) {
      const LoadedLabelledImage got = (*cache)(entry);
      EXPECT_EQ(cv::norm(got.bgr, disk.bgr, cv::NORM_INF), 0.0) << entry.name;
      EXPECT_EQ(cv::norm(got.label, disk.label, cv::NORM_INF), 0.0) << entry.name;
    }
  }
}

// Training views (`train --scales --grey`): each photo once per scale, its
// labels resized by nearest neighbour (no blended class colours), grey in
// three equal channels; the cache gives the same pixels as the disk.
TEST(LabelledImageViews, ScaleAndGreyEachPhotoAsAskedAndTheCacheAgrees) {
  test::TempDir dir;
  test_util::write_synthetic_dataset(dir.path(), 2, 0, {40, 30});
  const std::vector<LabelledImage> images = read_facade_split(dir.path(), "train.txt");
  const std::vector<LabelledImage> views = with_views(images, {0.5, 1.0, 2.0}, true);
  ASSERT_EQ(views.size(), 6u);
  EXPECT_EQ(views[0].name, images[0].name);
  EXPECT_EQ(views[1].scale, 0.5);
  EXPECT_EQ(views[2].scale, 1.0);
  const DecodedImageCache cache(images, std::size_t{1} << 24);
  for (const LabelledImage& view : views) {
    EXPECT_TRUE(view.grey);
    const LoadedLabelledImage seen = load_labelled_image(view);
    EXPECT_EQ(seen.bgr.cols, static_cast<int>(40 * view.scale));
    EXPECT_EQ(seen.bgr.rows, static_cast<int>(30 * view.scale));
    EXPECT_EQ(seen.label.size(), seen.bgr.size());
    std::vector<cv::Mat> channels;
    cv::split(seen.bgr, channels);
    EXPECT_EQ(cv::norm(channels[0], channels[1], cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(channels[1], channels[2], cv::NORM_INF), 0.0);
    // Every label colour of the view is one of the stored label image's.
    const cv::Mat stored = load_labelled_image(images[view.name == images[0].name ? 0 : 1]).label;
    std::set<std::tuple<int, int, int>> colours;
    for (auto it = stored.begin<cv::Vec3b>(); it != stored.end<cv::Vec3b>(); ++it)
      colours.insert({(*it)[0], (*it)[1], (*it)[2]});
    for (auto it = seen.label.begin<cv::Vec3b>(); it != seen.label.end<cv::Vec3b>(); ++it)
      EXPECT_TRUE(colours.count({(*it)[0], (*it)[1], (*it)[2]})) << view.name << " at scale " << view.scale;
    const LoadedLabelledImage cached = cache(view);
    EXPECT_EQ(cv::norm(cached.bgr, seen.bgr, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(cached.label, seen.label, cv::NORM_INF), 0.0);
  }
  EXPECT_EQ(with_views(images, {1.0}, false).size(), 2u);
  EXPECT_FALSE(with_views(images, {1.0}, false)[0].grey);
  EXPECT_THROW(with_views(images, {}, false), Error);
  EXPECT_THROW(with_views(images, {0.0}, false), Error);
  EXPECT_THROW(with_views(images, {9.0}, false), Error);
}

}  // namespace
}  // namespace facadeslam::semantics
