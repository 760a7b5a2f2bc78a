// Calibrates the GA's cost model (semantics/optimiser/cost_model.hpp) and
// checks it against measurement:
//
//   bench_ga_cost_model [--repeats N] [--rounds K] [--check] [--config OPTIMISE.yaml] [GENOME...]
//
// 1. Times cv::SIFT (the "sift" point descriptor, the patch of radius 3..10)
//    and the steps the model adds up, on the bench's image (a 640x480
//    facade, bench_images.hpp) and its 3888 keypoints on a 9-pixel grid, one
//    OpenCV thread, the thread's CPU time: prepare() with chosen planes for
//    the per-image costs, extract() with chosen values (the image prepared
//    once) for the per-keypoint ones, at radius 10 and 3 for the exponents.
//    Each step is a difference of two runs, so what they share
//    (equalisation, the keypoint walk) is counted once; what the parts miss
//    together goes per value, from the genome with all 185. Every
//    repetition times the two runs and cv::SIFT back to back (each the
//    second of two runs: warm caches, as the bench's loops) and keeps the
//    ratio; a cost is the median of N such ratios (a busy host's speed
//    drifts; a back-to-back ratio much less). The whole calibration runs K times and each cost is the median
//    of its K values. Prints the `cost_model:` block for configs/optimise*.yaml.
// 2. For the thesis genome, models/default.genome, the GA runs' winners in
//    docs/ga/ and seeded random genomes (and any GENOME files given): the
//    measured ratio (the "modular" point descriptor, prepare + extract, over
//    "sift" with the genome's patch size, back to back, the median of N;
//    bench_semantics_modules' BM_GivenGenome measures the same), the ratio
//    the model just calibrated gives, and the one of --config's model (the
//    code's defaults without it). --check: only this, without calibrating.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <malloc.h>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "bench/bench_images.hpp"
#include "core/config/config_node.hpp"
#include "semantics/descriptor/extraction.hpp"
#include "semantics/descriptor/genome.hpp"
#include "semantics/descriptor/genome_io.hpp"
#include "semantics/optimiser/cost_model.hpp"
#include "semantics/optimiser/ga_options.hpp"
#include "semantics/optimiser/ga_random.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace {

using namespace facadeslam;
using namespace facadeslam::semantics;
namespace fs = std::filesystem;

int g_repeats = 9;

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

using Body = std::function<void()>;

// The second of two runs: the caches hold what the body reads, as in
// bench_semantics_modules' loops (cv::SIFT's pyramid would otherwise evict
// the image and planes before every run of the other side).
double seconds_of(const Body& body) {
  body();
  const double start = thread_seconds();
  body();
  return thread_seconds() - start;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Medians over g_repeats repetitions of a, b and `reference` timed back to
// back, and of (time of a - time of b) / time of `reference`; b may be
// empty (0 s).
struct Timing {
  double a = 0, b = 0, reference = 0;  // seconds
  double ratio = 0;
};

Timing time_against(const Body& a, const Body& b, const Body& reference) {
  std::vector<double> ta, tb, tr, ratios;
  for (int i = 0; i < g_repeats; ++i) {
    ta.push_back(seconds_of(a));
    tb.push_back(b ? seconds_of(b) : 0.0);
    tr.push_back(seconds_of(reference));
    ratios.push_back((ta.back() - tb.back()) / tr.back());
  }
  return {median(ta), median(tb), median(tr), median(ratios)};
}

double relative(const Body& a, const Body& b, const Body& reference) { return time_against(a, b, reference).ratio; }

const cv::Mat& frame() {
  static const cv::Mat image = bench::facade_image({640, 480});
  return image;
}

const std::vector<cv::Point2f>& grid() {
  static const std::vector<cv::Point2f> points = bench::grid_points(frame().size());
  return points;
}

// The thesis genome's parameters, no blur, RGB, the given radius and values.
DescriptorParams with(std::initializer_list<Module> modules, int radius = 10) {
  DescriptorParams p = Genome::thesis_best().decode();
  p.gaussian_kernel = 1;
  p.colour_space = ColourSpace::rgb;
  p.patch_radius = radius;
  p.activation.reset();
  for (const Module m : modules)
    for (int i = 0; i < module_size(m); ++i) p.activation.set(static_cast<std::size_t>(module_offset(m) + i));
  return p;
}

DescriptorParams with_values(std::initializer_list<const char*> names, int radius = 10) {
  DescriptorParams p = with({}, radius);
  for (const char* name : names) p.activation.set(static_cast<std::size_t>(*value_index(name)));
  return p;
}

// prepare() with `p`, reusing one PreparedImage.
Body preparing(const DescriptorParams& p) {
  auto prepared = std::make_shared<PreparedImage>();
  return [p, prepared] { prepare(frame(), p, *prepared); };
}

// extract() with `p` on the grid, the image prepared once.
Body extracting(const DescriptorParams& p) {
  auto prepared = std::make_shared<const PreparedImage>(prepare(frame(), p));
  return [p, prepared] {
    const cv::Mat rows = extract(*prepared, grid(), p);
    if (rows.rows != static_cast<int>(grid().size())) std::abort();
  };
}

// A point descriptor of `genome` ("modular": prepare + extract; "sift":
// cv::SIFT with the genome's patch size) on the grid.
Body describing(std::string_view name, const Genome& genome) {
  std::shared_ptr<PointDescriptor> descriptor = make_point_descriptor(name, genome);
  return [descriptor] { (void)descriptor->compute(frame(), grid()); };
}

Body sift_at(int radius) {
  DescriptorParams p = Genome::thesis_best().decode();
  p.patch_radius = radius;
  return describing("sift", Genome::encode(p));
}

Timing measure(const Genome& genome) {
  return time_against(describing("modular", genome), {}, describing("sift", genome));
}

// Uniform parameter fields, each activation bit on with `density` (as the
// GA's first generation draws them).
Genome random_genome(GaRandom& rng, double density) {
  Genome::Bits bits;
  for (int i = 0; i < Genome::kBits; ++i)
    bits.set(static_cast<std::size_t>(i), i < Genome::kParameterBits ? (rng() >> 63) != 0 : uniform01(rng) < density);
  return Genome(bits);
}

double positive(double v) { return std::max(0.0, v); }

CostModel calibrate() {
  CostModel m;
  const Body sift = sift_at(10);
  // Per image: (time of p - time of base) / SIFT's.
  const auto image = [&](const DescriptorParams& p, const Body& base) {
    return positive(relative(preparing(p), base, sift));
  };
  for (int r = 3; r < 10; ++r) m.sift[static_cast<std::size_t>(r - 3)] = relative(sift_at(r), {}, sift);
  m.sift[7] = 1.0;
  const Body one = preparing(with_values({"mean_c0"})), three = preparing(with({Module::mean_std}));
  m.colour_plane = image(with({Module::mean_std}), one) / 2;
  m.equalise = positive(image(with_values({"mean_c0"}), {}) - m.colour_plane);
  for (std::size_t s = 0; s < kColourSpaces.size(); ++s) {
    DescriptorParams p = with({Module::mean_std});
    p.colour_space = kColourSpaces[s];
    m.colour_space[s] = image(p, three);
  }
  // Blur: least squares through the origin of the extra share over the taps.
  double taps2 = 0.0, taps_share = 0.0;
  for (std::size_t k = 1; k < kGaussianKernels.size(); ++k) {
    DescriptorParams p = with({Module::mean_std});
    p.gaussian_kernel = kGaussianKernels[k];
    taps2 += p.gaussian_kernel * p.gaussian_kernel;
    taps_share += p.gaussian_kernel * relative(preparing(p), three, sift);
  }
  m.blur_per_tap = positive(taps_share / taps2);
  m.angle_plane = image(with_values({"angle00_c0"}), one);
  // These planes need no colour plane: over equalisation alone.
  const auto over_equalise = [&](Module module, int planes) {
    return positive(image(with({module}), {}) - m.equalise) / planes;
  };
  m.edge_distance = over_equalise(Module::edge_distance, 1);
  m.gevers_l_plane = over_equalise(Module::gevers_l, 3);
  m.gevers_c_plane = over_equalise(Module::gevers_c, 3);
  m.geusebroek_plane = over_equalise(Module::geusebroek, 2);

  // Per keypoint: each module over the walk that position alone costs.
  struct PerKeypoint {
    double statistics = 0, gradient = 0;
    std::array<double, 4> moments{};
    std::array<double, 3> singular{};
  };
  const auto per_keypoint = [&](int radius) {
    PerKeypoint k;
    const Body walk = extracting(with({Module::position}, radius));
    const auto extra = [&](const DescriptorParams& p) { return relative(extracting(p), walk, sift); };
    k.statistics = extra(with({Module::mean_std}, radius)) / 3;
    const Module orders[4] = {Module::moments2, Module::moments3, Module::moments4, Module::moments5};
    for (std::size_t o = 0; o < 4; ++o) k.moments[o] = extra(with({orders[o]}, radius)) / 3;
    for (int n = 1; n <= 3; ++n) {
      DescriptorParams p = with({}, radius);
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i)
          p.activation.set(static_cast<std::size_t>(module_offset(Module::singular_values) + 3 * c + i));
      k.singular[static_cast<std::size_t>(n - 1)] = extra(p) / 3;
    }
    k.gradient = extra(with({Module::gradient_angles}, radius)) / 3;
    return k;
  };
  const PerKeypoint at10 = per_keypoint(10), at3 = per_keypoint(3);
  m.position = positive(relative(extracting(with({Module::position})), {}, sift));
  m.statistics_plane = positive(at10.statistics);
  for (std::size_t o = 0; o < 4; ++o) m.moments[o] = positive(at10.moments[o]);
  for (std::size_t n = 0; n < 3; ++n) m.singular_values[n] = positive(at10.singular[n]);
  m.gradient_angles = positive(at10.gradient);
  const Body walk = extracting(with({Module::position}));
  // Per value: a channel's 7 Hu invariants over its moments of order 3, its
  // 10 affine invariants over those of order 5.
  m.hu = positive(relative(extracting(with({Module::hu})), walk, sift) / 3 - at10.moments[1]) / 7;
  m.affine = positive(relative(extracting(with({Module::affine_invariants})), walk, sift) / 3 - at10.moments[3]) / 10;
  const auto exponent = [](double share10, double share3) {
    return share10 > 0 && share3 > 0 ? std::clamp(std::log(share10 / share3) / std::log(21.0 / 7.0), 0.0, 4.0) : 1.0;
  };
  m.statistics_exponent = exponent(at10.statistics, at3.statistics);
  m.moments_exponent = exponent(at10.moments[2], at3.moments[2]);
  m.singular_values_exponent = exponent(at10.singular[2], at3.singular[2]);
  m.gradient_angles_exponent = exponent(at10.gradient, at3.gradient);
  // What the parts miss together, per value: all 185 values with the thesis
  // genome's preprocessing, measured against the sum of the parts.
  DescriptorParams all = Genome::thesis_best().decode();
  all.activation.set();
  m.per_value = 0.0;
  m.per_value = positive(measure(Genome::encode(all)).ratio - modelled_time_ratio(all, m)) / kValueCount;
  return m;
}

// Each figure the median of its values over `models`.
CostModel median_model(const std::vector<CostModel>& models) {
  nlohmann::json out = to_json(models.front());
  for (auto& [key, value] : out.items()) {
    const auto at = [&](const CostModel& m) { return to_json(m).at(key); };
    if (value.is_array()) {
      for (std::size_t i = 0; i < value.size(); ++i) {
        std::vector<double> v;
        for (const CostModel& m : models) v.push_back(at(m).at(i).get<double>());
        value[i] = median(v);
      }
    } else {
      std::vector<double> v;
      for (const CostModel& m : models) v.push_back(at(m).get<double>());
      value = median(v);
    }
  }
  CostModel m;
  read_cost_model(ConfigNode::parse_string(out.dump(), "the calibration"), m);  // JSON is YAML
  return m;
}

std::string list(const double* values, std::size_t n) {
  std::string s = "[";
  char number[32];
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf(number, sizeof number, "%s%.4f", i ? ", " : "", values[i]);
    s += number;
  }
  return s + "]";
}

void print_model(const CostModel& m) {
  std::printf("cost_model:\n");
  std::printf("  equalise: %.4f\n  blur_per_tap: %.4f\n  colour_space: %s\n", m.equalise, m.blur_per_tap,
              list(m.colour_space.data(), 8).c_str());
  std::printf("  colour_plane: %.4f\n  angle_plane: %.4f\n  edge_distance: %.4f\n", m.colour_plane, m.angle_plane,
              m.edge_distance);
  std::printf("  gevers_l_plane: %.4f\n  gevers_c_plane: %.4f\n  geusebroek_plane: %.4f\n", m.gevers_l_plane,
              m.gevers_c_plane, m.geusebroek_plane);
  std::printf("  position: %.4f\n  statistics_plane: %.4f\n  moments: %s\n", m.position, m.statistics_plane,
              list(m.moments.data(), 4).c_str());
  std::printf("  hu: %.4f\n  affine: %.4f\n  singular_values: %s\n  gradient_angles: %.4f\n  per_value: %.6f\n", m.hu,
              m.affine, list(m.singular_values.data(), 3).c_str(), m.gradient_angles, m.per_value);
  std::printf(
      "  statistics_exponent: %.2f\n  moments_exponent: %.2f\n  singular_values_exponent: %.2f\n"
      "  gradient_angles_exponent: %.2f\n",
      m.statistics_exponent, m.moments_exponent, m.singular_values_exponent, m.gradient_angles_exponent);
  std::printf("  sift: %s\n", list(m.sift.data(), 8).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  cv::setNumThreads(1);
  // Freed memory stays with the process: otherwise glibc hands cv::SIFT's
  // pyramid buffers back to the kernel or not depending on what ran before,
  // and SIFT's time (page faults on fresh pages) swings 2-4x between
  // otherwise equal runs, which no ratio to it survives.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  std::vector<std::pair<std::string, Genome>> genomes;
  CostModel configured;
  std::string configured_name = "code defaults";
  int rounds = 3;
  bool check_only = false;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--repeats" && i + 1 < argc) {
        g_repeats = std::max(1, std::atoi(argv[++i]));
      } else if (arg == "--check") {
        check_only = true;
      } else if (arg == "--rounds" && i + 1 < argc) {
        rounds = std::max(1, std::atoi(argv[++i]));
      } else if (arg == "--config" && i + 1 < argc) {
        configured_name = argv[++i];
        configured = load_ga_options(configured_name).cost_model;
      } else {
        genomes.emplace_back(arg, load_genome(arg));
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_ga_cost_model: %s\n", e.what());
    return 2;
  }
  std::printf("# image: 640x480 facade, %zu grid keypoints (step 9), one OpenCV thread, CPU time, median of %d",
              grid().size(), g_repeats);
  if (!check_only) std::printf("; costs the median of %d rounds", rounds);
  std::printf("\n");
  std::vector<CostModel> models;
  for (int round = 0; round < (check_only ? 0 : rounds); ++round) {
    models.push_back(calibrate());
    const Timing thesis = measure(Genome::thesis_best());
    std::printf("# round %d: thesis genome %.2f ms, cv::SIFT %.2f ms: measured %.4f, this round's model %.4f\n",
                round + 1, 1e3 * thesis.a, 1e3 * thesis.reference, thesis.ratio,
                modelled_time_ratio(Genome::thesis_best().decode(), models.back()));
  }
  const CostModel calibrated = models.empty() ? configured : median_model(models);
  if (!check_only) print_model(calibrated);

  genomes.insert(genomes.begin(), {"thesis genome", Genome::thesis_best()});
  const fs::path source = FACADESLAM_SOURCE_DIR;
  for (const char* file : {"models/default.genome", "docs/ga/best.genome", "docs/ga/fast-run/best.genome",
                           "docs/ga/refine-run/best.genome", "docs/ga/calibrated-run/best.genome"})
    if (fs::exists(source / file)) genomes.emplace_back(file, load_genome(source / file));
  GaRandom rng(42);
  for (const double density : {0.05, 0.05, 0.2, 0.5}) {
    Genome g = random_genome(rng, density);
    if (g.active_value_count() == 0) continue;
    char name[64];
    std::snprintf(name, sizeof name, "random, density %.2f", density);
    genomes.emplace_back(name, g);
  }
  if (check_only) {
    std::printf("\n| genome | values | radius | ms | cv::SIFT ms | measured | modelled (%s) |\n",
                configured_name.c_str());
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  } else {
    std::printf(
        "\n| genome | values | radius | ms | cv::SIFT ms | measured | modelled (this calibration) | "
        "modelled (%s) |\n",
        configured_name.c_str());
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  }
  for (const auto& [name, genome] : genomes) {
    const DescriptorParams p = genome.decode();
    const Timing m = measure(genome);
    std::printf("| %s | %d | %d | %.2f | %.2f | %.4f |", name.c_str(), p.active_value_count(), p.patch_radius,
                1e3 * m.a, 1e3 * m.reference, m.ratio);
    if (!check_only) std::printf(" %.4f |", modelled_time_ratio(p, calibrated));
    std::printf(" %.4f |\n", modelled_time_ratio(p, configured));
    std::fflush(stdout);
  }
  return 0;
}
