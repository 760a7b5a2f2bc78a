// The tracker's per-point building blocks on a real facade photo at 640x480:
// template warping, patch search (FAST corners + ZMSSD + sub-pixel
// refinement) and one robust pose-update iteration. The peer, measured in the
// same run, is cv::matchTemplate (TM_SQDIFF) of the same 8x8 patch over the
// same search window, so the patch search figure reads as a ratio.
//
// The current frame is the photo seen by the same camera rolled by 3 degrees
// and panned by ~0.3 degrees (an exact homography for a pure rotation), so
// templates really are warped and found off-grid.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "bench/bench_images.hpp"
#include "core/camera/camera.hpp"
#include "core/image/image_pyramid.hpp"
#include "core/map/map_point.hpp"
#include "core/patch/patch_search.hpp"
#include "core/patch/patch_warp.hpp"
#include "tracker/pose_update.hpp"

namespace {

using namespace facadeslam;
using namespace facadeslam::patch;

struct Point {
  PatchSource source;
  PointGeometry geometry;
};

struct Scene {
  Camera camera{640, 480, PinholeRadTan{500.0, 500.0, 319.5, 239.5}};
  std::shared_ptr<const ImagePyramid> source;
  std::unique_ptr<ImagePyramid> current;
  std::unique_ptr<SearchImage> frame;  // built once per frame by the tracker
  SE3d T_c_w;                          // source camera = world
  std::vector<Point> points;
  std::vector<Eigen::Vector2d> truth;  // level-0 projections in the current frame
};

const Scene& scene() {
  static const Scene s = [] {
    Scene sc;
    std::string name;
    const cv::Mat photo = to_grey(bench::facade_image({640, 480}, &name));
    benchmark::AddCustomContext("image", name);
    sc.source = std::make_shared<const ImagePyramid>(photo);

    Eigen::Matrix<double, 6, 1> xi;
    xi << 0, 0, 0, 0.002, -0.005, 3.0 * M_PI / 180.0;
    sc.T_c_w = SE3d::exp(xi);
    Eigen::Matrix3d K;
    K << 500, 0, 319.5, 0, 500, 239.5, 0, 0, 1;
    const Eigen::Matrix3d H = K * sc.T_c_w.rotation_matrix() * K.inverse();
    cv::Mat Hcv(3, 3, CV_64F), warped;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) Hcv.at<double>(r, c) = H(r, c);
    cv::warpPerspective(photo, warped, Hcv, photo.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    sc.current = std::make_unique<ImagePyramid>(warped);
    sc.frame = std::make_unique<SearchImage>(*sc.current);

    // Map points at the corners of every level, on a plane 3 m away.
    for (int level = 0; level < kPyramidLevels; ++level)
      for (const Corner& c : sc.source->level(level).corners) {
        const Eigen::Vector2d xl(c.x, c.y);
        Point p;
        p.source.pyramid = sc.source;
        p.source.level = level;
        p.source.pixel_level0 = ImagePyramid::level_to_level0(xl, level);
        const auto ray = [&](Eigen::Vector2d d) {
          return sc.camera.unproject(ImagePyramid::level_to_level0(xl + d, level));
        };
        p.geometry = fronto_parallel_geometry(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), ray({0, 0}),
                                              ray({1, 0}), ray({0, 1}), 3.0);
        const Eigen::Vector2d t = sc.camera.project(sc.T_c_w * p.geometry.p_w);
        if (!sc.camera.in_image(t, 16.0)) continue;
        sc.points.push_back(p);
        sc.truth.push_back(t);
      }
    return sc;
  }();
  return s;
}

// Templates made once for an evenly spread subset of the points, few enough
// (256 x ~0.9 KB) to stay in cache as they do in the tracker, which searches
// each template right after making it. The search benchmarks use these.
const std::vector<std::pair<PatchTemplate, Eigen::Vector2d>>& templates() {
  static const auto t = [] {
    std::vector<std::pair<PatchTemplate, Eigen::Vector2d>> all, out;
    const Scene& s = scene();
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      PatchTemplate tpl = make_patch_template(s.points[i].source, s.points[i].geometry, s.T_c_w, s.camera);
      if (tpl.valid()) all.emplace_back(tpl, s.truth[i]);
    }
    const std::size_t stride = std::max<std::size_t>(1, all.size() / 256);
    for (std::size_t i = 0; i < all.size() && out.size() < 256; i += stride) out.push_back(all[i]);
    return out;
  }();
  return t;
}

// Prediction error of a motion model, and the fine-stage radius (PTAM: a few
// level-0 pixels), converted to search-level pixels.
const Eigen::Vector2d kPredictionError(2.0, -1.5);
constexpr double kRadiusLevel0 = 6.0;
double radius_at(int level) { return kRadiusLevel0 / ImagePyramid::level_scale(level); }

// Minimum over repetitions (--benchmark_repetitions=N): on a shared machine
// the least disturbed run is the most repeatable figure.
double min_of(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

void per_point(benchmark::State& state, std::size_t points) {
  state.counters["points"] = static_cast<double>(points);
  state.counters["per_point"] = benchmark::Counter(
      static_cast<double>(points), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_MakePatchTemplate(benchmark::State& state) {
  const Scene& s = scene();
  for (auto _ : state)
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      PatchTemplate t = make_patch_template(s.points[i].source, s.points[i].geometry, s.T_c_w, s.camera);
      benchmark::DoNotOptimize(t.ssq);
    }
  per_point(state, s.points.size());
}
BENCHMARK(BM_MakePatchTemplate)->Unit(benchmark::kMicrosecond)->ComputeStatistics("min", min_of);

void BM_SearchPatch(benchmark::State& state) {
  const Scene& s = scene();
  const auto& tpls = templates();
  int found = 0, candidates = 0;
  double error = 0.0;
  for (auto _ : state) {
    found = candidates = 0;
    error = 0.0;
    for (const auto& [tpl, truth] : tpls) {
      const PatchSearchResult r = search_patch(tpl, *s.frame, truth + kPredictionError, radius_at(tpl.search_level));
      candidates += r.candidates;
      if (r.found()) {
        ++found;
        error += (r.pixel_level0 - truth).norm();
      }
    }
    benchmark::DoNotOptimize(found);
  }
  per_point(state, tpls.size());
  state.counters["found_ratio"] = static_cast<double>(found) / static_cast<double>(tpls.size());
  state.counters["candidates_per_point"] = static_cast<double>(candidates) / static_cast<double>(tpls.size());
  state.counters["mean_error_px"] = found ? error / found : 0.0;
}
BENCHMARK(BM_SearchPatch)->Unit(benchmark::kMicrosecond)->ComputeStatistics("min", min_of);

// The same through the overload without the per-frame row index.
void BM_SearchPatchNoRowIndex(benchmark::State& state) {
  const Scene& s = scene();
  const auto& tpls = templates();
  for (auto _ : state)
    for (const auto& [tpl, truth] : tpls) {
      const PatchSearchResult r = search_patch(tpl, *s.current, truth + kPredictionError, radius_at(tpl.search_level));
      benchmark::DoNotOptimize(r.zmssd);
    }
  per_point(state, tpls.size());
}
BENCHMARK(BM_SearchPatchNoRowIndex)->Unit(benchmark::kMicrosecond)->ComputeStatistics("min", min_of);

void BM_SearchPatchCoarseOnly(benchmark::State& state) {
  const Scene& s = scene();
  const auto& tpls = templates();
  SearchOptions options;
  options.subpixel = false;
  for (auto _ : state)
    for (const auto& [tpl, truth] : tpls) {
      const PatchSearchResult r =
          search_patch(tpl, *s.frame, truth + kPredictionError, radius_at(tpl.search_level), options);
      benchmark::DoNotOptimize(r.zmssd);
    }
  per_point(state, tpls.size());
}
BENCHMARK(BM_SearchPatchCoarseOnly)->Unit(benchmark::kMicrosecond)->ComputeStatistics("min", min_of);

// The peer: dense TM_SQDIFF of the same 8x8 patch (as 8-bit) over the same
// square window at the same level, plus the minimum search.
void BM_OpenCvMatchTemplate(benchmark::State& state) {
  const Scene& s = scene();
  const auto& tpls = templates();
  struct Job {
    cv::Mat patch;
    cv::Rect window;
    int level;
  };
  std::vector<Job> jobs;
  for (const auto& [tpl, truth] : tpls) {
    Job job;
    job.level = tpl.search_level;
    job.patch.create(kPatchSize, kPatchSize, CV_8UC1);
    for (int k = 0; k < kPatchPixels; ++k)
      job.patch.at<std::uint8_t>(k / kPatchSize, k % kPatchSize) =
          cv::saturate_cast<std::uint8_t>(tpl.values[static_cast<std::size_t>(k)] + tpl.mean);
    const Eigen::Vector2d p = ImagePyramid::level0_to_level(truth + kPredictionError, job.level);
    const int r = static_cast<int>(std::ceil(radius_at(job.level)));
    const cv::Mat& image = s.current->level(job.level).image;
    job.window =
        cv::Rect(static_cast<int>(std::lround(p.x())) - r - kPatchSize / 2,
                 static_cast<int>(std::lround(p.y())) - r - kPatchSize / 2, 2 * r + kPatchSize, 2 * r + kPatchSize) &
        cv::Rect(0, 0, image.cols, image.rows);
    if (job.window.width >= kPatchSize && job.window.height >= kPatchSize) jobs.push_back(job);
  }
  cv::Mat result;
  for (auto _ : state)
    for (const Job& job : jobs) {
      cv::matchTemplate(s.current->level(job.level).image(job.window), job.patch, result, cv::TM_SQDIFF);
      double min_value;
      cv::Point min_at;
      cv::minMaxLoc(result, &min_value, nullptr, &min_at, nullptr);
      benchmark::DoNotOptimize(min_at);
    }
  per_point(state, jobs.size());
}
BENCHMARK(BM_OpenCvMatchTemplate)->Unit(benchmark::kMicrosecond)->ComputeStatistics("min", min_of);

// What the tracker pays per point: make the template, then search it.
void BM_TemplateAndSearch(benchmark::State& state) {
  const Scene& s = scene();
  int found = 0;
  for (auto _ : state) {
    found = 0;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const PatchTemplate tpl = make_patch_template(s.points[i].source, s.points[i].geometry, s.T_c_w, s.camera);
      if (!tpl.valid()) continue;
      found += search_patch(tpl, *s.frame, s.truth[i] + kPredictionError, radius_at(tpl.search_level)).found();
    }
    benchmark::DoNotOptimize(found);
  }
  per_point(state, s.points.size());
  state.counters["found_ratio"] = static_cast<double>(found) / static_cast<double>(s.points.size());
}
BENCHMARK(BM_TemplateAndSearch)->Unit(benchmark::kMicrosecond)->ComputeStatistics("min", min_of);

// The per-frame row index the searches share.
void BM_SearchImageIndex(benchmark::State& state) {
  const Scene& s = scene();
  for (auto _ : state) {
    SearchImage frame(*s.current);
    benchmark::DoNotOptimize(&frame);
  }
}
BENCHMARK(BM_SearchImageIndex)->Unit(benchmark::kMicrosecond)->ComputeStatistics("min", min_of);

void BM_PoseUpdate(benchmark::State& state) {
  const Scene& s = scene();
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  std::vector<PoseMeasurement> m;
  cv::RNG rng(1);
  for (std::size_t i = 0; m.size() < n; ++i) {
    const Point& p = s.points[i % s.points.size()];
    PoseMeasurement meas;
    meas.p_w = p.geometry.p_w * rng.uniform(0.8, 1.5);  // spread the depths
    meas.pixel = s.camera.project(s.T_c_w * meas.p_w) + Eigen::Vector2d(rng.gaussian(0.5), rng.gaussian(0.5));
    meas.level = static_cast<int>(i % 4);
    m.push_back(meas);
  }
  Eigen::Matrix<double, 6, 1> xi;
  xi << 0.01, -0.02, 0.01, 0.005, 0.002, -0.004;
  const SE3d start = SE3d::exp(xi) * s.T_c_w;
  PoseUpdateOptions options;
  options.max_iterations = static_cast<int>(state.range(1));
  options.convergence = 0.0;  // always take every step
  for (auto _ : state) {
    const PoseUpdateResult r = update_pose(start, m, s.camera, options);
    benchmark::DoNotOptimize(r.T_c_w.translation().data());
  }
  per_point(state, n);
}
// Arguments: measurements, Gauss-Newton steps (each run also evaluates the
// weights and information at the final pose once).
BENCHMARK(BM_PoseUpdate)
    ->Args({50, 1})
    ->Args({1000, 1})
    ->Args({1000, 10})
    ->Unit(benchmark::kMicrosecond)
    ->ComputeStatistics("min", min_of);

}  // namespace

// The scene is built before the run so that the image used appears in the
// report's context (AddCustomContext must precede RunSpecifiedBenchmarks).
int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  scene();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
