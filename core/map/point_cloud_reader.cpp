#include "core/map/point_cloud_reader.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/util/byte_stream.hpp"
#include "core/util/error.hpp"

namespace facadeslam {
// Named, so that the unity build's other files in this library cannot clash with these helpers.
namespace ply_reader {
namespace {

// Every complaint says what a map.ply is, so that a user who passed the
// wrong file sees at once what the command wanted.
constexpr const char* kExpected = " (expected the binary little-endian PLY that `facadeslam replay` writes as map.ply)";

// The properties of the vertex element, in file order.
constexpr std::pair<const char*, const char*> kProperties[] = {
    {"float", "x"},     {"float", "y"},    {"float", "z"},     {"uchar", "red"},
    {"uchar", "green"}, {"uchar", "blue"}, {"uchar", "label"}, {"float", "confidence"}};
constexpr std::size_t kVertexBytes = 3 * 4 + 4 * 1 + 4;
// Our header is about 700 bytes; a file without end_header this early is not ours.
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  fail_file(path, what + kExpected);
}

std::string read_all(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail(path, "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the file");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

PointCloudClass parse_class(const std::filesystem::path& path, const std::string& rest) {
  std::istringstream in(rest);
  PointCloudClass c;
  int r = -1, g = -1, b = -1;
  std::string extra;
  if (!(in >> c.id >> c.name >> r >> g >> b) || (in >> extra) || c.id < 0 || c.id > 255 || r < 0 || r > 255 || g < 0 ||
      g > 255 || b < 0 || b > 255)
    fail(path, "bad class line 'comment class " + rest + "': expected 'comment class <id 0-255> <name> <r> <g> <b>'");
  c.r = static_cast<std::uint8_t>(r);
  c.g = static_cast<std::uint8_t>(g);
  c.b = static_cast<std::uint8_t>(b);
  return c;
}

struct Header {
  std::size_t vertices = 0;
  std::size_t body_offset = 0;
  std::vector<PointCloudClass> classes;
};

Header parse_header(const std::filesystem::path& path, const std::string& data) {
  const std::size_t end = data.find("end_header\n");
  if (data.rfind("ply\n", 0) != 0) fail(path, "does not start with the line 'ply'");
  if (end == std::string::npos || end > kMaxHeaderBytes) fail(path, "no 'end_header' line in the first 64 KiB");

  Header header;
  header.body_offset = end + std::strlen("end_header\n");
  std::istringstream lines(data.substr(4, end - 4));
  std::string line;
  bool format_seen = false, vertex_seen = false;
  std::size_t property = 0;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "comment") {
      if (line.rfind("comment class ", 0) == 0) header.classes.push_back(parse_class(path, line.substr(14)));
    } else if (keyword == "format") {
      if (line != "format binary_little_endian 1.0") fail(path, "format line '" + line + "'");
      format_seen = true;
    } else if (keyword == "element") {
      std::string name;
      long long count = -1;
      if (vertex_seen || !(words >> name >> count) || name != "vertex" || count < 0)
        fail(path, "element line '" + line + "': expected one 'element vertex <count>' and no other element");
      header.vertices = static_cast<std::size_t>(count);
      vertex_seen = true;
    } else if (keyword == "property") {
      std::string type, name, extra;
      const bool ok = vertex_seen && property < std::size(kProperties) && (words >> type >> name) &&
                      !(words >> extra) && type == kProperties[property].first && name == kProperties[property].second;
      if (!ok)
        fail(path, "property line '" + line +
                       "': expected the vertex properties float x, y, z, uchar red, green, blue, label, float "
                       "confidence in this order");
      ++property;
    } else if (!keyword.empty() && keyword != "obj_info") {
      fail(path, "unknown header line '" + line + "'");
    }
  }
  if (!format_seen) fail(path, "no 'format binary_little_endian 1.0' line");
  if (!vertex_seen) fail(path, "no 'element vertex <count>' line");
  if (property != std::size(kProperties))
    fail(path, "the vertex element has " + std::to_string(property) + " properties, not 8");
  return header;
}

}  // namespace
}  // namespace ply_reader

LabelledPointCloud read_labelled_point_cloud(const std::filesystem::path& ply_path) {
  using namespace ply_reader;
  const std::string data = read_all(ply_path);
  Header header = parse_header(ply_path, data);

  const std::size_t body = data.size() - header.body_offset;
  if (header.vertices > body / kVertexBytes || body != header.vertices * kVertexBytes)
    fail(ply_path, "the header announces " + std::to_string(header.vertices) + " vertices of 20 bytes, but " +
                       std::to_string(body) + " bytes follow it");

  LabelledPointCloud cloud;
  cloud.classes = std::move(header.classes);
  cloud.points.resize(header.vertices);
  // The body's size was checked above: the reader cannot run short.
  ByteReader in(std::string_view(data).substr(header.body_offset), ply_path, "damaged PLY body");
  for (std::size_t i = 0; i < header.vertices; ++i) {
    LabelledPoint& p = cloud.points[i];
    for (int k = 0; k < 3; ++k) p.p_w[k] = in.get<float>("a vertex");
    p.r = in.get<std::uint8_t>("a vertex");
    p.g = in.get<std::uint8_t>("a vertex");
    p.b = in.get<std::uint8_t>("a vertex");
    p.label = in.get<std::uint8_t>("a vertex");
    p.confidence = in.get<float>("a vertex");
    if (!p.p_w.allFinite()) fail(ply_path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  return cloud;
}

}  // namespace facadeslam
