#include "slam/slam_options.hpp"

#include <algorithm>
#include <cmath>

#include "core/config/config_node.hpp"
#include "core/config/settings_table.hpp"
#include "core/map/semantic_classes.hpp"

namespace facadeslam {
namespace {

SettingsTable<patch::SearchOptions> search_settings() {
  SettingsTable<patch::SearchOptions> t;
  t.add("max_zmssd_per_pixel", &patch::SearchOptions::max_zmssd_per_pixel,
        "patch match bound, grey levels^2 per pixel (zero-mean SSD / 64; PTAM 500)", Range::positive(65025));
  t.add("dense_radius", &patch::SearchOptions::dense_radius,
        "no FAST corner matches: score every pixel this near the prediction (search-level pixels)",
        Range::closed(0, 16));
  return t;
}

SettingsTable<PyramidOptions> pyramid_settings() {
  SettingsTable<PyramidOptions> t;
  const std::string key = "fast_thresholds";
  t.add_custom(
      [key](const ConfigNode& c, PyramidOptions& p) {
        if (!c.has(key)) return;
        const std::vector<double> values = c.get_doubles(key, kPyramidLevels, Range::closed(1, 255));
        for (std::size_t l = 0; l < values.size(); ++l) {
          if (values[l] != std::floor(values[l])) c.fail(key, "whole numbers from 1 to 255");
          p.fast[l].threshold = static_cast<int>(values[l]);
        }
      },
      [key](SettingsWriter& out, const PyramidOptions& p) {
        std::vector<std::string> values;
        for (const FastOptions& level : p.fast) values.push_back(std::to_string(level.threshold));
        out.value(key, SettingsWriter::format_list(values),
                  "FAST-9 intensity threshold per pyramid level, finest first (fast[level].threshold)");
      });
  return t;
}

SettingsTable<TrackerOptions> tracker_settings() {
  using T = TrackerOptions;
  SettingsTable<T> t;
  t.add("pyramid", &T::pyramid, pyramid_settings());
  t.add("search", &T::search, search_settings(), "the patch search around each point's predicted pixel");
  t.add("coarse_stage", &T::coarse_stage, "search a few coarse-level points over a wide radius first (fast motion)");
  t.add("coarse_min_level", &T::coarse_min_level, "... points searched at this pyramid level or above",
        Range::closed(0, kPyramidLevels - 1));
  t.add("coarse_max_points", &T::coarse_max_points, "... at most this many", Range::closed(0, 1000));
  t.add("coarse_min_found", &T::coarse_min_found, "... fewer found than this: the coarse pose is not used",
        Range::closed(0, 1000));
  t.add("coarse_radius_px", &T::coarse_radius_px, "coarse search radius, level-0 pixels", Range::positive(500));
  t.add("retry_from_prediction", &T::retry_from_prediction,
        "a fine stage failing from the coarse pose is run again from the motion model's prediction");
  t.add("fine_max_points", &T::fine_max_points, "points searched in the fine stage", Range::closed(10, 100000));
  t.add("fine_radius_px", &T::fine_radius_px, "fine radius when the coarse stage did not run, level-0 pixels",
        Range::positive(200));
  t.add("fine_radius_after_coarse_px", &T::fine_radius_after_coarse_px,
        "fine radius after a coarse pose update, level-0 pixels", Range::positive(200));
  t.add("velocity_decay", &T::velocity_decay, "constant-velocity motion model, decayed per frame", Range::closed(0, 1));
  t.add("quality_good", &T::quality_good, "found/searched ratio above which tracking is good (keyframes allowed)",
        Range::closed(0, 1));
  t.add("quality_lost", &T::quality_lost, "below this the frame is lost", Range::closed(0, 1));
  t.add("min_found", &T::min_found, "fewer points found than this is lost whatever the ratio", Range::closed(6, 10000));
  t.add("good_found", &T::good_found,
        "this many points found is good whatever the ratio (occlusions around 3D objects)", Range::closed(6, 100000));
  t.add("max_good_rms_px", &T::max_good_rms_px,
        "inliers this far from their projections (RMS, level-0 pixels) are not good tracking whatever their "
        "number (a facade's repeated windows)",
        Range::positive(1000));
  t.add("lost_frames_before_relocalising", &T::lost_frames_before_relocalising,
        "bad frames in a row still tracked from the motion model before the relocaliser takes over",
        Range::closed(0, 1000));
  t.add("relocalise_on_first_bad_frame", &T::relocalise_on_first_bad_frame,
        "... but the relocaliser is also tried at once on the first bad frame (a jump in the view)");
  t.add("keyframe_min_frames", &T::keyframe_min_frames, "frames between keyframes at least", Range::closed(1, 10000));
  t.add("keyframe_min_distance", &T::keyframe_min_distance, "a keyframe this near (x its mean scene depth) ...",
        Range::positive(100));
  t.add("keyframe_min_angle_deg", &T::keyframe_min_angle_deg,
        "... whose optical axis is within this angle already covers the view", Range::closed(1, 180));
  t.add("keyframe_min_frames_turning", &T::keyframe_min_frames_turning,
        "frames between keyframes when the camera turns near a keyframe", Range::closed(1, 10000));
  t.add("keyframe_distance_after_turn", &T::keyframe_distance_after_turn,
        "the first keyframe after a turn needs only this share of keyframe_min_distance", Range::positive(1));
  t.add("keyframe_max_queue", &T::keyframe_max_queue,
        "keyframes waiting for the map maker at most; a busy map maker gets no more", Range::closed(1, 100));
  t.add("keyframe_min_overlap", &T::keyframe_min_overlap,
        "a keyframe whenever the points found fall below this share of the most found since the last "
        "keyframe (forward motion) ...",
        Range::closed(0, 1));
  t.add("keyframe_min_frames_overlap", &T::keyframe_min_frames_overlap, "... at most every this many frames",
        Range::closed(1, 10000));
  t.add("keyframe_overlap_skips_revisits", &T::keyframe_overlap_skips_revisits,
        "... but not on mapped ground: a keyframe covers the view and the newest keyframe is far ...");
  t.add("keyframe_revisit_age_frames", &T::keyframe_revisit_age_frames, "... or this many frames old",
        Range::closed(1, 1000000));
  t.add("seed", &T::seed, "order in which points are sampled when there are too many", Range::closed(0, 2147483647));
  t.check([](const ConfigNode& c, const T& o) {
    if (o.quality_lost > o.quality_good) c.fail("quality_lost", "a value not above quality_good");
  });
  return t;
}

SettingsTable<TwoViewOptions> initialisation_settings() {
  using I = TwoViewOptions;
  SettingsTable<I> t;
  t.add("min_median_parallax_deg", &I::min_median_parallax_deg, "median parallax angle the two initial views need",
        Range::positive(45));
  t.add("min_points", &I::min_points, "triangulated points the initial map needs", Range::closed(8, 100000));
  return t;
}

SettingsTable<EpipolarSearchOptions> epipolar_settings() {
  using E = EpipolarSearchOptions;
  SettingsTable<E> t;
  t.add("max_zmssd_per_pixel", &E::max_zmssd_per_pixel, "patch match bound of the epipolar search for new points",
        Range::positive(65025));
  t.add("warp_templates", &E::warp_templates,
        "warp templates into the other keyframe at the mean depth (forward motion scales patches)");
  t.add("dense_line_search", &E::dense_line_search,
        "score every pixel along the epipolar segment, not only FAST corners near it");
  t.add("min_parallax_deg", &E::min_parallax_deg, "a new point's two rays must be this far from parallel (x 2^level)",
        Range::closed(0, 45));
  t.add("min_far_depth_factor", &E::min_far_depth_factor,
        "with a far partner, the search reaches out to at least this x scene depth (0: mean + 3 sigma only)",
        Range::non_negative(1000));
  return t;
}

SettingsTable<EpipolarPartnerOptions> epipolar_partner_settings() {
  using P = EpipolarPartnerOptions;
  SettingsTable<P> t;
  t.add("min_baseline", &P::min_baseline,
        "the keyframe searched against stands at least this far away (x scene depth) ...", Range::non_negative(10));
  t.add("max_axis_angle_deg", &P::max_axis_angle_deg,
        "... and looks within this angle of the new keyframe (else the nearest)", Range::closed(1, 180));
  t.add("far_baseline", &P::far_baseline,
        "a second partner at least this far away (x scene depth): parallax for the points ahead (0: none) ...",
        Range::non_negative(10));
  t.add("far_max_motion_angle_deg", &P::far_max_motion_angle_deg,
        "... when the camera moves within this angle of its optical axis (forward); else also no far depth",
        Range::closed(0, 180));
  return t;
}

SettingsTable<BundleAdjusterOptions> ba_settings() {
  SettingsTable<BundleAdjusterOptions> t;
  t.add("max_iterations", &BundleAdjusterOptions::max_iterations, "Levenberg-Marquardt iterations",
        Range::closed(1, 1000));
  return t;
}

SettingsTable<LocalBaOptions> local_ba_selection_settings() {
  SettingsTable<LocalBaOptions> t;
  t.add("neighbours", &LocalBaOptions::neighbours, "keyframes freed with the newest one in local BA",
        Range::closed(1, 100));
  return t;
}

SettingsTable<KeyFrameCullingOptions> culling_settings() {
  using K = KeyFrameCullingOptions;
  SettingsTable<K> t;
  t.add("enabled", &K::enabled,
        "remove keyframes whose points other keyframes already measure (bounded maps on revisits)");
  t.add("redundant_share", &K::redundant_share, "... when this share of a keyframe's points is measured by ...",
        Range::closed(0.5, 1));
  t.add("min_other_keyframes", &K::min_other_keyframes,
        "... at least this many other keyframes at the same, a finer or the next coarser level", Range::closed(1, 100));
  return t;
}

SettingsTable<GroundGaugeOptions> ground_gauge_settings() {
  using G = GroundGaugeOptions;
  SettingsTable<G> t;
  t.add("enabled", &G::enabled,
        "hold the camera's height above the road found under the first keyframes (a vehicle's camera)");
  t.add("keyframe_sigma", &G::keyframe_sigma, "how far a keyframe's height may stray from it (x the height)",
        Range::closed(1e-4, 1));
  t.add("point_sigma", &G::point_sigma, "a ground point's own height noise in the robust loss (x the height)",
        Range::closed(1e-4, 1));
  t.add("min_inliers", &G::min_inliers, "a keyframe's ground needs this many points ...", Range::closed(3, 10000));
  t.add("inlier_band", &G::inlier_band, "... within this of their median height (x the height) ...",
        Range::closed(1e-3, 0.5));
  t.add("search_window", &G::search_window, "... which is within this of the keyframe's last height (x the height)",
        Range::closed(0.01, 0.9));
  return t;
}

SettingsTable<MapMakerOptions> mapmaker_settings() {
  using M = MapMakerOptions;
  SettingsTable<M> t;
  t.add("densify_initial_map_min_parallax_deg", &M::densify_initial_map_min_parallax_deg,
        "with this much parallax the initial map also gets coarse-level points", Range::non_negative(180));
  t.add("local_ba_selection", &M::local_ba_selection, local_ba_selection_settings());
  t.add("local_ba", &M::local_ba, ba_settings(), "bundle adjustment after each keyframe");
  t.add("global_ba", &M::global_ba, ba_settings(), "bundle adjustment of the whole map");
  t.add("sync_global_ba_every", &M::sync_global_ba_every, "--sync: a global BA after every this many keyframes",
        Range::closed(1, 1000));
  t.add("newest_view_templates", &M::newest_view_templates,
        "the tracker searches each point's patch as the newest keyframe measuring it saw it");
  t.add("epipolar", &M::epipolar, epipolar_settings(), "the search for new points along epipolar lines");
  t.add("epipolar_partner", &M::epipolar_partner, epipolar_partner_settings(),
        "the keyframes a new keyframe is searched against");
  t.add("depth_prior_points", &M::depth_prior_points,
        "a keyframe made turning on the spot gets points at the scene depth where no keyframe has a baseline");
  t.add("outlier_min_searches", &M::outlier_min_searches, "a point searched this often ...", Range::closed(1, 100000));
  t.add("outlier_max_found_ratio", &M::outlier_max_found_ratio,
        "... and found less than this share of the time is removed", Range::closed(0, 1));
  t.add("culling", &M::culling, culling_settings());
  t.add("ground_gauge", &M::ground_gauge, ground_gauge_settings(),
        "the monocular scale held by the camera's height above the road");
  return t;
}

SettingsTable<MapResetOptions> map_reset_settings() {
  using R = MapResetOptions;
  SettingsTable<R> t;
  t.add("young_map_frames", &R::young_map_frames, "a map lost within this many frames of its initialisation ...",
        Range::closed(0, 1000000));
  t.add("young_map_lost_frames", &R::young_map_lost_frames,
        "... lost for this many frames in a row is a bad start: reset", Range::closed(1, 100000));
  t.add("lost_frames", &R::lost_frames, "any map lost this many frames in a row is reset (0: never)",
        Range::closed(0, 1000000));
  return t;
}

const SettingsTable<SlamOptions>& slam_settings() {
  static const SettingsTable<SlamOptions> table = [] {
    SettingsTable<SlamOptions> t;
    t.add("tracker", &SlamOptions::tracker, tracker_settings(), "the tracker thread: every frame's pose");
    t.add("initialisation", &SlamOptions::initialisation, initialisation_settings(),
          "start-up: the two views the first map is made from");
    t.add("mapmaker", &SlamOptions::mapmaker, mapmaker_settings(),
          "the map maker thread: keyframes, new points, bundle adjustment");
    t.add("map_reset", &SlamOptions::map_reset, map_reset_settings(),
          "when the map is given up and start-up begins again (each map's poses are kept: segments/N/)");
    return t;
  }();
  return table;
}

std::vector<std::string> class_names() {
  std::vector<std::string> names;
  names.reserve(kSemanticClasses.size());
  for (const SemanticClass& c : kSemanticClasses) names.emplace_back(c.name);
  return names;
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

// A list of class names as a set.
SettingsTable<UnreliableLabels>::Reader read_classes(const std::string& key) {
  return [key](const ConfigNode& c, UnreliableLabels& labels) {
    if (!c.has(key)) return;
    labels.classes.reset();
    for (const std::string& name : c.get_choices(key, class_names())) labels.classes.set(*semantic_class_by_name(name));
  };
}

SettingsTable<UnreliableLabels>::Writer write_classes(const std::string& key, const std::string& doc) {
  return [key, doc](SettingsWriter& out, const UnreliableLabels& labels) {
    std::vector<std::string> names;
    for (const SemanticClass& c : kSemanticClasses)
      if (labels.classes.test(c.id)) names.emplace_back(c.name);
    out.value(key, SettingsWriter::format_list(names), doc);
  };
}

SettingsTable<UnreliableLabels> class_rule_settings(const std::string& what) {
  using U = UnreliableLabels;
  SettingsTable<U> t;
  t.add_custom(read_classes("classes"), write_classes("classes", "points of these classes are " + what +
                                                                     " (LabelMeFacade's names; [] = none) ..."));
  t.add("min_confidence", &U::min_confidence, "... when their label's vote share is at least this",
        Range::closed(0, 1));
  t.add("regions", &U::regions, "... and so are points in the semantic worker's moving regions (moving_regions)");
  return t;
}

SettingsTable<LabelPolicy> label_policy_settings() {
  using L = LabelPolicy;
  SettingsTable<L> t;
  t.add("unreliable", &L::unreliable, class_rule_settings("weighed down in the tracker's pose update"));
  t.add("moving", &L::moving,
        class_rule_settings("left out altogether, by the tracker as with a weight of 0, by bundle adjustment and "
                            "by culling: a car's points move as one body and agree on a wrong motion"));
  t.add("unreliable_weight", &L::unreliable_weight,
        "the weight of an unreliable point in the pose update (0 = not searched at all)", Range::closed(0, 1));
  t.add("min_reliable_points", &L::min_reliable_points,
        "with weight 0: search them anyway when fewer other points are in view", Range::closed(0, 100000));
  t.add("verify_px", &L::verify_px,
        "a down-weighted point the pose reprojects within this many pixels (of its pyramid level) stands still: "
        "full weight in a second pose update (0 = never)",
        Range::closed(0, 100));
  return t;
}

SettingsTable<semantics::MovingRegionOptions> moving_region_settings() {
  using R = semantics::MovingRegionOptions;
  SettingsTable<R> t;
  t.add("step", &R::step,
        "the keyframe is also classified on a grid of cells this many pixels wide (0 = no regions, else 4..256; "
        "the worker's time per keyframe grows with 1/step^2)",
        Range::closed(0, 256));
  t.add("sigma_cells", &R::sigma_cells,
        "each cell's call (moving class or not) is smoothed by a Gaussian of this many cells", Range::closed(0.1, 100));
  t.add("min_density", &R::min_density,
        "a point whose views mostly see at least this share of moving calls around it is left out", Range::positive(1));
  t.check([](const ConfigNode& c, const R& r) {
    // Each halving of the step describes 4x the cells: 4 pixels is 16x the shipped 16.
    if (r.step > 0 && r.step < 4) c.fail("step", "0 (no regions) or 4 to 256 pixels");
  });
  return t;
}

// A model path: relative to the settings file's folder, not to wherever the
// program is run from ("" stays empty: no model).
SettingsTable<SemanticsOptions>::Reader read_model(const std::string& key,
                                                   std::filesystem::path SemanticsOptions::*member) {
  return [key, member](const ConfigNode& c, SemanticsOptions& o) {
    if (!c.has(key)) return;
    const std::filesystem::path model = c.get_string(key);
    o.*member = model.empty() || model.is_absolute() ? model : std::filesystem::path(c.origin()).parent_path() / model;
  };
}

SettingsTable<SemanticsOptions>::Writer write_model(const std::string& key,
                                                    std::filesystem::path SemanticsOptions::*member,
                                                    const std::string& doc) {
  return [key, member, doc](SettingsWriter& out, const SemanticsOptions& o) {
    out.value(key, SettingsWriter::format((o.*member).lexically_normal().string()), doc);
  };
}

const SettingsTable<SemanticsOptions>& semantics_settings() {
  static const SettingsTable<SemanticsOptions> table = [] {
    using S = SemanticsOptions;
    SettingsTable<S> t;
    t.add("enabled", &S::enabled, "label the map with the semantic worker (replay --semantics on|off overrides)");
    t.add_custom(read_model("model", &S::model),
                 write_model("model", &S::model,
                             "forest model (.fsmodel), relative to this file's folder (replay --model overrides)"));
    t.add_custom(read_model("grey_model", &S::grey_model),
                 write_model("grey_model", &S::grey_model,
                             "model for grey images (a grey camera: `train --grey`); \"\" = leave them unlabelled "
                             "(replay --grey-model overrides)"));
    t.add_custom(
        [](const ConfigNode& c, S& o) {
          if (const auto prior = c.optional_child("class_prior")) {
            for (const SemanticClass& k : kSemanticClasses)
              o.class_prior[k.id] = static_cast<float>(prior->get_double(std::string(k.name), Range::positive()));
            prior->finish();
          }
        },
        [](SettingsWriter& out, const S& o) {
          out.open("class_prior",
                   "how common each class is (any scale), e.g. grid keypoints per class of the model's "
                   "training data; all classes or none");
          for (const SemanticClass& k : kSemanticClasses)
            out.value(std::string(k.name), SettingsWriter::format(o.class_prior[k.id]), "");
          out.close();
        });
    t.add("class_prior_weight", &S::class_prior_weight,
          "each view's votes are multiplied by prior^weight before fusion: 0 = the forest's votes, 1 = the full prior "
          "(for class-balanced forests)",
          Range::closed(0, 1));
    t.add("context_scale", &S::context_scale,
          "each point is also classified in its keyframe shrunk to this scale and the two votes added: the "
          "descriptor's patch sees more of the facade around it (0 = full size only)",
          Range::closed(0, 0.9));
    t.add("label_neighbours", &S::label_neighbours,
          "a point's label in the map (map.ply, report) is its votes fused with those of its this many nearest map "
          "points (0 = its own votes); the tracker weighs points by their own votes' label",
          Range::closed(0, 100));
    t.add("sky_only_at_infinity", &S::sky_only_at_infinity,
          "a point two keyframes measure at a finite depth is not labelled sky in the map (its next class instead)");
    t.add("max_queued_keyframes", &S::max_queued_keyframes,
          "keyframes waiting for the semantic worker at most (threaded); with more the map maker waits for it",
          Range::closed(1, 1000));
    t.add("labels", &S::labels, label_policy_settings(),
          "how the tracker, bundle adjustment and culling treat a point by its label");
    t.add("moving_regions", &S::moving_regions, moving_region_settings(),
          "regions dense with the forest's calls of a moving class: a close-up car's points are called car one by "
          "one seldom, its region often");
    return t;
  }();
  return table;
}

}  // namespace

SemanticsOptions load_semantics_options(const std::filesystem::path& path, SemanticsOptions options) {
  return semantics_settings().load(path, std::move(options));
}

void write_semantics_settings(std::ostream& out, const SemanticsOptions& options) {
  semantics_settings().write_yaml(out, options);
}

SlamOptions load_slam_options(const std::filesystem::path& path) { return slam_settings().load(path); }

void write_slam_settings(std::ostream& out, const SlamOptions& options) { slam_settings().write_yaml(out, options); }

}  // namespace facadeslam
