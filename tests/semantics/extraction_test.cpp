#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "semantics/descriptor/extraction.hpp"
#include "semantics/descriptor/genome.hpp"
#include "semantics/descriptor/modules/plane_statistics.hpp"
#include "tests/semantics/semantics_test_util.hpp"

namespace facadeslam::semantics {
namespace {

using ::testing::HasSubstr;

// The thesis genome's preprocessing with exactly the named values active.
DescriptorParams thesis_with(std::initializer_list<const char*> names) {
  return test_util::with_values(names, Genome::thesis_best().decode());
}

std::vector<cv::Point2f> grid(cv::Size size, int step) {
  std::vector<cv::Point2f> points;
  for (int y = 0; y < size.height; y += step)
    for (int x = 0; x < size.width; x += step) points.emplace_back(static_cast<float>(x), static_cast<float>(y));
  return points;
}

class Extraction : public ::testing::Test {
 protected:
  cv::Mat image = test_util::textured_image({96, 72}, 5);
  std::vector<cv::Point2f> keypoints = grid({96, 72}, 9);
};

TEST_F(Extraction, ThesisGenomeGivesOneRowPerKeypointAnd93Columns) {
  const DescriptorParams p = Genome::thesis_best().decode();
  ExtractionStats stats;
  const cv::Mat d = extract(prepare(image, p), keypoints, p, &stats);
  EXPECT_EQ(d.type(), CV_32F);
  EXPECT_EQ(d.rows, static_cast<int>(keypoints.size()));
  EXPECT_EQ(d.cols, 93);
  EXPECT_EQ(active_value_names(p).size(), 93u);
  EXPECT_EQ(stats.keypoints, keypoints.size());
  for (int m = 0; m < kModuleCount; ++m) EXPECT_EQ(stats.module_calls[static_cast<std::size_t>(m)], keypoints.size());
  EXPECT_TRUE(cv::checkRange(d)) << "no NaN or infinity";
}

TEST_F(Extraction, ColumnsArePopcountOfActivation) {
  std::mt19937 rng(8);
  std::bernoulli_distribution coin(0.2);
  for (int trial = 0; trial < 5; ++trial) {
    DescriptorParams p = Genome::thesis_best().decode();
    for (int i = 0; i < kValueCount; ++i) p.activation.set(static_cast<std::size_t>(i), coin(rng));
    const cv::Mat d = extract(prepare(image, p), keypoints, p);
    EXPECT_EQ(d.cols, static_cast<int>(p.activation.count()));
    EXPECT_EQ(d.rows, static_cast<int>(keypoints.size()));
  }
}

TEST_F(Extraction, InactiveModulesAreNotRun) {
  const DescriptorParams p = thesis_with({"mean_c0", "eta11_c1"});
  ExtractionStats stats;
  const cv::Mat d = extract(prepare(image, p), keypoints, p, &stats);
  EXPECT_EQ(d.cols, 2);
  const auto n = keypoints.size();
  EXPECT_EQ(stats.calls(Module::mean_std), n);
  EXPECT_EQ(stats.calls(Module::moments2), n);
  for (const Module m : {Module::position, Module::moments3, Module::moments4, Module::moments5, Module::hu,
                         Module::gevers_l, Module::gevers_c, Module::geusebroek, Module::affine_invariants,
                         Module::edge_distance, Module::singular_values, Module::gradient_angles})
    EXPECT_EQ(stats.calls(m), 0u) << module_name(m);
  EXPECT_EQ(stats.moment_calls[0], 0u);
  EXPECT_EQ(stats.moment_calls[1], n) << "moments only for the channel that needs them";
  EXPECT_EQ(stats.moment_calls[2], 0u);
}

TEST(ExtractionPlan, MomentOrderFollowsTheActiveValues) {
  const auto plan_for = [](std::initializer_list<const char*> names) {
    return plan_extraction(thesis_with(names).activation);
  };
  EXPECT_EQ(plan_for({"eta20_c0"}).moment_order, (std::array<int, 3>{2, -1, -1}));
  EXPECT_EQ(plan_for({"hu1_c2"}).moment_order, (std::array<int, 3>{-1, -1, 3}));
  EXPECT_EQ(plan_for({"ami1_c1"}).moment_order, (std::array<int, 3>{-1, 2, -1}));
  EXPECT_EQ(plan_for({"ami7_c1", "eta30_c1"}).moment_order, (std::array<int, 3>{-1, 4, -1}));
  EXPECT_EQ(plan_for({"ami10_c0", "mean_c1", "sv1_c2"}).moment_order, (std::array<int, 3>{5, -1, -1}));
  const ExtractionPlan plan = plan_for({"sv1_c2", "x_norm"});
  EXPECT_EQ(plan.modules, (std::vector<Module>{Module::position, Module::singular_values}));
  EXPECT_EQ(plan.columns, (std::vector<int>{0, value_index("sv1_c2").value()}));
}

TEST_F(Extraction, SubsetColumnsEqualTheFullDescriptorColumns) {
  DescriptorParams all = Genome::thesis_best().decode();
  all.activation.set();
  const cv::Mat full = extract(prepare(image, all), keypoints, all);
  ASSERT_EQ(full.cols, 185);
  const DescriptorParams thesis = Genome::thesis_best().decode();
  const cv::Mat part = extract(prepare(image, thesis), keypoints, thesis);
  const auto names = active_value_names(thesis);
  for (int col = 0; col < part.cols; ++col) {
    const int index = value_index(names[static_cast<std::size_t>(col)]).value();
    // Bit-identical, except singular values: their iteration stops later when
    // more of them are wanted (singular_values_module.hpp).
    const bool singular = module_of_value(index) == Module::singular_values;
    const double tolerance = singular ? 1e-5 * cv::norm(full.col(index), cv::NORM_INF) : 0.0;
    EXPECT_LE(cv::norm(part.col(col), full.col(index), cv::NORM_INF), tolerance)
        << names[static_cast<std::size_t>(col)];
  }
}

TEST_F(Extraction, IsDeterministic) {
  const DescriptorParams p = Genome::thesis_best().decode();
  const cv::Mat a = extract(prepare(image, p), keypoints, p);
  const cv::Mat b = extract(prepare(image, p), keypoints, p);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data, b.data, a.total() * a.elemSize()), 0);
}

TEST_F(Extraction, ARowDoesNotDependOnTheOtherKeypoints) {
  // Keypoints on one image row share column sums; the values of one must be
  // the same alone, in a batch, and in any order.
  const DescriptorParams p = Genome::thesis_best().decode();
  const PreparedImage prepared = prepare(image, p);
  const std::vector<cv::Point2f> batch{{50.0f, 30.0f}, {12.3f, 30.2f}, {40.0f, 29.8f}, {70.0f, 5.0f}, {41.0f, 30.0f}};
  const cv::Mat together = extract(prepared, batch, p);
  for (std::size_t k = 0; k < batch.size(); ++k) {
    const cv::Mat alone = extract(prepared, {batch[k]}, p);
    EXPECT_EQ(std::memcmp(alone.ptr<float>(0), together.ptr<float>(static_cast<int>(k)), alone.cols * sizeof(float)), 0)
        << "keypoint " << k;
  }
}

TEST_F(Extraction, ValuesMatchTheirDefinitions) {
  DescriptorParams p = thesis_with({"x_norm", "mean_c1", "std_c2", "mean_edge_distance"});
  const PreparedImage prepared = prepare(image, p);
  const std::vector<cv::Point2f> points{{40.2f, 30.7f}};
  const cv::Mat d = extract(prepared, points, p);
  ASSERT_EQ(d.cols, 4);
  EXPECT_FLOAT_EQ(d.at<float>(0, 0), 40.2f / 96.0f);
  // The patch is centred on the nearest pixel (40, 31).
  const cv::Rect patch(40 - 10, 31 - 10, 21, 21);
  cv::Scalar mean, sigma;
  cv::meanStdDev(prepared.interior(colour_plane(1))(patch), mean, sigma);
  EXPECT_NEAR(d.at<float>(0, 1), mean[0], 1e-5);
  cv::meanStdDev(prepared.interior(colour_plane(2))(patch), mean, sigma);
  EXPECT_NEAR(d.at<float>(0, 2), sigma[0], 1e-5);
  cv::meanStdDev(prepared.interior(PlaneId::edge_distance)(patch), mean, sigma);
  EXPECT_NEAR(d.at<float>(0, 3), mean[0], 1e-4);
}

TEST_F(Extraction, PatchesAtTheBorderAreReflected) {
  const DescriptorParams p = thesis_with({"mean_c0", "std_c0"});
  const PreparedImage prepared = prepare(image, p);
  const cv::Mat d = extract(prepared, {{0.0f, 0.0f}, {95.4f, 71.4f}}, p);
  cv::Mat reflected;
  cv::copyMakeBorder(prepared.interior(colour_plane(0)), reflected, 10, 10, 10, 10, cv::BORDER_REFLECT_101);
  cv::Scalar mean, sigma;
  cv::meanStdDev(reflected(cv::Rect(0, 0, 21, 21)), mean, sigma);
  EXPECT_NEAR(d.at<float>(0, 0), mean[0], 1e-5);
  EXPECT_NEAR(d.at<float>(0, 1), sigma[0], 1e-5);
  cv::meanStdDev(reflected(cv::Rect(95, 71, 21, 21)), mean, sigma);
  EXPECT_NEAR(d.at<float>(1, 0), mean[0], 1e-5);
}

TEST_F(Extraction, EmptyInputs) {
  const DescriptorParams p = Genome::thesis_best().decode();
  const cv::Mat none = extract(prepare(image, p), {}, p);
  EXPECT_EQ(none.rows, 0);
  const DescriptorParams nothing = thesis_with({});
  const cv::Mat no_values = extract(prepare(image, nothing), keypoints, nothing);
  EXPECT_EQ(no_values.cols, 0);
}

TEST_F(Extraction, RejectsKeypointsOutsideTheImage) {
  const DescriptorParams p = thesis_with({"mean_c0"});
  const PreparedImage prepared = prepare(image, p);
  EXPECT_THAT(
      [&] {
        extract(prepared, {{1, 1}, {96.0f, 10.0f}}, p);
      },
      ::testing::ThrowsMessage<Error>(::testing::AllOf(HasSubstr("keypoint 1"), HasSubstr("outside the 96x72"))));
  EXPECT_THAT(
      [&] {
        extract(prepared, {{-0.6f, 10.0f}}, p);
      },
      ::testing::ThrowsMessage<Error>(HasSubstr("keypoint 0")));
  EXPECT_THAT([&] { extract(prepared, {{5.0f, NAN}}, p); }, ::testing::ThrowsMessage<Error>(HasSubstr("not finite")));
  EXPECT_NO_THROW(extract(prepared, {{-0.4f, 71.4f}}, p)) << "rounds to pixel (0, 71)";
}

TEST_F(Extraction, RejectsAMismatchedPreparedImage) {
  const DescriptorParams p = thesis_with({"mean_c0"});
  const PreparedImage prepared = prepare(image, p);
  DescriptorParams other_space = p;
  other_space.colour_space = ColourSpace::lab;
  EXPECT_THAT([&] { extract(prepared, keypoints, other_space); },
              ::testing::ThrowsMessage<Error>(HasSubstr("other preprocessing parameters")));
  DescriptorParams missing = thesis_with({"mean_c0", "std_gevers_c2"});
  EXPECT_THAT([&] { extract(prepared, keypoints, missing); },
              ::testing::ThrowsMessage<Error>(HasSubstr("lacks the Gevers c2 plane")));
  DescriptorParams small = p;
  small.patch_radius = 3;
  const PreparedImage small_border = prepare(image, small);
  EXPECT_THAT([&] { extract(small_border, keypoints, p); },
              ::testing::ThrowsMessage<Error>(HasSubstr("exceeds the prepared border")));
  EXPECT_NO_THROW(extract(prepared, keypoints, small)) << "a smaller patch fits the wider border";
}

TEST_F(Extraction, EveryColourSpaceAndOperatorGivesFiniteValues) {
  DescriptorParams p = Genome::thesis_best().decode();
  p.activation.set();
  for (const ColourSpace space : kColourSpaces)
    for (const GradientOperator op : kGradientOperators) {
      p.colour_space = space;
      p.gradient_operator = op;
      p.patch_radius = 4;
      const cv::Mat d = extract(prepare(image, p), keypoints, p);
      EXPECT_TRUE(cv::checkRange(d)) << colour_space_name(space) << " " << gradient_operator_name(op);
    }
}

}  // namespace
}  // namespace facadeslam::semantics
