// The replay with the augmented view drawn after every frame (what `replay
// --render` adds on the replay thread: map snapshots, the plane and the
// object once, the overlay and the map view; the PNG and video encoding run
// on a writer thread and are not in it), next to the same replay without it
// in the same run: frames per second of the embedded demo (150 frames at
// 640x480, scripts/make-demo), threaded as the
// README's command runs it, semantics off (the shipped model is not the
// subject).
#include <memory>
#include <optional>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/bench_sequences.hpp"
#include "render/ar/ar_view.hpp"
#include "render/ar/follow_camera.hpp"
#include "render/ar/map_occlusion.hpp"
#include "render/ar/object_placement.hpp"
#include "render/ar/virtual_object.hpp"
#include "render/map_view.hpp"
#include "render/map_view_framing.hpp"
#include "slam/system.hpp"

namespace {

using namespace facadeslam;

using DemoFrames = bench::BenchSequence;
const DemoFrames* demo() { return bench::demo_sequence(); }

// Draws the frame's augmented view and map view (the drawing of
// apps/replay/replay_render.cpp, without its files).
class AugmentedViewDrawer {
 public:
  // `occlusion`: the map's points hide the object (render/ar/map_occlusion),
  // all of them sparse occluders, as unlabelled points are.
  AugmentedViewDrawer(const Camera& camera, bool occlusion)
      : ar_view_(camera), height_(camera.height()), occlusion_(occlusion) {}

  void draw(const Frame& frame, const FrameReport& report, const System& system) {
    if (!report.has_pose) return;
    const std::vector<PointSnapshot> points = system.map().snapshot_points();
    const std::vector<KeyFrameSnapshot> keyframes = system.map().snapshot_keyframes();
    std::vector<Eigen::Vector3d> points_w;
    points_w.reserve(points.size());
    for (const PointSnapshot& p : points) points_w.push_back(p.geometry.p_w);
    if (!object_ && points.size() >= 80 && keyframes.size() >= 3) {
      std::vector<render::ar::PlacementPoint> placement_points;
      placement_points.reserve(points_w.size());
      for (const Eigen::Vector3d& p : points_w) placement_points.push_back({p, false});
      std::vector<Eigen::Isometry3d> keyframes_T_c_w;
      keyframes_T_c_w.reserve(keyframes.size());
      for (const KeyFrameSnapshot& kf : keyframes) keyframes_T_c_w.push_back(kf.T_c_w.isometry());
      if (const auto placement = render::ar::place_object(placement_points, keyframes_T_c_w))
        object_ = placement->object;
    }
    render::ar::ArFrameContent content;
    content.image = frame.colour;
    content.T_w_c = report.T_c_w.inverse().isometry();
    content.object = object_;
    if (occlusion_ && object_) {
      std::vector<render::ar::OccluderPoint> occluders;
      occluders.reserve(points_w.size());
      for (const Eigen::Vector3d& p : points_w) occluders.push_back({p, render::ar::OccluderKind::sparse});
      const render::PinholeIntrinsics& intrinsics = ar_view_.object_intrinsics();
      const Eigen::Isometry3d T_c_w = report.T_c_w.isometry();
      content.occluder_depth = render::ar::occluder_depth(occluders, T_c_w, intrinsics, spacing_.of(occluders), {},
                                                          render::ar::object_region(*object_, T_c_w, intrinsics));
    }
    content.points.reserve(points_w.size());
    for (const Eigen::Vector3d& p : points_w) content.points.push_back({p, cv::Vec3b(0, 0, 255)});
    benchmark::DoNotOptimize(ar_view_.render(content).data);

    render::MapViewContent map;
    std::vector<Eigen::Isometry3d> keyframes_T_c_w;
    keyframes_T_c_w.reserve(keyframes.size());
    for (const KeyFrameSnapshot& kf : keyframes) keyframes_T_c_w.push_back(kf.T_c_w.isometry());
    map.points_w.reserve(points_w.size());
    for (const Eigen::Vector3d& p : points_w) map.points_w.emplace_back(p.cast<float>());
    map.colours_bgr.assign(map.points_w.size(), cv::Vec3b(0, 0, 128));
    map.keyframes_T_c_w = keyframes_T_c_w;
    const render::MapViewCamera camera =
        render::ar::follow_camera(*content.T_w_c, render::view_axes_from_cameras(keyframes_T_c_w),
                                  keyframes.front().mean_depth, height_ * 4 / 3, height_);
    benchmark::DoNotOptimize(map_view_.render(map, camera).data);
  }

 private:
  render::ar::ArView ar_view_;
  render::MapView map_view_;
  int height_;
  bool occlusion_;
  std::optional<render::ar::VirtualObject> object_;
  render::ar::MapSpacing spacing_;  // as the replay measures it
};

enum class Drawing { none, augmented_view, with_occlusion };

void replay(benchmark::State& state, Drawing drawing) {
  const DemoFrames* d = demo();
  if (!d) {
    state.SkipWithError("data/demo/sequence is not rendered (run scripts/make-demo)");
    return;
  }
  for (auto _ : state) {
    SlamOptions options;
    options.semantics.enabled = false;
    System system(d->camera, options);
    std::optional<AugmentedViewDrawer> drawer;
    if (drawing != Drawing::none) drawer.emplace(d->camera, drawing == Drawing::with_occlusion);
    for (const Frame& f : d->frames) {
      const FrameReport report = system.process(f);
      if (drawer) drawer->draw(f, report, system);
    }
    system.finish();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * d->frames.size()));
}

void BM_ReplayThreaded(benchmark::State& state) { replay(state, Drawing::none); }
void BM_ReplayThreadedWithAugmentedView(benchmark::State& state) { replay(state, Drawing::augmented_view); }
void BM_ReplayThreadedWithOcclusion(benchmark::State& state) { replay(state, Drawing::with_occlusion); }
BENCHMARK(BM_ReplayThreaded)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReplayThreadedWithAugmentedView)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReplayThreadedWithOcclusion)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
