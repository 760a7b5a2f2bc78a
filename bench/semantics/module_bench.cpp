// The modular descriptor's cost, module by module, and the thesis genome's
// against SIFT on the same keypoints, measured in the same run.
//
// Image: a 640x480 facade photo (bench_images.hpp), keypoints on a 9-pixel
// grid (the thesis' evaluation grid), genome parameters of the thesis' best
// genome (XYZ, radius 10, blur 7/1.5, Canny 5/65, Sobel).
//  - BM_ModuleExtract/<module>: extract() with only that module's values
//    active; counter ns_per_keypoint. BM_ModulePrepare/<module>: prepare()
//    for those values (what the per-image planes cost), per keypoint too.
//  - BM_SingularValuesUpTo/<k>: sigma1..sigma_k of all three channels (the
//    module's cost depends on the highest active value of each channel).
//  - BM_ThesisGenome: prepare() + extract() of the 93-value thesis genome;
//    BM_ThesisGenomePrepareOnly its prepare() alone (sift_over_this: the
//    ratio the genome could reach if its modules cost nothing), and
//    BM_OpenCvPreparation the same steps with OpenCV's functions;
//    BM_ThesisGenomeWithoutSingularValues / ...WithoutCostliest the genome
//    without its costliest modules (what a time-aware GA could gain).
//  - BM_SiftSparse / BM_ThesisGenomeSparse: the same pair on the 300
//    strongest FAST corners, a keyframe's worth (the semantic worker's case;
//    prepare() dominates there).
//  - BM_Sift: cv::SIFT::compute on the same keypoints. SIFT's descriptor
//    spans 4 x 4 cells of 3 sigma with sigma = size / 2, so size = (2r+1)/6
//    makes it cover the same 21 x 21 patch as ours: the like-for-like peer.
//  - BM_SiftPatchDiameter: the same with KeyPoint::size = 2r+1 (OpenCV's
//    "diameter of the meaningful neighbourhood"), for reference only: SIFT
//    then describes a ~6x wider region, and its cost grows with its area.
//  - BM_OpponentSift / BM_Edd: the thesis' own speed claim (V.3: EDD "26
//    times faster than the Opponent SIFT" over a whole image's keypoints),
//    both through the label evaluation's PointDescriptor (per-image
//    preparation included); BM_Edd reports opponent_sift_over_edd and
//    sift_over_edd.
// BM_ThesisGenome reports sift_over_thesis = SIFT time / thesis-genome time
// (issue 5 asks >= 10, ideally 20; the thesis gives no time for the genome). Everything runs on
// one OpenCV thread so the ratio compares work, not core counts, and the
// counters use the thread's CPU time, which a busy machine disturbs less
// than wall time. prepare() reuses one PreparedImage, as a frame or
// keyframe stream does.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "bench/bench_images.hpp"
#include "semantics/descriptor/extraction.hpp"
#include "semantics/descriptor/genome.hpp"
#include "semantics/descriptor/genome_io.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace {

using namespace facadeslam;
using namespace facadeslam::semantics;

// CPU seconds used by this thread so far.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Runs body() once per benchmark iteration (one image) and returns the CPU
// seconds per iteration; sets the ns_per_keypoint and keypoints counters.
template <class Body>
double seconds_per_image(benchmark::State& state, std::size_t keypoints, Body&& body) {
  const double start = thread_seconds();
  for (auto _ : state) body();
  const double seconds = (thread_seconds() - start) / static_cast<double>(state.iterations());
  const double n = static_cast<double>(keypoints);
  state.counters["ns_per_keypoint"] = 1e9 * seconds / n;
  state.counters["keypoints"] = n;
  return seconds;
}

const cv::Mat& frame() {
  static const cv::Mat image = [] {
    cv::setNumThreads(1);
    std::string source;
    cv::Mat img = bench::facade_image({640, 480}, &source);
    benchmark::AddCustomContext("image", source);
    benchmark::AddCustomContext("opencv_threads", "1");
    return img;
  }();
  return image;
}

const std::vector<cv::Point2f>& grid_keypoints() {
  static const std::vector<cv::Point2f> points = bench::grid_points(frame().size());
  return points;
}

DescriptorParams only_module(Module m) {
  DescriptorParams p = Genome::thesis_best().decode();
  p.activation.reset();
  for (int i = 0; i < module_size(m); ++i) p.activation.set(static_cast<std::size_t>(module_offset(m) + i));
  return p;
}

// prepare() + extract() with `p` on `points` (extract() alone when
// `prepare_each` is false); returns the CPU seconds per image.
double run_genome(benchmark::State& state, const DescriptorParams& p, const std::vector<cv::Point2f>& points,
                  bool prepare_each = true) {
  cv::Mat d;
  PreparedImage prepared = prepare(frame(), p);
  const double seconds = seconds_per_image(state, points.size(), [&] {
    if (prepare_each) prepare(frame(), p, prepared);
    d = extract(prepared, points, p);
    benchmark::DoNotOptimize(d.data);
  });
  state.counters["values"] = d.cols;
  return seconds;
}

void BM_ModuleExtract(benchmark::State& state) {
  const auto m = static_cast<Module>(state.range(0));
  state.SetLabel(std::string(module_name(m)));
  run_genome(state, only_module(m), grid_keypoints(), false);
}
BENCHMARK(BM_ModuleExtract)->DenseRange(0, kModuleCount - 1)->Unit(benchmark::kMillisecond);

void BM_ModulePrepare(benchmark::State& state) {
  const auto m = static_cast<Module>(state.range(0));
  state.SetLabel(std::string(module_name(m)));
  const DescriptorParams p = only_module(m);
  PreparedImage prepared = prepare(frame(), p);
  seconds_per_image(state, grid_keypoints().size(), [&] {
    prepare(frame(), p, prepared);
    benchmark::DoNotOptimize(prepared.planes[0].data);
  });
}
BENCHMARK(BM_ModulePrepare)->DenseRange(0, kModuleCount - 1)->Unit(benchmark::kMillisecond);

// The singular-value module's cost grows with the highest active value per
// channel (3 bidiagonalisation steps each): sigma1..sigma_k of all three
// channels.
void BM_SingularValuesUpTo(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  DescriptorParams p = only_module(Module::singular_values);
  p.activation.reset();
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < k; ++i)
      p.activation.set(static_cast<std::size_t>(module_offset(Module::singular_values) + 3 * c + i));
  run_genome(state, p, grid_keypoints(), false);
}
BENCHMARK(BM_SingularValuesUpTo)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);

// A keyframe's worth of sparse keypoints, as the semantic worker describes
// them: the 300 strongest FAST corners (threshold 20, non-maximum
// suppression) at least r pixels from the border.
const std::vector<cv::Point2f>& sparse_keypoints() {
  static const std::vector<cv::Point2f> points = [] {
    cv::Mat grey;
    cv::cvtColor(frame(), grey, cv::COLOR_BGR2GRAY);
    std::vector<cv::KeyPoint> corners;
    cv::FAST(grey, corners, 20, true);
    cv::KeyPointsFilter::runByImageBorder(corners, grey.size(), Genome::thesis_best().decode().patch_radius);
    cv::KeyPointsFilter::retainBest(corners, 300);
    std::vector<cv::Point2f> p;
    for (const cv::KeyPoint& k : corners) p.push_back(k.pt);
    return p;
  }();
  return points;
}

// cv::SIFT::compute on `points` with KeyPoint::size `size`; returns the CPU
// seconds per image.
double run_sift(benchmark::State& state, const std::vector<cv::Point2f>& points, float size) {
  std::vector<cv::KeyPoint> keypoints;
  for (const cv::Point2f& p : points) keypoints.emplace_back(p, size);
  const cv::Ptr<cv::SIFT> sift = cv::SIFT::create();
  cv::Mat descriptors;
  const double seconds = seconds_per_image(state, points.size(), [&] {
    std::vector<cv::KeyPoint> kps = keypoints;  // compute() may drop or reorder keypoints
    sift->compute(frame(), kps, descriptors);
    benchmark::DoNotOptimize(descriptors.data);
  });
  state.counters["descriptors"] = descriptors.rows;
  return seconds;
}

// Peers' seconds per image, from the SIFT benchmarks (registered first).
double g_sift_seconds = 0.0, g_sift_diameter_seconds = 0.0, g_sift_sparse_seconds = 0.0;

float sift_size() { return static_cast<float>(2 * Genome::thesis_best().decode().patch_radius + 1) / 6.0f; }

void BM_Sift(benchmark::State& state) { g_sift_seconds = run_sift(state, grid_keypoints(), sift_size()); }
BENCHMARK(BM_Sift)->Unit(benchmark::kMillisecond);

void BM_SiftPatchDiameter(benchmark::State& state) {
  g_sift_diameter_seconds = run_sift(state, grid_keypoints(), 6.0f * sift_size());
}
BENCHMARK(BM_SiftPatchDiameter)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_SiftSparse(benchmark::State& state) {
  g_sift_sparse_seconds = run_sift(state, sparse_keypoints(), sift_size());
}
BENCHMARK(BM_SiftSparse)->Unit(benchmark::kMillisecond);

// PointDescriptor `name` (evaluate labels' and the GA's harness) for
// `genome` on the grid keypoints; returns the CPU seconds per image.
double run_point_descriptor(benchmark::State& state, std::string_view name,
                            const Genome& genome = Genome::thesis_best()) {
  const auto descriptor = make_point_descriptor(name, genome);
  cv::Mat d;
  const double seconds = seconds_per_image(state, grid_keypoints().size(), [&] {
    d = descriptor->compute(frame(), grid_keypoints());
    benchmark::DoNotOptimize(d.data);
  });
  state.counters["values"] = d.cols;
  return seconds;
}

double g_opponent_sift_seconds = 0.0;

void BM_OpponentSift(benchmark::State& state) {
  g_opponent_sift_seconds = run_point_descriptor(state, "opponent-sift");
}
BENCHMARK(BM_OpponentSift)->Unit(benchmark::kMillisecond);

void BM_Edd(benchmark::State& state) {
  const double per_image = run_point_descriptor(state, "edd");
  if (g_opponent_sift_seconds > 0) state.counters["opponent_sift_over_edd"] = g_opponent_sift_seconds / per_image;
  if (g_sift_seconds > 0) state.counters["sift_over_edd"] = g_sift_seconds / per_image;
}
BENCHMARK(BM_Edd)->Unit(benchmark::kMillisecond);

void BM_ThesisGenome(benchmark::State& state) {
  const double per_image = run_genome(state, Genome::thesis_best().decode(), grid_keypoints());
  if (g_sift_seconds > 0) state.counters["sift_over_thesis"] = g_sift_seconds / per_image;
  if (g_sift_diameter_seconds > 0) state.counters["sift_diameter_over_thesis"] = g_sift_diameter_seconds / per_image;
}
BENCHMARK(BM_ThesisGenome)->Unit(benchmark::kMillisecond);

// What the GA could gain: the thesis genome without its singular values
// (the costliest module per value), same image and keypoints.
DescriptorParams thesis_without(std::initializer_list<Module> modules) {
  DescriptorParams p = Genome::thesis_best().decode();
  for (const Module m : modules)
    for (int i = 0; i < module_size(m); ++i) p.activation.reset(static_cast<std::size_t>(module_offset(m) + i));
  return p;
}

void BM_ThesisGenomeWithoutSingularValues(benchmark::State& state) {
  const DescriptorParams p = thesis_without({Module::singular_values});
  const double per_image = run_genome(state, p, grid_keypoints());
  if (g_sift_seconds > 0) state.counters["sift_over_this"] = g_sift_seconds / per_image;
}
BENCHMARK(BM_ThesisGenomeWithoutSingularValues)->Unit(benchmark::kMillisecond);

// The same without the three modules that cost most per image (singular
// values, edge distance and gradient angles: 29 of the 93 values, and the
// Canny/distance and angle planes): still short of 10x.
void BM_ThesisGenomeWithoutCostliest(benchmark::State& state) {
  const DescriptorParams p = thesis_without({Module::singular_values, Module::edge_distance, Module::gradient_angles});
  const double per_image = run_genome(state, p, grid_keypoints());
  if (g_sift_seconds > 0) state.counters["sift_over_this"] = g_sift_seconds / per_image;
}
BENCHMARK(BM_ThesisGenomeWithoutCostliest)->Unit(benchmark::kMillisecond);

// The thesis genome's per-image preparation alone (its 14 planes):
// sift_over_this bounds the genome's ratio from above, as if every module
// were free.
void BM_ThesisGenomePrepareOnly(benchmark::State& state) {
  const DescriptorParams p = Genome::thesis_best().decode();
  PreparedImage prepared = prepare(frame(), p);
  const double per_image = seconds_per_image(state, grid_keypoints().size(), [&] {
    prepare(frame(), p, prepared);
    benchmark::DoNotOptimize(prepared.planes[0].data);
  });
  if (g_sift_seconds > 0) state.counters["sift_over_this"] = g_sift_seconds / per_image;
}
BENCHMARK(BM_ThesisGenomePrepareOnly)->Unit(benchmark::kMillisecond);

// For reference, the same preparation steps done with OpenCV's own
// functions (equalisation of Y, 7 x 7 blur, XYZ, Canny 5 x 5 with the exact
// distance transform, Sobel and cv::phase of the three channels), without
// the colour invariants: what preparation costs without hand-written passes.
void BM_OpenCvPreparation(benchmark::State& state) {
  const DescriptorParams p = Genome::thesis_best().decode();
  cv::Mat ycrcb, equalised, blurred, unit, xyz, grey, edges, not_edges, distance, dx, dy, angle;
  std::vector<cv::Mat> channels;
  const double per_image = seconds_per_image(state, grid_keypoints().size(), [&] {
    cv::cvtColor(frame(), ycrcb, cv::COLOR_BGR2YCrCb);
    cv::split(ycrcb, channels);
    cv::equalizeHist(channels[0], channels[0]);
    cv::merge(channels, ycrcb);
    cv::cvtColor(ycrcb, equalised, cv::COLOR_YCrCb2BGR);
    cv::GaussianBlur(equalised, blurred, {p.gaussian_kernel, p.gaussian_kernel}, p.gaussian_sigma);
    blurred.convertTo(unit, CV_32F, 1.0 / 255.0);
    cv::cvtColor(unit, xyz, cv::COLOR_BGR2XYZ);
    cv::cvtColor(blurred, grey, cv::COLOR_BGR2GRAY);
    cv::Canny(grey, edges, p.canny_low_threshold, p.canny_high_threshold(), p.canny_kernel);
    cv::compare(edges, 0, not_edges, cv::CMP_EQ);
    cv::distanceTransform(not_edges, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    cv::split(xyz, channels);
    for (const cv::Mat& c : channels) {
      cv::Sobel(c, dx, CV_32F, 1, 0);
      cv::Sobel(c, dy, CV_32F, 0, 1);
      cv::phase(dx, dy, angle);
    }
    benchmark::DoNotOptimize(angle.data);
  });
  if (g_sift_seconds > 0) state.counters["sift_over_this"] = g_sift_seconds / per_image;
}
BENCHMARK(BM_OpenCvPreparation)->Unit(benchmark::kMillisecond);

void BM_ThesisGenomeExtractOnly(benchmark::State& state) {
  run_genome(state, Genome::thesis_best().decode(), grid_keypoints(), false);
}
BENCHMARK(BM_ThesisGenomeExtractOnly)->Unit(benchmark::kMillisecond);

// The semantic worker's case: one keyframe's sparse corners, where the
// per-image preparation dominates.
void BM_ThesisGenomeSparse(benchmark::State& state) {
  const double per_image = run_genome(state, Genome::thesis_best().decode(), sparse_keypoints());
  if (g_sift_sparse_seconds > 0) state.counters["sift_over_thesis"] = g_sift_sparse_seconds / per_image;
}
BENCHMARK(BM_ThesisGenomeSparse)->Unit(benchmark::kMillisecond);

// Any genome (an optimise run's best.genome, issue 18's 10x), named by
// $FACADESLAM_BENCH_GENOME (a genome file or the 0/1 string), through the
// harness `evaluate labels` and the GA use, next to cv::SIFT with that
// genome's patch size on the same keypoints (the GA's time term, here on one
// core with CPU time): sift_over_genome. Skipped when the variable is unset.
const Genome* bench_genome() {
  static const std::optional<Genome> genome = []() -> std::optional<Genome> {
    const char* value = std::getenv("FACADESLAM_BENCH_GENOME");
    if (!value || !*value) return std::nullopt;
    std::error_code ec;
    if (std::filesystem::is_regular_file(value, ec)) return load_genome(value);
    return Genome::parse(value, "FACADESLAM_BENCH_GENOME");
  }();
  return genome ? &*genome : nullptr;
}

double g_genome_sift_seconds = 0.0;

void BM_GivenGenomeSiftPeer(benchmark::State& state) {
  if (!bench_genome()) return state.SkipWithError("set FACADESLAM_BENCH_GENOME to a genome file or string");
  g_genome_sift_seconds = run_point_descriptor(state, "sift", *bench_genome());
}
BENCHMARK(BM_GivenGenomeSiftPeer)->Unit(benchmark::kMillisecond);

void BM_GivenGenome(benchmark::State& state) {
  if (!bench_genome()) return state.SkipWithError("set FACADESLAM_BENCH_GENOME to a genome file or string");
  const double per_image = run_point_descriptor(state, "modular", *bench_genome());
  if (g_genome_sift_seconds > 0) state.counters["sift_over_genome"] = g_genome_sift_seconds / per_image;
}
BENCHMARK(BM_GivenGenome)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
