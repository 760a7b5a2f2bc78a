// configs/slam.yaml: the shipped file holds the defaults, and every mistake in
// a user's file (unknown key, value out of range, inconsistent thresholds) is
// an Error naming the file and the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

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

// The shipped file is what `config --dump slam` writes for the defaults: every
// key, under what it means, at its default.
TEST(SlamOptions, ShippedConfigIsTheDumpOfTheDefaults) {
  std::ostringstream dump;
  write_slam_settings(dump, SlamOptions{});
  const std::string shipped = test::read_text(test::source_dir() / "configs" / "slam.yaml");
  EXPECT_NE(shipped.find(dump.str()), std::string::npos)
      << "configs/slam.yaml is not the defaults: rewrite it with `facadeslam config --dump slam`";
}

// Every setting written is read back to the same value, nested ones included.
TEST(SlamOptions, DumpReadsBackToTheSameSettings) {
  SlamOptions changed;
  changed.tracker.pyramid.fast[3].threshold = 7;
  changed.tracker.search.max_zmssd_per_pixel = 612.5f;
  changed.tracker.velocity_decay = 0.8125;
  changed.tracker.seed = 3;
  changed.initialisation.min_points = 77;
  changed.mapmaker.epipolar.warp_templates = false;
  changed.mapmaker.epipolar_partner.far_baseline = 0.15;
  changed.mapmaker.culling.enabled = false;
  changed.mapmaker.local_ba_selection.neighbours = 6;
  changed.map_reset.lost_frames = 0;
  std::ostringstream first;
  write_slam_settings(first, changed);
  test::TempDir dir;
  test::write_text(dir / "slam.yaml", first.str());
  const SlamOptions read = load_slam_options(dir / "slam.yaml");
  std::ostringstream second;
  write_slam_settings(second, read);
  EXPECT_EQ(first.str(), second.str());
  EXPECT_EQ(read.tracker.pyramid.fast[3].threshold, 7);
  EXPECT_EQ(read.tracker.search.max_zmssd_per_pixel, 612.5f);
  EXPECT_EQ(read.tracker.seed, 3u);
  EXPECT_FALSE(read.mapmaker.culling.enabled);
  EXPECT_EQ(read.mapmaker.local_ba_selection.neighbours, 6u);
  EXPECT_EQ(read.map_reset.lost_frames, 0);
}

TEST(SlamOptions, ReadsGivenValues) {
  test::TempDir dir;
  test::write_text(dir / "slam.yaml",
                   "tracker:\n  fine_max_points: 500\n  pyramid: {fast_thresholds: [10, 8, 12, 6]}\n"
                   "mapmaker:\n  local_ba_selection: {neighbours: 3}\n");
  const SlamOptions o = load_slam_options(dir / "slam.yaml");
  EXPECT_EQ(o.tracker.fine_max_points, 500);
  EXPECT_EQ(o.tracker.pyramid.fast[2].threshold, 12);
  EXPECT_EQ(o.tracker.pyramid.fast[0].threshold, SlamOptions{}.tracker.pyramid.fast[0].threshold);
  EXPECT_EQ(o.mapmaker.local_ba_selection.neighbours, 3u);
}

TEST(SlamOptions, RejectsUnknownKeysAtEveryLevel) {
  EXPECT_THAT(load_error("tracker:\n  fine_radius: 8\n"), AllOf(HasSubstr("slam.yaml"), HasSubstr("fine_radius")));
  EXPECT_THAT(load_error("mapmaker:\n  local_ba_selection: {neighbors: 4}\n"),
              HasSubstr("mapmaker.local_ba_selection.neighbors"));
  EXPECT_THAT(load_error("tracker:\n  pyramid: {fast_thresholds: [10, 8, 8, 6, 5]}\n"),
              HasSubstr("tracker.pyramid.fast_thresholds"));
  EXPECT_THAT(load_error("semantic:\n  x: 1\n"), HasSubstr("semantic"));
}

TEST(SlamOptions, RejectsBadValues) {
  EXPECT_THAT(load_error("tracker:\n  quality_good: 1.5\n"), HasSubstr("quality_good"));
  EXPECT_THAT(load_error("tracker:\n  fine_max_points: many\n"), HasSubstr("fine_max_points"));
  EXPECT_THAT(load_error("tracker:\n  pyramid: {fast_thresholds: [0, 8, 8, 6]}\n"), HasSubstr("fast_thresholds"));
  EXPECT_THAT(load_error("tracker:\n  quality_good: 0.2\n  quality_lost: 0.3\n"), HasSubstr("quality_lost"));
  EXPECT_THAT(load_error("mapmaker:\n  outlier_max_found_ratio: -0.1\n"), HasSubstr("outlier_max_found_ratio"));
  EXPECT_THAT(load_error("tracker:\n  keyframe_min_angle_deg: 0\n"), HasSubstr("keyframe_min_angle_deg"));
  EXPECT_THAT(load_error("mapmaker:\n  epipolar_partner: {max_axis_angle_deg: 200}\n"),
              HasSubstr("mapmaker.epipolar_partner.max_axis_angle_deg"));
  EXPECT_THAT(load_error("mapmaker:\n  epipolar_partner: {min_baseline: -1}\n"),
              HasSubstr("epipolar_partner.min_baseline"));
  EXPECT_THAT(load_error("tracker:\n  good_found: 0\n"), HasSubstr("good_found"));
  EXPECT_THAT(load_error("tracker:\n  keyframe_min_frames_turning: 0\n"), HasSubstr("keyframe_min_frames_turning"));
  EXPECT_THAT(load_error("tracker:\n  keyframe_distance_after_turn: 2\n"), HasSubstr("keyframe_distance_after_turn"));
  EXPECT_THAT(load_error("mapmaker:\n  densify_initial_map_min_parallax_deg: -1\n"),
              HasSubstr("densify_initial_map_min_parallax_deg"));
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
  test::write_text(path, "moving_regions:\n  step: 0\n  sigma_cells: 1.5\n  min_density: 0.4\n");
  const SemanticsOptions o = load_semantics_options(path);
  EXPECT_EQ(o.moving_regions.step, 0);
  EXPECT_EQ(o.moving_regions.sigma_cells, 1.5);
  EXPECT_EQ(o.moving_regions.min_density, 0.4);
}

TEST(SemanticsOptions, ReadsClassLists) {
  test::TempDir dir;
  const auto path = dir / "semantics.yaml";
  test::write_text(path, "labels:\n  unreliable: {classes: [sky]}\n  moving: {classes: []}\n");
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
  EXPECT_THAT(semantics_error("labels: {unreliable: {classes: [car, bus]}}\n"),
              AllOf(HasSubstr("semantics.yaml"), HasSubstr("labels.unreliable.classes"), HasSubstr("bus")));
  EXPECT_THAT(semantics_error("labels: {moving: {min_confidence: 1.5}}\n"), HasSubstr("labels.moving.min_confidence"));
  EXPECT_THAT(semantics_error("class_prior_weight: -1\n"), HasSubstr("class_prior_weight"));
  EXPECT_THAT(semantics_error("class_prior: {car: 1}\n"), HasSubstr("class_prior.various"));
  EXPECT_THAT(semantics_error("class_prior: {various: 1, building: 1, car: 1, door: 1, pavement: 1, road: 1, sky: 1, "
                              "vegetation: 1, window: 0}\n"),
              HasSubstr("class_prior.window"));
  EXPECT_THAT(semantics_error("modell: x.fsmodel\n"), HasSubstr("modell"));
  EXPECT_THAT(semantics_error("labels: {unreliable_weight: 2}\n"), HasSubstr("labels.unreliable_weight"));
  EXPECT_THAT(semantics_error("labels: {verify_px: -1}\n"), HasSubstr("labels.verify_px"));
  EXPECT_THAT(semantics_error("grey_model: [a, b]\n"), HasSubstr("grey_model"));
  EXPECT_THAT(semantics_error("context_scale: 1\n"), HasSubstr("context_scale"));
  EXPECT_THAT(semantics_error("labels: {moving: {classes: [lorry]}}\n"),
              AllOf(HasSubstr("semantics.yaml"), HasSubstr("labels.moving.classes"), HasSubstr("lorry")));
  EXPECT_THAT(semantics_error("labels: {moving: {classes: car}}\n"), HasSubstr("labels.moving.classes"));
  EXPECT_THAT(semantics_error("moving_regions: {step: -1}\n"), HasSubstr("moving_regions.step"));
  EXPECT_THAT(semantics_error("moving_regions: {step: 2}\n"),
              AllOf(HasSubstr("moving_regions.step"), HasSubstr("0 (no regions) or 4 to 256 pixels")));
  EXPECT_THAT(semantics_error("moving_regions: {min_density: 0}\n"), HasSubstr("moving_regions.min_density"));
  EXPECT_THAT(semantics_error("moving_regions: {sigma_cells: 0}\n"), HasSubstr("moving_regions.sigma_cells"));
  EXPECT_THAT(semantics_error("moving_regions: {stepp: 8}\n"), HasSubstr("moving_regions.stepp"));
  // The flat keys of earlier files are unknown now, not silently ignored.
  EXPECT_THAT(semantics_error("unreliable_classes: [car]\n"), HasSubstr("unknown"));
}

}  // namespace
}  // namespace facadeslam
