#pragma once
// The per-image float planes the modules read their patches from. prepare()
// computes only the planes the active values need (required_planes).
#include <array>
#include <bitset>
#include <string_view>

#include "semantics/descriptor/descriptor_params.hpp"

namespace facadeslam::semantics {

enum class PlaneId : int {
  colour0,
  colour1,
  colour2,  // the genome's colour space, channels in [0, 1]
  angle0,
  angle1,
  angle2,         // gradient angle of each colour channel, radians [0, 2pi)
  edge_distance,  // pixels to the nearest Canny edge
  gevers_l1,
  gevers_l2,
  gevers_l3,  // [0, 1]
  gevers_c1,
  gevers_c2,
  gevers_c3,     // radians [0, pi/2]
  geusebroek_h,  // atan2(E_lambda, E_lambdalambda), radians [0, 2pi)
  geusebroek_c,  // E_lambda / E
};

inline constexpr int kPlaneCount = 15;
using PlaneSet = std::bitset<kPlaneCount>;

constexpr PlaneId colour_plane(int channel) {
  return static_cast<PlaneId>(static_cast<int>(PlaneId::colour0) + channel);
}
constexpr PlaneId angle_plane(int channel) { return static_cast<PlaneId>(static_cast<int>(PlaneId::angle0) + channel); }
constexpr std::size_t plane_bit(PlaneId p) { return static_cast<std::size_t>(p); }

std::string_view plane_name(PlaneId plane);

// The planes the active values of `activation` read, including the colour
// channels the gradient angles are computed from.
PlaneSet required_planes(const ActivationMask& activation);

}  // namespace facadeslam::semantics
