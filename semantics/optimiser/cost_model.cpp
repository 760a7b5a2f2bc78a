#include "semantics/optimiser/cost_model.hpp"

#include <bit>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "core/config/config_node.hpp"
#include "semantics/descriptor/extraction.hpp"
#include "semantics/descriptor/planes.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kCalibrationRadius = 10;

// Bits of a channel-major module that belong to channel c.
std::uint64_t channel_bits(std::uint64_t bits, int per_channel, int c) {
  return (bits >> (per_channel * c)) & ((std::uint64_t{1} << per_channel) - 1);
}

int planes_among(const PlaneSet& planes, PlaneId first, int n) {
  int k = 0;
  for (int i = 0; i < n; ++i) k += planes.test(plane_bit(first) + static_cast<std::size_t>(i)) ? 1 : 0;
  return k;
}

}  // namespace

CostBreakdown modelled_cost(const DescriptorParams& p, const CostModel& m) {
  CostBreakdown cost;
  const PlaneSet planes = required_planes(p.activation);
  if (planes.any()) {
    double image = m.equalise;
    if (p.gaussian_kernel > 1) image += m.blur_per_tap * p.gaussian_kernel;
    const int colour = planes_among(planes, PlaneId::colour0, 3);
    if (colour > 0) image += m.colour_space[static_cast<std::size_t>(p.colour_space)] + m.colour_plane * colour;
    image += m.angle_plane * planes_among(planes, PlaneId::angle0, 3);
    if (planes.test(plane_bit(PlaneId::edge_distance))) image += m.edge_distance;
    image += m.gevers_l_plane * planes_among(planes, PlaneId::gevers_l1, 3);
    image += m.gevers_c_plane * planes_among(planes, PlaneId::gevers_c1, 3);
    image += m.geusebroek_plane * planes_among(planes, PlaneId::geusebroek_h, 2);
    cost.per_image = image;
  }

  const double side = (2.0 * p.patch_radius + 1.0) / (2.0 * kCalibrationRadius + 1.0);
  const auto scaled = [&](double exponent) { return std::pow(side, exponent); };
  const ExtractionPlan plan = plan_extraction(p.activation);
  const auto bits = [&](Module module) { return plan.bits[static_cast<std::size_t>(module)]; };
  // The walk over the keypoints, whichever values are active.
  double keypoints = p.activation.any() ? m.position : 0.0;
  // The statistics modules sum one strip per plane they read.
  const PlaneSet statistics = required_planes(restricted_to(p.activation, kStatisticsModules));
  keypoints += m.statistics_plane * static_cast<double>(statistics.count()) * scaled(m.statistics_exponent);
  double moments = 0.0, singular = 0.0, gradient = 0.0;
  for (int c = 0; c < 3; ++c) {
    const int order = plan.moment_order[static_cast<std::size_t>(c)];
    if (order >= 2) moments += m.moments[static_cast<std::size_t>(order - 2)];
    // Hu's and the affine invariants are each a formula over the moments:
    // paid per value.
    moments += m.hu * std::popcount(channel_bits(bits(Module::hu), 7, c));
    moments += m.affine * std::popcount(channel_bits(bits(Module::affine_invariants), 10, c));
    // Sigma_k costs the bidiagonalisation steps of sigma_1..sigma_k.
    const std::uint64_t sv = channel_bits(bits(Module::singular_values), 3, c);
    for (int k = 3; k >= 1; --k)
      if ((sv >> (k - 1)) & 1) {
        singular += m.singular_values[static_cast<std::size_t>(k - 1)];
        break;
      }
    const std::uint64_t angles = bits(Module::gradient_angles);
    if (channel_bits(angles, 5, c) || channel_bits(angles >> 15, 10, c)) gradient += m.gradient_angles;
  }
  keypoints += moments * scaled(m.moments_exponent) + singular * scaled(m.singular_values_exponent) +
               gradient * scaled(m.gradient_angles_exponent);
  keypoints += m.per_value * p.active_value_count();
  cost.per_keypoint = keypoints;
  const double sift = m.sift[static_cast<std::size_t>(p.patch_radius - kPatchRadii.front())];
  cost.ratio = (cost.per_image + cost.per_keypoint) / sift;
  return cost;
}

void read_cost_model(const ConfigNode& node, CostModel& m) {
  const Range cost = Range::closed(0, 100);
  const auto array = [&](const std::string& key, auto& values, Range range) {
    if (!node.has(key)) return;
    const std::vector<double> read = node.get_doubles(key, values.size(), range);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = read[i];
  };
  m.equalise = node.get_double("equalise", cost, m.equalise);
  m.blur_per_tap = node.get_double("blur_per_tap", cost, m.blur_per_tap);
  array("colour_space", m.colour_space, cost);
  m.colour_plane = node.get_double("colour_plane", cost, m.colour_plane);
  m.angle_plane = node.get_double("angle_plane", cost, m.angle_plane);
  m.edge_distance = node.get_double("edge_distance", cost, m.edge_distance);
  m.gevers_l_plane = node.get_double("gevers_l_plane", cost, m.gevers_l_plane);
  m.gevers_c_plane = node.get_double("gevers_c_plane", cost, m.gevers_c_plane);
  m.geusebroek_plane = node.get_double("geusebroek_plane", cost, m.geusebroek_plane);
  m.position = node.get_double("position", cost, m.position);
  m.statistics_plane = node.get_double("statistics_plane", cost, m.statistics_plane);
  array("moments", m.moments, cost);
  m.hu = node.get_double("hu", cost, m.hu);
  m.affine = node.get_double("affine", cost, m.affine);
  array("singular_values", m.singular_values, cost);
  m.gradient_angles = node.get_double("gradient_angles", cost, m.gradient_angles);
  m.per_value = node.get_double("per_value", cost, m.per_value);
  const Range exponent = Range::closed(0, 4);
  m.statistics_exponent = node.get_double("statistics_exponent", exponent, m.statistics_exponent);
  m.moments_exponent = node.get_double("moments_exponent", exponent, m.moments_exponent);
  m.singular_values_exponent = node.get_double("singular_values_exponent", exponent, m.singular_values_exponent);
  m.gradient_angles_exponent = node.get_double("gradient_angles_exponent", exponent, m.gradient_angles_exponent);
  // SIFT's cost is a divisor: never 0.
  array("sift", m.sift, Range::positive(100));
  node.finish();
}

nlohmann::json to_json(const CostModel& m) {
  return {{"equalise", m.equalise},
          {"blur_per_tap", m.blur_per_tap},
          {"colour_space", m.colour_space},
          {"colour_plane", m.colour_plane},
          {"angle_plane", m.angle_plane},
          {"edge_distance", m.edge_distance},
          {"gevers_l_plane", m.gevers_l_plane},
          {"gevers_c_plane", m.gevers_c_plane},
          {"geusebroek_plane", m.geusebroek_plane},
          {"position", m.position},
          {"statistics_plane", m.statistics_plane},
          {"moments", m.moments},
          {"hu", m.hu},
          {"affine", m.affine},
          {"singular_values", m.singular_values},
          {"gradient_angles", m.gradient_angles},
          {"per_value", m.per_value},
          {"statistics_exponent", m.statistics_exponent},
          {"moments_exponent", m.moments_exponent},
          {"singular_values_exponent", m.singular_values_exponent},
          {"gradient_angles_exponent", m.gradient_angles_exponent},
          {"sift", m.sift}};
}

}  // namespace facadeslam::semantics
