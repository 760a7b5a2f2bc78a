#include "semantics/descriptor/planes.hpp"

namespace facadeslam::semantics {
namespace {

constexpr std::array<std::string_view, kPlaneCount> kPlaneNames{
    "colour channel 0", "colour channel 1", "colour channel 2", "gradient angle 0", "gradient angle 1",
    "gradient angle 2", "edge distance",    "Gevers l1",        "Gevers l2",        "Gevers l3",
    "Gevers c1",        "Gevers c2",        "Gevers c3",        "Geusebroek H",     "Geusebroek C"};

// Bits of a per-channel module (channel-major groups of `per_channel` values)
// that belong to channel c.
bool channel_used(std::uint64_t bits, int per_channel, int c) {
  const std::uint64_t group = ((std::uint64_t{1} << per_channel) - 1) << (c * per_channel);
  return (bits & group) != 0;
}

// Mean/std modules hold [mean_0..mean_(k-1), std_0..std_(k-1)].
bool statistic_used(std::uint64_t bits, int k, int i) { return ((bits >> i) & 1) != 0 || ((bits >> (k + i)) & 1) != 0; }

}  // namespace

std::string_view plane_name(PlaneId plane) { return kPlaneNames[plane_bit(plane)]; }

PlaneSet required_planes(const ActivationMask& activation) {
  PlaneSet planes;
  const auto bits = [&](Module m) { return module_bits(activation, m); };
  for (int c = 0; c < 3; ++c) {
    bool colour = statistic_used(bits(Module::mean_std), 3, c);
    colour |= channel_used(bits(Module::moments2), 3, c);
    colour |= channel_used(bits(Module::moments3), 4, c);
    colour |= channel_used(bits(Module::moments4), 5, c);
    colour |= channel_used(bits(Module::moments5), 6, c);
    colour |= channel_used(bits(Module::hu), 7, c);
    colour |= channel_used(bits(Module::affine_invariants), 10, c);
    colour |= channel_used(bits(Module::singular_values), 3, c);
    const std::uint64_t angles = bits(Module::gradient_angles);
    const bool angle = channel_used(angles, 5, c) || channel_used(angles >> 15, 10, c);
    planes.set(plane_bit(colour_plane(c)), colour || angle);
    planes.set(plane_bit(angle_plane(c)), angle);
  }
  planes.set(plane_bit(PlaneId::edge_distance), bits(Module::edge_distance) != 0);
  for (int i = 0; i < 3; ++i) {
    planes.set(plane_bit(PlaneId::gevers_l1) + static_cast<std::size_t>(i),
               statistic_used(bits(Module::gevers_l), 3, i));
    planes.set(plane_bit(PlaneId::gevers_c1) + static_cast<std::size_t>(i),
               statistic_used(bits(Module::gevers_c), 3, i));
  }
  planes.set(plane_bit(PlaneId::geusebroek_h), statistic_used(bits(Module::geusebroek), 2, 0));
  planes.set(plane_bit(PlaneId::geusebroek_c), statistic_used(bits(Module::geusebroek), 2, 1));
  return planes;
}

}  // namespace facadeslam::semantics
