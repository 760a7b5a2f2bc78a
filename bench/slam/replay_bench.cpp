// The whole SLAM system over the embedded demo (150 frames at 640x480,
// rendered at set-up by scripts/make-demo): frames per second of a replay,
// the images already decoded in memory so that only the system is measured.
//
// BM_ReplayThreaded is the product (tracker on this thread, map maker on its
// own); its peer in the same run is BM_ReplaySynchronous, the same replay
// with the map maker inline (what --sync does), whose frame rate is bound by
// bundle adjustment; BM_ReplayThreadedSemantics adds the semantic worker
// thread (the shipped model; goal >= 60 frames/s, the tracker's median
// within 5 % of BM_ReplayThreaded's); BM_PyramidOnly, building each frame's pyramid and FAST
// corners and nothing else, is the floor every frame pays. Goal: threaded
// >= 60 frames/s on 2 cores.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>
#include <spdlog/spdlog.h>

#include "bench/bench_sequences.hpp"
#include "core/image/image_pyramid.hpp"
#include "core/util/median.hpp"
#include "sequences/open_sequence.hpp"
#include "slam/system.hpp"

namespace {

using namespace facadeslam;

using DemoFrames = bench::BenchSequence;
const DemoFrames* demo() { return bench::demo_sequence(); }

// The shipped semantic settings and model (configs/semantics.yaml).
SemanticsOptions semantics_on() {
  const std::filesystem::path source = bench::source_dir();
  SemanticsOptions options = load_semantics_options(source / "configs" / "semantics.yaml");
  options.model = source / "models" / "default.fsmodel";
  options.enabled = true;
  return options;
}

void replay(benchmark::State& state, bool synchronous, bool semantics) {
  const DemoFrames* d = demo();
  if (!d) {
    state.SkipWithError("data/demo/sequence is not rendered (run scripts/make-demo)");
    return;
  }
  spdlog::set_level(spdlog::level::warn);
  std::size_t tracked = 0;
  std::vector<double> tracker_ms, worker_ms;
  double worker_us_per_point = 0.0;
  for (auto _ : state) {
    SlamOptions options;
    options.synchronous = synchronous;
    if (semantics) options.semantics = semantics_on();
    System system(d->camera, options);
    for (const Frame& f : d->frames) {
      const FrameReport r = system.process(f);
      tracked += r.has_pose;
      if (r.status != FrameStatus::tracking) continue;
      const StageTimings& t = r.tracking.timings;
      tracker_ms.push_back(r.pyramid_ms + t.snapshot_ms + t.coarse_ms + t.fine_ms + t.pose_ms);
    }
    system.finish();
    if (const auto stats = system.semantic_stats()) {
      worker_ms.insert(worker_ms.end(), stats->keyframe_ms.begin(), stats->keyframe_ms.end());
      double total = 0.0;
      for (const double ms : stats->keyframe_ms) total += ms;
      if (stats->observations_labelled)
        worker_us_per_point = 1000.0 * total / static_cast<double>(stats->observations_labelled);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * d->frames.size()));
  state.counters["tracked_share"] =
      static_cast<double>(tracked) / static_cast<double>(state.iterations() * d->frames.size());
  state.counters["tracker_median_ms"] = median(tracker_ms);
  if (semantics) {
    state.counters["worker_ms_per_keyframe"] = median(worker_ms);
    state.counters["worker_us_per_point"] = worker_us_per_point;
  }
}

void BM_ReplayThreaded(benchmark::State& state) { replay(state, false, false); }
// The product as the README runs it: the semantic worker as a third thread.
void BM_ReplayThreadedSemantics(benchmark::State& state) { replay(state, false, true); }
void BM_ReplaySynchronous(benchmark::State& state) { replay(state, true, false); }

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
BENCHMARK(BM_ReplayThreadedSemantics)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(5.0);
BENCHMARK(BM_ReplaySynchronous)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(5.0);
BENCHMARK(BM_PyramidOnly)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
