// The region-level detector of moving things: a grid of cells, each cell's
// prior-weighted call, smoothed into a density of moving calls.
#include "semantics/worker/moving_regions.hpp"

#include <functional>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace facadeslam::semantics {
namespace {
// Named: the unity build puts this file beside other tests of the worker.
namespace moving_regions_test {

constexpr std::size_t kBuilding = 1, kCar = 2;

// Shares for a forest of two classes (building, car), one row per cell:
// car wins in the cells `car_cell` says.
cv::Mat shares_where(const MovingRegions& regions, const std::function<bool(const cv::Point2f&)>& car_cell,
                     float car_share = 0.7f) {
  cv::Mat shares(static_cast<int>(regions.cells().size()), 2, CV_32F);
  for (int i = 0; i < shares.rows; ++i) {
    const bool car = car_cell(regions.cells()[static_cast<std::size_t>(i)]);
    shares.at<float>(i, 0) = car ? 1.f - car_share : car_share;
    shares.at<float>(i, 1) = car ? car_share : 1.f - car_share;
  }
  return shares;
}

ClassVotes ones() {
  ClassVotes w;
  w.fill(1.f);
  return w;
}

const std::vector<int> kColumns{static_cast<int>(kBuilding), static_cast<int>(kCar)};
const ClassSet kMoving = ClassSet().set(kCar);

TEST(MovingRegions, CellsCoverTheImageAtTheirCentres) {
  const MovingRegions regions(cv::Size(64, 40), {.step = 16, .sigma_cells = 1.0, .min_density = 0.2});
  ASSERT_EQ(regions.cells().size(), 4u * 3u);  // 40 / 16 rounds up: the last row is clamped into the image
  EXPECT_EQ(regions.cells()[0], cv::Point2f(8, 8));
  EXPECT_EQ(regions.cells()[5], cv::Point2f(24, 24));
  EXPECT_EQ(regions.cells()[11], cv::Point2f(56, 39));
}

// A car filling the left half, where a quarter of the cells call it (the
// forest's recall on close-up cars), and a lone car call on the right (a
// mistake): the left half is a region, the lone call is not.
TEST(MovingRegions, DenseMovingCallsMakeARegionALoneCallDoesNot) {
  MovingRegions regions(cv::Size(320, 240), {.step = 16, .sigma_cells = 3.0, .min_density = 0.2});
  EXPECT_EQ(regions.density({10, 10}), 0.0) << "no calls yet";
  const auto cell = [](const cv::Point2f& p) {
    return cv::Point(static_cast<int>(p.x) / 16, static_cast<int>(p.y) / 16);
  };
  regions.set_calls(shares_where(regions,
                                 [&](const cv::Point2f& p) {
                                   const cv::Point c = cell(p);
                                   return (c.x < 8 && c.x % 2 == 0 && c.y % 2 == 0) || c == cv::Point(15, 7);
                                 }),
                    kColumns, ones(), kMoving);
  EXPECT_TRUE(regions.contains({60, 120}));
  EXPECT_TRUE(regions.contains({40, 200}));
  EXPECT_FALSE(regions.contains({15 * 16 + 8, 7 * 16 + 8})) << "a lone call made a region";
  EXPECT_FALSE(regions.contains({300, 20}));
}

// The class prior weighs each cell's votes before its call: car at 0.6
// against building at 0.4 loses when building is weighed 2x.
TEST(MovingRegions, TheClassPriorDecidesEachCellsCall) {
  MovingRegions regions(cv::Size(160, 160), {.step = 16, .sigma_cells = 1.0, .min_density = 0.5});
  const auto everywhere = [](const cv::Point2f&) { return true; };
  regions.set_calls(shares_where(regions, everywhere, 0.6f), kColumns, ones(), kMoving);
  EXPECT_TRUE(regions.contains({80, 80}));
  ClassVotes prior = ones();
  prior[kBuilding] = 2.f;
  regions.set_calls(shares_where(regions, everywhere, 0.6f), kColumns, prior, kMoving);
  EXPECT_FALSE(regions.contains({80, 80}));
  regions.set_calls(shares_where(regions, everywhere, 0.6f), kColumns, ones(), ClassSet());
  EXPECT_FALSE(regions.contains({80, 80})) << "no moving class, no region";
}

TEST(MovingRegions, BadOptionsAndSharesAreRejected) {
  using ::testing::HasSubstr;
  using ::testing::ThrowsMessage;
  EXPECT_THAT([] { MovingRegions(cv::Size(64, 64), {.step = 0}); }, ThrowsMessage<Error>(HasSubstr("step > 0")));
  EXPECT_THAT([] { MovingRegions(cv::Size(64, 64), {.step = 8, .sigma_cells = 0.0}); },
              ThrowsMessage<Error>(HasSubstr("sigma > 0")));
  EXPECT_THAT([] { MovingRegions(cv::Size(64, 64), {.step = 8, .sigma_cells = 1.0, .min_density = 1.5}); },
              ThrowsMessage<Error>(HasSubstr("density in (0, 1]")));
  MovingRegions regions(cv::Size(64, 64), {.step = 16});
  EXPECT_THAT([&] { regions.set_calls(cv::Mat::zeros(3, 2, CV_32F), kColumns, ones(), kMoving); },
              ThrowsMessage<Error>(HasSubstr("one row of 2 vote shares per cell (16)")));
}

}  // namespace moving_regions_test
}  // namespace
}  // namespace facadeslam::semantics
