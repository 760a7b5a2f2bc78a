// End to end: `facadeslam render-map` on a small map.ply, keyframes and
// trajectory written here: a PNG of the asked size with the map on it, and
// one-line errors (no PNG) for bad input.
#include <cmath>
#include <cstring>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "tests/apps/cli_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using ::testing::HasSubstr;

std::string quoted(const std::filesystem::path& p) { return test::shell_quoted(p.string()); }

bool is_one_line(const std::string& s) { return !s.empty() && s.back() == '\n' && s.find('\n') == s.size() - 1; }

class RenderMapCli : public ::testing::Test {
 protected:
  void SetUp() override {
    // A facade (building, dark red) and a road (brown) in front of cameras
    // that walk along x looking along +z, upright (y down): our maps' frame.
    std::string body;
    int n = 0;
    const auto add = [&](float x, float y, float z, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                         std::uint8_t label) {
      const float xyz[] = {x, y, z}, confidence = 0.5f;
      char bytes[20];
      std::memcpy(bytes, xyz, 12);
      bytes[12] = static_cast<char>(r), bytes[13] = static_cast<char>(g), bytes[14] = static_cast<char>(b);
      bytes[15] = static_cast<char>(label);
      std::memcpy(bytes + 16, &confidence, 4);
      body.append(bytes, 20);
      ++n;
    };
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 10; ++j) add(0.1f * i, -0.2f * j, 5.f, 128, 0, 0, 1);
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 10; ++j) add(0.1f * i, 1.5f, 1.f + 0.4f * j, 128, 64, 0, 5);
    const std::string header =
        "ply\nformat binary_little_endian 1.0\ncomment class 1 building 128 0 0\ncomment class 5 road 128 64 0\n"
        "element vertex " +
        std::to_string(n) +
        "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
        "property uchar blue\nproperty uchar label\nproperty float confidence\nend_header\n";
    test::write_text(ply(), header + body);
    std::string tum;
    for (int i = 0; i < 5; ++i) tum += std::to_string(i) + " " + std::to_string(i) + " 0 0 0 0 0 1\n";
    test::write_text(keyframes(), tum);
  }

  test::CliResult run(const std::string& arguments) { return test::run_cli(FACADESLAM_BINARY, arguments, dir_.path()); }
  std::filesystem::path ply() const { return dir_ / "map.ply"; }
  std::filesystem::path keyframes() const { return dir_ / "keyframes.txt"; }
  std::filesystem::path png() const { return dir_ / "out" / "map.png"; }

  test::TempDir dir_;
};

TEST_F(RenderMapCli, WritesAPngOfTheAskedSizeWithTheMapOnIt) {
  for (const char* view : {"oblique", "top"}) {
    const auto r =
        run("render-map --map-ply " + quoted(ply()) + " --keyframes " + quoted(keyframes()) + " --trajectory " +
            quoted(keyframes()) + " --out " + quoted(png()) + " --size 320x200 --view " + view);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("800 points, 5 keyframes, 5 trajectory poses"));
    const cv::Mat image = cv::imread(png().string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(image.type(), CV_8UC3);
    EXPECT_EQ(image.size(), cv::Size(320, 200));
    // Both classes are drawn, in their colours (BGR).
    const cv::Mat pixels = image.reshape(1, image.rows * image.cols);  // one row of B, G, R per pixel
    const cv::Mat building = (pixels.col(2) == 128) & (pixels.col(1) == 0), road = pixels.col(1) == 64;
    EXPECT_GT(cv::countNonZero(building), 50) << view;
    EXPECT_GT(cv::countNonZero(road), 50) << view;
  }
}

TEST_F(RenderMapCli, DefaultsTo1280x720WithoutKeyframes) {
  const auto r = run("render-map --map-ply " + quoted(ply()) + " --out " + quoted(png()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(cv::imread(png().string()).size(), cv::Size(1280, 720));
}

TEST_F(RenderMapCli, RejectsABadPlyWithOneLineAndWritesNothing) {
  test::write_text(dir_ / "bad.ply", "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n");
  const auto r = run("render-map --map-ply " + quoted(dir_ / "bad.ply") + " --out " + quoted(png()));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(is_one_line(r.err)) << r.err;
  EXPECT_THAT(r.err, HasSubstr((dir_ / "bad.ply").string() + ": format line 'format ascii 1.0'"));
  EXPECT_THAT(r.err, HasSubstr("expected the binary little-endian PLY"));
  EXPECT_FALSE(std::filesystem::exists(png()));
}

TEST_F(RenderMapCli, RejectsBadOptionsWithOneLine) {
  const std::string base = "render-map --map-ply " + quoted(ply()) + " ";
  const auto size = run(base + "--out " + quoted(png()) + " --size 320by200");
  EXPECT_EQ(size.exit_code, 2);  // a bad command line (README)
  EXPECT_THAT(size.err, HasSubstr("--size: expected WIDTHxHEIGHT"));
  const auto not_png = run(base + "--out " + quoted(dir_ / "map.jpg"));
  EXPECT_EQ(not_png.exit_code, 1);
  EXPECT_THAT(not_png.err, HasSubstr("expected an output file name ending in .png"));
  const auto missing = run(base + "--out " + quoted(png()) + " --keyframes " + quoted(dir_ / "none.txt"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, HasSubstr("none.txt: no such file"));
  const auto view = run(base + "--out " + quoted(png()) + " --view side");
  EXPECT_EQ(view.exit_code, 2);
  for (const auto& r : {size, not_png, missing}) EXPECT_TRUE(is_one_line(r.err)) << r.err;
  EXPECT_FALSE(std::filesystem::exists(png()));
}

}  // namespace
}  // namespace facadeslam
