// Random forest: learning, vote shares, determinism, the model file and its
// failure modes (damaged, truncated, mismatched).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <opencv2/core.hpp>

#include "core/util/error.hpp"
#include "semantics/forest/forest_model.hpp"
#include "semantics/forest/random_forest.hpp"
#include "tests/semantics/forest_test_data.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

using test_util::blobs;
using test_util::read_bytes;
using test_util::small_forest;
using test_util::write_bytes;
using ::testing::AllOf;
using ::testing::HasSubstr;

class Forest : public ::testing::Test {
 protected:
  void SetUp() override {
    blobs(100, 1, train_x, train_y);
    blobs(50, 2, test_x, test_y);
    forest = RandomForest::train(train_x, train_y, small_forest());
  }
  cv::Mat train_x, test_x;
  std::vector<int> train_y, test_y;
  RandomForest forest;
};

TEST_F(Forest, LearnsASeparableProblem) {
  ASSERT_TRUE(forest.trained());
  EXPECT_EQ(forest.descriptor_width(), 3);
  EXPECT_EQ(forest.tree_count(), 15);
  EXPECT_EQ(forest.classes(), (std::vector<int>{1, 4, 6}));
  const std::vector<int> predicted = forest.predict(test_x);
  ASSERT_EQ(predicted.size(), test_y.size());
  int correct = 0;
  for (std::size_t i = 0; i < predicted.size(); ++i) correct += predicted[i] == test_y[i];
  EXPECT_GE(correct, static_cast<int>(0.97 * static_cast<double>(test_y.size())));
}

TEST_F(Forest, ProbabilitiesAreVoteSharesSummingToOne) {
  cv::Mat p;
  const std::vector<int> predicted = forest.predict(test_x, p);
  ASSERT_EQ(p.rows, test_x.rows);
  ASSERT_EQ(p.cols, 3);
  ASSERT_EQ(p.type(), CV_32F);
  for (int r = 0; r < p.rows; ++r) {
    double sum = 0;
    int best = 0;
    for (int c = 0; c < p.cols; ++c) {
      const float v = p.at<float>(r, c);
      EXPECT_GE(v, 0.f);
      EXPECT_LE(v, 1.f);
      // A vote share is a multiple of 1 / trees.
      EXPECT_NEAR(v * 15.f, std::round(v * 15.f), 1e-4);
      sum += v;
      if (v > p.at<float>(r, best)) best = c;
    }
    EXPECT_NEAR(sum, 1.0, 1e-5) << "row " << r;
    EXPECT_EQ(predicted[static_cast<std::size_t>(r)], forest.classes()[static_cast<std::size_t>(best)]);
  }
  // Far inside a blob the forest is unanimous.
  const cv::Mat centre = (cv::Mat_<float>(1, 3) << 5.f, 0.f, 0.5f);
  const cv::Mat q = forest.probabilities(centre);
  EXPECT_FLOAT_EQ(q.at<float>(0, 1), 1.f);
}

TEST_F(Forest, FlatTreeWalkVotesLikeOpenCv) {
  EXPECT_EQ(cv::norm(forest.votes(test_x), forest.opencv_votes(test_x), cv::NORM_INF), 0.0);
  // Values on and around the thresholds too: a grid over the whole space,
  // and rows of the training data (thresholds sit between their values).
  cv::Mat grid(0, 3, CV_32F);
  for (float x = -2.f; x <= 7.f; x += 0.25f)
    for (float y = -2.f; y <= 7.f; y += 0.25f) grid.push_back(cv::Mat((cv::Mat_<float>(1, 3) << x, y, 0.5f)));
  EXPECT_EQ(cv::norm(forest.votes(grid), forest.opencv_votes(grid), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(forest.votes(train_x), forest.opencv_votes(train_x), cv::NORM_INF), 0.0);
  // A wider forest on many classes and values.
  cv::Mat x(600, 12, CV_32F);
  cv::randu(x, 0, 1);
  std::vector<int> y;
  for (int r = 0; r < x.rows; ++r) y.push_back(static_cast<int>(x.at<float>(r, 0) * 4 + x.at<float>(r, 3) * 3) % 7);
  ForestParams p;
  p.trees = 30;
  p.split_variables = 5;
  const RandomForest wide = RandomForest::train(x, y, p);
  cv::Mat probe(300, 12, CV_32F);
  cv::randu(probe, 0, 1);
  EXPECT_EQ(cv::norm(wide.votes(probe), wide.opencv_votes(probe), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(wide.votes(x), wide.opencv_votes(x), cv::NORM_INF), 0.0);
}

TEST_F(Forest, TrainingIsDeterministic) {
  const RandomForest again = RandomForest::train(train_x, train_y, small_forest());
  cv::Mat p1, p2;
  forest.predict(test_x, p1);
  again.predict(test_x, p2);
  EXPECT_EQ(cv::norm(p1, p2, cv::NORM_INF), 0.0);
}

TEST_F(Forest, ClampsSplitVariablesToTheWidth) {
  ForestParams p = small_forest();
  p.split_variables = 35;
  EXPECT_NO_THROW(RandomForest::train(train_x, train_y, p));
}

TEST_F(Forest, RejectsBadInput) {
  EXPECT_THROW(RandomForest::train(cv::Mat(0, 3, CV_32F), {}, small_forest()), Error);
  EXPECT_THROW(RandomForest::train(train_x, std::vector<int>(5, 1), small_forest()), Error);
  cv::Mat doubles;
  train_x.convertTo(doubles, CV_64F);
  EXPECT_THROW(RandomForest::train(doubles, train_y, small_forest()), Error);
  cv::Mat with_nan = train_x.clone();
  with_nan.at<float>(7, 1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THAT([&] { RandomForest::train(with_nan, train_y, small_forest()); },
              ::testing::ThrowsMessage<Error>(HasSubstr("row 7")));
  std::vector<int> negative = train_y;
  negative[0] = -1;
  EXPECT_THROW(RandomForest::train(train_x, negative, small_forest()), Error);
  ForestParams zero = small_forest();
  zero.trees = 0;
  EXPECT_THROW(RandomForest::train(train_x, train_y, zero), Error);
  EXPECT_THAT([&] { forest.predict(cv::Mat::zeros(2, 4, CV_32F)); },
              ::testing::ThrowsMessage<Error>(HasSubstr("trained on 3")));
  EXPECT_THROW(RandomForest().predict(test_x), Error);
}

TEST(ForestParamsTest, ComeFromTheGenome) {
  const ForestParams p = forest_params(Genome::thesis_best().decode());
  EXPECT_EQ(p.trees, 100);
  EXPECT_EQ(p.max_depth, 35);
  EXPECT_EQ(p.split_variables, 16);
}

// ---------------------------------------------------------------- model file

class ForestModelFile : public Forest {
 protected:
  void SetUp() override {
    Forest::SetUp();
    model.descriptor = "edd";
    model.genome = Genome::thesis_best();
    model.classes = labelmefacade_class_table();
    model.forest = forest;
    expected.descriptor = "edd";
    expected.descriptor_width = 3;
    expected.genome = Genome::thesis_best();
    expected.classes = labelmefacade_class_table();
  }
  test::TempDir dir;
  ForestModel model;
  ForestExpectation expected;
};

TEST_F(ForestModelFile, RoundTripGivesIdenticalPredictions) {
  const auto path = dir / "model.yml.gz";
  save_forest_model(path, model);
  ASSERT_TRUE(std::filesystem::exists(path));
  // gzip magic: OpenCV compressed it.
  const std::string bytes = read_bytes(path);
  ASSERT_GE(bytes.size(), 2u);
  EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0x1f);
  EXPECT_EQ(static_cast<unsigned char>(bytes[1]), 0x8b);
  // No temporary file left beside it.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1);

  const ForestModel loaded = load_forest_model(path, expected);
  EXPECT_EQ(loaded.descriptor, "edd");
  EXPECT_EQ(loaded.genome, Genome::thesis_best());
  EXPECT_EQ(loaded.classes, labelmefacade_class_table());
  EXPECT_EQ(loaded.forest.classes(), forest.classes());
  EXPECT_EQ(loaded.forest.tree_count(), 15);
  cv::Mat p1, p2;
  EXPECT_EQ(forest.predict(test_x, p1), loaded.forest.predict(test_x, p2));
  EXPECT_EQ(cv::norm(p1, p2, cv::NORM_INF), 0.0);
}

TEST_F(ForestModelFile, PlainYamlAndXmlAlsoRoundTrip) {
  for (const char* name : {"model.yml", "model.xml.gz"}) {
    save_forest_model(dir / name, model);
    const ForestModel loaded = load_forest_model(dir / name, expected);
    EXPECT_EQ(loaded.forest.predict(test_x), forest.predict(test_x)) << name;
  }
}

TEST_F(ForestModelFile, TruncatedFileFailsClearly) {
  const auto path = dir / "model.yml.gz";
  save_forest_model(path, model);
  const std::string bytes = read_bytes(path);
  for (const std::size_t keep : {bytes.size() / 2, bytes.size() - 20, std::size_t{10}}) {
    write_bytes(path, bytes.substr(0, keep));
    EXPECT_THAT([&] { load_forest_model(path); }, ::testing::ThrowsMessage<Error>(HasSubstr(path.string())))
        << "kept " << keep << " of " << bytes.size() << " bytes";
  }
}

TEST_F(ForestModelFile, DamagedFilesFailClearly) {
  const auto path = dir / "model.yml.gz";
  write_bytes(path, "this is not a model at all\n\x01\x02\x03");
  EXPECT_THAT([&] { load_forest_model(path); }, ::testing::ThrowsMessage<Error>(HasSubstr(path.string())));
  const auto yaml = dir / "other.yml";
  write_bytes(yaml, "%YAML:1.0\n---\nformat: something-else\n");
  EXPECT_THAT([&] { load_forest_model(yaml); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr(yaml.string()), HasSubstr("facadeslam-forest"))));
  EXPECT_THAT([&] { load_forest_model(dir / "missing.yml.gz"); },
              ::testing::ThrowsMessage<Error>(HasSubstr("no such model file")));
}

TEST_F(ForestModelFile, MissingClassTableFailsClearly) {
  const auto path = dir / "model.yml";
  save_forest_model(path, model);
  std::string text = read_bytes(path);
  const auto from = text.find("classes:"), to = text.find("forest:");
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  text.erase(from, to - from);
  write_bytes(path, text);
  EXPECT_THAT([&] { load_forest_model(path); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr(path.string()), HasSubstr("'classes'"))));
}

TEST_F(ForestModelFile, MismatchedModelFailsClearly) {
  const auto path = dir / "model.yml.gz";
  save_forest_model(path, model);
  ForestExpectation wrong_width = expected;
  wrong_width.descriptor_width = 93;
  EXPECT_THAT([&] { load_forest_model(path, wrong_width); },
              ::testing::ThrowsMessage<Error>(
                  AllOf(HasSubstr(path.string()), HasSubstr("with 3 values"), HasSubstr("expected 'edd' with 93"))));
  ForestExpectation wrong_descriptor = expected;
  wrong_descriptor.descriptor = "sift";
  EXPECT_THAT([&] { load_forest_model(path, wrong_descriptor); },
              ::testing::ThrowsMessage<Error>(HasSubstr("expected 'sift'")));
  ForestExpectation other_genome = expected;
  Genome g = Genome::thesis_best();
  g.set_bit(30, !g.bit(30));
  other_genome.genome = g;
  EXPECT_THAT([&] { load_forest_model(path, other_genome); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr("another genome"), HasSubstr("bit 30"))));
  ForestExpectation other_classes = expected;
  other_classes.classes.pop_back();
  EXPECT_THAT([&] { load_forest_model(path, other_classes); },
              ::testing::ThrowsMessage<Error>(HasSubstr("class table")));
}

TEST_F(ForestModelFile, HeaderInconsistentWithTheForestFails) {
  const auto path = dir / "model.yml";
  save_forest_model(path, model);
  std::string text = read_bytes(path);
  const auto at = text.find("descriptor_width: 3");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 19, "descriptor_width: 7");
  write_bytes(path, text);
  EXPECT_THAT([&] { load_forest_model(path); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr(path.string()), HasSubstr("header says 7"))));
}

TEST_F(ForestModelFile, SaveRejectsBadModelsAndNames) {
  ForestModel untrained = model;
  untrained.forest = RandomForest();
  EXPECT_THROW(save_forest_model(dir / "a.yml.gz", untrained), Error);
  ForestModel missing_class = model;
  missing_class.classes.resize(2);  // the forest predicts 4 and 6
  EXPECT_THAT([&] { save_forest_model(dir / "b.yml.gz", missing_class); },
              ::testing::ThrowsMessage<Error>(HasSubstr("class id 4")));
  EXPECT_THROW(save_forest_model(dir / "c.model", model), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "a.yml.gz"));
  EXPECT_FALSE(std::filesystem::exists(dir / "b.yml.gz"));
}

}  // namespace
}  // namespace facadeslam::semantics
