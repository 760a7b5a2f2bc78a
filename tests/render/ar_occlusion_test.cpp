// Occlusion of the AR object by the map (render/ar/map_occlusion.hpp), its
// score against the true depth (occlusion_score.hpp) and where the object
// stands (object_placement.hpp).
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/camera/camera.hpp"
#include "render/ar/map_occlusion.hpp"
#include "render/ar/object_placement.hpp"
#include "render/ar/occlusion_score.hpp"
#include "tests/render/render_test_scenes.hpp"

namespace facadeslam {
namespace {

using render::ar::OccluderKind;
using render::ar::OccluderPoint;

const Camera kCamera(640, 480, PinholeRadTan{.fx = 500, .fy = 500, .cx = 319.5, .cy = 239.5});
const render::PinholeIntrinsics kPinhole{640, 480, 500, 500, 319.5, 239.5};

// A 2 x 2 wall of points 0.05 apart, 4 in front of the camera (z forward).
std::vector<OccluderPoint> wall(OccluderKind kind, double z = 4.0) {
  std::vector<OccluderPoint> points;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) points.push_back({{-1.0 + 0.05 * i, -1.0 + 0.05 * j, z}, kind});
  return points;
}

TEST(MapOcclusion, AFacadesPointsCloseIntoASurfaceAndTheSkyNeverOccludes) {
  const auto facade = wall(OccluderKind::surface);
  const double spacing = render::ar::point_spacing(facade);
  EXPECT_NEAR(spacing, 0.05, 1e-9);
  const cv::Mat depth = render::ar::occluder_depth(facade, Eigen::Isometry3d::Identity(), kPinhole, spacing);
  // The wall spans 250 pixels around the centre: every pixel inside is covered at z = 4.
  int covered = 0;
  for (int y = 140; y < 340; ++y)
    for (int x = 220; x < 420; ++x) covered += depth.at<float>(y, x) == 4.0f;
  EXPECT_EQ(covered, 200 * 200);
  EXPECT_TRUE(std::isinf(depth.at<float>(10, 10)));
  const cv::Mat sky =
      render::ar::occluder_depth(wall(OccluderKind::none), Eigen::Isometry3d::Identity(), kPinhole, spacing);
  EXPECT_EQ(cv::countNonZero(sky < std::numeric_limits<float>::infinity()), 0);
}

// A growing map's spacing is measured again only when it has grown by a
// tenth, and afresh after a reset.
TEST(MapOcclusion, TheSpacingIsMeasuredAgainWhenTheMapHasGrownByATenth) {
  render::ar::MapSpacing spacing;
  const auto points = wall(OccluderKind::surface);  // 0.05 apart, 1681 points
  EXPECT_NEAR(spacing.of(points), 0.05, 1e-9);
  // Each point gets a twin 0.01 away: first 160 of them (under a tenth)...
  std::vector<OccluderPoint> grown = points;
  for (std::size_t i = 0; i < 160; ++i)
    grown.push_back({points[i].p_w + Eigen::Vector3d(0.01, 0.0, 0.0), points[i].kind});
  EXPECT_NEAR(spacing.of(grown), 0.05, 1e-9) << "grown by less than a tenth: the spacing kept";
  // ... then all: measured again, the spacing is the twins'.
  for (std::size_t i = 160; i < points.size(); ++i)
    grown.push_back({points[i].p_w + Eigen::Vector3d(0.01, 0.0, 0.0), points[i].kind});
  EXPECT_NEAR(spacing.of(grown), 0.01, 1e-9);
  spacing.reset();
  EXPECT_NEAR(spacing.of(points), 0.05, 1e-9);
}

// Drawn only in a region, the occluders' depth there is what the whole
// image's is (the closing reaches across the region's edge alike), and
// nothing outside it.
TEST(MapOcclusion, ARegionHoldsWhatTheWholeImageHoldsThere) {
  auto points = wall(OccluderKind::surface);
  for (OccluderPoint& p : points) p.p_w.x() += 0.013 * std::sin(7.0 * p.p_w.y());  // gaps to close
  const auto sparse = wall(OccluderKind::sparse, 3.0);
  for (std::size_t i = 0; i < sparse.size(); i += 7) points.push_back(sparse[i]);
  const double spacing = render::ar::point_spacing(points);
  const Eigen::Isometry3d T_c_w = Eigen::Isometry3d::Identity();
  const cv::Mat whole = render::ar::occluder_depth(points, T_c_w, kPinhole, spacing);
  const cv::Rect region(200, 150, 90, 70);
  const cv::Mat part = render::ar::occluder_depth(points, T_c_w, kPinhole, spacing, {}, region);
  int compared = 0;
  for (int y = 0; y < whole.rows; ++y)
    for (int x = 0; x < whole.cols; ++x) {
      if (region.contains({x, y})) {
        ASSERT_EQ(part.at<float>(y, x), whole.at<float>(y, x)) << x << "," << y;
        compared += std::isfinite(whole.at<float>(y, x));
      } else {
        ASSERT_TRUE(std::isinf(part.at<float>(y, x))) << x << "," << y;
      }
    }
  EXPECT_GT(compared, 90 * 70 / 2);
}

// The object's region: its corners' box, a little grown, inside the image.
TEST(MapOcclusion, TheObjectsRegionIsItsBoxOnTheImage) {
  render::ar::VirtualObject object;
  object.T_w_o.translation() = Eigen::Vector3d(0, 0, 5);
  object.size = 1.0;
  const cv::Rect region = render::ar::object_region(object, Eigen::Isometry3d::Identity(), kPinhole);
  // Corners at x, y = +-0.5 and z 5..6: +-50 px around the centre at z = 5.
  EXPECT_NEAR(region.x, 319.5 - 50 - 2, 1.5);
  EXPECT_NEAR(region.width, 100 + 5, 2.5);
  Eigen::Isometry3d behind = Eigen::Isometry3d::Identity();
  behind.translation() = Eigen::Vector3d(0, 0, -5.5);  // the camera inside the cube's depth
  EXPECT_EQ(render::ar::object_region(object, behind, kPinhole), cv::Rect(0, 0, 640, 480));
  // Off to the side: an empty region, and nothing drawn in it.
  object.T_w_o.translation() = Eigen::Vector3d(30, 0, 5);
  const cv::Rect off_screen = render::ar::object_region(object, Eigen::Isometry3d::Identity(), kPinhole);
  EXPECT_TRUE(off_screen.empty());
  const cv::Mat depth = render::ar::occluder_depth(wall(OccluderKind::surface), Eigen::Isometry3d::Identity(), kPinhole,
                                                   0.05, {}, off_screen);
  double nearest = 0.0;
  cv::minMaxLoc(depth, &nearest);
  EXPECT_TRUE(std::isinf(nearest));
}

TEST(MapOcclusion, SparsePointsCoverLessThanASurface) {
  const auto tree = wall(OccluderKind::sparse);
  const double spacing = render::ar::point_spacing(tree);
  const cv::Mat depth = render::ar::occluder_depth(tree, Eigen::Isometry3d::Identity(), kPinhole, spacing);
  const int covered = cv::countNonZero(depth(cv::Rect(220, 140, 200, 200)) < 5.f);
  EXPECT_GT(covered, 200 * 200 / 3);
  EXPECT_LT(covered, 200 * 200);
}

// Half the object behind a wall: the render hiding exactly the truth's
// pixels scores 1, hiding nothing scores 0, and a steady scene does not flicker.
TEST(OcclusionScore, IsTheOverlapOfWhatTheRenderAndTheTruthHide) {
  render::ar::VirtualObject object;
  object.size = 1.0;
  object.T_w_o.translation() = Eigen::Vector3d(0, 0, 6);  // the object's z axis along the camera's
  const cv::Mat object_z = render::ar::object_depth(object, kCamera, Eigen::Isometry3d::Identity());
  ASSERT_GT(cv::countNonZero(object_z < 100.f), 1000);
  EXPECT_NEAR(object_z.at<float>(240, 320), 6.0, 1e-4);  // its bottom face, facing the camera
  cv::Mat truth(object_z.size(), CV_32FC1, cv::Scalar(std::numeric_limits<float>::infinity()));
  truth(cv::Rect(0, 0, 320, 480)).setTo(3.0f);  // a wall over the left half
  render::ar::OcclusionScore exact, none;
  const cv::Mat nothing(object_z.size(), CV_32FC1, cv::Scalar(std::numeric_limits<float>::infinity()));
  for (int frame = 0; frame < 3; ++frame) {
    exact.add_frame(object_z, truth, truth);
    none.add_frame(object_z, nothing, truth);
  }
  EXPECT_DOUBLE_EQ(*exact.iou(), 1.0);
  EXPECT_DOUBLE_EQ(*none.iou(), 0.0);
  EXPECT_EQ(exact.frames_visible(), 3u);
  EXPECT_DOUBLE_EQ(exact.flicker_render(), 0.0);
}

// Three keyframes 1.5 above the ground at y = 0 (y down), upright, looking
// along z, each 0.5 behind the one before: the newest at z = -1.
std::vector<Eigen::Isometry3d> upright_cameras() {
  std::vector<Eigen::Isometry3d> keyframes_T_c_w;
  for (int k = 0; k < 3; ++k) {
    Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
    T_w_c.translation() = Eigen::Vector3d(0.0, -1.5, -0.5 * k);
    keyframes_T_c_w.push_back(T_w_c.inverse());
  }
  return keyframes_T_c_w;
}

// A street: ground points below level cameras and a facade to the side,
// larger than the ground: the object stands on the ground all the same, in
// front of the camera, and the ground points are its band.
TEST(ObjectPlacement, PrefersTheGroundToALargerFacade) {
  std::vector<render::ar::PlacementPoint> points;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 10; ++j)
      points.push_back({{-2.0 + 0.2 * j, 0.0, 1.0 + 0.5 * i}, false});  // y down: ground at 0
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 20; ++j) points.push_back({{3.0, -0.2 * j, 1.0 + 0.25 * i}, false});  // facade at x = 3
  const std::vector<Eigen::Isometry3d> keyframes_T_c_w = upright_cameras();
  const auto placement = render::ar::place_object(points, keyframes_T_c_w);
  ASSERT_TRUE(placement.has_value());
  EXPECT_TRUE(placement->on_ground);
  EXPECT_EQ(placement->reason, "the lowest points, below the cameras");
  const Eigen::Vector3d base = placement->object.T_w_o.translation();
  EXPECT_NEAR(base.y(), 0.0, 1e-6);
  EXPECT_GT((keyframes_T_c_w.back() * base).z(), 0.0) << "in front of the reference camera";
  EXPECT_NEAR(placement->object.T_w_o.linear().col(2).dot(Eigen::Vector3d(0, -1, 0)), 1.0, 1e-6) << "upright";
  EXPECT_GT(placement->ground_band, 0.0);
}

// A road with few points of its own: the ground's points lie far to the
// side (a lawn), so the object stands straight ahead on the plane, at their
// median depth, not beside the road where the camera would lose it at once.
TEST(ObjectPlacement, StandsStraightAheadWhenTheGroundsPointsAreToTheSide) {
  std::vector<render::ar::PlacementPoint> points;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 10; ++j) points.push_back({{6.0 + 0.2 * j, 0.0, 4.0 + 0.5 * i}, true});  // y down
  const std::vector<Eigen::Isometry3d> keyframes_T_c_w = upright_cameras();
  const auto placement = render::ar::place_object(points, keyframes_T_c_w);
  ASSERT_TRUE(placement.has_value());
  EXPECT_TRUE(placement->on_ground);
  const Eigen::Vector3d base = placement->object.T_w_o.translation();
  EXPECT_NEAR(base.x(), 0.0, 1e-9);
  EXPECT_NEAR(base.y(), 0.0, 1e-9);
  // The median depth of the points in front of the reference camera (at z = -1).
  EXPECT_NEAR(base.z(), -1.0 + 10.0, 0.3);
}

// The same through the dominant plane: too few points for "the lowest
// points" (5 % of 100 is under 8), a level dominant plane is ground too.
TEST(ObjectPlacement, ALevelDominantPlaneIsGroundStraightAheadToo) {
  std::vector<render::ar::PlacementPoint> points;
  points.reserve(100);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) points.push_back({{6.0 + 0.2 * j, 0.0, 4.0 + 1.0 * i}, false});
  const std::vector<Eigen::Isometry3d> keyframes_T_c_w = upright_cameras();
  const auto placement = render::ar::place_object(points, keyframes_T_c_w);
  ASSERT_TRUE(placement.has_value());
  EXPECT_EQ(placement->reason, "no ground plane in the map: its dominant plane");
  EXPECT_TRUE(placement->on_ground);
  EXPECT_NEAR(placement->object.T_w_o.translation().x(), 0.0, 1e-6) << "straight ahead, not beside the road";
}

// Bad input: five points, or a cloud with no plane and nothing below the
// cameras, give no placement (the replay then renders without the object).
TEST(ObjectPlacement, NothingForFivePointsOrACloudWithoutAPlane) {
  std::vector<Eigen::Isometry3d> keyframes_T_c_w(3, Eigen::Isometry3d::Identity());
  std::vector<render::ar::PlacementPoint> five;
  five.reserve(5);
  for (int i = 0; i < 5; ++i) five.push_back({{0.1 * i, 1.0, 2.0 + i}, true});
  EXPECT_FALSE(render::ar::place_object(five, keyframes_T_c_w).has_value());

  // Points scattered through a ball above the cameras (y down: negative y).
  std::vector<render::ar::PlacementPoint> cloud;
  cloud.reserve(300);
  unsigned state = 7;
  const auto uniform = [&state] {
    state = state * 1103515245u + 12345u;
    return static_cast<double>((state >> 8) & 0xffff) / 65535.0 - 0.5;
  };
  for (int i = 0; i < 300; ++i) cloud.push_back({{4 * uniform(), -3.0 + 2 * uniform(), 6.0 + 4 * uniform()}, false});
  EXPECT_FALSE(render::ar::place_object(cloud, keyframes_T_c_w).has_value());
}

}  // namespace
}  // namespace facadeslam
