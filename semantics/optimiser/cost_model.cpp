#include "semantics/optimiser/cost_model.hpp"

#include <bit>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "core/config/config_node.hpp"
#include "core/config/settings_table.hpp"
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

namespace {

// A fixed-length list of costs, e.g. one per colour space.
template <std::size_t N>
void add_costs(SettingsTable<CostModel>& t, const std::string& key, std::array<double, N> CostModel::*member,
               Range range, const std::string& doc) {
  t.add_custom(
      [key, member, range](const ConfigNode& node, CostModel& m) {
        if (!node.has(key)) return;
        const std::vector<double> read = node.get_doubles(key, N, range);
        for (std::size_t i = 0; i < N; ++i) (m.*member)[i] = read[i];
      },
      [key, member, doc](SettingsWriter& out, const CostModel& m) {
        std::vector<std::string> values;
        for (const double v : m.*member) values.push_back(SettingsWriter::format(v));
        out.value(key, SettingsWriter::format_list(values), doc);
      });
}

}  // namespace

const SettingsTable<CostModel>& cost_model_settings() {
  static const SettingsTable<CostModel> table = [] {
    using C = CostModel;
    SettingsTable<C> t;
    const Range cost = Range::closed(0, 100);
    t.add("equalise", &C::equalise, "equalising the luma and splitting the channels (any value reading a plane)", cost);
    t.add("blur_per_tap", &C::blur_per_tap, "Gaussian blur, per tap of the genome's kernel (kernel 1: no blur)", cost);
    add_costs(t, "colour_space", &C::colour_space, cost,
              "converting to RGB, Lab, Luv, XYZ, HSV, HLS, YCrCb, opponent, beyond writing its planes");
    t.add("colour_plane", &C::colour_plane, "one colour channel as a float plane", cost);
    t.add("angle_plane", &C::angle_plane, "one gradient-angle plane (Sobel or Scharr)", cost);
    t.add("edge_distance", &C::edge_distance, "grey image, Canny and the distance to its edges", cost);
    t.add("gevers_l_plane", &C::gevers_l_plane, "one Gevers l plane", cost);
    t.add("gevers_c_plane", &C::gevers_c_plane, "one Gevers c plane", cost);
    t.add("geusebroek_plane", &C::geusebroek_plane, "one Geusebroek plane (H or C)", cost);
    t.add("position", &C::position,
          "per keypoint from here on, at patch radius 10: walking the keypoints and writing the rows (any active "
          "value); the position values themselves cost next to nothing",
          cost);
    t.add("statistics_plane", &C::statistics_plane,
          "mean and sigma of one plane over the patch (colour, Gevers, Geusebroek, edge distance)", cost);
    add_costs(t, "moments", &C::moments, cost,
              "a channel's moments up to order 2, 3, 4, 5 (the highest any moment, Hu or affine value needs)");
    t.add("hu", &C::hu, "one Hu invariant, beyond its channel's moments", cost);
    t.add("affine", &C::affine, "one affine moment invariant, beyond its channel's moments", cost);
    add_costs(t, "singular_values", &C::singular_values, cost,
              "a channel's sigma1..sigma_k for its highest active k = 1, 2, 3");
    t.add("gradient_angles", &C::gradient_angles, "a channel's gradient-angle region means and differences", cost);
    t.add("per_value", &C::per_value,
          "each active value: what the parts, timed alone, miss together (from the genome with all 185 values)", cost);
    const Range exponent = Range::closed(0, 4);
    t.add("statistics_exponent", &C::statistics_exponent,
          "per-keypoint cost at radius r = cost at 10 x ((2r+1)/21)^exponent: statistics", exponent);
    t.add("moments_exponent", &C::moments_exponent, "... moments, Hu and affine invariants", exponent);
    t.add("singular_values_exponent", &C::singular_values_exponent, "... singular values", exponent);
    t.add("gradient_angles_exponent", &C::gradient_angles_exponent, "... gradient angles", exponent);
    // SIFT's cost is a divisor: never 0.
    add_costs(t, "sift", &C::sift, Range::positive(100),
              "cv::SIFT's cost with the patch of radius 3, 4, ..., 10, relative to radius 10 (the divisor of the "
              "ratio)");
    return t;
  }();
  return table;
}

void read_cost_model(const ConfigNode& node, CostModel& m) { cost_model_settings().read(node, m); }

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
