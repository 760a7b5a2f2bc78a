#pragma once
// The labelled point cloud: binary little-endian PLY that Open3D,
// CloudCompare and MeshLab read, with per vertex
//   x y z (float), red green blue (uchar, the class colour), label (uchar),
//   confidence (float);
// the class table (id, name, colour) in the header comments, and the same
// table with counts in a JSON sidecar (<name>.classes.json). Both atomic.
#include <filesystem>

#include "core/map/map.hpp"

namespace facadeslam {

// Writes the map's good points; returns how many were written.
std::size_t write_labelled_point_cloud(const std::filesystem::path& ply_path, const Map& map);

}  // namespace facadeslam
