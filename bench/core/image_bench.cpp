// Pyramid + FAST, as the tracker runs it on every frame, next to a plain
// cv::FAST on the full-resolution grey image measured in the same run.
#include <benchmark/benchmark.h>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "bench/bench_images.hpp"
#include "core/image/image_pyramid.hpp"

namespace {

using namespace facadeslam;

std::string g_image_source;

const cv::Mat& frame() {
  static const cv::Mat image = bench::facade_image({640, 480}, &g_image_source);
  return image;
}

void BM_PyramidAndFast(benchmark::State& state) {
  std::size_t corners = 0;
  for (auto _ : state) {
    ImagePyramid pyramid(frame());
    corners = 0;
    for (int l = 0; l < pyramid.levels(); ++l) corners += pyramid.level(l).corners.size();
    benchmark::DoNotOptimize(corners);
  }
  state.counters["corners"] = static_cast<double>(corners);
}
BENCHMARK(BM_PyramidAndFast)->Unit(benchmark::kMillisecond);

void BM_PyramidOnly(benchmark::State& state) {
  PyramidOptions options;
  options.detect_corners = false;
  for (auto _ : state) {
    ImagePyramid pyramid(frame(), options);
    benchmark::DoNotOptimize(pyramid.level(3).image.data);
  }
}
BENCHMARK(BM_PyramidOnly)->Unit(benchmark::kMillisecond);

void BM_FastLevel0(benchmark::State& state) {
  const cv::Mat grey = to_grey(frame());
  const FastOptions options = PyramidOptions{}.fast[0];
  std::size_t corners = 0;
  for (auto _ : state) {
    corners = detect_fast(grey, options).size();
    benchmark::DoNotOptimize(corners);
  }
  state.counters["corners"] = static_cast<double>(corners);
}
BENCHMARK(BM_FastLevel0)->Unit(benchmark::kMillisecond);

// The segment test alone (what detect_fast starts from): the rest of
// detect_fast's time is its exact scoring and raster-order suppression.
void BM_OpenCvFastCandidatesLevel0(benchmark::State& state) {
  const cv::Mat grey = to_grey(frame());
  std::vector<cv::KeyPoint> keypoints;
  for (auto _ : state) {
    cv::FAST(grey, keypoints, PyramidOptions{}.fast[0].threshold, false);
    benchmark::DoNotOptimize(keypoints.data());
  }
  state.counters["candidates"] = static_cast<double>(keypoints.size());
}
BENCHMARK(BM_OpenCvFastCandidatesLevel0)->Unit(benchmark::kMillisecond);

// The peer: OpenCV's FAST-9 with its own non-maximum suppression on level 0.
void BM_OpenCvFastLevel0(benchmark::State& state) {
  const cv::Mat grey = to_grey(frame());
  std::vector<cv::KeyPoint> keypoints;
  for (auto _ : state) {
    cv::FAST(grey, keypoints, PyramidOptions{}.fast[0].threshold, true);
    benchmark::DoNotOptimize(keypoints.data());
  }
  state.counters["corners"] = static_cast<double>(keypoints.size());
}
BENCHMARK(BM_OpenCvFastLevel0)->Unit(benchmark::kMillisecond);

}  // namespace

// Own main so the image's provenance is in the report header (the context
// must be added before the benchmarks run).
int main(int argc, char** argv) {
  frame();
  benchmark::AddCustomContext("image", g_image_source);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
