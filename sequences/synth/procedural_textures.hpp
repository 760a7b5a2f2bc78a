#pragma once
// Procedural textures for the ground and the sky, evaluated as functions of
// WORLD coordinates (metres, or a direction for the sky), so that tiles of
// one surface join without seams and nothing repeats: the SLAM tracks FAST
// corners on these surfaces, and a periodic texture would let it match the
// wrong copy. All randomness is seeded (deterministic_random.hpp).
#include <cstdint>

#include <opencv2/core.hpp>

#include "sequences/synth/scene.hpp"

namespace facadeslam::synth {

// Smooth value noise in [0, 1] on the unit lattice (C1 quintic blending).
double value_noise(double x, double y, std::uint64_t seed);
double value_noise(double x, double y, double z, std::uint64_t seed);
// Fractal sums of `octaves` octaves (each twice the frequency and half the
// amplitude of the previous one), normalised to [0, 1].
double fractal_noise(double x, double y, int octaves, std::uint64_t seed);
double fractal_noise(double x, double y, double z, int octaves, std::uint64_t seed);

// A rectangle of the ground plane: texel (i, j) of the texture covers world
// x in [x0 + i texel, x0 + (i+1) texel) and y in (y1 - (j+1) texel_y,
// y1 - j texel_y] (rows run towards -y, so that the texture lies on a quad
// whose `down` edge points to -y). texel_y is texel stretched a little so
// that a strip's rows fill its width exactly (strips must not overlap).
struct GroundArea {
  double x0 = 0.0;
  double y1 = 0.0;
  int columns = 1;
  int rows = 1;
  double texel = 0.02;
  double texel_y = 0.02;
};

// Asphalt for the road of `street` (BGR): grain and aggregate, worn patches,
// repairs, manhole covers, a dashed centre line and edge lines.
cv::Mat road_texture(const GroundArea& area, const StreetSpec& street, std::uint64_t seed);

// Pavement (BGR): a granite kerb along the road edge, then concrete slabs of
// varying size, tone and wear. `side` is +1 for the pavement at y > 0, -1
// for the one at y < 0.
cv::Mat pavement_texture(const GroundArea& area, const StreetSpec& street, int side, std::uint64_t seed);

// An equirectangular sky panorama (BGR, columns = azimuth -180..180 degrees,
// rows = elevation 90..-90 degrees; see render::Sky): a gradient from the
// horizon to the zenith colour, with clouds.
cv::Mat sky_panorama(int width, int height, const SkySpec& sky, std::uint64_t seed);

}  // namespace facadeslam::synth
