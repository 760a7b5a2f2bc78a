// End to end: `facadeslam evaluate labels` on a small synthetic dataset the
// test writes itself; bad input must give one line on stderr and a non-zero
// exit code.
#include <algorithm>
#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "semantics/descriptor/genome.hpp"
#include "semantics/text.hpp"
#include "tests/apps/cli_run.hpp"
#include "tests/apps/dataset_cli_test_fixture.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

class EvaluateLabelsCli : public test::DatasetCliTest {
 protected:
  std::string dataset_option() const {
    std::string s = "--dataset ";
    return s.append(test::shell_quoted(data().string()));
  }
  // " --json J --confusion P", quoted.
  static std::string report_options(const std::filesystem::path& json, const std::filesystem::path& png) {
    return semantics::cat(" --json ", test::shell_quoted(json.string()), " --confusion ",
                          test::shell_quoted(png.string()));
  }
  // The run must fail with exactly one line on stderr.
  void expect_one_line_error(const test::CliResult& r, const std::string& mention) {
    EXPECT_NE(r.exit_code, 0);
    EXPECT_THAT(r.err, HasSubstr(mention));
    const auto lines = std::count(r.err.begin(), r.err.end(), '\n');
    EXPECT_EQ(lines, 1) << r.err;
  }
};

TEST_F(EvaluateLabelsCli, WritesReportPlotAndModel) {
  const auto json = dir_ / "out/report.json", png = dir_ / "out/confusion.png", model = dir_ / "out/model.yml.gz";
  std::string args = "-q evaluate labels ";
  args.append(dataset_option())
      .append(" --descriptor edd --step 7")
      .append(report_options(json, png))
      .append(" --model-out ")
      .append(test::shell_quoted(model.string()));
  const auto r = run(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("overall recognition rate"));
  const std::string report = test::read_file_text(json);
  for (const char* key :
       {"overall_recognition_rate", "average_recognition_rate", "extraction_ms_per_image", "forest_ms_per_image"})
    EXPECT_TRUE(std::isfinite(test::json_number(report, key))) << key;
  EXPECT_GT(test::json_number(report, "overall_recognition_rate"), 0.8);
  EXPECT_EQ(test::json_number(report, "test_images"), 2.0);
  EXPECT_THAT(report, HasSubstr("\"per_class\""));
  EXPECT_FALSE(cv::imread(png.string()).empty());
  EXPECT_TRUE(std::filesystem::exists(model));
}

TEST_F(EvaluateLabelsCli, SeveralDescriptorsInOneRunGiveAComparison) {
  const auto json = dir_ / "out/report.json", png = dir_ / "out/confusion.png";
  std::string args = "-q evaluate labels ";
  args.append(dataset_option()).append(" --descriptor edd,orb --max-test 1 --step 9").append(report_options(json, png));
  const auto r = run(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("| edd | 113 |"));
  EXPECT_THAT(r.out, HasSubstr("| orb | 256 |"));
  const std::string report = test::read_file_text(json);
  EXPECT_THAT(report, HasSubstr("\"comparison\""));
  EXPECT_THAT(report, HasSubstr("\"runs\""));
  EXPECT_FALSE(cv::imread((dir_ / "out/confusion_edd.png").string()).empty());
  EXPECT_FALSE(cv::imread((dir_ / "out/confusion_orb.png").string()).empty());
  EXPECT_FALSE(std::filesystem::exists(png));
  // A model file holds one forest.
  expect_one_line_error(
      run(semantics::cat("evaluate labels ", dataset_option(), " --descriptor all --model-out m.yml.gz")),
      "one --descriptor");
}

TEST_F(EvaluateLabelsCli, GenomeAsStringOrFile) {
  const std::string bits = semantics::Genome::thesis_best().to_string();
  test::write_text(dir_ / "genome.txt", bits + "\n");
  for (const std::string& genome : {bits, (dir_ / "genome.txt").string()}) {
    std::string args = "-q evaluate labels ";
    args.append(dataset_option())
        .append(" --max-train 1 --max-test 1 --step 12 --genome ")
        .append(test::shell_quoted(genome));
    const auto r = run(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
  }
}

TEST_F(EvaluateLabelsCli, MissingDatasetFolder) {
  expect_one_line_error(run("evaluate labels --dataset /nonexistent/facades"), "no such dataset folder");
}

TEST_F(EvaluateLabelsCli, MissingTrainList) {
  std::filesystem::remove(data() / "train.txt");
  expect_one_line_error(run(semantics::cat("evaluate labels ", dataset_option())), "train.txt");
}

TEST_F(EvaluateLabelsCli, ImageWithoutLabel) {
  std::filesystem::remove(data() / "labels/facade_4.png");
  expect_one_line_error(run(semantics::cat("evaluate labels ", dataset_option())), "facade_4.png");
}

TEST_F(EvaluateLabelsCli, LabelOfAnotherSize) {
  cv::imwrite((data() / "labels/facade_0.png").string(), cv::Mat(20, 30, CV_8UC3, cv::Scalar::all(0)));
  expect_one_line_error(run(semantics::cat("evaluate labels ", dataset_option())), "30x20");
}

TEST_F(EvaluateLabelsCli, UnknownDescriptor) {
  const auto r = run(semantics::cat("evaluate labels ", dataset_option(), " --descriptor surf"));
  expect_one_line_error(r, "--descriptor");
}

TEST_F(EvaluateLabelsCli, BadGenomeString) {
  expect_one_line_error(run(semantics::cat("evaluate labels ", dataset_option(), " --genome 0101")), "211");
  expect_one_line_error(run(semantics::cat("evaluate labels ", dataset_option(), " --genome nonsense.txt")),
                        "neither a genome file nor");
  std::string bad = semantics::Genome::thesis_best().to_string();
  bad[5] = '2';
  expect_one_line_error(run(semantics::cat("evaluate labels ", dataset_option(), " --genome ", bad)), "character 5");
}

TEST_F(EvaluateLabelsCli, BadOutputNamesFailBeforeTheRun) {
  expect_one_line_error(run(semantics::cat("evaluate labels ", dataset_option(), " --confusion cm.jpg")), ".png");
  expect_one_line_error(run(semantics::cat("evaluate labels ", dataset_option(), " --model-out model.bin")),
                        ".fsmodel");
}

}  // namespace
}  // namespace facadeslam
