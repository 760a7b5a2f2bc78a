#pragma once
// A small but complete map (two keyframes with images, measured points with
// labels) for the map and map I/O tests, and the map fuzzer's seed.
#include <memory>
#include <string>

#include "core/camera/camera.hpp"
#include "core/map/map.hpp"

namespace facadeslam::test {

Camera small_test_camera();
// Fills `map` with 2 keyframes and `n_points` points measured in both. The
// points sit at pixels (20 + i, 30 + i): a camera smaller than the default
// needs fewer points.
void build_test_map(Map& map, int n_points = 20, const Camera& camera = small_test_camera());

// A map file's body with its trailing checksum appended, as save_map writes
// it: hostile values behind a valid checksum (the map I/O tests, the fuzzer).
std::string with_map_checksum(std::string body);

}  // namespace facadeslam::test
