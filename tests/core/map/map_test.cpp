#include "core/map/map.hpp"

#include <thread>

#include <gtest/gtest.h>

#include "tests/support/small_map.hpp"

namespace facadeslam {
namespace {

ClassVotes votes_for(std::initializer_list<std::pair<std::size_t, float>> shares) {
  ClassVotes votes{};
  for (const auto& [c, share] : shares) votes[c] = share;
  return votes;
}

TEST(MapPoint, VotesGiveTheLabelAndItsShare) {
  MapPoint p(0, {}, {});
  p.set_votes(votes_for({{7, 0.875f}, {1, 0.125f}}));
  EXPECT_EQ(p.label(), (SemanticLabel{7, 0.875f}));
  p.set_votes({});
  EXPECT_EQ(p.label().label, kUnlabelled);
}

TEST(MapPoint, LaterObservationsAreFusedIntoTheVoteSums) {
  MapPoint p(0, {}, {});
  p.add_votes(votes_for({{2, 0.6f}, {1, 0.4f}}));  // first view: car
  EXPECT_EQ(p.label(), (SemanticLabel{2, 0.6f}));
  p.add_votes(votes_for({{1, 0.9f}, {2, 0.1f}}));  // second view outvotes it
  EXPECT_EQ(p.label().label, 1);
  EXPECT_FLOAT_EQ(p.label().confidence, 1.3f / 2.0f);
  EXPECT_FLOAT_EQ(p.votes()[2], 0.7f);
}

// A point is in a moving region when most of the views the detector looked
// at saw it in one; a tie is not most.
TEST(MapPoint, MostViewsInAMovingRegionPutThePointInOne) {
  MapPoint p(0, {}, {});
  EXPECT_FALSE(p.in_moving_region());
  p.add_region_view(true);
  EXPECT_TRUE(p.in_moving_region());
  p.add_region_view(false);
  EXPECT_FALSE(p.in_moving_region()) << "one of two views";
  p.add_region_view(true);
  EXPECT_TRUE(p.in_moving_region());
  EXPECT_EQ(p.region_views(), (MapPoint::RegionViews{.views = 3, .in_region = 2}));
  p.set_region_views({.views = 4, .in_region = 1});
  EXPECT_FALSE(p.in_moving_region());
}

TEST(MapPoint, TiesGoToTheLowerClassId) {
  EXPECT_EQ(label_from_votes(votes_for({{5, 0.5f}, {3, 0.5f}})).label, 3);
  EXPECT_EQ(label_from_votes({}).label, kUnlabelled);
}

TEST(MapPoint, NewPointsAreUnlabelled) {
  MapPoint p(0, {}, {});
  EXPECT_EQ(p.label().label, kUnlabelled);
  EXPECT_FALSE(p.is_bad());
}

TEST(MapPoint, SearchStatistics) {
  MapPoint p(0, {}, {});
  p.count_search(true);
  p.count_search(false);
  p.count_search(false);
  EXPECT_EQ(p.times_searched(), 3u);
  EXPECT_EQ(p.times_found(), 1u);
}

TEST(MapPoint, FrontoParallelGeometryScalesPixelOffsetsWithDepth) {
  const Eigen::Matrix3d R_w_c = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d centre(1, 2, 3);
  const PointGeometry g = fronto_parallel_geometry(R_w_c, centre, {0.1, 0, 1}, {0.11, 0, 1}, {0.1, 0.01, 1}, 5.0);
  EXPECT_TRUE(g.p_w.isApprox(Eigen::Vector3d(1.5, 2, 8)));
  EXPECT_TRUE(g.right_w.isApprox(Eigen::Vector3d(0.05, 0, 0)));
  EXPECT_TRUE(g.down_w.isApprox(Eigen::Vector3d(0, 0.05, 0)));
  EXPECT_NEAR(g.normal_w.norm(), 1.0, 1e-12);
  EXPECT_LT(g.normal_w.z(), 0);  // points back towards the camera
}

TEST(Map, IdsAreUniqueAndLookupsWork) {
  Map map;
  test::build_test_map(map, 5);
  EXPECT_EQ(map.keyframe_count(), 2u);
  EXPECT_EQ(map.point_count(), 5u);
  for (const auto& p : map.points()) EXPECT_EQ(map.point(p->id()), p);
  EXPECT_EQ(map.point(999), nullptr);
  EXPECT_EQ(map.keyframe(1)->id(), 1u);
  EXPECT_NE(map.new_point_id(), map.new_point_id());
}

TEST(Map, BadPointsLeaveSnapshotsAndAreRemovedWithTheirMeasurements) {
  Map map;
  test::build_test_map(map, 6);
  const auto bad = map.points()[2];
  map.update([&](MapEditor& edit) { edit.mark_bad(*bad); });
  EXPECT_EQ(map.snapshot_points().size(), 5u);
  for (const auto& kf : map.keyframes()) ASSERT_EQ(kf->measurements().count(bad->id()), 1u);
  const auto removed = map.remove_bad_points();
  ASSERT_EQ(removed, std::vector<MapPoint::Id>{bad->id()});
  EXPECT_EQ(map.point_count(), 5u);
  EXPECT_EQ(map.point(removed[0]), nullptr);
  for (const auto& kf : map.keyframes()) {
    EXPECT_EQ(kf->measurements().count(bad->id()), 0u);
    EXPECT_EQ(kf->measurements().size(), 5u);
  }
}

// The tracker's snapshot is refreshed only when the map changed: every
// exclusive section (update, add, remove_bad_points, clear) counts.
TEST(Map, APointsSnapshotIsRefreshedOnlyAfterAChange) {
  Map map;
  test::build_test_map(map, 6);
  std::vector<PointSnapshot> points;
  std::uint64_t revision = 0;
  EXPECT_TRUE(map.refresh_points_snapshot(points, revision));
  EXPECT_EQ(points.size(), 6u);
  EXPECT_FALSE(map.refresh_points_snapshot(points, revision)) << "nothing changed";
  map.read([](const MapView&) {});
  EXPECT_FALSE(map.refresh_points_snapshot(points, revision)) << "a read changes nothing";
  const auto bad = map.points()[1];
  map.update([&](MapEditor& edit) { edit.mark_bad(*bad); });
  EXPECT_TRUE(map.refresh_points_snapshot(points, revision));
  EXPECT_EQ(points.size(), 5u);
  map.remove_bad_points();
  EXPECT_TRUE(map.refresh_points_snapshot(points, revision));
  map.add({}, {std::make_shared<MapPoint>(map.new_point_id(), map.points().front()->source(), PointGeometry{})});
  EXPECT_TRUE(map.refresh_points_snapshot(points, revision));
  EXPECT_EQ(points.size(), 6u);
  map.clear();
  EXPECT_TRUE(map.refresh_points_snapshot(points, revision));
  EXPECT_TRUE(points.empty());
}

TEST(Map, ObservationsArePublishedWithTheirPoints) {
  Map map;
  test::build_test_map(map, 2);
  const auto kf = map.keyframes().back();
  auto point = std::make_shared<MapPoint>(map.new_point_id(), map.points().front()->source(), PointGeometry{});
  NewPoints more;
  more.points.push_back(point);
  more.observations.push_back({kf, point->id(), {1, {3.0, 4.0}, false}});
  map.add(more);
  EXPECT_EQ(map.point(point->id()), point);
  ASSERT_EQ(kf->measurements().count(point->id()), 1u);
  EXPECT_EQ(kf->measurements().at(point->id()).level, 1);
  map.update([&](MapEditor& edit) { EXPECT_TRUE(edit.erase_measurement(*kf, point->id())); });
  EXPECT_EQ(kf->measurements().count(point->id()), 0u);
}

TEST(Map, APointsViewFollowsItsSourceUntilAnotherKeyframeTakesIt) {
  Map map;
  test::build_test_map(map, 2);
  const auto p = map.points().front();
  EXPECT_EQ(p->view().keyframe_id, p->source().keyframe_id);
  PointGeometry moved = p->geometry();
  moved.p_w.x() += 1.0;
  map.update([&](MapEditor& edit) { edit.set_geometry(*p, moved); });
  EXPECT_EQ(p->view_geometry().p_w, moved.p_w) << "a view at the source moves with the point";

  const auto other = map.keyframes().back();
  const PatchSource view{other->id(), other->pyramid(), 1, {30.0, 40.0}};
  PointGeometry seen = moved;
  seen.right_w = Eigen::Vector3d(0.02, 0, 0);
  map.update([&](MapEditor& edit) { edit.set_view(*p, view, seen); });
  moved.p_w.y() += 1.0;
  map.update([&](MapEditor& edit) { edit.set_geometry(*p, moved); });
  EXPECT_EQ(p->view().keyframe_id, other->id());
  EXPECT_EQ(p->view_geometry().right_w, seen.right_w) << "another keyframe's view is the map maker's to refresh";
  const auto snapshot = map.snapshot_points();
  EXPECT_EQ(snapshot.front().view.keyframe_id, other->id());
  EXPECT_EQ(snapshot.front().view_geometry.right_w, seen.right_w);
}

TEST(Map, KeyFrameSnapshotsCopyPoseAndDepth) {
  Map map;
  test::build_test_map(map, 2);
  const auto kf = map.keyframes().back();
  const SE3d moved = SE3d::exp((Eigen::Matrix<double, 6, 1>() << 1, 2, 3, 0, 0, 0.1).finished());
  map.update([&](MapEditor& edit) {
    edit.set_pose(*kf, moved);
    edit.set_depth_stats(*kf, 7.0, 0.25);
  });
  const auto snapshot = map.snapshot_keyframes();
  ASSERT_EQ(snapshot.size(), 2u);
  EXPECT_EQ(snapshot.back().keyframe, kf);
  EXPECT_EQ(snapshot.back().T_c_w.matrix(), moved.matrix());
  EXPECT_EQ(snapshot.back().mean_depth, 7.0);
  EXPECT_EQ(snapshot.back().depth_sigma, 0.25);
  EXPECT_TRUE(snapshot.back().centre_w().isApprox(moved.inverse().translation()));
}

TEST(Map, SnapshotCopiesGeometry) {
  Map map;
  test::build_test_map(map, 3);
  const auto snapshot = map.snapshot_points();
  ASSERT_EQ(snapshot.size(), 3u);
  for (const auto& s : snapshot) EXPECT_EQ(s.geometry.p_w, s.point->position());
}

TEST(Map, ConcurrentReadersAndWriterSeeWholeObjects) {
  // Run under ThreadSanitizer: a writer publishing points and moving them
  // under the lock while readers snapshot and relabel.
  Map map;
  test::build_test_map(map, 10);
  std::atomic<bool> stop{false};
  // The writer starts once the reader is running, so that the two overlap
  // even when the machine is loaded (no sleeping: an atomic wait).
  std::atomic<bool> reading{false};
  std::thread writer([&] {
    reading.wait(false);
    for (int i = 0; i < 200; ++i) {
      auto source = map.points().front()->source();
      map.add({}, {std::make_shared<MapPoint>(map.new_point_id(), source, PointGeometry{})});
      const auto points = map.points();
      map.update([&](MapEditor& edit) {
        for (const auto& p : points) {
          PointGeometry g = p->geometry();
          g.p_w.x() += 1e-3;
          edit.set_geometry(*p, g);
        }
      });
    }
    stop = true;
  });
  do {
    const auto snapshot = map.snapshot_points();
    for (const auto& s : snapshot) s.point->add_votes(votes_for({{1, 0.5f}}));
    EXPECT_GE(snapshot.size(), 10u);
    if (!reading.exchange(true)) reading.notify_one();
  } while (!stop);
  writer.join();
  EXPECT_EQ(map.point_count(), 210u);
}

TEST(Map, ACulledKeyframeHandsItsPointsOnAndLeavesALinkForItsFrames) {
  Map map;
  test::build_test_map(map, 3);
  const auto keyframes = map.keyframes();
  const auto gone = keyframes.front(), stays = keyframes.back();
  const auto p = map.points().front();
  ASSERT_EQ(p->source().keyframe_id, gone->id());
  ASSERT_FALSE(stays->measurements().at(p->id()).from_source);

  const Measurement& m = stays->measurements().at(p->id());
  const PatchSource source{stays->id(), stays->pyramid(), m.level, m.pixel};
  PointGeometry geometry = p->geometry();
  geometry.right_w = Eigen::Vector3d(0.03, 0, 0);
  const CulledKeyFrame link{stays->id(), gone->T_c_w() * stays->T_c_w().inverse()};
  map.update([&](MapEditor& edit) {
    edit.set_source(*p, *stays, source, geometry);
    edit.cull_keyframe(gone->id(), link);
  });
  EXPECT_EQ(p->source().keyframe_id, stays->id());
  EXPECT_EQ(p->geometry().right_w, geometry.right_w);
  EXPECT_TRUE(stays->measurements().at(p->id()).from_source) << "bundle adjustment never drops a source measurement";
  EXPECT_EQ(map.keyframe_count(), 1u);
  EXPECT_EQ(map.keyframe(gone->id()), nullptr);
  const auto culled = map.culled_keyframes();
  ASSERT_EQ(culled.size(), 1u);
  EXPECT_EQ(culled.at(gone->id()).parent, stays->id());
  EXPECT_EQ(map.snapshot_points().front().source.keyframe_id, stays->id()) << "snapshots carry the source";
  map.clear();
  EXPECT_TRUE(map.culled_keyframes().empty()) << "a cleared map forgets its culled keyframes";
}

TEST(Map, ClearEmptiesEverything) {
  Map map;
  test::build_test_map(map, 4);
  map.clear();
  EXPECT_EQ(map.keyframe_count(), 0u);
  EXPECT_EQ(map.point_count(), 0u);
}

}  // namespace
}  // namespace facadeslam
