// The whole SLAM system over the embedded demo (150 frames at 640x480,
// rendered at set-up by scripts/make-demo): frames per second of a replay,
// the images already decoded in memory so that only the system is measured.
//
// BM_ReplayThreaded is the product (tracker on this thread, map maker on its
// own); its peer in the same run is BM_ReplaySynchronous, the same replay
// with the map maker inline (what --sync does), whose frame rate is bound by
// bundle adjustment; BM_PyramidOnly, building each frame's pyramid and FAST
// corners and nothing else, is the floor every frame pays. Goal: threaded
// >= 60 frames/s on 2 cores.
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/camera/camera_yaml.hpp"
#include "core/image/image_pyramid.hpp"
#include "sequences/open_sequence.hpp"
#include "slam/system.hpp"

namespace {

using namespace facadeslam;

struct DemoFrames {
  Camera camera;
  std::vector<Frame> frames;
};

// The demo, read once; nullptr (and the benchmarks skip) when not rendered.
const DemoFrames* demo() {
  static const std::unique_ptr<DemoFrames> frames = []() -> std::unique_ptr<DemoFrames> {
    const char* root = std::getenv("FACADESLAM_SOURCE_DIR");
    const std::filesystem::path folder =
        std::filesystem::path(root ? root : FACADESLAM_SOURCE_DIR) / "data" / "demo" / "sequence";
    if (!std::filesystem::exists(folder / "rgb.txt")) return nullptr;
    auto d = std::make_unique<DemoFrames>(DemoFrames{load_camera(folder / "camera.yaml"), {}});
    auto source = open_sequence(folder / "rgb.txt", SequenceOptions{});
    while (auto frame = source->next()) d->frames.push_back(std::move(*frame));
    return d;
  }();
  return frames.get();
}

void replay(benchmark::State& state, bool synchronous) {
  const DemoFrames* d = demo();
  if (!d) {
    state.SkipWithError("data/demo/sequence is not rendered (run scripts/make-demo)");
    return;
  }
  std::size_t tracked = 0;
  for (auto _ : state) {
    SlamOptions options;
    options.synchronous = synchronous;
    System system(d->camera, options);
    for (const Frame& f : d->frames) tracked += system.process(f).has_pose;
    system.finish();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * d->frames.size()));
  state.counters["tracked_share"] =
      static_cast<double>(tracked) / static_cast<double>(state.iterations() * d->frames.size());
}

void BM_ReplayThreaded(benchmark::State& state) { replay(state, false); }
void BM_ReplaySynchronous(benchmark::State& state) { replay(state, true); }

void BM_PyramidOnly(benchmark::State& state) {
  const DemoFrames* d = demo();
  if (!d) {
    state.SkipWithError("data/demo/sequence is not rendered (run scripts/make-demo)");
    return;
  }
  const PyramidOptions options = SlamOptions{}.tracker.pyramid;
  for (auto _ : state)
    for (const Frame& f : d->frames) benchmark::DoNotOptimize(ImagePyramid(f.colour, options));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * d->frames.size()));
}

BENCHMARK(BM_ReplayThreaded)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(5.0);
BENCHMARK(BM_ReplaySynchronous)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(5.0);
BENCHMARK(BM_PyramidOnly)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
