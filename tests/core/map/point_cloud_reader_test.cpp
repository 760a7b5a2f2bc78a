// map.ply read back: what the writer writes comes back bit for bit, and
// files that are not exactly our format are refused with one message that
// names the file and what was wrong.
#include "core/map/point_cloud_reader.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/map/point_cloud_writer.hpp"
#include "core/map/semantic_classes.hpp"
#include "tests/support/small_map.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;
using ::testing::AllOf;
using ::testing::HasSubstr;

void write_bytes(const std::filesystem::path& p, const std::string& data) {
  std::ofstream(p, std::ios::binary) << data;
}

constexpr const char* kProperties =
    "property float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
    "property uchar blue\nproperty uchar label\nproperty float confidence\nend_header\n";

std::string header(int vertices, const std::string& extra = "") {
  return "ply\nformat binary_little_endian 1.0\n" + extra + "element vertex " + std::to_string(vertices) + "\n" +
         kProperties;
}

std::string vertex(float x, float y, float z, std::uint8_t label, float confidence) {
  std::string out(20, '\0');
  const float xyz[] = {x, y, z};
  std::memcpy(out.data(), xyz, 12);
  const SemanticClass& c = semantic_class(label);
  out[12] = static_cast<char>(c.r);
  out[13] = static_cast<char>(c.g);
  out[14] = static_cast<char>(c.b);
  out[15] = static_cast<char>(label);
  std::memcpy(out.data() + 16, &confidence, 4);
  return out;
}

TEST(PointCloudReader, ReadsBackWhatTheWriterWrote) {
  Map map;
  test::build_test_map(map, 25);
  test::TempDir dir;
  const auto path = dir / "map.ply";
  const std::size_t written = write_labelled_point_cloud(path, map);

  const LabelledPointCloud cloud = read_labelled_point_cloud(path);
  const auto points = map.snapshot_points();
  ASSERT_EQ(cloud.points.size(), written);
  ASSERT_EQ(cloud.points.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const LabelledPoint& p = cloud.points[i];
    EXPECT_EQ(p.p_w, points[i].geometry.p_w.cast<float>()) << i;
    const SemanticLabel label = points[i].point->label();
    EXPECT_EQ(p.label, label.label) << i;
    EXPECT_EQ(p.confidence, label.confidence) << i;
    const SemanticClass& c = semantic_class(label.label);
    EXPECT_EQ(std::tie(p.r, p.g, p.b), std::tie(c.r, c.g, c.b)) << i;
  }
  // The class table of the header: our nine classes, then "unlabelled".
  ASSERT_EQ(cloud.classes.size(), kSemanticClasses.size() + 1);
  EXPECT_EQ(cloud.classes[1].name, "building");
  EXPECT_EQ(std::tie(cloud.classes[1].r, cloud.classes[1].g, cloud.classes[1].b),
            std::tie(kSemanticClasses[1].r, kSemanticClasses[1].g, kSemanticClasses[1].b));
  EXPECT_EQ(cloud.classes.back().id, 255);
  EXPECT_EQ(cloud.classes.back().name, "unlabelled");
}

TEST(PointCloudReader, ReadsAnEmptyCloud) {
  test::TempDir dir;
  write_bytes(dir / "empty.ply", header(0));
  EXPECT_TRUE(read_labelled_point_cloud(dir / "empty.ply").points.empty());
}

TEST(PointCloudReader, ReadsHandWrittenVertices) {
  test::TempDir dir;
  write_bytes(dir / "two.ply", header(2, "comment class 1 building 128 0 0\n") + vertex(1.5f, -2.f, 3.25f, 1, 0.75f) +
                                   vertex(0.f, 0.f, -1.f, 255, 0.f));
  const LabelledPointCloud cloud = read_labelled_point_cloud(dir / "two.ply");
  ASSERT_EQ(cloud.points.size(), 2u);
  EXPECT_EQ(cloud.points[0].p_w, Eigen::Vector3f(1.5f, -2.f, 3.25f));
  EXPECT_EQ(cloud.points[0].label, 1);
  EXPECT_EQ(cloud.points[0].r, 128);
  EXPECT_EQ(cloud.points[0].confidence, 0.75f);
  EXPECT_EQ(cloud.points[1].label, 255);
  EXPECT_EQ(cloud.points[1].r, 200);
  ASSERT_EQ(cloud.classes.size(), 1u);
  EXPECT_EQ(cloud.classes[0].name, "building");
}

struct BadPly {
  const char* name;
  std::string bytes;
  const char* message;
};

class PointCloudReaderRejects : public ::testing::TestWithParam<BadPly> {};

TEST_P(PointCloudReaderRejects, WithOneLineNamingTheFile) {
  test::TempDir dir;
  const auto path = dir / "map.ply";
  write_bytes(path, GetParam().bytes);
  const std::string message = error_of([&] { read_labelled_point_cloud(path); });
  EXPECT_THAT(message, AllOf(HasSubstr(path.string() + ": "), HasSubstr(GetParam().message),
                             HasSubstr("expected the binary little-endian PLY that `facadeslam replay` writes")));
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

const std::string kOneVertex = vertex(1.f, 2.f, 3.f, 4, 0.5f);

INSTANTIATE_TEST_SUITE_P(
    BadFiles, PointCloudReaderRejects,
    ::testing::Values(
        BadPly{"Empty", "", "does not start with the line 'ply'"},
        BadPly{"NotAPly", "P6\n2 2\n255\n", "does not start with the line 'ply'"},
        BadPly{"NoEndHeader", "ply\nformat binary_little_endian 1.0\nelement vertex 1\n", "no 'end_header' line"},
        BadPly{"Ascii", "ply\nformat ascii 1.0\nelement vertex 1\n" + std::string(kProperties) + "1 2 3 0 0 0 0 0\n",
               "format line 'format ascii 1.0'"},
        BadPly{"BigEndian",
               "ply\nformat binary_big_endian 1.0\nelement vertex 1\n" + std::string(kProperties) + kOneVertex,
               "format line 'format binary_big_endian 1.0'"},
        BadPly{"NoFormat", "ply\nelement vertex 1\n" + std::string(kProperties) + kOneVertex,
               "no 'format binary_little_endian 1.0' line"},
        BadPly{"DoublePositions",
               "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty double x\nend_header\n",
               "property line 'property double x'"},
        BadPly{"MissingProperties",
               "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
               "property float z\nend_header\n" +
                   std::string(12, '\0'),
               "the vertex element has 3 properties, not 8"},
        BadPly{"Faces", header(1).substr(0, header(1).size() - 11) + "element face 1\nend_header\n" + kOneVertex,
               "element line 'element face 1'"},
        BadPly{"UnknownLine", "ply\nformat binary_little_endian 1.0\nvertices 3\nend_header\n",
               "unknown header line 'vertices 3'"},
        BadPly{"BadClass", header(1, "comment class 1 building red 0 0\n") + kOneVertex,
               "bad class line 'comment class 1 building red 0 0'"},
        BadPly{"Truncated", header(2) + kOneVertex + kOneVertex.substr(0, 7),
               "the header announces 2 vertices of 20 bytes, but 27 bytes follow it"},
        BadPly{"TrailingBytes", header(1) + kOneVertex + "xx",
               "the header announces 1 vertices of 20 bytes, but 22 bytes follow it"},
        BadPly{"HugeCount", header(2000000000) + kOneVertex,
               "the header announces 2000000000 vertices of 20 bytes, but 20 bytes follow it"},
        BadPly{"NotFinite", header(2) + kOneVertex + vertex(1.f, std::numeric_limits<float>::quiet_NaN(), 3.f, 1, 0.5f),
               "vertex 1 has a non-finite coordinate"}),
    [](const ::testing::TestParamInfo<BadPly>& info) { return std::string(info.param.name); });

TEST(PointCloudReader, RejectsAMissingFile) {
  test::TempDir dir;
  EXPECT_THAT(error_of([&] { read_labelled_point_cloud(dir / "none.ply"); }),
              AllOf(HasSubstr("none.ply: no such file"), HasSubstr("map.ply")));
}

}  // namespace
}  // namespace facadeslam
