// End to end: `facadeslam evaluate invariance` on small images the test
// writes itself, and one clear line on stderr with a non-zero exit for bad
// input.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "semantics/text.hpp"
#include "tests/apps/cli_run.hpp"
#include "tests/semantics/semantics_test_util.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using semantics::cat;
using ::testing::HasSubstr;

// The numbers under `key` in the case `case_name` of an invariance report
// (the case's own keys, then its match rates per descriptor); null is NaN.
std::vector<double> case_numbers(const std::string& report, const std::string& case_name, const std::string& key) {
  std::vector<double> values;
  const nlohmann::json json = nlohmann::json::parse(report);
  for (const nlohmann::json& c : json.at("cases")) {
    if (c.at("case") != case_name) continue;
    const nlohmann::json& array = c.contains(key) ? c.at(key) : c.at("match_rate").at(key);
    for (const nlohmann::json& v : array) values.push_back(v.is_null() ? std::nan("") : v.get<double>());
  }
  return values;
}

class EvaluateInvarianceCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(scratch());
    std::filesystem::create_directories(images());
    cv::imwrite((images() / "facade_a.png").string(), semantics::test_util::textured_image({120, 90}, 21));
    cv::imwrite((images() / "facade_b.png").string(), semantics::test_util::textured_image({130, 100}, 22));
  }
  std::filesystem::path images() const { return dir_ / "images"; }
  std::filesystem::path scratch() const { return dir_ / "scratch"; }
  std::string images_option() const { return cat("--images ", test::shell_quoted(images().string())); }
  test::CliResult run(const std::string& arguments) { return test::run_cli(FACADESLAM_BINARY, arguments, scratch()); }
  void expect_one_line_error(const std::string& arguments, const std::string& mention) {
    const test::CliResult r = run(cat("evaluate invariance ", arguments));
    EXPECT_NE(r.exit_code, 0) << arguments;
    EXPECT_THAT(r.err, HasSubstr(mention)) << arguments;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  test::TempDir dir_;
};

TEST_F(EvaluateInvarianceCli, WritesReportAndPlots) {
  const auto json = dir_ / "out/invariance.json", png = dir_ / "out/invariance.png", plots = dir_ / "out/cases";
  const auto r = run(cat("-q evaluate invariance ", images_option(),
                         " --descriptor edd,orb --cases blur,rotation,temperature --blur 1,7 --rotation 0,30",
                         " --temperature 3000,6500 --step 10 --json ", test::shell_quoted(json.string()), " --plot ",
                         test::shell_quoted(png.string()), " --plot-dir ", test::shell_quoted(plots.string())));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("Gaussian blur: match rate per kernel size (px)"));
  const std::string report = test::read_file_text(json);
  EXPECT_EQ(test::json_number(report, "image_count"), 2.0);
  EXPECT_THAT(report, HasSubstr("\"genome\""));
  // Identity values match every keypoint. (ORB still tells these few
  // keypoints apart after a 7 x 7 blur; EDD loses some.)
  EXPECT_LT(case_numbers(report, "blur", "edd").at(1), 0.9);
  for (const char* descriptor : {"edd", "orb"}) {
    const std::vector<double> blur = case_numbers(report, "blur", descriptor);
    ASSERT_EQ(blur.size(), 2u) << descriptor;
    EXPECT_EQ(blur[0], 1.0) << descriptor;
    const std::vector<double> light = case_numbers(report, "temperature", descriptor);
    ASSERT_EQ(light.size(), 2u) << descriptor;
    EXPECT_EQ(light[1], 1.0) << descriptor;  // 6500 K is the reference
  }
  EXPECT_EQ(case_numbers(report, "rotation", "values"), (std::vector<double>{0, 30}));
  EXPECT_FALSE(cv::imread(png.string()).empty());
  for (const char* name : {"invariance-blur.png", "invariance-rotation.png", "invariance-temperature.png"})
    EXPECT_FALSE(cv::imread((plots / name).string()).empty()) << name;
  EXPECT_FALSE(std::filesystem::exists(plots / "invariance-jpeg.png"));  // not run
}

TEST_F(EvaluateInvarianceCli, EveryDescriptorByDefaultAndImagesFromAList) {
  // A LabelMeFacade-style list: names, looked up as images/NAME.{jpg,jpeg,png}.
  test::write_text(dir_ / "test.txt", "facade_b\n");
  const auto json = dir_ / "report.json";
  const auto r = run(cat("-q evaluate invariance --images ", test::shell_quoted((dir_ / "test.txt").string()),
                         " --cases jpeg --jpeg 90 --json ", test::shell_quoted(json.string())));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(json);
  EXPECT_EQ(test::json_number(report, "image_count"), 1.0);
  EXPECT_THAT(report, HasSubstr("images/facade_b.png"));
  for (const char* descriptor : {"modular", "sift", "opponent-sift", "orb", "edd"}) {
    const std::vector<double> rates = case_numbers(report, "jpeg", descriptor);
    ASSERT_EQ(rates.size(), 1u) << descriptor;
    EXPECT_GT(rates[0], 0.0) << descriptor;
  }
}

TEST_F(EvaluateInvarianceCli, MissingImagesFolder) {
  expect_one_line_error("--images /nonexistent/photos", "/nonexistent/photos: no such image file, folder or list");
}

TEST_F(EvaluateInvarianceCli, EmptyImagesFolder) {
  std::filesystem::create_directories(dir_ / "empty");
  expect_one_line_error(cat("--images ", test::shell_quoted((dir_ / "empty").string())),
                        "no image files in the folder");
}

TEST_F(EvaluateInvarianceCli, UnknownDescriptorOrCase) {
  expect_one_line_error(cat(images_option(), " --descriptor sift,surf"), "--descriptor");
  expect_one_line_error(cat(images_option(), " --cases blur,shear"), "--cases: unknown invariance case 'shear'");
}

TEST_F(EvaluateInvarianceCli, BadCaseParameters) {
  expect_one_line_error(cat(images_option(), " --blur 3,4"), "--blur: 4 is not a valid kernel size (px)");
  expect_one_line_error(cat(images_option(), " --jpeg 101"), "--jpeg: 101 is not a valid quality");
  expect_one_line_error(cat(images_option(), " --resize=-1"), "--resize: -1 is not a valid scale factor");
  expect_one_line_error(cat(images_option(), " --affine 11"), "--affine: 11");
  expect_one_line_error(cat(images_option(), " --cases blur --jpeg 50"),
                        "--jpeg: values given for a case that --cases leaves out");
  expect_one_line_error(cat(images_option(), " --step 0"), "--step");
}

TEST_F(EvaluateInvarianceCli, BadOutputNameOrGenomeFailBeforeTheRun) {
  expect_one_line_error(cat(images_option(), " --plot figure.jpg"), "figure.jpg: expected a file name ending in .png");
  expect_one_line_error(cat(images_option(), " --genome 0101"), "211");
}

}  // namespace
}  // namespace facadeslam
