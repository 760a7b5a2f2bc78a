#pragma once
// A small scene file for the synth tests, built from the photos committed in
// data/demo/photos (so the tests run without ../shared/data).
#include <filesystem>
#include <string>

namespace facadeslam::test {

// The YAML text of a valid scene: two facades, a short street, 160x120
// frames at 10 fps, `frames` frames of a 1 s walk. Paths are absolute.
std::string small_scene_yaml(int frames = 4);

// Writes `yaml` to dir/scene.yaml and returns the path.
std::filesystem::path write_scene(const std::filesystem::path& dir, const std::string& yaml);

// `text` with the first occurrence of `from` replaced by `to`; fails the
// test (ADD_FAILURE) when `from` is absent, so that a stale mutation cannot
// silently test the unmodified scene.
std::string replace_once(std::string text, const std::string& from, const std::string& to);

inline constexpr const char* kFacadePhotoA = "spatial_envelope_256x256_static_8outdoorcategories__insidecity_a223049";
inline constexpr const char* kFacadePhotoB = "static_outdoor_street_city_cambridge_uk__IMG_8830";
inline constexpr const char* kCarPhoto = "static_street_statacenter_cambridge_outdoor_2005__img_0257";
inline constexpr const char* kTreePhoto =
    "static_submitted_saxena_chung_ng_nips2005_learningdepth__img-060705-17.10.14-p-142t000";

}  // namespace facadeslam::test
