#include "core/map/point_cloud_writer.hpp"

#include <map>
#include <sstream>

#include "core/map/semantic_classes.hpp"
#include "core/util/atomic_write.hpp"
#include "core/util/byte_stream.hpp"
#include "core/util/json.hpp"

namespace facadeslam {

std::size_t write_labelled_point_cloud(const std::filesystem::path& ply_path, const Map& map) {
  struct Vertex {
    Eigen::Vector3f p;
    SemanticLabel label;
  };
  std::vector<Vertex> vertices;
  for (const PointSnapshot& p : map.snapshot_points())
    vertices.push_back({p.geometry.p_w.cast<float>(), p.point->label()});

  std::ostringstream header;
  header << "ply\nformat binary_little_endian 1.0\ncomment facadeslam labelled map points\n";
  for (const auto& c : kSemanticClasses)
    header << "comment class " << int(c.id) << ' ' << c.name << ' ' << int(c.r) << ' ' << int(c.g) << ' ' << int(c.b)
           << '\n';
  header << "comment class " << int(kUnlabelledClass.id) << ' ' << kUnlabelledClass.name << ' '
         << int(kUnlabelledClass.r) << ' ' << int(kUnlabelledClass.g) << ' ' << int(kUnlabelledClass.b) << '\n';
  header << "element vertex " << vertices.size() << '\n'
         << "property float x\nproperty float y\nproperty float z\n"
         << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
         << "property uchar label\nproperty float confidence\nend_header\n";

  ByteWriter data;
  const std::string header_text = header.str();
  data.put_bytes(header_text.data(), header_text.size());
  std::map<std::uint8_t, std::size_t> counts;
  for (const auto& v : vertices) {
    const SemanticClass& c = semantic_class(v.label.label);
    for (int i = 0; i < 3; ++i) data.put(v.p[i]);
    data.put(c.r);
    data.put(c.g);
    data.put(c.b);
    data.put(v.label.label);
    data.put(v.label.confidence);
    ++counts[c.id];
  }
  write_text_atomically(ply_path, data.bytes());

  Json classes = Json::array();
  auto add_class = [&](const SemanticClass& c) {
    Json entry = Json::object();
    entry["id"] = static_cast<int>(c.id);
    entry["name"] = std::string(c.name);
    entry["colour_rgb"] = Json::array({int(c.r), int(c.g), int(c.b)});
    entry["points"] = counts.count(c.id) ? counts[c.id] : std::size_t{0};
    classes.push_back(entry);
  };
  for (const auto& c : kSemanticClasses) add_class(c);
  add_class(kUnlabelledClass);
  Json sidecar = Json::object();
  sidecar["point_cloud"] = ply_path.filename().string();
  sidecar["points"] = vertices.size();
  sidecar["classes"] = classes;
  std::filesystem::path json_path = ply_path;
  json_path.replace_extension(".classes.json");
  write_json(json_path, sidecar);
  return vertices.size();
}

}  // namespace facadeslam
