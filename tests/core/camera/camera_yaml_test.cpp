#include "core/camera/camera_yaml.hpp"

#include <cmath>
#include <numbers>
#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "tests/core/camera/camera_test_util.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;
using ::testing::AllOf;
using ::testing::HasSubstr;

const char* const kValidPinhole =
    "model: pinhole\nwidth: 640\nheight: 480\nfx: 500\nfy: 500\ncx: 319.5\ncy: 239.5\n"
    "distortion: [0.1, 0.01, 0.001, -0.001, 0.0]\n";

std::filesystem::path camera_dir() { return test::source_dir() / "configs" / "camera"; }

// Writes `yaml` to a file in `dir` and returns the load error message.
std::string load_error(const test::TempDir& dir, const std::string& yaml) {
  const auto path = dir / "cam.yaml";
  test::write_text(path, yaml);
  return error_of([&] { load_camera(path); });
}

// `yaml` with the line starting with `key:` replaced by `line` (or removed when empty).
std::string with_line(std::string yaml, const std::string& key, const std::string& line) {
  const auto at = yaml.find(key + ":");
  if (at == std::string::npos) return yaml + line + "\n";
  const auto end = yaml.find('\n', at);
  return yaml.replace(at, end - at + 1, line.empty() ? "" : line + "\n");
}

TEST(CameraYaml, ValidFileLoads) {
  test::TempDir dir;
  test::write_text(dir / "cam.yaml", kValidPinhole);
  const Camera camera = load_camera(dir / "cam.yaml");
  EXPECT_EQ(camera.model_name(), "pinhole");
  EXPECT_EQ(camera.width(), 640);
  EXPECT_EQ(camera.height(), 480);
  const auto& m = std::get<PinholeRadTan>(camera.model());
  EXPECT_EQ(m.fx, 500);
  EXPECT_EQ(m.cy, 239.5);
  EXPECT_EQ(m.k1, 0.1);
  EXPECT_EQ(m.p2, -0.001);
}

TEST(CameraYaml, DistortionMayBeOmitted) {
  test::TempDir dir;
  test::write_text(dir / "cam.yaml", with_line(kValidPinhole, "distortion", ""));
  const Camera camera = load_camera(dir / "cam.yaml");
  EXPECT_FALSE(std::get<PinholeRadTan>(camera.model()).has_distortion());
}

TEST(CameraYaml, EveryShippedFileLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(camera_dir())) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    EXPECT_NO_THROW(load_camera(entry.path())) << entry.path();
  }
  EXPECT_GE(count, 4);
}

TEST(CameraYaml, ShippedFilesHaveTheDocumentedValues) {
  const Camera left = load_camera(camera_dir() / "opencv-left.yaml");
  const auto& l = std::get<PinholeRadTan>(left.model());
  const PinholeRadTan expected = test::opencv_left_model();
  EXPECT_EQ(left.width(), 640);
  EXPECT_EQ(left.height(), 480);
  EXPECT_EQ(l.fx, expected.fx);
  EXPECT_EQ(l.fy, expected.fy);
  EXPECT_EQ(l.cx, expected.cx);
  EXPECT_EQ(l.cy, expected.cy);
  EXPECT_EQ(l.k1, expected.k1);
  EXPECT_EQ(l.k2, expected.k2);
  EXPECT_EQ(l.p1, expected.p1);
  EXPECT_EQ(l.p2, expected.p2);
  EXPECT_EQ(l.k3, expected.k3);

  const Camera synthetic = load_camera(camera_dir() / "synthetic-640x480.yaml");
  EXPECT_EQ(synthetic.fx(), 500);
  EXPECT_EQ(synthetic.cx(), 319.5);
  EXPECT_EQ(synthetic.cy(), 239.5);
  EXPECT_FALSE(std::get<PinholeRadTan>(synthetic.model()).has_distortion());

  const Camera atan_camera = load_camera(camera_dir() / "ptam-atan-example.yaml");
  EXPECT_EQ(atan_camera.model_name(), "atan");
  EXPECT_EQ(std::get<AtanCamera>(atan_camera.model()).w, 0.93);
}

TEST(CameraYaml, OpenCvLeftMatchesTheSharedSample) {
  FACADESLAM_REQUIRE_SHARED_DATA("opencv-samples/left_intrinsics.yml");
  cv::FileStorage fs((test::shared_data_dir() / "opencv-samples/left_intrinsics.yml").string(), cv::FileStorage::READ);
  ASSERT_TRUE(fs.isOpened());
  cv::Mat K, dist;
  fs["camera_matrix"] >> K;
  fs["distortion_coefficients"] >> dist;
  const Camera camera = load_camera(camera_dir() / "opencv-left.yaml");
  EXPECT_EQ(camera.width(), static_cast<int>(fs["image_width"]));
  EXPECT_EQ(camera.height(), static_cast<int>(fs["image_height"]));
  EXPECT_EQ(cv::norm(camera.K(), K, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(camera.distortion(), dist.reshape(1, 1), cv::NORM_INF), 0.0);
}

TEST(CameraYaml, MiddleburyTempleMatchesTheParFile) {
  FACADESLAM_REQUIRE_SHARED_DATA("middlebury/templeRing/templeR_par.txt");
  std::ifstream par(test::shared_data_dir() / "middlebury/templeRing/templeR_par.txt");
  int views = 0;
  std::string name;
  double k[9];
  par >> views >> name;
  for (double& v : k) par >> v;
  ASSERT_TRUE(par) << "could not parse templeR_par.txt";
  const Camera camera = load_camera(camera_dir() / "middlebury-temple.yaml");
  EXPECT_EQ(camera.fx(), k[0]);
  EXPECT_EQ(camera.cx(), k[2]);
  EXPECT_EQ(camera.fy(), k[4]);
  EXPECT_EQ(camera.cy(), k[5]);
  EXPECT_EQ(k[1], 0.0);
}

TEST(CameraYaml, SaveThenLoadIsExact) {
  test::TempDir dir;
  // Values that need all 17 digits to survive a text round trip.
  const PinholeRadTan pinhole{.fx = 500.0 / 3.0,
                              .fy = std::nextafter(500.0, 1000.0),
                              .cx = 0.1 + 0.2,
                              .cy = 239.5,
                              .k1 = -1.0 / 7.0,
                              .k2 = 1e-17,
                              .p1 = 0.0017831947042852964,
                              .p2 = -std::sqrt(2.0) * 1e-4,
                              .k3 = 0.05};
  const AtanCamera atan_model{
      .fx = 4500.0 / 7.0, .fy = 451.1, .cx = 319.5 + 1e-13, .cy = -0.25, .w = std::numbers::pi / 4};
  for (const Camera& original : {Camera(641, 479, pinhole), Camera(640, 480, atan_model)}) {
    const auto path = dir / "sub" / (original.model_name() + ".yaml");
    save_camera(path, original, "calibrated by a test\n\nsecond line");
    const Camera loaded = load_camera(path);
    EXPECT_EQ(loaded.width(), original.width());
    EXPECT_EQ(loaded.height(), original.height());
    EXPECT_EQ(loaded.model_name(), original.model_name());
    if (const auto* p = std::get_if<PinholeRadTan>(&loaded.model())) {
      const auto& o = std::get<PinholeRadTan>(original.model());
      EXPECT_EQ(p->fx, o.fx);
      EXPECT_EQ(p->fy, o.fy);
      EXPECT_EQ(p->cx, o.cx);
      EXPECT_EQ(p->cy, o.cy);
      EXPECT_EQ(p->k1, o.k1);
      EXPECT_EQ(p->k2, o.k2);
      EXPECT_EQ(p->p1, o.p1);
      EXPECT_EQ(p->p2, o.p2);
      EXPECT_EQ(p->k3, o.k3);
    } else {
      const auto& a = std::get<AtanCamera>(loaded.model());
      const auto& o = std::get<AtanCamera>(original.model());
      EXPECT_EQ(a.fx, o.fx);
      EXPECT_EQ(a.fy, o.fy);
      EXPECT_EQ(a.cx, o.cx);
      EXPECT_EQ(a.cy, o.cy);
      EXPECT_EQ(a.w, o.w);
    }
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_THAT(text.str(), AllOf(HasSubstr("# calibrated by a test\n#\n# second line\n"), HasSubstr("model: ")));
  }
  // Only the two outputs: no temporary file left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir / "sub")) ++files;
  EXPECT_EQ(files, 2);
}

TEST(CameraYaml, SavedShippedCameraReloadsIdentically) {
  test::TempDir dir;
  const Camera left = load_camera(camera_dir() / "opencv-left.yaml");
  save_camera(dir / "left.yaml", left);
  const Camera again = load_camera(dir / "left.yaml");
  EXPECT_EQ(cv::norm(again.K(), left.K(), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(again.distortion(), left.distortion(), cv::NORM_INF), 0.0);
}

TEST(CameraYamlErrors, MissingFile) {
  test::TempDir dir;
  EXPECT_THAT(error_of([&] { load_camera(dir / "absent.yaml"); }),
              AllOf(HasSubstr("absent.yaml"), HasSubstr("cannot open")));
}

TEST(CameraYamlErrors, UnknownKey) {
  test::TempDir dir;
  EXPECT_THAT(load_error(dir, std::string(kValidPinhole) + "fxx: 3\n"),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'fxx'"), HasSubstr("unknown key")));
}

TEST(CameraYamlErrors, MissingKey) {
  test::TempDir dir;
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "fy", "")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'fy'"), HasSubstr("missing")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "model", "")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'model'"), HasSubstr("missing")));
  const std::string atan_without_w = "model: atan\nwidth: 640\nheight: 480\nfx: 450\nfy: 450\ncx: 319.5\ncy: 239.5\n";
  EXPECT_THAT(load_error(dir, atan_without_w), AllOf(HasSubstr("cam.yaml"), HasSubstr("'w'"), HasSubstr("missing")));
}

TEST(CameraYamlErrors, WrongType) {
  test::TempDir dir;
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "fx", "fx: wide")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'fx'"), HasSubstr("got 'wide'")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "width", "width: 640.5")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'width'"), HasSubstr("an integer")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "distortion", "distortion: 0.1")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'distortion'"), HasSubstr("a list of 5 numbers")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "distortion", "distortion: [0.1, x, 0, 0, 0]")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'distortion'"), HasSubstr("got 'x'")));
}

TEST(CameraYamlErrors, OutOfRangeValues) {
  test::TempDir dir;
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "model", "model: fisheye")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'model'"), HasSubstr("'pinhole', 'atan'")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "width", "width: 8")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'width'"), HasSubstr("[16, 20000]")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "height", "height: 20001")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'height'"), HasSubstr("[16, 20000]")));
  // Focal lengths between 0.05 and 500 x the image size (fields of view of
  // ~170 to ~0.1 degrees): 0, negative, 0.001 and 1e12 are typos.
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "fx", "fx: 0")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'fx'"), HasSubstr("expected a number in [")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "fy", "fy: -500")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'fy'"), HasSubstr("expected a number in [")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "fx", "fx: 0.001")), HasSubstr("'fx'"));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "fx", "fx: 1e12")), HasSubstr("'fx'"));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "cx", "cx: 1281")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'cx'"), HasSubstr("[-640, 1280]")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "cy", "cy: -481")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'cy'"), HasSubstr("[-480, 960]")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "distortion", "distortion: [0.1, .nan, 0, 0, 0]")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'distortion'")));
  const std::string atan_base = "model: atan\nwidth: 640\nheight: 480\nfx: 450\nfy: 450\ncx: 319.5\ncy: 239.5\n";
  EXPECT_THAT(load_error(dir, atan_base + "w: 3.0\n"),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'w'"), HasSubstr("[0, 3)")));
  EXPECT_THAT(load_error(dir, atan_base + "w: -0.1\n"),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'w'"), HasSubstr("[0, 3)")));
}

TEST(CameraYamlErrors, WrongDistortionLength) {
  test::TempDir dir;
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "distortion", "distortion: [0.1, 0.01, 0, 0]")),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'distortion'"), HasSubstr("a list of 5 numbers"),
                    HasSubstr("got 'a list of 4'")));
  EXPECT_THAT(load_error(dir, with_line(kValidPinhole, "distortion", "distortion: [0, 0, 0, 0, 0, 0, 0, 0]")),
              AllOf(HasSubstr("'distortion'"), HasSubstr("got 'a list of 8'")));
}

TEST(CameraYamlErrors, ModelSpecificKeyOnTheOtherModel) {
  test::TempDir dir;
  EXPECT_THAT(load_error(dir, std::string(kValidPinhole) + "w: 0.9\n"),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'w'"), HasSubstr("unknown key")));
  const std::string atan_with_distortion =
      "model: atan\nwidth: 640\nheight: 480\nfx: 450\nfy: 450\ncx: 319.5\ncy: 239.5\nw: 0.9\n"
      "distortion: [0, 0, 0, 0, 0]\n";
  EXPECT_THAT(load_error(dir, atan_with_distortion),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'distortion'"), HasSubstr("unknown key")));
}

TEST(CameraYamlErrors, ModelThatCannotCoverTheImage) {
  test::TempDir dir;
  // Barrel distortion whose polynomial peaks (r = 0.82, r_d = 0.54) well
  // inside the image corners (r_d = 1.33): those pixels have no ray.
  const std::string folding =
      "model: pinhole\nwidth: 640\nheight: 480\nfx: 300\nfy: 300\ncx: 319.5\ncy: 239.5\n"
      "distortion: [-0.5, 0, 0, 0, 0]\n";
  EXPECT_THAT(load_error(dir, folding),
              AllOf(HasSubstr("cam.yaml"), HasSubstr("'distortion'"), HasSubstr("whole image")));
  // ATAN w so large that the corners lie beyond 90 degrees.
  const std::string wide = "model: atan\nwidth: 640\nheight: 480\nfx: 100\nfy: 100\ncx: 319.5\ncy: 239.5\nw: 2.9\n";
  EXPECT_THAT(load_error(dir, wide), AllOf(HasSubstr("cam.yaml"), HasSubstr("'w'"), HasSubstr("corner")));
}

TEST(CameraYamlErrors, NotAMapping) {
  test::TempDir dir;
  EXPECT_THAT(load_error(dir, "- 1\n- 2\n"), AllOf(HasSubstr("cam.yaml"), HasSubstr("mapping")));
}

}  // namespace
}  // namespace facadeslam
