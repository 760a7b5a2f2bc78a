// configs/slam.yaml: the shipped file holds the defaults, and every mistake in
// a user's file (unknown key, value out of range, inconsistent thresholds) is
// an Error naming the file and the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "slam/slam_options.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

// The error that loading `yaml` from a file named `name` gives.
template <class Load>
std::string error_loading(const std::string& yaml, const std::string& name, Load load) {
  test::TempDir dir;
  const auto path = dir / name;
  test::write_text(path, yaml);
  try {
    load(path);
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for:\n" << yaml;
  return {};
}

std::string load_error(const std::string& yaml) {
  return error_loading(yaml, "slam.yaml", [](const std::filesystem::path& p) { load_slam_options(p); });
}

TEST(SlamOptions, ShippedConfigHoldsTheDefaults) {
  const SlamOptions loaded = load_slam_options(test::source_dir() / "configs" / "slam.yaml");
  const SlamOptions defaults;
  const TrackerOptions &t = loaded.tracker, &d = defaults.tracker;
  for (int l = 0; l < kPyramidLevels; ++l)
    EXPECT_EQ(t.pyramid.fast[static_cast<std::size_t>(l)].threshold,
              d.pyramid.fast[static_cast<std::size_t>(l)].threshold);
  EXPECT_EQ(t.coarse_stage, d.coarse_stage);
  EXPECT_EQ(t.coarse_max_points, d.coarse_max_points);
  EXPECT_DOUBLE_EQ(t.coarse_radius, d.coarse_radius);
  EXPECT_EQ(t.fine_max_points, d.fine_max_points);
  EXPECT_DOUBLE_EQ(t.fine_radius, d.fine_radius);
  EXPECT_DOUBLE_EQ(t.fine_radius_after_coarse, d.fine_radius_after_coarse);
  EXPECT_DOUBLE_EQ(t.velocity_decay, d.velocity_decay);
  EXPECT_DOUBLE_EQ(t.quality_good, d.quality_good);
  EXPECT_DOUBLE_EQ(t.quality_lost, d.quality_lost);
  EXPECT_EQ(t.min_found, d.min_found);
  EXPECT_EQ(t.good_found, d.good_found);
  EXPECT_EQ(t.keyframe_min_frames, d.keyframe_min_frames);
  EXPECT_DOUBLE_EQ(t.keyframe_min_distance, d.keyframe_min_distance);
  EXPECT_DOUBLE_EQ(t.keyframe_min_angle_deg, d.keyframe_min_angle_deg);
  EXPECT_EQ(t.keyframe_min_frames_turning, d.keyframe_min_frames_turning);
  EXPECT_DOUBLE_EQ(t.keyframe_distance_after_turn, d.keyframe_distance_after_turn);
  EXPECT_FLOAT_EQ(t.search.max_zmssd_per_pixel, d.search.max_zmssd_per_pixel);
  EXPECT_EQ(t.seed, d.seed);
  const MapMakerOptions &m = loaded.mapmaker, &md = defaults.mapmaker;
  EXPECT_DOUBLE_EQ(loaded.initialisation.min_median_parallax_deg, defaults.initialisation.min_median_parallax_deg);
  EXPECT_EQ(loaded.initialisation.min_points, defaults.initialisation.min_points);
  EXPECT_DOUBLE_EQ(m.densify_initial_map_min_parallax_deg, md.densify_initial_map_min_parallax_deg);
  EXPECT_EQ(m.local_ba_selection.neighbours, md.local_ba_selection.neighbours);
  EXPECT_EQ(m.local_ba.max_iterations, md.local_ba.max_iterations);
  EXPECT_EQ(m.global_ba.max_iterations, md.global_ba.max_iterations);
  EXPECT_EQ(m.sync_global_ba_every, md.sync_global_ba_every);
  EXPECT_FLOAT_EQ(m.epipolar.max_zmssd_per_pixel, md.epipolar.max_zmssd_per_pixel);
  EXPECT_DOUBLE_EQ(m.epipolar_partner.min_baseline, md.epipolar_partner.min_baseline);
  EXPECT_DOUBLE_EQ(m.epipolar_partner.max_axis_angle_deg, md.epipolar_partner.max_axis_angle_deg);
  EXPECT_EQ(m.outlier_min_searches, md.outlier_min_searches);
  EXPECT_DOUBLE_EQ(m.outlier_max_found_ratio, md.outlier_max_found_ratio);
}

TEST(SlamOptions, ReadsGivenValues) {
  test::TempDir dir;
  test::write_text(dir / "slam.yaml",
                   "tracker:\n  fine_max_points: 500\n  fast_thresholds: {level2: 12}\n"
                   "mapmaker:\n  local_ba_neighbours: 3\n");
  const SlamOptions o = load_slam_options(dir / "slam.yaml");
  EXPECT_EQ(o.tracker.fine_max_points, 500);
  EXPECT_EQ(o.tracker.pyramid.fast[2].threshold, 12);
  EXPECT_EQ(o.tracker.pyramid.fast[0].threshold, SlamOptions{}.tracker.pyramid.fast[0].threshold);
  EXPECT_EQ(o.mapmaker.local_ba_selection.neighbours, 3u);
}

TEST(SlamOptions, RejectsUnknownKeysAtEveryLevel) {
  EXPECT_THAT(load_error("tracker:\n  fine_radius: 8\n"), AllOf(HasSubstr("slam.yaml"), HasSubstr("fine_radius")));
  EXPECT_THAT(load_error("mapmaker:\n  local_ba_neighbors: 4\n"), HasSubstr("local_ba_neighbors"));
  EXPECT_THAT(load_error("tracker:\n  fast_thresholds: {level4: 5}\n"), HasSubstr("level4"));
  EXPECT_THAT(load_error("semantic:\n  x: 1\n"), HasSubstr("semantic"));
}

TEST(SlamOptions, RejectsBadValues) {
  EXPECT_THAT(load_error("tracker:\n  quality_good: 1.5\n"), HasSubstr("quality_good"));
  EXPECT_THAT(load_error("tracker:\n  fine_max_points: many\n"), HasSubstr("fine_max_points"));
  EXPECT_THAT(load_error("tracker:\n  fast_thresholds: {level0: 0}\n"), HasSubstr("level0"));
  EXPECT_THAT(load_error("tracker:\n  quality_good: 0.2\n  quality_lost: 0.3\n"), HasSubstr("quality_lost"));
  EXPECT_THAT(load_error("mapmaker:\n  outlier_max_found_ratio: -0.1\n"), HasSubstr("outlier_max_found_ratio"));
  EXPECT_THAT(load_error("tracker:\n  keyframe_min_angle_deg: 0\n"), HasSubstr("keyframe_min_angle_deg"));
  EXPECT_THAT(load_error("mapmaker:\n  epipolar_partner_max_angle_deg: 200\n"),
              HasSubstr("epipolar_partner_max_angle_deg"));
  EXPECT_THAT(load_error("mapmaker:\n  epipolar_partner_min_baseline: -1\n"),
              HasSubstr("epipolar_partner_min_baseline"));
  EXPECT_THAT(load_error("tracker:\n  good_found: 0\n"), HasSubstr("good_found"));
  EXPECT_THAT(load_error("tracker:\n  keyframe_min_frames_turning: 0\n"), HasSubstr("keyframe_min_frames_turning"));
  EXPECT_THAT(load_error("tracker:\n  keyframe_distance_after_turn: 2\n"), HasSubstr("keyframe_distance_after_turn"));
  EXPECT_THAT(load_error("mapmaker:\n  init_densify_min_parallax_deg: -1\n"),
              HasSubstr("init_densify_min_parallax_deg"));
}

std::string semantics_error(const std::string& yaml) {
  return error_loading(yaml, "semantics.yaml", [](const std::filesystem::path& p) { load_semantics_options(p); });
}

// configs/semantics.yaml holds exactly the built-in defaults, which the
// regression tests use.
TEST(SemanticsOptions, ShippedConfigHoldsTheDefaults) {
  SemanticsOptions defaults;
  defaults.enabled = true;
  defaults.model = test::source_dir() / "configs" / ".." / "models" / "default.fsmodel";
  defaults.grey_model = test::source_dir() / "configs" / ".." / "models" / "grey.fsmodel";
  const SemanticsOptions shipped = load_semantics_options(test::source_dir() / "configs" / "semantics.yaml");
  EXPECT_EQ(shipped.enabled, defaults.enabled);
  EXPECT_EQ(shipped.model, defaults.model);
  EXPECT_EQ(shipped.grey_model, defaults.grey_model);
  EXPECT_EQ(shipped.labels.verify_px, defaults.labels.verify_px);
  EXPECT_EQ(shipped.class_prior, defaults.class_prior);
  EXPECT_EQ(shipped.class_prior_weight, defaults.class_prior_weight);
  EXPECT_EQ(shipped.context_scale, defaults.context_scale);
  EXPECT_EQ(shipped.label_neighbours, defaults.label_neighbours);
  EXPECT_EQ(shipped.sky_only_at_infinity, defaults.sky_only_at_infinity);
  EXPECT_EQ(shipped.labels.unreliable, defaults.labels.unreliable);
  EXPECT_EQ(shipped.labels.moving, defaults.labels.moving);
  EXPECT_EQ(shipped.labels.min_reliable_points, defaults.labels.min_reliable_points);
  EXPECT_EQ(shipped.labels.unreliable_weight, defaults.labels.unreliable_weight);
  for (const char* name : {"car", "vegetation", "sky", "various"})
    EXPECT_TRUE(shipped.labels.unreliable.classes.test(*semantic_class_by_name(name))) << name;
  EXPECT_EQ(shipped.labels.moving.classes, ClassSet().set(*semantic_class_by_name("car")));
  EXPECT_EQ(shipped.moving_regions.step, defaults.moving_regions.step);
  EXPECT_EQ(shipped.moving_regions.sigma_cells, defaults.moving_regions.sigma_cells);
  EXPECT_EQ(shipped.moving_regions.min_density, defaults.moving_regions.min_density);
  EXPECT_GT(shipped.moving_regions.step, 0) << "the shipped settings detect moving regions";
}

TEST(SemanticsOptions, ReadsMovingRegions) {
  test::TempDir dir;
  const auto path = dir / "semantics.yaml";
  test::write_text(path, "moving_regions:\n  step: 0\n  sigma: 1.5\n  min_density: 0.4\n");
  const SemanticsOptions o = load_semantics_options(path);
  EXPECT_EQ(o.moving_regions.step, 0);
  EXPECT_EQ(o.moving_regions.sigma_cells, 1.5);
  EXPECT_EQ(o.moving_regions.min_density, 0.4);
}

TEST(SemanticsOptions, ReadsClassLists) {
  test::TempDir dir;
  const auto path = dir / "semantics.yaml";
  test::write_text(path, "unreliable_classes: [sky]\nmoving_classes: []\n");
  const SemanticsOptions o = load_semantics_options(path);
  EXPECT_EQ(o.labels.unreliable.classes, ClassSet().set(*semantic_class_by_name("sky")));
  EXPECT_TRUE(o.labels.moving.classes.none());
}

TEST(SemanticsOptions, ClassWeightsArePriorToTheWeight) {
  SemanticsOptions o;
  o.class_prior.fill(1.f);
  o.class_prior[1] = 4.f;
  o.class_prior_weight = 0.5;
  const ClassVotes w = o.class_weights();
  EXPECT_FLOAT_EQ(w[1], 1.f);
  EXPECT_FLOAT_EQ(w[0], 0.5f);
  o.class_prior_weight = 0.0;
  EXPECT_FLOAT_EQ(o.class_weights()[0], 1.f);
}

TEST(SemanticsOptions, RejectsBadValues) {
  EXPECT_THAT(semantics_error("unreliable_classes: [car, bus]\n"),
              AllOf(HasSubstr("semantics.yaml"), HasSubstr("unreliable_classes"), HasSubstr("bus")));
  EXPECT_THAT(semantics_error("min_confidence: 1.5\n"), HasSubstr("min_confidence"));
  EXPECT_THAT(semantics_error("class_prior_weight: -1\n"), HasSubstr("class_prior_weight"));
  EXPECT_THAT(semantics_error("class_prior: {car: 1}\n"), HasSubstr("class_prior.various"));
  EXPECT_THAT(semantics_error("class_prior: {various: 1, building: 1, car: 1, door: 1, pavement: 1, road: 1, sky: 1, "
                              "vegetation: 1, window: 0}\n"),
              HasSubstr("class_prior.window"));
  EXPECT_THAT(semantics_error("modell: x.fsmodel\n"), HasSubstr("modell"));
  EXPECT_THAT(semantics_error("unreliable_weight: 2\n"), HasSubstr("unreliable_weight"));
  EXPECT_THAT(semantics_error("unreliable_verify_px: -1\n"), HasSubstr("unreliable_verify_px"));
  EXPECT_THAT(semantics_error("grey_model: [a, b]\n"), HasSubstr("grey_model"));
  EXPECT_THAT(semantics_error("context_scale: 1\n"), HasSubstr("context_scale"));
  EXPECT_THAT(semantics_error("moving_classes: [lorry]\n"),
              AllOf(HasSubstr("semantics.yaml"), HasSubstr("moving_classes"), HasSubstr("lorry")));
  EXPECT_THAT(semantics_error("moving_classes: car\n"), HasSubstr("moving_classes"));
  EXPECT_THAT(semantics_error("moving_regions: {step: -1}\n"), HasSubstr("moving_regions.step"));
  EXPECT_THAT(semantics_error("moving_regions: {step: 2}\n"),
              AllOf(HasSubstr("moving_regions.step"), HasSubstr("0 (no regions) or 4 to 256 pixels")));
  EXPECT_THAT(semantics_error("moving_regions: {min_density: 0}\n"), HasSubstr("moving_regions.min_density"));
  EXPECT_THAT(semantics_error("moving_regions: {sigma: 0}\n"), HasSubstr("moving_regions.sigma"));
  EXPECT_THAT(semantics_error("moving_regions: {stepp: 8}\n"), HasSubstr("moving_regions.stepp"));
}

}  // namespace
}  // namespace facadeslam
