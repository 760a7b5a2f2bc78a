#include "core/map/map_io.hpp"

#include <fstream>
#include <functional>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/map/binary_stream.hpp"
#include "core/util/error.hpp"
#include "tests/support/small_map.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;

using ::testing::AllOf;
using ::testing::HasSubstr;

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_file(const std::filesystem::path& p, const std::string& data) { std::ofstream(p, std::ios::binary) << data; }

bool mats_equal(const cv::Mat& a, const cv::Mat& b) {
  if (a.type() != b.type() || a.size() != b.size()) return false;
  if (a.empty()) return true;
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  return cv::countNonZero(diff.reshape(1)) == 0;
}

void expect_identical(const Map& a, const Map& b) {
  const auto ka = a.keyframes(), kb = b.keyframes();
  ASSERT_EQ(ka.size(), kb.size());
  for (std::size_t i = 0; i < ka.size(); ++i) {
    EXPECT_EQ(ka[i]->id(), kb[i]->id());
    EXPECT_EQ(ka[i]->frame_index(), kb[i]->frame_index());
    EXPECT_EQ(ka[i]->timestamp(), kb[i]->timestamp());
    EXPECT_EQ(ka[i]->T_c_w().matrix(), kb[i]->T_c_w().matrix());
    EXPECT_EQ(ka[i]->mean_depth(), kb[i]->mean_depth());
    EXPECT_TRUE(mats_equal(ka[i]->colour(), kb[i]->colour()));
    EXPECT_TRUE(mats_equal(ka[i]->small_blurred(), kb[i]->small_blurred()));
    for (int l = 0; l < kPyramidLevels; ++l) {
      EXPECT_TRUE(mats_equal(ka[i]->pyramid()->level(l).image, kb[i]->pyramid()->level(l).image));
      const auto& ca = ka[i]->pyramid()->level(l).corners;
      const auto& cb = kb[i]->pyramid()->level(l).corners;
      ASSERT_EQ(ca.size(), cb.size());
      for (std::size_t c = 0; c < ca.size(); ++c) {
        EXPECT_EQ(ca[c].x, cb[c].x);
        EXPECT_EQ(ca[c].score, cb[c].score);
      }
    }
    ASSERT_EQ(ka[i]->measurements().size(), kb[i]->measurements().size());
    for (const auto& [id, m] : ka[i]->measurements()) {
      const auto& n = kb[i]->measurements().at(id);
      EXPECT_EQ(m.level, n.level);
      EXPECT_EQ(m.pixel, n.pixel);
      EXPECT_EQ(m.from_source, n.from_source);
    }
  }
  const auto pa = a.points(), pb = b.points();
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i) {
    EXPECT_EQ(pa[i]->id(), pb[i]->id());
    EXPECT_EQ(pa[i]->geometry().p_w, pb[i]->geometry().p_w);
    EXPECT_EQ(pa[i]->geometry().right_w, pb[i]->geometry().right_w);
    EXPECT_EQ(pa[i]->geometry().normal_w, pb[i]->geometry().normal_w);
    EXPECT_EQ(pa[i]->source().keyframe_id, pb[i]->source().keyframe_id);
    EXPECT_EQ(pa[i]->source().level, pb[i]->source().level);
    EXPECT_EQ(pa[i]->source().pixel_level0, pb[i]->source().pixel_level0);
    EXPECT_EQ(pa[i]->label(), pb[i]->label());
    EXPECT_EQ(pa[i]->votes(), pb[i]->votes());
    EXPECT_EQ(pa[i]->region_views(), pb[i]->region_views());
    EXPECT_EQ(pa[i]->in_moving_region(), pb[i]->in_moving_region());
    EXPECT_EQ(pa[i]->is_bad(), pb[i]->is_bad());
  }
  EXPECT_EQ(a.next_point_id_value(), b.next_point_id_value());
  EXPECT_EQ(a.next_keyframe_id_value(), b.next_keyframe_id_value());
}

class MapIo : public ::testing::Test {
 protected:
  void SetUp() override {
    test::build_test_map(map, 25);
    const auto bad = map.points()[4];
    map.update([&](MapEditor& edit) { edit.mark_bad(*bad); });
    save_map(file, map, camera);
  }
  test::TempDir dir;
  std::filesystem::path file = dir / "map.fslmap";
  Camera camera = test::small_test_camera();
  Map map;
};

TEST_F(MapIo, RoundTripGivesAnIdenticalMap) {
  Map loaded;
  const Camera c = load_map(file, loaded, &camera);
  EXPECT_TRUE(same_camera(c, camera));
  expect_identical(map, loaded);
  // Points share their source keyframe's pyramid, as in the original.
  EXPECT_EQ(loaded.points()[0]->source().pyramid, loaded.keyframe(0)->pyramid());
}

TEST_F(MapIo, SavingTwiceGivesTheSameBytes) {
  save_map(dir / "again.fslmap", map, camera);
  EXPECT_EQ(read_file(file), read_file(dir / "again.fslmap"));
}

TEST_F(MapIo, TruncatedFileIsRejected) {
  const std::string data = read_file(file);
  write_file(dir / "cut.fslmap", data.substr(0, data.size() / 2));
  Map loaded;
  EXPECT_THAT(error_of([&] { load_map(dir / "cut.fslmap", loaded); }),
              AllOf(HasSubstr("cut.fslmap"), HasSubstr("corrupt")));
  EXPECT_EQ(loaded.point_count(), 0u) << "nothing half-loaded";
}

TEST_F(MapIo, FlippedByteIsRejected) {
  std::string data = read_file(file);
  data[data.size() / 3] ^= 0x40;
  write_file(dir / "flip.fslmap", data);
  Map loaded;
  EXPECT_THAT(error_of([&] { load_map(dir / "flip.fslmap", loaded); }), HasSubstr("checksum"));
}

TEST_F(MapIo, WrongVersionIsRejected) {
  std::string data = read_file(file);
  data[8] = 99;  // the u32 after the 8-byte magic
  write_file(dir / "v99.fslmap", data);
  Map loaded;
  EXPECT_THAT(error_of([&] { load_map(dir / "v99.fslmap", loaded); }),
              AllOf(HasSubstr("v99.fslmap"), HasSubstr("version 99"), HasSubstr("reads versions 2 to 4")));
}

// A point record: id, source keyframe, level, pixel, geometry; then its
// votes (9 floats), its region views (2 x u32, version 4) and its flag byte.
// Point records are the file's last bytes before the checksum.
constexpr std::size_t kPointHead = 8 + 8 + 4 + 2 * 8 + 12 * 8, kVotes = sizeof(ClassVotes), kRegionViews = 8;
constexpr std::size_t kPointRecord = kPointHead + kVotes + kRegionViews + 1;

// Rewrites a version 4 file as version 3 (no region views) or 2 (label and
// confidence instead of the votes) did.
std::string as_older_version(const std::string& v4, const std::vector<std::shared_ptr<MapPoint>>& points, int version) {
  const std::size_t body = v4.size() - 8, first = body - points.size() * kPointRecord;
  std::string old = v4.substr(0, first);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t at = first + i * kPointRecord;
    old += v4.substr(at, kPointHead);
    if (version == 2) {
      const SemanticLabel label = points[i]->label();
      old.push_back(static_cast<char>(label.label));
      old.append(reinterpret_cast<const char*>(&label.confidence), sizeof(float));
    } else {
      old += v4.substr(at + kPointHead, kVotes);
    }
    old.push_back(v4[at + kPointHead + kVotes + kRegionViews]);
  }
  old[8] = static_cast<char>(version);
  return test::with_map_checksum(old);
}

// A hostile file with a valid checksum (issue 20): the loader checks what
// the data means, naming the file and the field. Point records are the
// file's last bytes before the checksum (see kPointRecord).

TEST_F(MapIo, HostileValuesWithAValidChecksumAreRejectedNamingTheField) {
  constexpr std::size_t kRecord = kPointRecord;
  const std::string good = read_file(file);
  const std::size_t body = good.size() - 8, first = body - map.point_count() * kRecord;
  const auto load_edited = [&](const std::string& name, const std::function<void(std::string&)>& edit) {
    std::string data = good.substr(0, body);
    edit(data);
    write_file(dir / name, test::with_map_checksum(data));
    Map loaded;
    return error_of([&] { load_map(dir / name, loaded); });
  };
  // Point 1 takes point 0's id.
  EXPECT_THAT(load_edited("dup.fslmap", [&](std::string& d) { d.replace(first + kRecord, 8, d.substr(first, 8)); }),
              AllOf(HasSubstr("dup.fslmap"), HasSubstr("appears twice")));
  // Point 0's position is NaN.
  EXPECT_THAT(load_edited("nan.fslmap",
                          [&](std::string& d) {
                            const double nan = std::numeric_limits<double>::quiet_NaN();
                            d.replace(first + 36, 8, std::string(reinterpret_cast<const char*>(&nan), 8));
                          }),
              AllOf(HasSubstr("nan.fslmap"), HasSubstr("point geometry is not a finite number")));
  // Point 0's source level 99.
  EXPECT_THAT(load_edited("level.fslmap",
                          [&](std::string& d) {
                            const std::int32_t level = 99;
                            d.replace(first + 16, 4, std::string(reinterpret_cast<const char*>(&level), 4));
                          }),
              AllOf(HasSubstr("level.fslmap"), HasSubstr("level out of range")));
}

// Found by fuzz_map_file: an empty pyramid level got as far as the
// relocaliser's blur. Keyframe images must be of the camera's size.
TEST_F(MapIo, KeyframeImagesOfAnotherSizeThanTheCameraAreRejected) {
  Map other;
  test::build_test_map(other, 4, Camera(128, 96, PinholeRadTan{120, 120, 63.5, 47.5, 0, 0, 0, 0, 0}));
  save_map(dir / "sizes.fslmap", other, camera);  // under the fixture's 160x120 camera
  Map loaded;
  EXPECT_THAT(error_of([&] { load_map(dir / "sizes.fslmap", loaded); }),
              AllOf(HasSubstr("sizes.fslmap"), HasSubstr("pyramid level is 128x96, expected 160x120")));
}

TEST_F(MapIo, Version3MapsLoadWithTheirVotesAndNoRegionViews) {
  write_file(dir / "v3.fslmap", as_older_version(read_file(file), map.points(), 3));
  Map loaded;
  load_map(dir / "v3.fslmap", loaded, &camera);
  const auto pa = map.points(), pb = loaded.points();
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i) {
    EXPECT_EQ(pa[i]->votes(), pb[i]->votes());
    EXPECT_EQ(pb[i]->region_views(), MapPoint::RegionViews{});
    EXPECT_FALSE(pb[i]->in_moving_region());
  }
}

TEST_F(MapIo, MoreRegionViewsInARegionThanViewsAreRejected) {
  std::string data = read_file(file).substr(0, read_file(file).size() - 8);
  const std::size_t first = data.size() - map.point_count() * kPointRecord;
  const std::uint32_t views = 1, in_region = 2;
  data.replace(first + kPointHead + kVotes, 4, std::string(reinterpret_cast<const char*>(&views), 4));
  data.replace(first + kPointHead + kVotes + 4, 4, std::string(reinterpret_cast<const char*>(&in_region), 4));
  write_file(dir / "region.fslmap", test::with_map_checksum(data));
  Map loaded;
  EXPECT_THAT(error_of([&] { load_map(dir / "region.fslmap", loaded); }),
              AllOf(HasSubstr("region.fslmap"), HasSubstr("more in a region than views")));
}

TEST_F(MapIo, Version2MapsLoadWithTheirLabels) {
  write_file(dir / "v2.fslmap", as_older_version(read_file(file), map.points(), 2));
  Map loaded;
  load_map(dir / "v2.fslmap", loaded, &camera);
  const auto pa = map.points(), pb = loaded.points();
  ASSERT_EQ(pa.size(), pb.size());
  std::size_t labelled = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    EXPECT_EQ(pa[i]->label().label, pb[i]->label().label);
    EXPECT_NEAR(pa[i]->label().confidence, pb[i]->label().confidence, 1e-6);
    labelled += pa[i]->label().label != kUnlabelled;
  }
  EXPECT_GT(labelled, 5u);
}

TEST_F(MapIo, NotAMapFile) {
  write_file(dir / "text.fslmap", "hello, this is not a map at all");
  Map loaded;
  EXPECT_THAT(error_of([&] { load_map(dir / "text.fslmap", loaded); }), HasSubstr("not a facadeslam map"));
  EXPECT_THAT(error_of([&] { load_map(dir / "absent.fslmap", loaded); }),
              AllOf(HasSubstr("absent.fslmap"), HasSubstr("cannot open")));
}

TEST_F(MapIo, MapFromAnotherCameraIsRejected) {
  const Camera other(160, 120, PinholeRadTan{180, 180, 79.5, 59.5, 0, 0, 0, 0, 0});
  Map loaded;
  EXPECT_THAT(error_of([&] { load_map(file, loaded, &other); }),
              AllOf(HasSubstr("map.fslmap"), HasSubstr("fx=150"), HasSubstr("fx=180")));
  const Camera bigger(320, 240, PinholeRadTan{150, 150, 79.5, 59.5, 0.01, 0, 0, 0, 0});
  EXPECT_THAT(error_of([&] { load_map(file, loaded, &bigger); }), HasSubstr("320x240"));
}

// The caller's bug, not the user's: FACADESLAM_ASSERT.
TEST_F(MapIo, LoadingIntoANonEmptyMapIsAnInternalError) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(load_map(file, map), "internal error.*loaded into an empty one");
}

}  // namespace
}  // namespace facadeslam
