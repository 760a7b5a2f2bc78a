// The Tracker on an exactly rendered textured plane: a map of one keyframe
// whose points are the plane's FAST corners at every pyramid level, then
// views along a smooth path. Checks the poses against the truth, the quality
// and keyframe decisions, and relocalisation after a blank frame.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/map/keyframe_candidate.hpp"
#include "core/map/map.hpp"
#include "tests/support/rendered_plane.hpp"
#include "tracker/tracker.hpp"

namespace facadeslam {
namespace {

using test::RenderedPlane;

// The plane's map: one keyframe at the world origin looking at the plane.
class PlaneTracking : public ::testing::Test {
 protected:
  void SetUp() override {
    auto pyramid = std::make_shared<const ImagePyramid>(test::render(plane_, camera_, SE3d()));
    const KeyFrame::Id keyframe_id = map_.new_keyframe_id();
    Measurements measurements;
    std::vector<std::shared_ptr<MapPoint>> points;
    const int per_level[kPyramidLevels] = {300, 150, 60, 25};
    for (int level = 0; level < kPyramidLevels; ++level)
      for (auto& p : test::points_from_source(plane_, camera_, pyramid, level, per_level[level])) {
        p.source.keyframe_id = keyframe_id;
        auto point = std::make_shared<MapPoint>(map_.new_point_id(), p.source, p.geometry);
        measurements[point->id()] = {level, p.source.pixel_level0, true};
        points.push_back(std::move(point));
      }
    keyframe_ =
        std::make_shared<KeyFrame>(keyframe_id, Frame{0, 0.0, cv::Mat(), {}, pyramid}, SE3d(), std::move(measurements));
    map_.add({keyframe_}, points);
    map_.update([&](MapEditor& edit) { edit.set_depth_stats(*keyframe_, plane_.plane_depth, 0.0); });
  }

  // Frame i of a smooth path: sideways and up, rolling and tilting a little.
  SE3d path_pose(int i) const {
    const double s = 0.004 * i;  // metres
    return test::view_pose(plane_, plane_.plane_depth - 0.5 * s, 0.3 * s, 0.2 * s, s, -0.5 * s);
  }

  Frame frame(std::size_t index, const cv::Mat& image) const {
    return {index, static_cast<double>(index) / 30.0, image, {}, std::make_shared<const ImagePyramid>(image)};
  }

  static double position_error(const SE3d& a, const SE3d& b) {
    return (a.inverse().translation() - b.inverse().translation()).norm();
  }
  static double rotation_error_deg(const SE3d& a, const SE3d& b) {
    return (a * b.inverse()).log().tail<3>().norm() * 180.0 / M_PI;
  }

  RenderedPlane plane_ = test::make_plane(2);
  Camera camera_ = test::test_camera();
  Map map_;
  KeyFrameQueue queue_{TrackerOptions{}.keyframe_max_queue};
  std::shared_ptr<KeyFrame> keyframe_;
};

TEST_F(PlaneTracking, FollowsASmoothPathAccurately) {
  Tracker tracker(camera_, map_, queue_, TrackerOptions{});
  tracker.start(SE3d(), 0);
  for (int i = 1; i <= 40; ++i) {
    const SE3d truth = path_pose(i);
    const TrackingResult r = tracker.track(frame(static_cast<std::size_t>(i), test::render(plane_, camera_, truth)));
    ASSERT_TRUE(r.tracked) << "frame " << i;
    EXPECT_EQ(r.quality, TrackingQuality::good) << "frame " << i;
    EXPECT_GT(r.fine_found, 200) << "frame " << i;
    EXPECT_GE(r.fine_found, r.fine_searched / 2) << "frame " << i;
    EXPECT_LT(position_error(r.T_c_w, truth), 2e-3) << "frame " << i;
    EXPECT_LT(rotation_error_deg(r.T_c_w, truth), 0.05) << "frame " << i;
    EXPECT_LT(r.inlier_rms_px, 0.5) << "frame " << i;
    // Every search is accounted for.
    const SearchCounts& c = r.fine_counts;
    EXPECT_EQ(r.fine_searched, r.fine_found + c.no_candidate + c.score_too_high + c.subpixel_failed + c.outliers);
  }
}

TEST_F(PlaneTracking, AsksForAKeyframeOnlyAfterMovingFarEnough) {
  TrackerOptions options;
  options.keyframe_min_frames = 5;
  options.keyframe_min_distance = 0.05;  // x the plane depth: 0.1 m
  Tracker tracker(camera_, map_, queue_, options);
  tracker.start(SE3d(), 0);
  int first_request = -1;
  for (int i = 1; i <= 40 && first_request < 0; ++i) {
    const TrackingResult r =
        tracker.track(frame(static_cast<std::size_t>(i), test::render(plane_, camera_, path_pose(i))));
    ASSERT_TRUE(r.tracked) << "frame " << i;
    if (r.keyframe_requested) first_request = i;
  }
  // The first frame whose centre is more than 0.1 m from the keyframe's.
  ASSERT_GT(first_request, 0);
  const auto moved = [&](int i) { return path_pose(i).inverse().translation().norm(); };
  EXPECT_GT(moved(first_request), 0.1);
  EXPECT_LE(moved(first_request - 1), 0.1);
  const auto candidate = queue_.try_pop();
  ASSERT_TRUE(candidate);
  EXPECT_EQ(candidate->frame.index, static_cast<std::size_t>(first_request));
  EXPECT_GT(candidate->measurements.size(), 200u);
  EXPECT_NE(candidate->frame.pyramid, nullptr) << "the keyframe shares the tracked frame's pyramid";
  EXPECT_FALSE(candidate->turned_on_the_spot);
}

// The view sliding off the mapped part of the plane: with PTAM's distance
// and angle rules out of reach, the overlap rule still asks for a keyframe,
// once the points found fall below its share of those found at the start.
TEST_F(PlaneTracking, AsksForAKeyframeWhenTheViewLeavesTheMap) {
  const auto sliding = [&](int i) { return test::view_pose(plane_, plane_.plane_depth, 0.0, 0.0, 0.03 * i, 0.0); };
  for (const double min_overlap : {0.85, 0.0}) {
    TrackerOptions options;
    options.keyframe_min_frames = 1000;
    options.keyframe_min_frames_turning = 1000;
    options.keyframe_min_overlap = min_overlap;
    Tracker tracker(camera_, map_, queue_, options);
    tracker.start(SE3d(), 0);
    int first_request = -1, found_first = 0, found_at_request = 0;
    for (int i = 1; i <= 25 && first_request < 0; ++i) {
      const TrackingResult r =
          tracker.track(frame(static_cast<std::size_t>(i), test::render(plane_, camera_, sliding(i))));
      ASSERT_TRUE(r.tracked) << "frame " << i;
      if (i == 1) found_first = r.fine_found;
      if (r.keyframe_requested) {
        first_request = i;
        found_at_request = r.fine_found;
      }
    }
    if (min_overlap > 0) {
      ASSERT_GT(first_request, 1) << "no keyframe while the view slid off the map";
      EXPECT_LT(found_at_request, 0.85 * found_first);
      EXPECT_GE(found_at_request, 0.6 * found_first) << "asked too late";
    } else {
      EXPECT_EQ(first_request, -1) << "the overlap rule is off";
    }
    while (queue_.try_pop()) {
    }
  }
}

// Turning on the spot: PTAM's distance rule never fires, the angle rule does
// once the optical axis has turned past keyframe_min_angle_deg.
TEST_F(PlaneTracking, AsksForAKeyframeWhenTurningOnTheSpot) {
  const auto turned = [](int i) {
    return SE3d(SO3d::exp(Eigen::Vector3d(0, 0.25 * i * M_PI / 180.0, 0)), Eigen::Vector3d::Zero());
  };
  for (const double min_angle : {5.0, 180.0}) {
    TrackerOptions options;
    options.keyframe_min_frames = 5;
    options.keyframe_min_distance = 0.05;
    options.keyframe_min_angle_deg = min_angle;
    options.keyframe_min_overlap = 0.0;  // this test is about the angle rule alone
    Tracker tracker(camera_, map_, queue_, options);
    tracker.start(SE3d(), 0);
    int first_request = -1;
    for (int i = 1; i <= 30 && first_request < 0; ++i) {
      const TrackingResult r =
          tracker.track(frame(static_cast<std::size_t>(i), test::render(plane_, camera_, turned(i))));
      ASSERT_TRUE(r.tracked) << "frame " << i;
      if (r.keyframe_requested) first_request = i;
    }
    if (min_angle < 90) {
      EXPECT_EQ(first_request, 21) << "the first frame turned more than 5 degrees (0.25 degrees per frame)";
      const auto candidate = queue_.try_pop();
      ASSERT_TRUE(candidate);
      EXPECT_TRUE(candidate->turned_on_the_spot);
    } else {
      EXPECT_EQ(first_request, -1) << "no translation, and the angle rule is off";
    }
    while (queue_.try_pop()) {
    }
  }
}

TEST_F(PlaneTracking, LosesABlankFrameAndRelocalisesOnTheNextRealOne) {
  Tracker tracker(camera_, map_, queue_, TrackerOptions{});
  tracker.start(SE3d(), 0);
  for (int i = 1; i <= 5; ++i)
    ASSERT_TRUE(tracker.track(frame(static_cast<std::size_t>(i), test::render(plane_, camera_, path_pose(i)))).tracked);
  const cv::Mat blank(camera_.height(), camera_.width(), CV_8UC1, cv::Scalar(0));
  for (int i = 6; i <= 8; ++i) {
    const TrackingResult r = tracker.track(frame(static_cast<std::size_t>(i), blank));
    EXPECT_FALSE(r.tracked);
    EXPECT_TRUE(tracker.is_lost());
  }
  // The camera moved on meanwhile (as if the blank frames were real).
  const SE3d truth = path_pose(9);
  const TrackingResult r = tracker.track(frame(9, test::render(plane_, camera_, truth)));
  ASSERT_TRUE(r.tracked);
  EXPECT_TRUE(r.relocalised);
  EXPECT_FALSE(tracker.is_lost());
  EXPECT_LT(position_error(r.T_c_w, truth), 2e-3);
  EXPECT_LT(rotation_error_deg(r.T_c_w, truth), 0.05);
}

TEST_F(PlaneTracking, IsLostWhenNothingOfTheMapIsInView) {
  Tracker tracker(camera_, map_, queue_, TrackerOptions{});
  // Turned 90 degrees away: no point projects into the image.
  const SE3d away(SO3d::exp(Eigen::Vector3d(0, M_PI / 2, 0)), Eigen::Vector3d::Zero());
  tracker.start(away, 0);
  const TrackingResult r = tracker.track(frame(1, test::render(plane_, camera_, away)));
  EXPECT_FALSE(r.tracked);
  EXPECT_EQ(r.quality, TrackingQuality::bad);
  EXPECT_EQ(r.fine_counts.projected, 0);
  EXPECT_TRUE(tracker.is_lost());
}

// Label-aware tracking on a scene where nothing moves: the points labelled
// with an unreliable class stand exactly where the pose puts them, so the
// verification gives them their full weight back when the reliable points
// alone are few (as on a street filmed from a car, whose near structure is
// parked cars and trees), and never when it is switched off or when the
// reliable points are many.
class LabelledPlaneTracking : public PlaneTracking {
 protected:
  // Labels every point but one in `every` as a car, the unreliable class here.
  void label_cars(int every) {
    ClassVotes car{};
    car[2] = 1.f;  // LabelMeFacade's car
    int i = 0;
    for (const auto& point : map_.points())
      if (i++ % every != 0) point->add_votes(car);
  }
  // Tracks 20 frames of the path; returns the fine stage's verified points.
  int track_path(const TrackerOptions& options, double& worst_position_error) {
    Tracker tracker(camera_, map_, queue_, options);
    tracker.start(SE3d(), 0);
    int verified = 0;
    worst_position_error = 0.0;
    for (int i = 1; i <= 20; ++i) {
      const SE3d truth = path_pose(i);
      const TrackingResult r = tracker.track(frame(static_cast<std::size_t>(i), test::render(plane_, camera_, truth)));
      EXPECT_TRUE(r.tracked) << "frame " << i;
      EXPECT_GT(r.points_down_weighted, 0) << "frame " << i;
      EXPECT_LE(r.points_verified, r.points_down_weighted) << "frame " << i;
      verified += r.points_verified;
      worst_position_error = std::max(worst_position_error, position_error(r.T_c_w, truth));
    }
    return verified;
  }
  static TrackerOptions label_aware(double verify_px) {
    TrackerOptions options;
    options.labels.unreliable.classes.set(2);
    options.labels.unreliable.min_confidence = 0.5f;
    options.labels.unreliable_weight = 0.1;
    options.labels.min_reliable_points = 100;
    options.labels.verify_px = verify_px;
    return options;
  }
};

TEST_F(LabelledPlaneTracking, GivesStaticDownWeightedPointsTheirWeightBackWhenReliableOnesAreFew) {
  label_cars(10);  // ~50 reliable points, ~480 cars
  double error = 0.0;
  const int verified = track_path(label_aware(2.0), error);
  EXPECT_GT(verified, 20 * 200) << "the static car points were not verified";
  EXPECT_LT(error, 2e-3);
  EXPECT_EQ(track_path(label_aware(0.0), error), 0) << "verification switched off, yet points were verified";
}

TEST_F(LabelledPlaneTracking, KeepsTheDownWeightingWhereReliablePointsAreMany) {
  label_cars(2);  // half of them reliable: ~260
  double error = 0.0;
  EXPECT_EQ(track_path(label_aware(2.0), error), 0);
  EXPECT_LT(error, 2e-3);
}

// Moving classes (cars) are left out of the search, like a weight of 0,
// whatever the unreliable weight is; where the others are too few they are
// searched after all, and those that stand still are verified.
TEST_F(LabelledPlaneTracking, LeavesPointsOfMovingClassesOut) {
  for (const int every : {2, 10}) {  // ~260 reliable points, or ~50 (under min_reliable_points)
    SCOPED_TRACE(every);
    int n = 0;
    for (const auto& point : map_.points()) {
      ClassVotes votes{};
      if (n++ % every != 0) votes[2] = 1.f;  // a car
      point->set_votes(votes);
    }
    TrackerOptions options = label_aware(2.0);
    options.labels.moving = options.labels.unreliable;
    Tracker tracker(camera_, map_, queue_, options);
    tracker.start(SE3d(), 0);
    for (int i = 1; i <= 5; ++i) {
      const SE3d truth = path_pose(i);
      const TrackingResult r = tracker.track(frame(static_cast<std::size_t>(i), test::render(plane_, camera_, truth)));
      ASSERT_TRUE(r.tracked) << "frame " << i;
      EXPECT_LT(position_error(r.T_c_w, truth), 2e-3) << "frame " << i;
      if (every == 2) {
        EXPECT_GT(r.points_dropped, 100) << "frame " << i;
        EXPECT_EQ(r.points_down_weighted, 0) << "frame " << i;
      } else {
        EXPECT_EQ(r.points_dropped, 0) << "frame " << i;
        EXPECT_GT(r.points_verified, 200) << "frame " << i;
      }
    }
  }
}

}  // namespace
}  // namespace facadeslam
