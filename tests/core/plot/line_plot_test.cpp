#include "core/plot/line_plot.hpp"

#include <cmath>
#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/plot/png_file.hpp"
#include "core/util/error.hpp"
#include "core/util/png_signature.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::plot {
namespace {

// Pixels of exactly this BGR colour (anti-aliased edges blend; line centres don't).
int count_colour(const cv::Mat& image, const cv::Scalar& colour) {
  cv::Mat mask;
  cv::inRange(image, colour, colour, mask);
  return cv::countNonZero(mask);
}

cv::Rect bounding_box_of(const cv::Mat& image, const cv::Scalar& colour) {
  cv::Mat mask;
  cv::inRange(image, colour, colour, mask);
  std::vector<cv::Point> points;
  cv::findNonZero(mask, points);
  return cv::boundingRect(points);
}

LinePlot two_series_plot() {
  LinePlot plot;
  plot.set_title("Fitness per generation");
  plot.set_x_label("generation");
  plot.set_y_label("fitness");
  std::vector<double> best, mean;
  for (int g = 0; g < 30; ++g) {
    best.push_back(0.5 + 0.25 * (1.0 - std::exp(-0.2 * g)));
    mean.push_back(0.4 + 0.2 * (1.0 - std::exp(-0.1 * g)));
  }
  plot.add_indexed_series("best", best);
  SeriesStyle dots;
  dots.markers = true;
  plot.add_indexed_series("mean", mean, dots);
  return plot;
}

TEST(LinePlot, TwoSeriesWriteAPngOfTheRightSizeWithLegend) {
  test::TempDir dir;
  const auto plot = two_series_plot();
  plot.save_png(dir / "plots" / "fitness.png");
  const cv::Mat image = cv::imread((dir / "plots" / "fitness.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 1000);
  EXPECT_EQ(image.rows, 800);

  // Not blank: a white background with a fair amount drawn on it.
  cv::Mat grey, drawn;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  cv::threshold(grey, drawn, 250, 255, cv::THRESH_BINARY_INV);
  EXPECT_GT(cv::countNonZero(drawn), 5000);
  EXPECT_LT(cv::countNonZero(drawn), image.total() / 2);
  EXPECT_EQ(image.at<cv::Vec3b>(2, 2), cv::Vec3b(255, 255, 255));

  // Both series colours are in the legend box, and distinct.
  const auto layout = plot.layout();
  ASSERT_FALSE(layout.legend.empty());
  EXPECT_TRUE((cv::Rect(0, 0, 1000, 800) & layout.legend) == layout.legend);
  EXPECT_NE(series_colour(0), series_colour(1));
  const cv::Mat legend = image(layout.legend);
  EXPECT_GT(count_colour(legend, series_colour(0)), 20);
  EXPECT_GT(count_colour(legend, series_colour(1)), 20);
  // And the curves are drawn in the plot area, outside the legend too.
  EXPECT_GT(count_colour(image(layout.plot_area), series_colour(0)), count_colour(legend, series_colour(0)) + 100);
}

TEST(LinePlot, RenderHasTheRequestedSize) {
  LinePlot plot(640, 480);
  plot.add_indexed_series("", {1.0, 2.0, 3.0});
  const cv::Mat image = plot.render();
  EXPECT_EQ(image.size(), cv::Size(640, 480));
  EXPECT_EQ(image.type(), CV_8UC3);
  EXPECT_TRUE(plot.layout().legend.empty());  // no named series, no legend
  EXPECT_GT(count_colour(image, series_colour(0)), 50);
}

TEST(LinePlot, EqualAxesDrawACircleAsACircle) {
  LinePlot plot;  // 1000 x 800: unequal axes would stretch it
  plot.set_equal_axes(true);
  std::vector<double> x, y;
  for (int i = 0; i <= 360; ++i) {
    x.push_back(3.0 + 2.0 * std::cos(i * std::numbers::pi / 180.0));
    y.push_back(-1.0 + 2.0 * std::sin(i * std::numbers::pi / 180.0));
  }
  SeriesStyle red;
  red.colour = cv::Scalar(0, 0, 255);
  plot.add_series("", x, y, red);
  const cv::Rect box = bounding_box_of(plot.render(), cv::Scalar(0, 0, 255));
  EXPECT_GT(box.width, 300);
  EXPECT_NEAR(box.width, box.height, 3);

  plot.set_equal_axes(false);
  const cv::Rect stretched = bounding_box_of(plot.render(), cv::Scalar(0, 0, 255));
  EXPECT_GT(std::abs(stretched.width - stretched.height), 50);
}

TEST(LinePlot, NonFinitePointsAreSkipped) {
  LinePlot plot;
  plot.add_series("gaps", {0.0, 1.0, std::nan(""), 3.0, 4.0}, {0.0, 1.0, 2.0, 3.0, 4.0});
  EXPECT_NO_THROW(plot.render());
}

TEST(LinePlot, SinglePointWithEqualAxesIsDrawn) {
  LinePlot plot;
  plot.set_equal_axes(true);
  SeriesStyle dot;
  dot.markers = true;
  dot.colour = cv::Scalar(0, 0, 255);
  plot.add_series("", {2.0}, {-1.0}, dot);
  const cv::Rect box = bounding_box_of(plot.render(), cv::Scalar(0, 0, 255));
  EXPECT_GE(box.width, 3);
  EXPECT_TRUE(plot.layout().plot_area.contains(box.tl()));
}

TEST(LinePlot, FixedYRangePlacesValuesOnItsScale) {
  // A flat line at 0.2: alone it would sit mid-plot (its range is widened
  // around the value); on a 0..1 axis it sits at a fifth of the height.
  LinePlot plot;
  SeriesStyle red;
  red.colour = cv::Scalar(0, 0, 255);
  plot.add_series("", {0.0, 1.0}, {0.2, 0.2}, red);
  const cv::Rect area = plot.layout().plot_area;
  const auto height_fraction = [&] {
    const cv::Rect box = bounding_box_of(plot.render(), cv::Scalar(0, 0, 255));
    return (area.y + area.height - 1 - (box.y + box.height / 2.0)) / (area.height - 1);
  };
  EXPECT_NEAR(height_fraction(), 0.5, 0.02);
  plot.set_y_range(0.0, 1.0);
  EXPECT_NEAR(height_fraction(), (0.2 + 0.03) / 1.06, 0.02);  // 3 % of air below 0 and above 1
}

TEST(LinePlot, FixedXRangePlacesValuesOnItsScale) {
  // A vertical segment at x = 100 of a 0..1000 axis sits at a tenth of the
  // width (3 % of air either side), not where nice ticks around 100 put it.
  LinePlot plot;
  SeriesStyle red;
  red.colour = cv::Scalar(0, 0, 255);
  plot.add_series("", {100.0, 100.0}, {0.0, 1.0}, red);
  plot.add_series("", {900.0}, {0.5});
  plot.set_x_range(0.0, 1000.0);
  const cv::Rect area = plot.layout().plot_area;
  const cv::Rect box = bounding_box_of(plot.render(), cv::Scalar(0, 0, 255));
  EXPECT_NEAR((box.x + box.width / 2.0 - area.x) / (area.width - 1), (100.0 + 30.0) / 1060.0, 0.02);
}

TEST(LinePlot, BadRangeIsAnError) {
  LinePlot plot;
  EXPECT_THROW(plot.set_y_range(1.0, 1.0), Error);
  EXPECT_THROW(plot.set_y_range(1.0, 0.0), Error);
  EXPECT_THROW(plot.set_y_range(0.0, std::nan("")), Error);
  EXPECT_THROW(plot.set_x_range(2.0, -1.0), Error);
}

TEST(LinePlot, EmptyPlotStillRenders) {
  const cv::Mat image = LinePlot().render();
  EXPECT_EQ(image.size(), cv::Size(1000, 800));
}

TEST(LinePlot, BadOutputPathIsAnError) {
  test::TempDir dir;
  test::write_text(dir / "file", "x");
  const auto plot = two_series_plot();
  const auto target = dir / "file" / "plot.png";  // parent is a regular file
  try {
    plot.save_png(target);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr((dir / "file").string()));
  }
  EXPECT_FALSE(std::filesystem::exists(target));
}

TEST(LinePlot, NonPngNameIsAnError) {
  test::TempDir dir;
  EXPECT_THROW(two_series_plot().save_png(dir / "plot.jpg"), Error);
  EXPECT_THROW(two_series_plot().save_png(dir / "plot"), Error);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

// Every PNG the program writes is signed as its own (output_policy.hpp
// replaces only those) and reads back pixel for pixel, 16-bit ones too.
TEST(PngFile, IsSignedAndReadsBack) {
  test::TempDir dir;
  cv::Mat picture(40, 60, CV_8UC3);
  cv::randu(picture, 0, 255);
  cv::Mat depth(40, 60, CV_16UC1);
  cv::randu(depth, 0, 65535);
  save_png(dir / "picture.png", picture);
  save_png(dir / "depth.png", depth, {cv::IMWRITE_PNG_COMPRESSION, 1});
  EXPECT_TRUE(is_signed_png(dir / "picture.png"));
  EXPECT_TRUE(is_signed_png(dir / "depth.png"));
  EXPECT_EQ(cv::norm(cv::imread((dir / "picture.png").string(), cv::IMREAD_UNCHANGED), picture, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(cv::imread((dir / "depth.png").string(), cv::IMREAD_UNCHANGED), depth, cv::NORM_INF), 0.0);
  ASSERT_TRUE(cv::imwrite((dir / "photo.png").string(), picture));
  EXPECT_FALSE(is_signed_png(dir / "photo.png")) << "a PNG another program wrote";
  EXPECT_FALSE(is_signed_png(dir / "missing.png"));
}

TEST(LinePlot, MismatchedSeriesIsAnError) {
  LinePlot plot;
  EXPECT_THROW(plot.add_series("bad", std::vector<double>{1.0, 2.0}, std::vector<double>{1.0}), Error);
}

TEST(LinePlot, TooSmallIsAnError) { EXPECT_THROW(LinePlot(100, 100), Error); }

}  // namespace
}  // namespace facadeslam::plot
