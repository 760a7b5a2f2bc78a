// The invariance suite end to end in the library: identity changes give a
// match rate of 1 for every descriptor; a colour-ratio descriptor keeps its
// matches under a light intensity change while raw colour values lose them
// (the suite measures invariance, not just "something"); bad input fails with
// one clear message; the image list, report and plots.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/util/error.hpp"
#include "semantics/invariance/illuminant.hpp"
#include "semantics/invariance/image_list.hpp"
#include "semantics/invariance/invariance_plot.hpp"
#include "semantics/invariance/invariance_report.hpp"
#include "semantics/invariance/invariance_suite.hpp"
#include "tests/semantics/semantics_test_util.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// The colours of the 5 x 5 patch around a keypoint, either as stored (B, G,
// R: 75 values) or as normalised rgb, r = R / (R + G + B), g = G / (R + G + B)
// (50 values), which a light intensity change a (R, G, B) leaves unchanged
// (Gevers and Smeulders' normalised rgb, thesis Table 2.5).
class PatchColours : public PointDescriptor {
 public:
  explicit PatchColours(bool normalised) : normalised_(normalised) {}
  std::string_view name() const override { return normalised_ ? "normalised-rgb" : "raw-colour"; }
  int width() const override { return normalised_ ? 50 : 75; }
  cv::Mat compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) override {
    check_descriptor_input(name(), bgr, keypoints);
    cv::Mat rows(static_cast<int>(keypoints.size()), width(), CV_32F);
    for (std::size_t k = 0; k < keypoints.size(); ++k) {
      float* row = rows.ptr<float>(static_cast<int>(k));
      int column = 0;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const int x = std::clamp(cvRound(keypoints[k].x) + dx, 0, bgr.cols - 1);
          const int y = std::clamp(cvRound(keypoints[k].y) + dy, 0, bgr.rows - 1);
          const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
          if (normalised_) {
            const float sum = std::max(1.0f, static_cast<float>(p[0] + p[1] + p[2]));
            row[column++] = p[2] / sum;
            row[column++] = p[1] / sum;
          } else {
            for (int c = 0; c < 3; ++c) row[column++] = p[c];
          }
        }
    }
    return rows;
  }

 private:
  bool normalised_;
};

// Every keypoint sees its own mix of colours: red grows to the right, green
// downwards, blue falls to the right, with a little noise.
cv::Mat colour_ramp(cv::Size size) {
  cv::Mat image(size, CV_8UC3);
  cv::RNG rng(3);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const int blue_noise = rng.uniform(0, 3);  // one draw a statement: in order
      const int green_noise = rng.uniform(0, 3);
      const int red_noise = rng.uniform(0, 3);
      image.at<cv::Vec3b>(y, x) =
          cv::Vec3b(cv::saturate_cast<uchar>(170 - x / 2 + blue_noise),
                    cv::saturate_cast<uchar>(60 + 1.3 * y + green_noise), cv::saturate_cast<uchar>(60 + x + red_noise));
    }
  return image;
}

fs::path write_image(const fs::path& path, const cv::Mat& image) {
  cv::imwrite(path.string(), image);
  return path;
}

InvarianceOptions only(std::vector<InvarianceCaseRun> cases) {
  InvarianceOptions options;
  options.cases = std::move(cases);
  return options;
}

double rate(const InvarianceResult& r, std::size_t case_index, std::size_t descriptor, std::size_t value) {
  return r.cases.at(case_index).match_rate.at(descriptor).at(value);
}

TEST(InvarianceSuite, IdentityChangesGiveMatchRateOneForEveryDescriptor) {
  test::TempDir dir;
  const fs::path image = write_image(dir / "textured.png", test_util::textured_image({150, 110}, 11));
  std::vector<std::unique_ptr<PointDescriptor>> owned;
  std::vector<PointDescriptor*> descriptors;
  for (const std::string_view name : kPointDescriptorNames) {
    owned.push_back(make_point_descriptor(name, Genome::thesis_best()));
    descriptors.push_back(owned.back().get());
  }
  const InvarianceResult r = run_invariance({image}, descriptors,
                                            only({{InvarianceCase::blur, {1}},
                                                  {InvarianceCase::rotation, {0}},
                                                  {InvarianceCase::resize, {1}},
                                                  {InvarianceCase::affine, {0}},
                                                  {InvarianceCase::intensity_scale, {1}},
                                                  {InvarianceCase::intensity_shift, {0}},
                                                  {InvarianceCase::temperature, {kReferenceKelvin}}}));
  // Grid 15 .. 134 x 15 .. 94 in steps of 9.
  EXPECT_EQ(r.reference_keypoints, 14u * 9u);
  ASSERT_EQ(r.descriptors.size(), 5u);
  for (std::size_t c = 0; c < r.cases.size(); ++c)
    for (std::size_t d = 0; d < descriptors.size(); ++d) {
      EXPECT_EQ(rate(r, c, d, 0), 1.0) << case_info(r.cases[c].id).name << " " << r.descriptors[d];
      EXPECT_EQ(r.cases[c].compared[d][0], r.reference_keypoints);
    }
}

TEST(InvarianceSuite, ColourRatiosSurviveALightIntensityChangeRawColoursDoNot) {
  test::TempDir dir;
  const fs::path image = write_image(dir / "ramp.png", colour_ramp({160, 120}));
  PatchColours raw(false), ratios(true);
  const InvarianceResult r =
      run_invariance({image}, {&raw, &ratios}, only({{InvarianceCase::intensity_scale, {1, 0.5, 0.75}}}));
  // Both tell the keypoints apart in the unchanged image ...
  EXPECT_EQ(rate(r, 0, 0, 0), 1.0);
  EXPECT_EQ(rate(r, 0, 1, 0), 1.0);
  // ... but only the ratios still do after a (R, G, B) -> a (R, G, B) change.
  for (const std::size_t v : {1u, 2u}) {
    EXPECT_GT(rate(r, 0, 1, v), 0.9) << "factor " << r.cases[0].values[v];
    EXPECT_LT(rate(r, 0, 0, v), 0.2) << "factor " << r.cases[0].values[v];
  }
}

TEST(InvarianceSuite, GeometricChangesKeepOnlyKeypointsThatStayInside) {
  test::TempDir dir;
  const fs::path image = write_image(dir / "ramp.png", colour_ramp({160, 120}));
  PatchColours raw(false);
  const InvarianceResult r =
      run_invariance({image}, {&raw}, only({{InvarianceCase::rotation, {0, 45}}, {InvarianceCase::resize, {0.25}}}));
  const auto& turned = r.cases[0].compared[0];
  EXPECT_EQ(turned[0], r.reference_keypoints);
  EXPECT_GT(turned[1], 0u);
  EXPECT_LT(turned[1], turned[0]);  // the corners fall into the fill margin
  // A quarter of 160 x 120 is 40 x 30: no keypoint keeps a 15-pixel margin.
  EXPECT_EQ(r.cases[1].compared[0][0], 0u);
  EXPECT_TRUE(std::isnan(rate(r, 1, 0, 0)));
}

TEST(InvarianceSuite, CurvePointsAreMeansOverImages) {
  test::TempDir dir;
  const fs::path a = write_image(dir / "a.png", colour_ramp({160, 120}));
  const fs::path b = write_image(dir / "b.png", test_util::textured_image({160, 120}, 12));
  PatchColours raw(false);
  const InvarianceResult r = run_invariance({a, b}, {&raw}, only({{InvarianceCase::blur, {1, 9}}}));
  const auto& c = r.cases[0];
  for (std::size_t v = 0; v < 2; ++v)
    EXPECT_DOUBLE_EQ(c.match_rate[0][v], 0.5 * (c.per_image[0][v][0] + c.per_image[0][v][1]));
  EXPECT_EQ(c.match_rate[0][0], 1.0);
  EXPECT_LT(c.match_rate[0][1], 1.0);  // a 9 x 9 blur moves raw colours
}

class InvarianceBadInput : public ::testing::Test {
 protected:
  void SetUp() override { image_ = write_image(dir_ / "ok.png", colour_ramp({80, 60})); }
  std::string error_with(const InvarianceOptions& options, std::vector<fs::path> images = {}) {
    if (images.empty()) images = {image_};
    return test::error_of([&] { run_invariance(images, {&raw_}, options); });
  }
  test::TempDir dir_;
  fs::path image_;
  PatchColours raw_{false};
};

TEST_F(InvarianceBadInput, BadOptionsNameTheProblem) {
  InvarianceOptions o = only({{InvarianceCase::blur, {1}}});
  o.step = 0;
  EXPECT_THAT(error_with(o), HasSubstr("grid step must be at least 1"));
  o.step = 9;
  o.margin = -2;
  EXPECT_THAT(error_with(o), HasSubstr("margin must be >= 0"));
  EXPECT_THAT(error_with(only({})), HasSubstr("no case"));
  EXPECT_THAT(error_with(only({{InvarianceCase::blur, {1}}, {InvarianceCase::blur, {3}}})),
              HasSubstr("blur is listed twice"));
  EXPECT_THAT(error_with(only({{InvarianceCase::jpeg, {150}}})), HasSubstr("jpeg: 150"));
  EXPECT_THAT(test::error_of([&] {
                run_invariance({image_}, {}, only({{InvarianceCase::blur, {1}}}));
              }),
              HasSubstr("no descriptor"));
}

TEST_F(InvarianceBadInput, UnreadableOrTinyImagesAreNamed) {
  test::write_text(dir_ / "fake.png", "not a picture");
  const InvarianceOptions o = only({{InvarianceCase::blur, {1}}});
  EXPECT_THAT(error_with(o, {image_, dir_ / "fake.png"}), HasSubstr((dir_ / "fake.png").string()));
  const fs::path tiny = write_image(dir_ / "tiny.png", colour_ramp({25, 25}));
  const std::string message = error_with(o, {tiny});
  EXPECT_THAT(message, HasSubstr("tiny.png"));
  EXPECT_THAT(message, HasSubstr("25x25: too small"));
}

TEST(ImageList, FoldersFilesAndListsInTheGivenOrder) {
  test::TempDir dir;
  fs::create_directories(dir / "photos");
  fs::create_directories(dir / "set/images");
  for (const char* name :
       {"photos/b.png", "photos/a.jpg", "set/images/street_1.jpg", "set/images/street_2.png", "one.png"})
    write_image(dir / name, colour_ramp({20, 20}));
  fs::rename(dir / "photos/a.jpg", dir / "photos/a.JPG");  // extensions in any case
  test::write_text(dir / "photos/notes.txt", "not an image");
  test::write_text(dir / "set/test.txt", "# LabelMeFacade-style names\nstreet_2\n\nimages/street_1.jpg\n");
  const auto images = list_images({dir / "photos", dir / "one.png", dir / "set/test.txt"});
  const std::vector<fs::path> expected{dir / "photos/a.JPG", dir / "photos/b.png", dir / "one.png",
                                       dir / "set/images/street_2.png", dir / "set/images/street_1.jpg"};
  EXPECT_EQ(images, expected);
  EXPECT_EQ(list_images({dir / "photos", dir / "one.png"}, 2).size(), 2u);
}

TEST(ImageList, BadInputsAreNamed) {
  test::TempDir dir;
  fs::create_directories(dir / "empty");
  test::write_text(dir / "empty/readme.md", "no pictures here");
  test::write_text(dir / "list.txt", "missing_one\n");
  test::write_text(dir / "blank.txt", "# nothing\n\n");
  test::write_text(dir / "data.csv", "1,2\n");
  EXPECT_THAT(test::error_of([&] { list_images({dir / "nowhere"}); }),
              HasSubstr((dir / "nowhere").string().append(": no such image file, folder or list")));
  EXPECT_THAT(test::error_of([&] { list_images({dir / "empty"}); }), HasSubstr("no image files in the folder"));
  EXPECT_THAT(test::error_of([&] { list_images({dir / "list.txt"}); }), HasSubstr("line 1: no image 'missing_one'"));
  EXPECT_THAT(test::error_of([&] { list_images({dir / "blank.txt"}); }), HasSubstr("names no image"));
  EXPECT_THAT(test::error_of([&] { list_images({dir / "data.csv"}); }), HasSubstr("not an image file name"));
  EXPECT_THAT(test::error_of([&] { list_images({}); }), HasSubstr("no images given"));
}

InvarianceResult hand_made_result() {
  InvarianceResult r;
  r.images = {"a.png", "b.png"};
  r.descriptors = {"sift", "edd"};
  r.descriptor_widths = {128, 113};
  r.step = 9;
  r.margin = 15;
  r.reference_keypoints = 40;
  InvarianceCaseResult c;
  c.id = InvarianceCase::rotation;
  c.values = {0, 90};
  c.match_rate = {{1.0, 0.25}, {1.0, std::nan("")}};
  c.compared = {{40, 8}, {40, 0}};
  c.matched = {{40, 2}, {40, 0}};
  c.per_image = {{{1.0, 1.0}, {0.25, std::nan("")}}, {{1.0, 1.0}, {std::nan(""), std::nan("")}}};
  r.cases.push_back(c);
  c.id = InvarianceCase::jpeg;
  c.values = {10, 90};
  r.cases.push_back(c);
  return r;
}

TEST(InvarianceReport, JsonHoldsEveryCaseWithValuesAndRatesPerDescriptor) {
  const std::string json = to_json(hand_made_result()).dump();
  EXPECT_THAT(json, HasSubstr("\"case\":\"rotation\""));
  EXPECT_THAT(json, HasSubstr("\"case\":\"jpeg\""));
  EXPECT_THAT(json, HasSubstr("\"values\":[0.0,90.0]"));
  EXPECT_THAT(json, HasSubstr("\"sift\":[1.0,0.25]"));
  EXPECT_THAT(json, HasSubstr("\"edd\":[1.0,null]"));  // no keypoint, no rate
  EXPECT_THAT(json, HasSubstr("\"reference_keypoints\":40"));
  EXPECT_THAT(json, HasSubstr("\"width\":113"));
}

TEST(InvarianceReport, TableHasARowPerValueAndAColumnPerDescriptor) {
  const std::string table = invariance_table(hand_made_result());
  EXPECT_THAT(table, HasSubstr("2 images, 40 reference keypoints (grid step 9, margin 15)"));
  EXPECT_THAT(table, HasSubstr("         sift           edd\n"));
  EXPECT_THAT(table, HasSubstr("\n          90         0.250             -\n"));  // no keypoint, no rate
  EXPECT_THAT(table, HasSubstr("JPEG"));
}

TEST(InvariancePlot, OnePanelPerCaseAndOneFilePerCase) {
  const InvarianceResult r = hand_made_result();
  const cv::Mat figure = invariance_figure(r, 4, {400, 300});
  EXPECT_EQ(figure.size(), cv::Size(800, 300));  // two cases: two panels in a row
  test::TempDir dir;
  const auto files = save_case_plots(dir / "plots", r);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1], dir / "plots/invariance-jpeg.png");
  EXPECT_FALSE(cv::imread(files[0].string()).empty());
  save_invariance_figure(dir / "all.png", r);
  EXPECT_EQ(cv::imread((dir / "all.png").string()).size(), cv::Size(1120, 400));
  EXPECT_THAT(test::error_of([&] { save_invariance_figure(dir / "all.jpg", r); }), HasSubstr(".png"));
}

}  // namespace
}  // namespace facadeslam::semantics
