#pragma once
// Reads back the labelled point cloud that point_cloud_writer.hpp writes
// (map.ply): binary little-endian PLY with exactly one vertex element of
//   x y z (float), red green blue (uchar), label (uchar), confidence (float)
// in this order, and the class table in `comment class <id> <name> <r> <g> <b>`
// header lines. Anything else (ASCII PLY, other properties, faces, a body
// shorter or longer than the header says, non-finite coordinates) is refused
// with an Error naming the file and what was expected: it is not a general
// PLY reader, only the replay's output read back (render-map, tests).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace facadeslam {

struct LabelledPoint {
  Eigen::Vector3f p_w;
  std::uint8_t r = 0, g = 0, b = 0;  // the class colour as written
  std::uint8_t label = 255;          // 255 = unlabelled
  float confidence = 0.f;
};

// One row of the header's class table.
struct PointCloudClass {
  int id = 0;
  std::string name;
  std::uint8_t r = 0, g = 0, b = 0;
};

struct LabelledPointCloud {
  std::vector<LabelledPoint> points;
  std::vector<PointCloudClass> classes;  // in header order; empty if the header has none
};

LabelledPointCloud read_labelled_point_cloud(const std::filesystem::path& ply_path);

}  // namespace facadeslam
