#include "render/mesh.hpp"

#include "core/util/error.hpp"

namespace facadeslam::render {

Mesh make_textured_quad(const Eigen::Vector3d& top_left, const Eigen::Vector3d& right, const Eigen::Vector3d& down,
                        TextureId colour, TextureId labels, std::uint8_t label, int columns, int rows) {
  if (columns < 1 || rows < 1) throw Error("render: a quad needs at least one cell in each direction");
  Mesh mesh;
  mesh.colour = colour;
  mesh.labels = labels;
  mesh.label = label;
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c <= columns; ++c) {
      const double a = static_cast<double>(c) / columns, b = static_cast<double>(r) / rows;
      mesh.vertices.push_back({top_left + a * right + b * down, Eigen::Vector2d(a, b)});
    }
  const auto index = [columns](int c, int r) { return static_cast<std::uint32_t>(r * (columns + 1) + c); };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      mesh.indices.insert(mesh.indices.end(), {index(c, r), index(c + 1, r), index(c + 1, r + 1)});
      mesh.indices.insert(mesh.indices.end(), {index(c, r), index(c + 1, r + 1), index(c, r + 1)});
    }
  return mesh;
}

}  // namespace facadeslam::render
