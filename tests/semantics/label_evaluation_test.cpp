// Label evaluation pieces: grid, ground truth from label colours, metrics on
// a hand-computed confusion matrix, the training sample, the dataset
// reader's errors, the confusion PNG, and a whole run on a synthetic
// dataset.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <tuple>

#include <opencv2/imgcodecs.hpp>

#include "core/util/error.hpp"
#include "semantics/evaluation/confusion_matrix.hpp"
#include "semantics/evaluation/confusion_plot.hpp"
#include "semantics/evaluation/facade_dataset.hpp"
#include "semantics/evaluation/map_label_accuracy.hpp"
#include "semantics/evaluation/corner_keypoints.hpp"
#include "semantics/evaluation/grid_keypoints.hpp"
#include "semantics/evaluation/label_comparison.hpp"
#include "semantics/evaluation/label_evaluation.hpp"
#include "semantics/evaluation/label_image.hpp"
#include "semantics/evaluation/training_sample.hpp"
#include "semantics/forest/forest_model.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

TEST(GridKeypoints, KeepTheBorderAndTheStep) {
  const auto points = grid_keypoints({50, 40}, 9, 10);
  // x in {10, 19, 28, 37}, y in {10, 19, 28}.
  ASSERT_EQ(points.size(), 12u);
  EXPECT_EQ(points.front(), cv::Point2f(10, 10));
  EXPECT_EQ(points.back(), cv::Point2f(37, 28));
  EXPECT_TRUE(grid_keypoints({15, 15}, 9, 10).empty());
  EXPECT_EQ(grid_keypoints({3, 2}, 1, 0).size(), 6u);
  EXPECT_THROW(grid_keypoints({50, 40}, 0, 10), Error);
  EXPECT_THROW(grid_keypoints({50, 40}, 9, -1), Error);
}

// A bright square on black: FAST finds its four corners (at full and half
// resolution, each pixel once), nothing within the border, nothing on flat
// ground.
TEST(CornerKeypoints, FindTheCornersOfASquareInsideTheBorder) {
  cv::Mat image(120, 160, CV_8UC3, cv::Scalar::all(0));
  cv::rectangle(image, cv::Rect(40, 30, 60, 50), cv::Scalar::all(255), cv::FILLED);
  const std::vector<cv::Point2f> points = corner_keypoints(image, 10);
  ASSERT_FALSE(points.empty());
  for (const cv::Point2f& p : points) {
    const bool near_a_corner =
        (std::abs(p.x - 40) <= 3 || std::abs(p.x - 99) <= 3) && (std::abs(p.y - 30) <= 3 || std::abs(p.y - 79) <= 3);
    EXPECT_TRUE(near_a_corner) << p;
  }
  for (std::size_t i = 1; i < points.size(); ++i)
    EXPECT_TRUE(points[i - 1].y < points[i].y || (points[i - 1].y == points[i].y && points[i - 1].x < points[i].x));
  EXPECT_TRUE(corner_keypoints(cv::Mat(120, 160, CV_8UC3, cv::Scalar::all(90)), 10).empty());
  // The square's corners lie within a 50-pixel border: none kept.
  EXPECT_TRUE(corner_keypoints(image, 50).empty());
  EXPECT_EQ(parse_keypoint_source("corners", "--keypoints"), KeypointSource::corners);
  EXPECT_THROW(parse_keypoint_source("fast", "--keypoints"), Error);
}

TEST(LabelImage, ColoursMapToTheNineClasses) {
  EXPECT_EQ(class_of_colour(cv::Vec3b(0, 0, 0)), 0);        // various
  EXPECT_EQ(class_of_colour(cv::Vec3b(0, 0, 128)), 1);      // building (RGB 128,0,0)
  EXPECT_EQ(class_of_colour(cv::Vec3b(128, 0, 128)), 2);    // car
  EXPECT_EQ(class_of_colour(cv::Vec3b(0, 128, 128)), 3);    // door (RGB 128,128,0)
  EXPECT_EQ(class_of_colour(cv::Vec3b(128, 128, 128)), 4);  // pavement
  EXPECT_EQ(class_of_colour(cv::Vec3b(0, 64, 128)), 5);     // road (RGB 128,64,0)
  EXPECT_EQ(class_of_colour(cv::Vec3b(128, 128, 0)), 6);    // sky (RGB 0,128,128)
  EXPECT_EQ(class_of_colour(cv::Vec3b(0, 128, 0)), 7);      // vegetation
  EXPECT_EQ(class_of_colour(cv::Vec3b(128, 0, 0)), 8);      // window (RGB 0,0,128)
  EXPECT_EQ(class_of_colour(cv::Vec3b(1, 2, 3)), kUnknownClass);
}

TEST(LabelImage, SixteenBitRgbaPngReadsAsClassColours) {
  test::TempDir dir;
  // LabelMeFacade's labels are 16-bit RGBA: 128 is stored as 128 * 257.
  cv::Mat label(4, 6, CV_16UC4, cv::Scalar(0, 0, 128 * 257, 65535));              // BGRA: building
  label(cv::Rect(3, 0, 3, 4)).setTo(cv::Scalar(128 * 257, 128 * 257, 0, 65535));  // sky
  cv::imwrite((dir / "label.png").string(), label);
  const cv::Mat read = read_label_image(dir / "label.png");
  const auto classes = classes_at(read, {cv::Point2f(1, 1), cv::Point2f(4, 2)});
  EXPECT_EQ(classes, (std::vector<std::uint8_t>{1, 6}));
  EXPECT_THAT([&] { read_label_image(dir / "none.png"); }, ::testing::ThrowsMessage<Error>(HasSubstr("none.png")));
}

TEST(ConfusionMatrixMetrics, HandComputedExample) {
  // truth \ predicted:  c0 c1 c2
  //   c0                 5  1  0
  //   c1                 2  3  1
  //   c2                 0  0  0   (absent from the ground truth)
  ConfusionMatrix m(3);
  m.add(0, 0, 5);
  m.add(0, 1);
  m.add(1, 0, 2);
  m.add(1, 1, 3);
  m.add(1, 2);
  EXPECT_EQ(m.total(), 12u);

  const ClassMetrics a = m.metrics(0);
  EXPECT_EQ(a.tp, 5u);
  EXPECT_EQ(a.fn, 1u);
  EXPECT_EQ(a.fp, 2u);
  EXPECT_EQ(a.tn, 4u);
  EXPECT_DOUBLE_EQ(a.accuracy, 9.0 / 12);
  EXPECT_DOUBLE_EQ(a.precision, 5.0 / 7);
  EXPECT_DOUBLE_EQ(a.recall, 5.0 / 6);
  EXPECT_DOUBLE_EQ(a.specificity, 4.0 / 6);
  EXPECT_DOUBLE_EQ(a.npv, 4.0 / 5);
  EXPECT_DOUBLE_EQ(a.f1, 10.0 / 13);

  const ClassMetrics b = m.metrics(1);
  EXPECT_EQ(b.tp, 3u);
  EXPECT_EQ(b.fn, 3u);
  EXPECT_EQ(b.fp, 1u);
  EXPECT_EQ(b.tn, 5u);
  EXPECT_DOUBLE_EQ(b.accuracy, 8.0 / 12);
  EXPECT_DOUBLE_EQ(b.precision, 3.0 / 4);
  EXPECT_DOUBLE_EQ(b.recall, 0.5);
  EXPECT_DOUBLE_EQ(b.specificity, 5.0 / 6);
  EXPECT_DOUBLE_EQ(b.npv, 5.0 / 8);
  EXPECT_DOUBLE_EQ(b.f1, 6.0 / 10);

  const ClassMetrics c = m.metrics(2);
  EXPECT_EQ(c.tp, 0u);
  EXPECT_EQ(c.fp, 1u);
  EXPECT_EQ(c.fn, 0u);
  EXPECT_EQ(c.tn, 11u);
  EXPECT_DOUBLE_EQ(c.precision, 0.0);
  EXPECT_TRUE(std::isnan(c.recall)) << "no ground truth: recall undefined";
  EXPECT_DOUBLE_EQ(c.specificity, 11.0 / 12);
  EXPECT_DOUBLE_EQ(c.npv, 1.0);
  EXPECT_DOUBLE_EQ(c.f1, 0.0);

  EXPECT_DOUBLE_EQ(m.overall_recognition_rate(), 8.0 / 12);
  EXPECT_DOUBLE_EQ(m.average_recognition_rate(), (5.0 / 6 + 0.5) / 2) << "only classes in the ground truth";
  EXPECT_THROW(m.add(3, 0), Error);
  EXPECT_THROW(m.add(0, -1), Error);
  EXPECT_TRUE(std::isnan(ConfusionMatrix(2).overall_recognition_rate()));
}

std::vector<SampleCandidate> candidates_with_counts(const std::vector<int>& counts) {
  std::vector<SampleCandidate> out;
  std::uint32_t keypoint = 0;
  for (std::size_t c = 0; c < counts.size(); ++c)
    for (int i = 0; i < counts[c]; ++i)
      out.push_back({static_cast<std::uint32_t>(i % 3), keypoint++, static_cast<std::uint8_t>(c)});
  return out;
}

std::vector<std::size_t> class_counts(const std::vector<SampleCandidate>& sample, int classes) {
  std::vector<std::size_t> counts(static_cast<std::size_t>(classes), 0);
  for (const auto& s : sample) ++counts[s.class_id];
  return counts;
}

TEST(TrainingSample, DefaultKeepsEverythingOrCapsUniformly) {
  const auto candidates = candidates_with_counts({400, 100, 0, 20});
  const auto all = choose_training_sample(candidates, 4, {});
  EXPECT_EQ(all.size(), candidates.size());
  EXPECT_TRUE(std::is_sorted(all.begin(), all.end(), [](const auto& a, const auto& b) {
    return std::tie(a.image, a.keypoint) < std::tie(b.image, b.keypoint);
  }));
  SampleOptions capped;
  capped.max_samples = 104;
  const auto sample = choose_training_sample(candidates, 4, capped);
  EXPECT_EQ(sample.size(), 104u);
  const auto counts = class_counts(sample, 4);
  EXPECT_GT(counts[0], counts[1]) << "proportions are kept, roughly";
  EXPECT_EQ(sample, choose_training_sample(candidates, 4, capped)) << "deterministic";
  capped.seed = 2;
  EXPECT_NE(sample, choose_training_sample(candidates, 4, capped));
}

TEST(TrainingSample, BalanceGivesEveryPresentClassTheMedianCount) {
  const auto candidates = candidates_with_counts({400, 100, 0, 20});
  EXPECT_EQ(balanced_class_target({400, 100, 0, 20}, 0), 100u);
  EXPECT_EQ(balanced_class_target({400, 100, 0, 20}, 60), 20u);
  EXPECT_EQ(balanced_class_target({0, 0}, 0), 0u);
  SampleOptions options;
  options.balance = true;
  const auto sample = choose_training_sample(candidates, 4, options);
  EXPECT_EQ(class_counts(sample, 4), (std::vector<std::size_t>{100, 100, 0, 100}));
  // The rare class keeps all 20 of its keypoints, then repeats them.
  std::set<std::uint32_t> rare;
  for (const auto& s : sample)
    if (s.class_id == 3) rare.insert(s.keypoint);
  EXPECT_EQ(rare.size(), 20u);
  options.max_samples = 90;
  EXPECT_EQ(class_counts(choose_training_sample(candidates, 4, options), 4), (std::vector<std::size_t>{30, 30, 0, 30}));
  EXPECT_THROW(choose_training_sample(candidates, 3, SampleOptions{true, 0, 1}), Error);
}

TEST(TrainingSample, PartBalanceLiesBetweenTheProportionsAndBalance) {
  // Median 100: class c gets 100 * (n_c / 100)^(1 - p) rows.
  EXPECT_EQ(balanced_class_rows({400, 100, 0, 20}, 0, 1.0), (std::vector<std::size_t>{100, 100, 0, 100}));
  EXPECT_EQ(balanced_class_rows({400, 100, 0, 20}, 0, 0.5), (std::vector<std::size_t>{200, 100, 0, 44}));
  // Capped: scaled down together (344.7 wanted, 172 allowed; rounded down).
  EXPECT_EQ(balanced_class_rows({400, 100, 0, 20}, 172, 0.5), (std::vector<std::size_t>{99, 49, 0, 22}));
  EXPECT_THROW(balanced_class_rows({1, 2}, 0, 0.0), Error);
  EXPECT_THROW(balanced_class_rows({1, 2}, 0, 1.5), Error);
  SampleOptions options;
  options.balance = true;
  options.balance_power = 0.5;
  const auto sample = choose_training_sample(candidates_with_counts({400, 100, 0, 20}), 4, options);
  EXPECT_EQ(class_counts(sample, 4), (std::vector<std::size_t>{200, 100, 0, 44}));
}

// ------------------------------------------------------------------ dataset

class SyntheticDataset : public ::testing::Test {
 protected:
  void SetUp() override { test_util::write_synthetic_dataset(dir.path(), 4, 3); }
  test::TempDir dir;
};

TEST_F(SyntheticDataset, ListsResolveToImagesAndLabels) {
  const auto train = read_facade_split(dir.path(), "train.txt");
  ASSERT_EQ(train.size(), 4u);
  EXPECT_EQ(train[0].name, "facade_0");
  EXPECT_EQ(train[0].image, dir / "images/facade_0.jpg");
  EXPECT_EQ(train[0].label, dir / "labels/facade_0.png");
  const auto loaded = load_labelled_image(train[1]);
  EXPECT_EQ(loaded.bgr.size(), loaded.label.size());
}

TEST_F(SyntheticDataset, ClearErrorsForBrokenLayouts) {
  EXPECT_THAT([&] { read_facade_split(dir / "nope", "train.txt"); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr("nope"), HasSubstr("no such dataset folder"))));
  std::filesystem::remove(dir / "test.txt");
  EXPECT_THAT([&] { read_facade_split(dir.path(), "test.txt"); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr("test.txt"), HasSubstr("no such file"))));
  std::filesystem::remove(dir / "labels/facade_2.png");
  EXPECT_THAT([&] { read_facade_split(dir.path(), "train.txt"); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr("facade_2.png"), HasSubstr("no label image"))));
  test::write_text(dir / "empty.txt", "\n# nothing\n");
  EXPECT_THAT([&] { read_facade_split(dir.path(), "empty.txt"); },
              ::testing::ThrowsMessage<Error>(HasSubstr("lists no image")));
  test::write_text(dir / "ghost.txt", "ghost\n");
  EXPECT_THAT([&] { read_facade_split(dir.path(), "ghost.txt"); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr("line 1"), HasSubstr("images/ghost.jpg"))));
}

TEST_F(SyntheticDataset, LabelOfAnotherSizeFails) {
  cv::imwrite((dir / "labels/facade_1.png").string(), cv::Mat(10, 10, CV_8UC3, cv::Scalar::all(0)));
  const auto train = read_facade_split(dir.path(), "train.txt");
  EXPECT_THAT(
      [&] { load_labelled_image(train[1]); },
      ::testing::ThrowsMessage<Error>(AllOf(HasSubstr("facade_1.png"), HasSubstr("10x10"), HasSubstr("120x90"))));
}

TEST_F(SyntheticDataset, WholeRunLabelsTheSyntheticFacades) {
  LabelEvaluationOptions options;
  options.dataset = dir.path();
  options.descriptor = "edd";
  options.step = 6;
  options.model_out = dir / "out/model.yml.gz";
  const LabelEvaluation result = evaluate_labels(options);
  EXPECT_EQ(result.descriptor, "edd");
  EXPECT_EQ(result.descriptor_width, 113);
  EXPECT_EQ(result.train_images, 4u);
  EXPECT_EQ(result.test_images, 3u);
  EXPECT_EQ(result.train_samples, result.train_keypoints);
  EXPECT_EQ(result.confusion.total(), result.test_keypoints);
  EXPECT_EQ(result.unlabelled_keypoints, 0u);
  // Sky, building, window and road are easy to tell apart here.
  EXPECT_GT(result.confusion.overall_recognition_rate(), 0.85);
  EXPECT_GT(result.extraction_ms_per_image(), 0.0);
  EXPECT_GT(result.forest_ms_per_image(), 0.0);

  // The saved model is the one a user would load for this descriptor.
  ForestExpectation expected;
  expected.descriptor = "edd";
  expected.descriptor_width = 113;
  expected.genome = Genome::thesis_best();
  expected.classes = labelmefacade_class_table();
  const ForestModel model = load_forest_model(options.model_out, expected);
  EXPECT_EQ(model.forest.tree_count(), 100);

  const Json report = to_json(result, options);
  const std::string text = report.dump();
  for (const char* key : {"overall_recognition_rate", "average_recognition_rate", "per_class", "\"tp\"", "\"fp\"",
                          "\"fn\"", "\"tn\"", "\"accuracy\"", "\"precision\"", "\"recall\"", "\"specificity\"",
                          "\"npv\"", "\"f1\"", "extraction_ms_per_image", "forest_ms_per_image", "\"window\""})
    EXPECT_THAT(text, HasSubstr(key));
}

// --keypoints corners: trained and tested where FAST finds corners (where the
// map's points are), so the test count is the test images' labelled corners.
TEST_F(SyntheticDataset, CornerRunTestsTheImagesCorners) {
  LabelEvaluationOptions options;
  options.dataset = dir.path();
  options.descriptor = "edd";
  options.keypoints = KeypointSource::corners;
  options.max_test_images = 2;
  const LabelEvaluation result = evaluate_labels(options);
  std::size_t corners = 0;
  std::vector<LabelledImage> test = read_facade_split(dir.path(), "test.txt");
  test.resize(2);
  for (const LabelledImage& image : test) {
    const LoadedLabelledImage loaded = load_labelled_image(image);
    corners += labelled_keypoints(loaded.label, corner_keypoints(loaded.bgr)).points.size();
  }
  ASSERT_GT(corners, 0u);
  EXPECT_EQ(result.test_keypoints, corners);
  EXPECT_EQ(result.confusion.total(), corners);
  EXPECT_EQ(to_json(result, options)["keypoints"], "corners");
}

TEST_F(SyntheticDataset, BalancedRunEqualisesTheClasses) {
  LabelEvaluationOptions options;
  options.dataset = dir.path();
  options.descriptor = "edd";
  options.step = 8;
  options.balance = true;
  options.max_train_images = 2;
  options.max_test_images = 1;
  const LabelEvaluation result = evaluate_labels(options);
  EXPECT_EQ(result.train_images, 2u);
  EXPECT_EQ(result.test_images, 1u);
  std::set<std::size_t> present;
  for (const std::size_t n : result.train_samples_per_class)
    if (n) present.insert(n);
  EXPECT_EQ(present.size(), 1u) << "every present class has the same count";
}

TEST(ConfusionPlot, WritesAPngAtomically) {
  test::TempDir dir;
  ConfusionMatrix m(9);
  for (int k = 0; k < 9; ++k) m.add(k, k, 10 + static_cast<std::uint64_t>(k));
  m.add(3, 1, 7);
  const auto names = evaluation_class_names();
  const cv::Mat image = render_confusion_matrix(m, names, "test");
  EXPECT_EQ(image.type(), CV_8UC3);
  EXPECT_GT(image.cols, 9 * 60);
  save_confusion_matrix_png(dir / "cm.png", m, names, "test");
  const cv::Mat read = cv::imread((dir / "cm.png").string());
  EXPECT_EQ(read.size(), image.size());
  EXPECT_THROW(save_confusion_matrix_png(dir / "cm.jpg", m, names, "test"), Error);
  EXPECT_THROW(render_confusion_matrix(m, {"a"}, "test"), Error);
}

// -------------------------------------------------------- shared real data

TEST(LabelMeFacade, LabelsUseOnlyTheNineClassColours) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  const auto root = test::shared_data_dir() / "labelmefacade";
  const auto train = read_facade_split(root, "train.txt");
  EXPECT_EQ(train.size(), 100u);
  EXPECT_EQ(read_facade_split(root, "test.txt").size(), 545u);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto loaded = load_labelled_image(train[i]);
    const auto classes = classes_at(loaded.label, grid_keypoints(loaded.label.size(), 9));
    EXPECT_EQ(std::count(classes.begin(), classes.end(), kUnknownClass), 0) << train[i].name;
  }
}

}  // namespace
}  // namespace facadeslam::semantics

namespace facadeslam::semantics {
namespace {

LabelEvaluation run_with(const std::string& name, std::initializer_list<std::pair<int, int>> truth_predicted) {
  LabelEvaluation r;
  r.descriptor = name;
  r.descriptor_width = 7;
  r.test_images = 2;
  r.test_extraction_seconds = 0.004;  // 2 ms per image
  r.forest_seconds = 0.001;
  r.confusion = ConfusionMatrix(9);
  for (const auto& [t, p] : truth_predicted) r.confusion.add(t, p);
  return r;
}

TEST(LabelComparison, OneRowPerDescriptorWithRecallsAndTimes) {
  const std::vector<LabelEvaluation> runs{run_with("modular", {{1, 1}, {1, 1}, {8, 8}, {8, 1}}),
                                          run_with("sift", {{1, 8}, {1, 1}, {8, 8}, {8, 8}})};
  const std::string table = comparison_table(runs);
  EXPECT_THAT(table, HasSubstr("| modular | 7 | 75.0 | 75.0 |"));  // building 2/2, window 1/2
  EXPECT_THAT(table, HasSubstr("| sift | 7 | 75.0 | 75.0 |"));
  EXPECT_THAT(table, HasSubstr("| 2.0 | 0.5 |"));
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 4);  // header, rule, two rows
  const Json json = comparison_json(runs);
  ASSERT_TRUE(json.is_array());
  const std::string text = json.dump();
  EXPECT_THAT(text, HasSubstr("\"descriptor\":\"modular\""));
  EXPECT_THAT(text, HasSubstr("\"descriptor\":\"sift\""));
  EXPECT_THAT(text, HasSubstr("\"window\":0.5"));
  EXPECT_THAT(text, HasSubstr("\"extraction_ms_per_image\":2"));
}

// A map point's true class: the label image at its rounded pixel, none
// outside the image or where the image has no class (the renderer's unknown).
TEST(MapLabelAccuracy, TrueClassIsTheLabelAtTheRoundedPixel) {
  cv::Mat truth(4, 6, CV_8UC1, cv::Scalar(1));
  truth.at<std::uint8_t>(2, 3) = 7;
  truth.at<std::uint8_t>(0, 0) = 200;
  EXPECT_EQ(true_class_at(truth, {2.6, 1.5}), std::optional<std::size_t>(7));
  EXPECT_EQ(true_class_at(truth, {2.4, 1.4}), std::optional<std::size_t>(1));
  EXPECT_EQ(true_class_at(truth, {0.0, 0.0}), std::nullopt);
  EXPECT_EQ(true_class_at(truth, {-0.6, 1.0}), std::nullopt);
  EXPECT_EQ(true_class_at(truth, {5.6, 1.0}), std::nullopt);
  EXPECT_EQ(true_class_at(cv::Mat(), {1.0, 1.0}), std::nullopt);
}

}  // namespace
}  // namespace facadeslam::semantics
