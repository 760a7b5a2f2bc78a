// The final trajectory is recomposed exactly from the final keyframe poses:
// a keyframe moved after its frames were tracked (a bundle adjustment
// correcting the map) moves those frames by the same rigid transform and no
// other frame; a frame whose reference keyframe left the map keeps its pose
// as tracked.
#include <gtest/gtest.h>

#include <memory>

#include <opencv2/core.hpp>

#include "core/image/image_pyramid.hpp"
#include "core/map/map.hpp"
#include "slam/relative_trajectory.hpp"

namespace facadeslam {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

SE3d pose(double tx, double ty, double tz, double rx, double ry, double rz) {
  return SE3d::exp((Vector6d() << tx, ty, tz, rx, ry, rz).finished());
}

std::shared_ptr<KeyFrame> make_keyframe(Map& map, std::size_t frame_index, const SE3d& T_c_w) {
  const cv::Mat colour(120, 160, CV_8UC3, cv::Scalar(90, 120, 150));
  const Frame frame{
      frame_index, static_cast<double>(frame_index), colour, {}, std::make_shared<const ImagePyramid>(colour)};
  auto keyframe = std::make_shared<KeyFrame>(map.new_keyframe_id(), frame, T_c_w);
  map.add_keyframe(keyframe);
  return keyframe;
}

// Camera-to-world poses agree to rounding.
void expect_same_pose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, std::size_t frame) {
  EXPECT_LT((a.matrix() - b.matrix()).cwiseAbs().maxCoeff(), 1e-12) << "frame " << frame << "\n"
                                                                    << a.matrix() << "\nvs\n"
                                                                    << b.matrix();
}

TEST(RelativeTrajectory, AKeyframeMovedAfterTrackingMovesItsFramesByTheSameRigidTransform) {
  Map map;
  const auto kf_a = make_keyframe(map, 0, pose(0, 0, 0, 0, 0, 0));
  const auto kf_b = make_keyframe(map, 10, pose(-0.5, 0.02, 0.1, 0.01, -0.2, 0.03));
  const SE3d T_a_w = kf_a->T_c_w(), T_b_w = kf_b->T_c_w();

  // Frames 1-4 tracked against keyframe a, 11-14 against b, at the poses
  // the map had then.
  RelativeTrajectory trajectory;
  for (std::size_t i = 1; i <= 4; ++i)
    trajectory.add(i, static_cast<double>(i), pose(-0.05 * i, 0.01, 0.0, 0.0, -0.02 * i, 0.0), kf_a->id(), T_a_w);
  for (std::size_t i = 11; i <= 14; ++i)
    trajectory.add(i, static_cast<double>(i), pose(-0.05 * i, 0.03, 0.1, 0.01, -0.02 * i, 0.03), kf_b->id(), T_b_w);
  const Trajectory online = trajectory.online();
  ASSERT_EQ(online.size(), 8u);

  // Nothing moved: the recomposed trajectory is the online one.
  {
    const auto unchanged = trajectory.recompose(map.snapshot_keyframes());
    EXPECT_EQ(unchanged.fallbacks, 0u);
    ASSERT_EQ(unchanged.trajectory.size(), online.size());
    for (std::size_t i = 0; i < online.size(); ++i) {
      EXPECT_EQ(unchanged.trajectory[i].timestamp, online[i].timestamp);
      expect_same_pose(unchanged.trajectory[i].T_w_c, online[i].T_w_c, i);
    }
  }

  // A correction moves keyframe b (and the world around it) by M = T_w'_w:
  // its pose becomes T_b_w' = T_b_w · M⁻¹, so each of its frames should end
  // at T_w'_c = M · T_w_c; keyframe a's frames stay where they were.
  const SE3d M = pose(0.3, -0.1, 0.05, 0.04, 0.1, -0.02);
  map.update([&](MapEditor& edit) { edit.set_pose(*kf_b, T_b_w * M.inverse()); });
  const auto corrected = trajectory.recompose(map.snapshot_keyframes());
  EXPECT_EQ(corrected.fallbacks, 0u);
  ASSERT_EQ(corrected.trajectory.size(), online.size());
  for (std::size_t i = 0; i < online.size(); ++i) {
    const bool on_b = trajectory.frames()[i].reference == kf_b->id();
    const Eigen::Isometry3d expected = on_b ? M.isometry() * online[i].T_w_c : online[i].T_w_c;
    expect_same_pose(corrected.trajectory[i].T_w_c, expected, trajectory.frames()[i].frame_index);
  }
}

TEST(RelativeTrajectory, AFrameWhoseReferenceLeftTheMapKeepsItsOnlinePose) {
  Map map;
  const auto kf_a = make_keyframe(map, 0, pose(0, 0, 0, 0, 0, 0));
  const auto kf_b = make_keyframe(map, 10, pose(-0.5, 0, 0, 0, -0.1, 0));
  RelativeTrajectory trajectory;
  trajectory.add(3, 3.0, pose(-0.2, 0, 0, 0, -0.05, 0), kf_a->id(), kf_a->T_c_w());
  trajectory.add(12, 12.0, pose(-0.6, 0, 0, 0, -0.12, 0), kf_b->id(), kf_b->T_c_w());
  trajectory.add_online(13, 13.0, pose(-0.65, 0, 0, 0, -0.13, 0));
  const Trajectory online = trajectory.online();

  // Keyframe b is gone (its map cleared, as when a map is discarded), and a
  // moves: frame 3 follows a, frame 12 falls back to its online pose, as
  // does frame 13, which never had a reference.
  const SE3d M = pose(0.1, 0.2, -0.3, 0.0, 0.05, 0.0);
  std::vector<KeyFrameSnapshot> final_keyframes = map.snapshot_keyframes();
  ASSERT_EQ(final_keyframes.size(), 2u);
  final_keyframes.pop_back();
  final_keyframes.front().T_c_w = kf_a->T_c_w() * M.inverse();
  const auto recomposed = trajectory.recompose(final_keyframes);
  EXPECT_EQ(recomposed.fallbacks, 1u);
  ASSERT_EQ(recomposed.trajectory.size(), 3u);
  expect_same_pose(recomposed.trajectory[0].T_w_c, M.isometry() * online[0].T_w_c, 3);
  expect_same_pose(recomposed.trajectory[1].T_w_c, online[1].T_w_c, 12);
  expect_same_pose(recomposed.trajectory[2].T_w_c, online[2].T_w_c, 13);
}

TEST(RelativeTrajectory, AFrameOfACulledKeyframeFollowsTheChainOfParentsToTheMap) {
  Map map;
  const auto kf_a = make_keyframe(map, 0, pose(0, 0, 0, 0, 0, 0));
  const auto kf_b = make_keyframe(map, 10, pose(-0.5, 0.02, 0.1, 0.01, -0.2, 0.03));
  const auto kf_c = make_keyframe(map, 20, pose(-0.9, 0.05, 0.1, 0.02, -0.3, 0.03));
  RelativeTrajectory trajectory;
  trajectory.add(21, 21.0, pose(-0.95, 0.05, 0.1, 0.02, -0.31, 0.03), kf_c->id(), kf_c->T_c_w());
  const Trajectory online = trajectory.online();

  // c is culled with parent b, then b with parent a; then the map moves a
  // by M. The frame was rigidly tied to c, c to b and b to a when each went,
  // so it moves by M too.
  map.update([&](MapEditor& edit) {
    edit.cull_keyframe(kf_c->id(), {kf_b->id(), kf_c->T_c_w() * kf_b->T_c_w().inverse()});
    edit.cull_keyframe(kf_b->id(), {kf_a->id(), kf_b->T_c_w() * kf_a->T_c_w().inverse()});
  });
  const SE3d M = pose(0.1, 0.2, -0.3, 0.0, 0.05, 0.0);
  map.update([&](MapEditor& edit) { edit.set_pose(*kf_a, kf_a->T_c_w() * M.inverse()); });
  const auto recomposed = trajectory.recompose(map.snapshot_keyframes(), map.culled_keyframes());
  EXPECT_EQ(recomposed.fallbacks, 0u);
  EXPECT_EQ(recomposed.culled_references, 1u);
  ASSERT_EQ(recomposed.trajectory.size(), 1u);
  expect_same_pose(recomposed.trajectory[0].T_w_c, M.isometry() * online[0].T_w_c, 21);

  // Without the links the frame could only keep its online pose.
  const auto without_links = trajectory.recompose(map.snapshot_keyframes());
  EXPECT_EQ(without_links.fallbacks, 1u);
  expect_same_pose(without_links.trajectory[0].T_w_c, online[0].T_w_c, 21);
}

}  // namespace
}  // namespace facadeslam
