#pragma once
// Geometry the renderer draws: textured triangle meshes in world coordinates.
//
// Texture coordinates: uv = (0, 0) is the top-left CORNER of the texture's
// top-left texel and uv = (1, 1) the bottom-right corner of the last texel,
// so texel (i, j) (column i, row j of the cv::Mat uploaded) covers
// [i/W, (i+1)/W) x [j/H, (j+1)/H) and its centre is at ((i + 0.5)/W,
// (j + 0.5)/H). Colour is filtered (trilinear, anisotropic); labels are
// looked up at the texel containing uv (nearest), never blended.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace facadeslam::render {

// A texture uploaded to a Renderer (an index into its list).
struct TextureId {
  int index = -1;
  bool valid() const { return index >= 0; }
};

// A label texel with this value is a hole: the surface is not there at all
// (no colour, label or depth), e.g. around a car cut out of a photo.
inline constexpr std::uint8_t kTransparentLabel = 255;

struct MeshVertex {
  Eigen::Vector3d p_w;  // world position, metres
  Eigen::Vector2d uv;   // texture coordinates (see above)
};

struct Mesh {
  std::vector<MeshVertex> vertices;
  std::vector<std::uint32_t> indices;  // triangles: three vertex indices each
  TextureId colour;                    // required: a colour texture
  TextureId labels;                    // optional label texture (class id per texel)
  std::uint8_t label = 0;              // the class everywhere when `labels` is not valid
};

// A flat rectangle showing a whole texture: `top_left` is the world position
// of uv (0, 0); `right` and `down` are the full edges to uv (1, 0) and
// (0, 1). The point top_left + a right + b down has uv (a, b). It is split
// into `columns` x `rows` cells so that it can be bent afterwards by moving
// vertices (swaying vegetation); vertex (c, r) is at index r (columns + 1) + c.
Mesh make_textured_quad(const Eigen::Vector3d& top_left, const Eigen::Vector3d& right, const Eigen::Vector3d& down,
                        TextureId colour, TextureId labels, std::uint8_t label = 0, int columns = 1, int rows = 1);

}  // namespace facadeslam::render
