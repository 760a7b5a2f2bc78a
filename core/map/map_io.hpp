#pragma once
// Map save/load in a versioned little-endian binary format:
//   magic "FSLAMMAP", u32 format version, camera (model, size, parameters),
//   id counters, keyframes (frame index, timestamp, pose, depth stats,
//   pyramid levels with their corners, colour image, measurements), points
//   (source, geometry, label votes, moving-region views, flags), and a
//   trailing FNV-1a checksum. The small blurry images are rebuilt from the
//   pyramids on load.
// Loading checks the magic, the version, the checksum and that the map was
// made with the camera of the current run; each failure is an Error naming
// the file and what was expected.
//
// Saving reads the whole map under its shared lock (Map::read), so it sees
// one consistent state even while the map maker runs.
#include <filesystem>

#include "core/camera/camera.hpp"
#include "core/map/map.hpp"

namespace facadeslam {

// 2: frame index added, small blurry image rebuilt; 3: per-class label votes
// instead of label + confidence (version 2 files still load, see map_io.cpp);
// 4: each point's moving-region views (MapPoint::RegionViews; older files
// load with none).
inline constexpr std::uint32_t kMapFormatVersion = 4;
inline constexpr std::uint32_t kOldestMapFormatVersion = 2;

void save_map(const std::filesystem::path& path, const Map& map, const Camera& camera);

// Loads into `map` (which must be empty). With `expected_camera`, a map made
// with another camera (model, size or parameters) is rejected.
Camera load_map(const std::filesystem::path& path, Map& map, const Camera* expected_camera = nullptr);

// "pinhole 640x480 fx=500 fy=500 cx=319.5 cy=239.5 ..." for messages.
std::string describe_camera(const Camera& camera);
bool same_camera(const Camera& a, const Camera& b);

}  // namespace facadeslam
