// Issue 16's multi-view facades (need ../shared/data/strecha): Strecha's
// fountain-P11, Herz-Jesus-P25 and entry-P10, real building facades photographed
// from 10-25 positions 1.6-1.8 m and 6-16 degrees apart, replayed as an
// ordered image list with configs/slam-multiview.yaml (every view may be a
// keyframe). The patch tracker alone cannot bridge such steps: the views come
// back through ORB + PnP relocalisation (tracker/descriptor_relocaliser.hpp).
// Holds: >= 60 % of the views localised (the goal is 80 %) and every
// localised camera centre within 2 % of the scene's extent (the diagonal of
// the true centres' bounding box) after Sim(3) alignment, on the final
// trajectory (trajectory.txt). Synchronous, fixed seed: reproducible.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/camera/camera_yaml.hpp"
#include "core/trajectory/metrics.hpp"
#include "sequences/open_sequence.hpp"
#include "slam/system.hpp"
#include "tests/slam/slam_test_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

// gt_dense_cameras/NAME.camera: K (3 lines), distortion, R (camera-to-world,
// 3 lines), centre C, size. Returns camera-to-world.
Eigen::Isometry3d read_strecha_camera(const fs::path& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  double skip[12];
  for (double& x : skip) in >> x;  // K and the distortion line
  Eigen::Matrix3d R;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) in >> R(r, c);
  Eigen::Vector3d C;
  in >> C.x() >> C.y() >> C.z();
  EXPECT_TRUE(in) << file << ": expected K, distortion, R and C";
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
  T_w_c.linear() = R;
  T_w_c.translation() = C;
  return T_w_c;
}

struct StrechaFigures {
  std::size_t views = 0, localised = 0, relocalised = 0;
  double extent_m = 0, worst_m = 0, ate_percent_of_path = 0;
};

StrechaFigures replay_strecha(const std::string& name) {
  const fs::path set = test::shared_data_dir() / "strecha" / name;
  SlamOptions options = load_slam_options(test::source_dir() / "configs" / "slam-multiview.yaml");
  options.synchronous = true;
  System system(load_camera(test::source_dir() / "configs" / "camera" / "strecha.yaml"), options);
  test::SlamRunLog log;
  Trajectory gt;
  Eigen::AlignedBox3d box;
  auto source = open_sequence(set / "images", SequenceOptions{});
  while (auto frame = source->next()) {
    const Eigen::Isometry3d T_w_c =
        read_strecha_camera(set / "gt_dense_cameras" / (frame->source.filename().string() + ".camera"));
    gt.push_back({frame->timestamp, T_w_c});
    box.extend(T_w_c.translation());
    log.add(system.process(std::move(*frame)));
  }
  system.finish();
  StrechaFigures f;
  f.views = log.frames.size();
  EXPECT_TRUE(system.initialised()) << name << " never initialised";
  if (!system.initialised()) return f;
  const Trajectory final = system.final_trajectory();
  f.localised = final.size();
  for (const FrameReport& r : log.frames) f.relocalised += r.status == FrameStatus::relocalised;
  f.extent_m = box.diagonal().norm();
  if (final.size() < 3) return f;
  const TrajectoryEvaluation ate = evaluate_trajectory(gt, final, {});
  EXPECT_EQ(ate.pairs, final.size()) << name << ": every localised view has its ground truth";
  for (std::size_t i = 0; i < ate.gt_positions.size(); ++i)
    f.worst_m = std::max(f.worst_m, (ate.gt_positions[i] - ate.aligned_est_positions[i]).norm());
  f.ate_percent_of_path = ate.ate_percent_of_path;
  std::printf(
      "[  FIGURES ] strecha %s: %zu of %zu views localised (%.0f %%, %zu by relocalisation), worst centre error "
      "%.4f m = %.3f %% of the %.2f m extent, ATE %.3f %% of the path\n",
      name.c_str(), f.localised, f.views, 100.0 * static_cast<double>(f.localised) / static_cast<double>(f.views),
      f.relocalised, f.worst_m, 100.0 * f.worst_m / f.extent_m, f.extent_m, f.ate_percent_of_path);
  std::fflush(stdout);
  return f;
}

void expect_localised(const std::string& name) {
  FACADESLAM_REQUIRE_SHARED_DATA("strecha/" + name);
  const StrechaFigures f = replay_strecha(name);
  ASSERT_GT(f.views, 0u);
  ::testing::Test::RecordProperty("localised", static_cast<int>(f.localised));
  EXPECT_GE(static_cast<double>(f.localised), 0.6 * static_cast<double>(f.views));
  EXPECT_LE(f.worst_m, 0.02 * f.extent_m);
}

TEST(StrechaRegression, FountainP11) { expect_localised("fountain-P11"); }
TEST(StrechaRegression, HerzJesusP25) { expect_localised("Herz-Jesus-P25"); }
TEST(StrechaRegression, EntryP10) { expect_localised("entry-P10"); }

}  // namespace
}  // namespace facadeslam
