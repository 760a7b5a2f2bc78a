// End to end: `facadeslam train` and `facadeslam evaluate labels --model` on
// a small synthetic dataset the test writes itself. A trained model tested
// on its own must score exactly what `evaluate labels` scores when it
// trains the same forest; bad input gives one line and a non-zero exit.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "semantics/forest/forest_model.hpp"
#include "semantics/text.hpp"
#include "tests/apps/cli_run.hpp"
#include "tests/apps/dataset_cli_test_fixture.hpp"
#include "tests/semantics/forest_test_data.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using semantics::cat;
using ::testing::HasSubstr;

class TrainCli : public test::DatasetCliTest {
 protected:
  std::filesystem::path model() const { return dir_ / "out/small.fsmodel"; }
  static std::string q(const std::filesystem::path& p) { return test::shell_quoted(p.string()); }
  std::string train_args(const std::filesystem::path& out) const {
    return cat("-q train --dataset ", q(data()), " --step 7 --seed 3 --trees 20 --depth 10 --out ", q(out));
  }
  void expect_one_line_error(const test::CliResult& r, const std::string& mention) {
    EXPECT_NE(r.exit_code, 0);
    EXPECT_THAT(r.err, HasSubstr(mention));
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
};

TEST_F(TrainCli, TrainsAModelThatEvaluateLabelsTestsWithoutRetraining) {
  const auto r = run(train_args(model()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("wrote"));
  ASSERT_TRUE(std::filesystem::exists(model()));
  const std::string summary = test::read_file_text(dir_ / "out/small.fsmodel.json");
  EXPECT_EQ(test::json_number(summary, "model_bytes"), static_cast<double>(std::filesystem::file_size(model())));
  EXPECT_EQ(test::json_number(summary, "trees"), 20.0);
  EXPECT_EQ(test::json_number(summary, "max_depth"), 10.0);
  EXPECT_EQ(test::json_number(summary, "train_images"), 3.0);
  EXPECT_GT(test::json_number(summary, "train_rows"), 100.0);
  EXPECT_GT(test::json_number(summary, "sky"), 0.0);  // per-class counts
  EXPECT_THAT(summary, HasSubstr(semantics::Genome::thesis_best().to_string()));

  const auto tested_json = dir_ / "out/tested.json";
  const auto t = run(
      cat("-q evaluate labels --dataset ", q(data()), " --step 7 --model ", q(model()), " --json ", q(tested_json)));
  ASSERT_EQ(t.exit_code, 0) << t.err;
  const std::string tested = test::read_file_text(tested_json);
  EXPECT_GT(test::json_number(tested, "overall_recognition_rate"), 0.8);
  EXPECT_EQ(test::json_number(tested, "test_images"), 2.0);
  EXPECT_THAT(tested, HasSubstr("small.fsmodel"));
  EXPECT_THAT(tested, HasSubstr("\"train_samples\": null"));

  // `evaluate labels` training the genome's forest itself and `train` with
  // the same options write the same model, and testing that model file
  // gives the figures of the run that trained it.
  const auto here = dir_ / "out/here.fsmodel", here_json = dir_ / "out/here.json";
  const auto e = run(cat("-q evaluate labels --dataset ", q(data()), " --step 7 --seed 3 --model-out ", q(here),
                         " --json ", q(here_json)));
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const auto full = dir_ / "out/full.fsmodel";
  ASSERT_EQ(run(cat("-q train --dataset ", q(data()), " --step 7 --seed 3 --out ", q(full))).exit_code, 0);
  EXPECT_EQ(test::read_file_text(full), test::read_file_text(here));
  const auto again_json = dir_ / "out/again.json";
  ASSERT_EQ(
      run(cat("-q evaluate labels --dataset ", q(data()), " --step 7 --model ", q(full), " --json ", q(again_json)))
          .exit_code,
      0);
  const std::string trained = test::read_file_text(here_json), again = test::read_file_text(again_json);
  for (const char* key : {"overall_recognition_rate", "average_recognition_rate", "test_keypoints"})
    EXPECT_EQ(test::json_number(trained, key), test::json_number(again, key)) << key;
}

TEST_F(TrainCli, NeverReadsTheTestList) {
  std::filesystem::remove(data() / "test.txt");
  const auto r = run(train_args(model()));
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(TrainCli, BadInputFailsBeforeTraining) {
  expect_one_line_error(run(train_args(dir_ / "out/model.yml.gz")), ".fsmodel");
  // The output folder cannot exist: a file is in the way.
  test::write_text(dir_ / "blocker", "x");
  expect_one_line_error(run(train_args(dir_ / "blocker/model.fsmodel")), "blocker");
  std::filesystem::create_directories(dir_ / "taken.fsmodel");
  expect_one_line_error(run(train_args(dir_ / "taken.fsmodel")), "is a folder");
  expect_one_line_error(run(cat("train --dataset /nonexistent/facades --out ", q(model()))), "no such dataset folder");
  expect_one_line_error(run(cat("train --dataset ", q(data()), " --genome 0101 --out ", q(model()))), "211");
  std::filesystem::remove(data() / "labels/facade_1.png");
  expect_one_line_error(run(train_args(model())), "facade_1.png");
  EXPECT_FALSE(std::filesystem::exists(model()));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out/small.fsmodel.json"));
}

TEST_F(TrainCli, EvaluateRejectsBadModels) {
  const std::string evaluate = cat("evaluate labels --dataset ", q(data()), " --model ");
  expect_one_line_error(run(evaluate + q(dir_ / "missing.fsmodel")), "missing.fsmodel");
  ASSERT_EQ(run(train_args(model())).exit_code, 0);
  // Training options make no sense with a model: a usage error.
  const auto r = run(evaluate + q(model()) + " --balance");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--balance"));

  // Truncated.
  const std::string bytes = test::read_file_text(model());
  const auto cut = dir_ / "cut.fsmodel";
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  expect_one_line_error(run(evaluate + q(cut)), "cut.fsmodel: truncated");

  // Another class table, and a forest of another width than the descriptor.
  semantics::ForestModel other = semantics::load_forest_model(model());
  other.classes[1].name = "house";
  semantics::save_forest_model(dir_ / "classes.fsmodel", other);
  expect_one_line_error(run(evaluate + q(dir_ / "classes.fsmodel")), "class table");
  cv::Mat x;
  std::vector<int> y;
  semantics::test_util::blobs(30, 1, x, y);
  other.classes = semantics::labelmefacade_class_table();
  other.forest = semantics::RandomForest::train(x, y, semantics::test_util::small_forest());
  semantics::save_forest_model(dir_ / "width.fsmodel", other);
  expect_one_line_error(run(evaluate + q(dir_ / "width.fsmodel")), "expected 'modular' with 93 values");
}

}  // namespace
}  // namespace facadeslam
