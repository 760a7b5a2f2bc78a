#include "sequences/synth/procedural_textures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sequences/synth/deterministic_random.hpp"

namespace facadeslam::synth {
namespace {

// Streams that keep the layers of one texture independent.
enum TextureStream : std::uint64_t {
  kRoadLarge = 1,
  kRoadMedium,
  kRoadGrain,
  kRoadRepair,
  kRoadManhole,
  kRoadDash,
  kRoadWear,
  kSlabRow,
  kSlabTone,
  kSlabStain,
  kSlabGrain,
  kKerb,
  kSkyClouds,
  kSkyShade,
};

double quintic(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

double lattice(std::int64_t x, std::int64_t y, std::uint64_t seed) {
  return uniform01(hash64(seed, static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y)));
}

double lattice(std::int64_t x, std::int64_t y, std::int64_t z, std::uint64_t seed) {
  return uniform01(
      hash64(seed, static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y), static_cast<std::uint64_t>(z)));
}

double lerp(double a, double b, double t) { return a + (b - a) * t; }

double smooth_edge(double lo, double hi, double v) {
  const double t = std::clamp((v - lo) / (hi - lo), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Per-texel white noise in [-1, 1], keyed by the texel's world index.
double grain(double x, double y, double texel, std::uint64_t seed) {
  const auto ix = static_cast<std::int64_t>(std::floor(x / texel));
  const auto iy = static_cast<std::int64_t>(std::floor(y / texel));
  return 2.0 * lattice(ix, iy, seed) - 1.0;
}

cv::Vec3b bgr(double b, double g, double r) {
  return {cv::saturate_cast<std::uint8_t>(b), cv::saturate_cast<std::uint8_t>(g), cv::saturate_cast<std::uint8_t>(r)};
}

// Texel centre -> world (x, y).
double texel_x(const GroundArea& a, int i) { return a.x0 + (i + 0.5) * a.texel; }
double texel_y(const GroundArea& a, int j) { return a.y1 - (j + 0.5) * a.texel_y; }

// Bilinear upsampling of `coarse`, sampled every `step` fine pixels starting
// at fine pixel 0, to rows x columns (CV_32FC1).
cv::Mat upsample(const cv::Mat& coarse, int step, int rows, int columns) {
  cv::Mat fine(rows, columns, CV_32FC1);
  for (int j = 0; j < rows; ++j) {
    const int j0 = j / step;
    const float wy = static_cast<float>(j % step) / step;
    const float* a = coarse.ptr<float>(j0);
    const float* b = coarse.ptr<float>(std::min(j0 + 1, coarse.rows - 1));
    float* out = fine.ptr<float>(j);
    for (int i = 0; i < columns; ++i) {
      const int i0 = i / step, i1 = std::min(i0 + 1, coarse.cols - 1);
      const float wx = static_cast<float>(i % step) / step;
      const float top = a[i0] + wx * (a[i1] - a[i0]), bottom = b[i0] + wx * (b[i1] - b[i0]);
      out[i] = top + wy * (bottom - top);
    }
  }
  return fine;
}

// fractal_noise(x / scale, y / scale) over a ground area. The field is
// smooth below its finest octave, so it is evaluated only every `step`
// texels (a power of two, at most a quarter of the finest wavelength) and
// interpolated in between; tiles start at multiples of the tile size, a
// multiple of every step, so tiles still join without a seam.
cv::Mat ground_field(const GroundArea& a, double scale, int octaves, std::uint64_t seed) {
  const double finest = scale / static_cast<double>(1 << (octaves - 1));
  int step = 1;
  while (step < 64 && 2.0 * step * a.texel <= finest / 4.0) step *= 2;
  cv::Mat coarse(a.rows / step + 2, a.columns / step + 2, CV_32FC1);
  for (int j = 0; j < coarse.rows; ++j)
    for (int i = 0; i < coarse.cols; ++i)
      coarse.at<float>(j, i) =
          static_cast<float>(fractal_noise(texel_x(a, i * step) / scale, texel_y(a, j * step) / scale, octaves, seed));
  return upsample(coarse, step, a.rows, a.columns);
}

}  // namespace

double value_noise(double x, double y, std::uint64_t seed) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  const double tx = quintic(x - fx), ty = quintic(y - fy);
  return lerp(lerp(lattice(ix, iy, seed), lattice(ix + 1, iy, seed), tx),
              lerp(lattice(ix, iy + 1, seed), lattice(ix + 1, iy + 1, seed), tx), ty);
}

double value_noise(double x, double y, double z, std::uint64_t seed) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy), iz = static_cast<std::int64_t>(fz);
  const double tx = quintic(x - fx), ty = quintic(y - fy), tz = quintic(z - fz);
  const auto plane = [&](std::int64_t k) {
    return lerp(lerp(lattice(ix, iy, k, seed), lattice(ix + 1, iy, k, seed), tx),
                lerp(lattice(ix, iy + 1, k, seed), lattice(ix + 1, iy + 1, k, seed), tx), ty);
  };
  return lerp(plane(iz), plane(iz + 1), tz);
}

double fractal_noise(double x, double y, int octaves, std::uint64_t seed) {
  double sum = 0.0, amplitude = 1.0, total = 0.0, frequency = 1.0;
  for (int o = 0; o < octaves; ++o) {
    // Each octave gets its own lattice (and an offset) so they do not align.
    sum += amplitude * value_noise(x * frequency + 17.3 * o, y * frequency - 9.1 * o, hash64(seed, o));
    total += amplitude;
    amplitude *= 0.5;
    frequency *= 2.0;
  }
  return sum / total;
}

double fractal_noise(double x, double y, double z, int octaves, std::uint64_t seed) {
  double sum = 0.0, amplitude = 1.0, total = 0.0, frequency = 1.0;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude *
           value_noise(x * frequency + 17.3 * o, y * frequency - 9.1 * o, z * frequency + 5.7 * o, hash64(seed, o));
    total += amplitude;
    amplitude *= 0.5;
    frequency *= 2.0;
  }
  return sum / total;
}

cv::Mat road_texture(const GroundArea& area, const StreetSpec& street, std::uint64_t seed) {
  cv::Mat out(area.rows, area.columns, CV_8UC3);
  const double half = 0.5 * street.road_width;
  const cv::Mat large = ground_field(area, 6.0, 3, hash64(seed, kRoadLarge));
  const cv::Mat medium = ground_field(area, 0.35, 3, hash64(seed, kRoadMedium));
  const cv::Mat repairs = ground_field(area, 2.5, 1, hash64(seed, kRoadRepair));
  // Manhole covers: at most one per 12 m cell, at a seeded place.
  constexpr double kManholeCell = 12.0, kManholeRadius = 0.32;
  for (int j = 0; j < area.rows; ++j) {
    const double y = texel_y(area, j);
    for (int i = 0; i < area.columns; ++i) {
      const double x = texel_x(area, i);
      double v = 88.0;
      v += 26.0 * (large.at<float>(j, i) - 0.5);
      v += 18.0 * (medium.at<float>(j, i) - 0.5);
      // Aggregate: fine grain, with sparse bright and dark stones.
      const double g = grain(x, y, area.texel, hash64(seed, kRoadGrain));
      v += 10.0 * g;
      if (g > 0.94) v += 34.0;
      if (g < -0.95) v -= 26.0;
      // Repairs: darker, sharp-edged patches.
      if (repairs.at<float>(j, i) > 0.78f) v -= 16.0 + 6.0 * g;
      double b = v + 2.0, gr = v + 1.0, r = v;
      // Road markings, worn: a dashed centre line (dash lengths vary) and
      // edge lines.
      const auto paint = [&](double coverage) {
        const double wear = fractal_noise(x / 0.15, y / 0.15, 2, hash64(seed, kRoadWear));
        const double c = coverage * std::clamp(1.3 * wear, 0.0, 1.0);
        b = lerp(b, 205.0, c);
        gr = lerp(gr, 205.0, c);
        r = lerp(r, 200.0, c);
      };
      const auto dash = static_cast<std::int64_t>(std::floor(x / 9.0));
      const double dash_start = dash * 9.0 + 2.0 * lattice(dash, 0, hash64(seed, kRoadDash));
      const double dash_length = 2.5 + 1.0 * lattice(dash, 1, hash64(seed, kRoadDash));
      if (std::abs(y) < 0.06 && x >= dash_start && x < dash_start + dash_length) paint(1.0);
      if (std::abs(std::abs(y) - (half - 0.3)) < 0.06) paint(0.9);
      // Manholes: dark iron discs with a ring and a cross-hatched lid.
      const auto cell = static_cast<std::int64_t>(std::floor(x / kManholeCell));
      if (lattice(cell, 7, hash64(seed, kRoadManhole)) < 0.6) {
        const double cx = (cell + 0.2 + 0.6 * lattice(cell, 8, hash64(seed, kRoadManhole))) * kManholeCell;
        const double cy = (lattice(cell, 9, hash64(seed, kRoadManhole)) - 0.5) * (street.road_width - 2.0);
        const double d = std::hypot(x - cx, y - cy);
        if (d < kManholeRadius) {
          const bool ring = d > kManholeRadius - 0.04;
          const bool hatch = std::fmod(std::abs(x - cx + y - cy) + 10.0, 0.09) < 0.03 ||
                             std::fmod(std::abs(x - cx - y + cy) + 10.0, 0.09) < 0.03;
          const double iron = ring ? 42.0 : hatch ? 58.0 : 75.0;
          b = iron + 4.0 * g;
          gr = iron + 6.0 + 4.0 * g;
          r = iron + 10.0 + 4.0 * g;
        }
      }
      out.at<cv::Vec3b>(j, i) = bgr(b, gr, r);
    }
  }
  return out;
}

cv::Mat pavement_texture(const GroundArea& area, const StreetSpec& street, int side, std::uint64_t seed) {
  cv::Mat out(area.rows, area.columns, CV_8UC3);
  const double edge = 0.5 * street.road_width;  // |y| of the road edge
  constexpr double kKerbWidth = 0.3, kRowWidth = 0.6, kJoint = 0.008;
  const cv::Mat stains = ground_field(area, 0.8, 3, hash64(seed, kSlabStain, side));
  for (int j = 0; j < area.rows; ++j) {
    const double y = texel_y(area, j);
    const double from_edge = side * y - edge;  // metres from the road edge, outwards
    for (int i = 0; i < area.columns; ++i) {
      const double x = texel_x(area, i);
      const double g = grain(x, y, area.texel, hash64(seed, kSlabGrain, side));
      double v, warm;
      if (from_edge < kKerbWidth) {
        // Granite kerb stones of seeded lengths: light, strongly speckled.
        const auto stone = static_cast<std::int64_t>(std::floor(x / 1.1));
        const double tone = 12.0 * (lattice(stone, side, hash64(seed, kKerb)) - 0.5);
        const double joint = std::min(x - stone * 1.1, (stone + 1) * 1.1 - x);
        v = 168.0 + tone + 22.0 * g;
        if (joint < kJoint * 1.5 || from_edge < 0.02) v -= 60.0;
        warm = 0.0;
      } else {
        // Concrete slabs: each row has its own slab length and offset.
        const double across = from_edge - kKerbWidth;
        const auto row = static_cast<std::int64_t>(std::floor(across / kRowWidth));
        const std::uint64_t row_key = hash64(seed, kSlabRow, side);
        const double length = 0.55 + 0.6 * lattice(row, 0, row_key);
        const double offset = length * lattice(row, 1, row_key);
        const auto slab = static_cast<std::int64_t>(std::floor((x + offset) / length));
        const double along = x + offset - slab * length;
        const double joint =
            std::min({along, length - along, across - row * kRowWidth, (row + 1) * kRowWidth - across});
        const double tone = 26.0 * (lattice(slab, row, hash64(seed, kSlabTone, side)) - 0.5);
        const double stain = stains.at<float>(j, i);
        v = 146.0 + tone + 30.0 * (stain - 0.5) + 7.0 * g;
        if (stain > 0.68) v -= 22.0 * smooth_edge(0.68, 0.74, stain);  // dark stains
        if (joint < kJoint) v -= 45.0;
        warm = 6.0;
      }
      out.at<cv::Vec3b>(j, i) = bgr(v - warm, v, v + warm);
    }
  }
  return out;
}

cv::Mat sky_panorama(int width, int height, const SkySpec& sky, std::uint64_t seed) {
  // Clouds are soft: their noise is evaluated on a grid four times coarser
  // and interpolated.
  constexpr int kStep = 4;
  const auto direction = [&](double i, double j) {
    const double elevation = std::numbers::pi * (0.5 - (j + 0.5) / height);
    const double azimuth = 2.0 * std::numbers::pi * ((i + 0.5) / width - 0.5);
    return cv::Vec3d(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                     std::sin(elevation));
  };
  cv::Mat density(height / kStep + 2, width / kStep + 2, CV_32FC1), shading(density.size(), CV_32FC1);
  for (int j = 0; j < density.rows; ++j)
    for (int i = 0; i < density.cols; ++i) {
      const cv::Vec3d d = direction(i * kStep, j * kStep);
      density.at<float>(j, i) =
          static_cast<float>(fractal_noise(3.0 * d[0], 3.0 * d[1], 3.0 * d[2], 5, hash64(seed, kSkyClouds)));
      shading.at<float>(j, i) =
          static_cast<float>(fractal_noise(6.0 * d[0], 6.0 * d[1], 6.0 * d[2], 3, hash64(seed, kSkyShade)));
    }
  const cv::Mat clouds = upsample(density, kStep, height, width);
  const cv::Mat shade = upsample(shading, kStep, height, width);
  cv::Mat out(height, width, CV_8UC3);
  for (int j = 0; j < height; ++j) {
    const double elevation = std::numbers::pi * (0.5 - (j + 0.5) / height);
    const double t = std::pow(std::max(elevation, 0.0) / (0.5 * std::numbers::pi), 0.55);
    cv::Vec3d gradient = (1.0 - t) * sky.horizon_rgb + t * sky.zenith_rgb;
    if (elevation < 0.0) gradient *= 0.85;
    for (int i = 0; i < width; ++i) {
      const double n = clouds.at<float>(j, i);
      const double cover = sky.clouds <= 0.0
                               ? 0.0
                               : smooth_edge(1.0 - 0.8 * sky.clouds - 0.25, 1.0 - 0.8 * sky.clouds + 0.05, n) *
                                     smooth_edge(-0.02, 0.12, elevation);
      const double grey = 238.0 * (0.82 + 0.18 * shade.at<float>(j, i));
      const cv::Vec3d rgb = (1.0 - cover) * gradient + cover * cv::Vec3d(grey, grey, grey * 242.0 / 238.0);
      out.at<cv::Vec3b>(j, i) = bgr(rgb[2], rgb[1], rgb[0]);
    }
  }
  return out;
}

}  // namespace facadeslam::synth
