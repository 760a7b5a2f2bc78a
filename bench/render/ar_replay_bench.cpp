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
#include "render/ar/plane_finder.hpp"
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
  explicit AugmentedViewDrawer(const Camera& camera) : ar_view_(camera), height_(camera.height()) {}

  void draw(const Frame& frame, const FrameReport& report, const System& system) {
    if (!report.has_pose) return;
    const std::vector<PointSnapshot> points = system.map().snapshot_points();
    const std::vector<KeyFrameSnapshot> keyframes = system.map().snapshot_keyframes();
    std::vector<Eigen::Vector3d> points_w;
    for (const PointSnapshot& p : points) points_w.push_back(p.geometry.p_w);
    if (!object_ && points.size() >= 80 && keyframes.size() >= 3)
      if (const auto fit = render::ar::find_dominant_plane(points_w))
        object_ = render::ar::place_on_plane(*fit, points_w, keyframes.back().T_c_w.inverse().isometry());
    render::ar::ArFrameContent content;
    content.image = frame.colour;
    content.T_w_c = report.T_c_w.inverse().isometry();
    content.object = object_;
    for (const Eigen::Vector3d& p : points_w) content.points.push_back({p, cv::Vec3b(0, 0, 255)});
    benchmark::DoNotOptimize(ar_view_.render(content).data);

    render::MapViewContent map;
    std::vector<Eigen::Isometry3d> keyframes_T_c_w;
    for (const KeyFrameSnapshot& kf : keyframes) keyframes_T_c_w.push_back(kf.T_c_w.isometry());
    for (const Eigen::Vector3d& p : points_w) map.points_w.push_back(p.cast<float>());
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
  std::optional<render::ar::VirtualObject> object_;
};

void replay(benchmark::State& state, bool draw) {
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
    if (draw) drawer.emplace(d->camera);
    for (const Frame& f : d->frames) {
      const FrameReport report = system.process(f);
      if (drawer) drawer->draw(f, report, system);
    }
    system.finish();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * d->frames.size()));
}

void BM_ReplayThreaded(benchmark::State& state) { replay(state, false); }
void BM_ReplayThreadedWithAugmentedView(benchmark::State& state) { replay(state, true); }
BENCHMARK(BM_ReplayThreaded)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReplayThreadedWithAugmentedView)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
