// The tracker's time per frame (issue 16: median <= 5 ms at 640x480), next
// to its peer measured in the same run: OpenCV's cv::buildPyramid + cv::FAST
// (non-maximum suppression on) over the same four levels of the same frames,
// the least any PTAM-style tracker pays before it searches a single patch.
//
// A synchronous replay of a sequence; each tracked frame's tracker time is
// the pyramid and FAST, the map snapshot, both search stages, the pose
// updates and any relocalisation (the map maker's work, inline in --sync,
// is not the tracker's). Counters: tracker_median_ms, tracker_p95_ms,
// opencv_peer_ms and their ratio. Sequences: the embedded demo (640x480,
// rendered by scripts/make-demo) and, when ../shared/data is there, the
// KITTI 06 snippet (1226x370).
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>
#include <spdlog/spdlog.h>

#include "bench/bench_sequences.hpp"
#include "core/image/image_pyramid.hpp"
#include "slam/system.hpp"

namespace {

using namespace facadeslam;

using Sequence = bench::BenchSequence;
const Sequence* demo() { return bench::demo_sequence(); }
const Sequence* kitti() { return bench::kitti_snippet(); }

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// OpenCV's pyramid and FAST per frame of `s`, milliseconds (median).
double opencv_peer_ms(const Sequence& s) {
  const int threshold = PyramidOptions{}.fast[0].threshold;
  std::vector<double> ms;
  for (const Frame& f : s.frames) {
    const auto start = std::chrono::steady_clock::now();
    cv::Mat grey;
    cv::cvtColor(f.colour, grey, cv::COLOR_BGR2GRAY);
    std::vector<cv::Mat> levels;
    cv::buildPyramid(grey, levels, kPyramidLevels - 1);
    std::size_t corners = 0;
    for (const cv::Mat& level : levels) {
      std::vector<cv::KeyPoint> keypoints;
      cv::FAST(level, keypoints, threshold, true);
      corners += keypoints.size();
    }
    benchmark::DoNotOptimize(corners);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return percentile(ms, 0.5);
}

void tracker_per_frame(benchmark::State& state, const Sequence* s) {
  if (!s) {
    state.SkipWithError("sequence not available (scripts/make-demo; ../shared/data for KITTI)");
    return;
  }
  spdlog::set_level(spdlog::level::warn);  // the replay's progress lines are not the benchmark's output
  std::vector<double> tracker_ms;
  double peer_ms = 0.0;
  for (auto _ : state) {
    SlamOptions options;
    options.synchronous = true;
    options.semantics.enabled = false;  // the tracker's time, not the worker's
    System system(s->camera, options);
    for (const Frame& f : s->frames) {
      const FrameReport r = system.process(f);
      if (r.status != FrameStatus::tracking && r.status != FrameStatus::relocalised) continue;
      const StageTimings& t = r.tracking.timings;
      tracker_ms.push_back(r.pyramid_ms + t.snapshot_ms + t.coarse_ms + t.fine_ms + t.pose_ms + t.relocalise_ms);
    }
    system.finish();
    peer_ms = opencv_peer_ms(*s);
  }
  const double median = percentile(tracker_ms, 0.5);
  state.counters["tracker_median_ms"] = median;
  state.counters["tracker_p95_ms"] = percentile(tracker_ms, 0.95);
  state.counters["opencv_peer_ms"] = peer_ms;
  state.counters["tracker_over_peer"] = peer_ms > 0 ? median / peer_ms : 0.0;
  state.counters["frames"] = static_cast<double>(tracker_ms.size());
}

void BM_TrackerPerFrameDemo640x480(benchmark::State& state) { tracker_per_frame(state, demo()); }
void BM_TrackerPerFrameKitti1226x370(benchmark::State& state) { tracker_per_frame(state, kitti()); }

BENCHMARK(BM_TrackerPerFrameDemo640x480)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(BM_TrackerPerFrameKitti1226x370)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
