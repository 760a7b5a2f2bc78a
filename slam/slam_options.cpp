#include "slam/slam_options.hpp"

#include <algorithm>
#include <cmath>

#include "core/config/config_node.hpp"
#include "core/map/semantic_classes.hpp"

namespace facadeslam {
namespace {

void read_tracker(const ConfigNode& c, TrackerOptions& t) {
  if (const auto fast = c.optional_child("fast_thresholds")) {
    for (int l = 0; l < kPyramidLevels; ++l)
      t.pyramid.fast[static_cast<std::size_t>(l)].threshold = fast->get_int(
          "level" + std::to_string(l), Range::closed(1, 255), t.pyramid.fast[static_cast<std::size_t>(l)].threshold);
    fast->finish();
  }
  t.coarse_stage = c.get_bool("coarse_stage", t.coarse_stage);
  t.retry_from_prediction = c.get_bool("retry_from_prediction", t.retry_from_prediction);
  t.coarse_max_points = c.get_int("coarse_max_points", Range::closed(0, 1000), t.coarse_max_points);
  t.coarse_radius = c.get_double("coarse_radius_px", Range::positive(500), t.coarse_radius);
  t.fine_max_points = c.get_int("fine_max_points", Range::closed(10, 100000), t.fine_max_points);
  t.fine_radius = c.get_double("fine_radius_px", Range::positive(200), t.fine_radius);
  t.fine_radius_after_coarse =
      c.get_double("fine_radius_after_coarse_px", Range::positive(200), t.fine_radius_after_coarse);
  t.velocity_decay = c.get_double("velocity_decay", Range::closed(0, 1), t.velocity_decay);
  t.quality_good = c.get_double("quality_good", Range::closed(0, 1), t.quality_good);
  t.quality_lost = c.get_double("quality_lost", Range::closed(0, 1), t.quality_lost);
  if (t.quality_lost > t.quality_good) c.fail("quality_lost", "a value not above quality_good");
  t.min_found = c.get_int("min_found", Range::closed(6, 10000), t.min_found);
  t.good_found = c.get_int("good_found", Range::closed(6, 100000), t.good_found);
  t.keyframe_min_frames = c.get_int("keyframe_min_frames", Range::closed(1, 10000), t.keyframe_min_frames);
  t.keyframe_min_distance = c.get_double("keyframe_min_distance", Range::positive(100), t.keyframe_min_distance);
  t.keyframe_min_frames_turning =
      c.get_int("keyframe_min_frames_turning", Range::closed(1, 10000), t.keyframe_min_frames_turning);
  t.keyframe_distance_after_turn =
      c.get_double("keyframe_distance_after_turn", Range::positive(1), t.keyframe_distance_after_turn);
  t.keyframe_min_overlap = c.get_double("keyframe_min_overlap", Range::closed(0, 1), t.keyframe_min_overlap);
  t.keyframe_min_frames_overlap =
      c.get_int("keyframe_min_frames_overlap", Range::closed(1, 10000), t.keyframe_min_frames_overlap);
  t.keyframe_overlap_skips_revisits = c.get_bool("keyframe_overlap_skips_revisits", t.keyframe_overlap_skips_revisits);
  t.keyframe_revisit_age_frames =
      c.get_int("keyframe_revisit_age_frames", Range::closed(1, 1000000), t.keyframe_revisit_age_frames);
  t.keyframe_min_angle_deg = c.get_double("keyframe_min_angle_deg", Range::closed(1, 180), t.keyframe_min_angle_deg);
  t.search.max_zmssd_per_pixel =
      static_cast<float>(c.get_double("max_zmssd_per_pixel", Range::positive(65025), t.search.max_zmssd_per_pixel));
  t.search.dense_radius = c.get_int("dense_search_radius_px", Range::closed(0, 16), t.search.dense_radius);
  t.seed = static_cast<std::uint64_t>(c.get_int("seed", Range::closed(0, 2147483647), static_cast<int>(t.seed)));
  c.finish();
}

void read_mapmaker(const ConfigNode& c, TwoViewOptions& init, MapMakerOptions& m) {
  init.min_median_parallax_deg =
      c.get_double("init_min_parallax_deg", Range::positive(45), init.min_median_parallax_deg);
  m.densify_initial_map_min_parallax_deg =
      c.get_double("init_densify_min_parallax_deg", Range::non_negative(180), m.densify_initial_map_min_parallax_deg);
  init.min_points = c.get_int("init_min_points", Range::closed(8, 100000), init.min_points);
  m.local_ba_selection.neighbours = static_cast<std::size_t>(
      c.get_int("local_ba_neighbours", Range::closed(1, 100), static_cast<int>(m.local_ba_selection.neighbours)));
  m.local_ba.max_iterations = c.get_int("local_ba_iterations", Range::closed(1, 1000), m.local_ba.max_iterations);
  m.global_ba.max_iterations = c.get_int("global_ba_iterations", Range::closed(1, 1000), m.global_ba.max_iterations);
  m.sync_global_ba_every = c.get_int("sync_global_ba_every", Range::closed(1, 1000), m.sync_global_ba_every);
  m.newest_view_templates = c.get_bool("newest_view_templates", m.newest_view_templates);
  m.epipolar.warp_templates = c.get_bool("epipolar_warp_templates", m.epipolar.warp_templates);
  m.epipolar.dense_line_search = c.get_bool("epipolar_dense_line_search", m.epipolar.dense_line_search);
  m.epipolar.max_zmssd_per_pixel = static_cast<float>(
      c.get_double("epipolar_max_zmssd_per_pixel", Range::positive(65025), m.epipolar.max_zmssd_per_pixel));
  m.epipolar_partner.min_baseline =
      c.get_double("epipolar_partner_min_baseline", Range::non_negative(10), m.epipolar_partner.min_baseline);
  m.epipolar_partner.max_axis_angle_deg =
      c.get_double("epipolar_partner_max_angle_deg", Range::closed(1, 180), m.epipolar_partner.max_axis_angle_deg);
  m.epipolar.min_parallax_deg =
      c.get_double("epipolar_min_parallax_deg", Range::closed(0, 45), m.epipolar.min_parallax_deg);
  m.epipolar.min_far_depth_factor =
      c.get_double("epipolar_min_far_depth", Range::non_negative(1000), m.epipolar.min_far_depth_factor);
  m.epipolar_partner.far_baseline =
      c.get_double("epipolar_far_partner_baseline", Range::non_negative(10), m.epipolar_partner.far_baseline);
  m.epipolar_partner.far_max_motion_angle_deg = c.get_double(
      "epipolar_far_partner_max_motion_angle_deg", Range::closed(0, 180), m.epipolar_partner.far_max_motion_angle_deg);
  m.outlier_min_searches = c.get_int("outlier_min_searches", Range::closed(1, 100000), m.outlier_min_searches);
  m.outlier_max_found_ratio = c.get_double("outlier_max_found_ratio", Range::closed(0, 1), m.outlier_max_found_ratio);
  m.culling.enabled = c.get_bool("cull_keyframes", m.culling.enabled);
  m.culling.redundant_share = c.get_double("cull_redundant_share", Range::closed(0.5, 1), m.culling.redundant_share);
  m.culling.min_other_keyframes =
      c.get_int("cull_min_other_keyframes", Range::closed(1, 100), m.culling.min_other_keyframes);
  c.finish();
}

std::vector<std::string> class_names() {
  std::vector<std::string> names;
  names.reserve(kSemanticClasses.size());
  for (const SemanticClass& c : kSemanticClasses) names.emplace_back(c.name);
  return names;
}

void read_reset(const ConfigNode& c, MapResetOptions& r) {
  r.young_map_frames = c.get_int("young_map_frames", Range::closed(0, 1000000), r.young_map_frames);
  r.young_map_lost_frames = c.get_int("young_map_lost_frames", Range::closed(1, 100000), r.young_map_lost_frames);
  r.lost_frames = c.get_int("lost_frames", Range::closed(0, 1000000), r.lost_frames);
  c.finish();
}

}  // namespace

ClassVotes SemanticsOptions::class_weights() const {
  ClassVotes weights{};
  float largest = 0.f;
  for (std::size_t c = 0; c < weights.size(); ++c) {
    weights[c] = static_cast<float>(std::pow(static_cast<double>(class_prior[c]), class_prior_weight));
    largest = std::max(largest, weights[c]);
  }
  for (float& w : weights) w /= largest;
  return weights;
}

namespace {

// A list of class names, as a set; `fallback` when the key is absent.
ClassSet read_classes(const ConfigNode& node, const std::string& key, ClassSet fallback) {
  if (!node.has(key)) return fallback;
  ClassSet classes;
  for (const std::string& name : node.get_choices(key, class_names())) classes.set(*semantic_class_by_name(name));
  return classes;
}

}  // namespace

SemanticsOptions load_semantics_options(const std::filesystem::path& path, SemanticsOptions options) {
  const ConfigNode root = ConfigNode::load_file(path);
  options.enabled = root.get_bool("enabled", options.enabled);
  // A model named in the file is relative to the file's folder, not to
  // wherever the program is run from ("" stays empty: no grey model).
  const auto beside_config = [&](const std::string& name) {
    const std::filesystem::path model = name;
    return model.empty() || model.is_absolute() ? model : path.parent_path() / model;
  };
  if (root.has("model")) options.model = beside_config(root.get_string("model"));
  if (root.has("grey_model")) options.grey_model = beside_config(root.get_string("grey_model"));
  if (const auto prior = root.optional_child("class_prior")) {
    for (const SemanticClass& c : kSemanticClasses)
      options.class_prior[c.id] = static_cast<float>(prior->get_double(std::string(c.name), Range::positive()));
    prior->finish();
  }
  options.class_prior_weight = root.get_double("class_prior_weight", Range::closed(0, 1), options.class_prior_weight);
  options.context_scale = root.get_double("context_scale", Range::closed(0, 0.9), options.context_scale);
  options.label_neighbours = root.get_int("label_neighbours", Range::closed(0, 100), options.label_neighbours);
  options.sky_only_at_infinity = root.get_bool("sky_only_at_infinity", options.sky_only_at_infinity);
  LabelPolicy& labels = options.labels;
  labels.unreliable.classes = read_classes(root, "unreliable_classes", labels.unreliable.classes);
  labels.moving.classes = read_classes(root, "moving_classes", labels.moving.classes);
  if (const auto regions = root.optional_child("moving_regions")) {
    semantics::MovingRegionOptions& region_options = options.moving_regions;
    region_options.step = regions->get_int("step", Range::closed(0, 256), region_options.step);
    // Each halving of the step describes 4x the cells: 4 pixels is 16x the shipped 16.
    if (region_options.step > 0 && region_options.step < 4) regions->fail("step", "0 (no regions) or 4 to 256 pixels");
    region_options.sigma_cells = regions->get_double("sigma", Range::closed(0.1, 100), region_options.sigma_cells);
    region_options.min_density = regions->get_double("min_density", Range::positive(1), region_options.min_density);
    regions->finish();
  }
  labels.unreliable.min_confidence = labels.moving.min_confidence =
      static_cast<float>(root.get_double("min_confidence", Range::closed(0, 1), labels.unreliable.min_confidence));
  labels.unreliable_weight = root.get_double("unreliable_weight", Range::closed(0, 1), labels.unreliable_weight);
  labels.min_reliable_points =
      root.get_int("min_reliable_points", Range::closed(0, 100000), labels.min_reliable_points);
  labels.verify_px = root.get_double("unreliable_verify_px", Range::closed(0, 100), labels.verify_px);
  root.finish();
  return options;
}

SlamOptions load_slam_options(const std::filesystem::path& path) {
  SlamOptions options;
  const ConfigNode root = ConfigNode::load_file(path);
  if (const auto tracker = root.optional_child("tracker")) read_tracker(*tracker, options.tracker);
  if (const auto mapmaker = root.optional_child("mapmaker"))
    read_mapmaker(*mapmaker, options.initialisation, options.mapmaker);
  if (const auto reset = root.optional_child("map_reset")) read_reset(*reset, options.reset);
  root.finish();
  return options;
}

}  // namespace facadeslam
