#pragma once
// A small but complete map (two keyframes with images, measured points with
// labels) for the map and map I/O tests.
#include <memory>

#include "core/camera/camera.hpp"
#include "core/map/map.hpp"

namespace facadeslam::test {

Camera small_test_camera();
// Fills `map` with 2 keyframes and `n_points` points measured in both.
void build_test_map(Map& map, int n_points = 20);

}  // namespace facadeslam::test
