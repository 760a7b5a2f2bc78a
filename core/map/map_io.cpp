#include "core/map/map_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <fstream>
#include <tuple>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "core/lie/manifolds.hpp"
#include "core/map/binary_stream.hpp"
#include "core/util/atomic_write.hpp"
#include "core/util/error.hpp"
#include "core/util/assert.hpp"

namespace facadeslam {
namespace {

constexpr char kMagic[8] = {'F', 'S', 'L', 'A', 'M', 'M', 'A', 'P'};

std::vector<double> camera_parameters(const Camera& camera) {
  return camera.visit([](const auto& m) -> std::vector<double> {
    using M = std::decay_t<decltype(m)>;
    if constexpr (std::is_same_v<M, PinholeRadTan>)
      return {m.fx, m.fy, m.cx, m.cy, m.k1, m.k2, m.p1, m.p2, m.k3};
    else
      return {m.fx, m.fy, m.cx, m.cy, m.w};
  });
}

Camera make_camera(const std::string& model, int width, int height, const std::vector<double>& p, ByteReader& in) {
  if (model == "pinhole" && p.size() == 9)
    return Camera(width, height, PinholeRadTan{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8]});
  if (model == "atan" && p.size() == 5) return Camera(width, height, AtanCamera{p[0], p[1], p[2], p[3], p[4]});
  in.fail("unknown camera model '" + model + "' with " + std::to_string(p.size()) + " parameters");
}

void put_pose(ByteWriter& out, const SE3d& T) {
  double params[kSe3ParamSize];
  se3_to_params(T, params);
  for (double v : params) out.put(v);
}

// A double that must be finite (NaN poses and infinite points would load
// and fail far from the file otherwise).
double get_finite(ByteReader& in, const char* what) {
  const double v = in.get<double>(what);
  if (!std::isfinite(v)) in.fail(std::string(what) + " is not a finite number");
  return v;
}

SE3d get_pose(ByteReader& in) {
  double params[kSe3ParamSize];
  for (double& v : params) v = get_finite(in, "keyframe pose");
  return se3_from_params(params);
}

void put_vec(ByteWriter& out, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) out.put(v[i]);
}

Eigen::Vector3d get_vec(ByteReader& in, const char* what) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = get_finite(in, what);
  return v;
}

ClassVotes get_votes(ByteReader& in) {
  ClassVotes votes{};
  for (float& v : votes) {
    v = in.get<float>("point votes");
    if (!std::isfinite(v) || v < 0.f) in.fail("point votes must be finite and non-negative");
  }
  return votes;
}

MapPoint::RegionViews get_region_views(ByteReader& in) {
  MapPoint::RegionViews views;
  views.views = in.get<std::uint32_t>("point region views");
  views.in_region = in.get<std::uint32_t>("point region views");
  if (views.in_region > views.views) in.fail("point region views: more in a region than views");
  return views;
}

// Version 2 kept only the label and its share. The winner keeps its share and
// the rest is spread evenly over the other classes: the label and confidence
// come out as they were (a winner's share is always above 1/9) and new votes
// fuse with them as with one earlier observation.
ClassVotes votes_from_version2_label(ByteReader& in) {
  const auto label = in.get<std::uint8_t>("point label");
  const auto confidence = in.get<float>("point label");
  ClassVotes votes{};
  if (label == kUnlabelled) return votes;
  if (label >= votes.size() || !(confidence > 0.f && confidence <= 1.f)) in.fail("point label out of range");
  const float rest = (1.f - confidence) / static_cast<float>(votes.size() - 1);
  for (std::size_t c = 0; c < votes.size(); ++c) votes[c] = c == label ? confidence : rest;
  return votes;
}

void put_pyramid(ByteWriter& out, const ImagePyramid& pyramid) {
  for (int l = 0; l < kPyramidLevels; ++l) {
    const auto& level = pyramid.level(l);
    put_mat(out, level.image);
    out.put(static_cast<std::uint32_t>(level.corners.size()));
    for (const auto& c : level.corners) {
      out.put(static_cast<std::int32_t>(c.x));
      out.put(static_cast<std::int32_t>(c.y));
      out.put(c.score);
    }
  }
}

// The levels must be what ImagePyramid would have made from a camera image:
// level 0 the camera's size, each next level half the one before (rounded
// down), corners inside their level. Everything that reads a keyframe
// (relocaliser, patch search, the semantic worker) relies on it.
std::shared_ptr<const ImagePyramid> get_pyramid(ByteReader& in, const Camera& camera) {
  std::array<PyramidLevel, kPyramidLevels> levels;
  cv::Size expected(camera.width(), camera.height());
  for (auto& level : levels) {
    level.image = get_mat(in, "pyramid image");
    if (level.image.type() != CV_8UC1) in.fail("pyramid level is not an 8-bit grey image");
    if (level.image.size() != expected)
      in.fail("a pyramid level is " + std::to_string(level.image.cols) + "x" + std::to_string(level.image.rows) +
              ", expected " + std::to_string(expected.width) + "x" + std::to_string(expected.height));
    level.corners.resize(in.count("corner count", 12));
    for (auto& c : level.corners) {
      c.x = in.get<std::int32_t>("corner");
      c.y = in.get<std::int32_t>("corner");
      c.score = in.get<float>("corner");
      if (c.x < 0 || c.y < 0 || c.x >= expected.width || c.y >= expected.height)
        in.fail("a pyramid corner lies outside its level");
    }
    expected = cv::Size(expected.width / 2, expected.height / 2);
  }
  return std::make_shared<const ImagePyramid>(std::move(levels));
}

// Colour images are stored PNG-compressed (lossless): raw they would dominate the file.
void put_colour(ByteWriter& out, const cv::Mat& colour) {
  std::vector<std::uint8_t> png;
  if (!colour.empty() && !cv::imencode(".png", colour, png, {cv::IMWRITE_PNG_COMPRESSION, 1}))
    throw Error("map save: cannot encode a keyframe colour image");
  out.put(static_cast<std::uint32_t>(png.size()));
  out.put_bytes(png.data(), png.size());
}

cv::Mat get_colour(ByteReader& in, const Camera& camera) {
  const auto size = in.get<std::uint32_t>("colour image size");
  if (size == 0) return {};
  if (size > in.remaining()) in.fail("colour image larger than the file");
  std::vector<std::uint8_t> png(size);
  in.get_bytes(png.data(), size, "colour image");
  cv::Mat colour = cv::imdecode(png, cv::IMREAD_UNCHANGED);
  if (colour.empty()) in.fail("a keyframe colour image does not decode");
  if (colour.size() != cv::Size(camera.width(), camera.height()) ||
      (colour.type() != CV_8UC3 && colour.type() != CV_8UC1))
    in.fail("a keyframe colour image is not an 8-bit grey or colour image of the camera's size");
  return colour;
}

}  // namespace

std::string describe_camera(const Camera& camera) {
  std::ostringstream s;
  s << camera.model_name() << ' ' << camera.width() << 'x' << camera.height();
  const auto p = camera_parameters(camera);
  const char* names_pinhole[] = {"fx", "fy", "cx", "cy", "k1", "k2", "p1", "p2", "k3"};
  const char* names_atan[] = {"fx", "fy", "cx", "cy", "w"};
  for (std::size_t i = 0; i < p.size(); ++i)
    s << ' ' << (p.size() == 9 ? names_pinhole[i] : names_atan[i]) << '=' << p[i];
  return s.str();
}

bool same_camera(const Camera& a, const Camera& b) {
  if (a.model_name() != b.model_name() || a.width() != b.width() || a.height() != b.height()) return false;
  const auto pa = camera_parameters(a), pb = camera_parameters(b);
  for (std::size_t i = 0; i < pa.size(); ++i)
    if (std::abs(pa[i] - pb[i]) > 1e-9 * std::max(1.0, std::abs(pa[i]))) return false;
  return true;
}

void save_map(const std::filesystem::path& path, const Map& map, const Camera& camera) {
  ByteWriter out;
  out.put_bytes(kMagic, sizeof kMagic);
  out.put(kMapFormatVersion);

  out.put_text(camera.model_name());
  out.put(static_cast<std::int32_t>(camera.width()));
  out.put(static_cast<std::int32_t>(camera.height()));
  const auto params = camera_parameters(camera);
  out.put(static_cast<std::uint32_t>(params.size()));
  for (double v : params) out.put(v);

  out.put(static_cast<std::uint64_t>(map.next_keyframe_id_value()));
  out.put(static_cast<std::uint64_t>(map.next_point_id_value()));

  // Under the shared lock: poses, positions and measurements from one moment.
  map.read([&](const MapView& view) {
    out.put(static_cast<std::uint32_t>(view.keyframes().size()));
    for (const auto& [kf_id, kf] : view.keyframes()) {
      out.put(static_cast<std::uint64_t>(kf->id()));
      out.put(static_cast<std::uint64_t>(kf->frame_index()));
      out.put(kf->timestamp());
      put_pose(out, kf->T_c_w());
      out.put(kf->mean_depth());
      out.put(kf->depth_sigma());
      put_pyramid(out, *kf->pyramid());
      put_colour(out, kf->colour());
      out.put(static_cast<std::uint32_t>(kf->measurements().size()));
      for (const auto& [point_id, m] : kf->measurements()) {
        out.put(static_cast<std::uint64_t>(point_id));
        out.put(static_cast<std::int32_t>(m.level));
        out.put(m.pixel.x());
        out.put(m.pixel.y());
        out.put(static_cast<std::uint8_t>(m.from_source));
      }
    }
    out.put(static_cast<std::uint32_t>(view.points().size()));
    for (const auto& [point_id, p] : view.points()) {
      out.put(static_cast<std::uint64_t>(p->id()));
      out.put(static_cast<std::uint64_t>(p->source().keyframe_id));
      out.put(static_cast<std::int32_t>(p->source().level));
      out.put(p->source().pixel_level0.x());
      out.put(p->source().pixel_level0.y());
      const auto& g = p->geometry();
      put_vec(out, g.p_w);
      put_vec(out, g.right_w);
      put_vec(out, g.down_w);
      put_vec(out, g.normal_w);
      for (const float v : p->votes()) out.put(v);
      const MapPoint::RegionViews region = p->region_views();
      out.put(region.views);
      out.put(region.in_region);
      out.put(static_cast<std::uint8_t>(p->is_bad()));
    }
  });
  const std::uint64_t checksum = fnv1a64(out.bytes().data(), out.bytes().size());
  out.put(checksum);
  write_text_atomically(path, out.bytes());
}

Camera load_map(const std::filesystem::path& path, Map& map, const Camera* expected_camera) {
  FACADESLAM_ASSERT(!map.keyframe_count() && !map.point_count(), "a map is loaded into an empty one");
  std::ifstream file(path, std::ios::binary);
  if (!file) fail_file(path, "cannot open the map file");
  std::string data((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  ByteReader in(data, path, "corrupt map file");

  char magic[sizeof kMagic];
  if (data.size() < sizeof kMagic + 4 + 8) fail_file(path, "not a facadeslam map file (too short)");
  in.get_bytes(magic, sizeof magic, "magic");
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) fail_file(path, "not a facadeslam map file (bad magic)");
  const auto version = in.get<std::uint32_t>("format version");
  if (version < kOldestMapFormatVersion || version > kMapFormatVersion)
    fail_file(path, "map format version " + std::to_string(version) + ", this build reads versions " +
                        std::to_string(kOldestMapFormatVersion) + " to " + std::to_string(kMapFormatVersion));
  const auto stored_checksum = ByteReader(std::string_view(data).substr(data.size() - 8), path, "corrupt map file")
                                   .get<std::uint64_t>("checksum");
  if (fnv1a64(data.data(), data.size() - 8) != stored_checksum)
    fail_file(path, "corrupt map file: checksum mismatch (truncated or damaged)");

  const std::string model = in.text("camera model");
  const auto width = in.get<std::int32_t>("camera width");
  const auto height = in.get<std::int32_t>("camera height");
  std::vector<double> params(in.count("camera parameters", 8, 16));
  for (double& v : params) v = in.get<double>("camera parameters");
  Camera camera = make_camera(model, width, height, params, in);
  if (expected_camera && !same_camera(camera, *expected_camera))
    fail_file(path, "map was made with camera [" + describe_camera(camera) + "] but this run uses [" +
                        describe_camera(*expected_camera) + "]");

  const auto next_kf = in.get<std::uint64_t>("id counters");
  const auto next_point = in.get<std::uint64_t>("id counters");

  std::vector<std::shared_ptr<KeyFrame>> keyframes;
  std::vector<std::tuple<std::shared_ptr<KeyFrame>, double, double>> depth_stats;
  std::map<KeyFrame::Id, std::shared_ptr<const ImagePyramid>> pyramids;
  const auto n_kf = in.get<std::uint32_t>("keyframe count");
  for (std::uint32_t k = 0; k < n_kf; ++k) {
    const auto id = in.get<std::uint64_t>("keyframe id");
    if (pyramids.count(id)) in.fail("keyframe id " + std::to_string(id) + " appears twice");
    const auto frame_index = in.get<std::uint64_t>("keyframe frame index");
    const double timestamp = get_finite(in, "keyframe timestamp");
    const SE3d T_c_w = get_pose(in);
    const double mean_depth = get_finite(in, "keyframe depth stats");
    const double depth_sigma = get_finite(in, "keyframe depth stats");
    if (mean_depth <= 0.0 || depth_sigma < 0.0) in.fail("keyframe " + std::to_string(id) + " depth stats out of range");
    auto pyramid = get_pyramid(in, camera);
    cv::Mat colour = get_colour(in, camera);
    const std::size_t n_meas = in.count("measurement count", 29);
    Measurements measurements;
    for (std::size_t i = 0; i < n_meas; ++i) {
      const auto point_id = in.get<std::uint64_t>("measurement");
      Measurement m;
      m.level = in.get<std::int32_t>("measurement");
      if (m.level < 0 || m.level >= kPyramidLevels)
        in.fail("measurement level " + std::to_string(m.level) + " in keyframe " + std::to_string(id) +
                " (expected 0.." + std::to_string(kPyramidLevels - 1) + ")");
      m.pixel.x() = get_finite(in, "measurement pixel");
      m.pixel.y() = get_finite(in, "measurement pixel");
      m.from_source = in.get<std::uint8_t>("measurement") != 0;
      if (!measurements.emplace(point_id, m).second)
        in.fail("keyframe " + std::to_string(id) + " measures point " + std::to_string(point_id) + " twice");
    }
    auto kf =
        std::make_shared<KeyFrame>(id, Frame{static_cast<std::size_t>(frame_index), timestamp, colour, {}, pyramid},
                                   T_c_w, std::move(measurements));
    depth_stats.emplace_back(kf, mean_depth, depth_sigma);
    pyramids.emplace(id, pyramid);
    keyframes.push_back(std::move(kf));
  }

  std::vector<std::shared_ptr<MapPoint>> points, bad;
  std::set<MapPoint::Id> point_ids;
  const auto n_points = in.get<std::uint32_t>("point count");
  for (std::uint32_t i = 0; i < n_points; ++i) {
    const auto id = in.get<std::uint64_t>("point id");
    if (!point_ids.insert(id).second) in.fail("point id " + std::to_string(id) + " appears twice");
    PatchSource source;
    source.keyframe_id = in.get<std::uint64_t>("point source");
    source.level = in.get<std::int32_t>("point source");
    source.pixel_level0.x() = get_finite(in, "point source pixel");
    source.pixel_level0.y() = get_finite(in, "point source pixel");
    const auto it = pyramids.find(source.keyframe_id);
    if (it == pyramids.end()) in.fail("point " + std::to_string(id) + " refers to a missing keyframe");
    if (source.level < 0 || source.level >= kPyramidLevels) in.fail("point level out of range");
    source.pyramid = it->second;
    PointGeometry g;
    g.p_w = get_vec(in, "point geometry");
    g.right_w = get_vec(in, "point geometry");
    g.down_w = get_vec(in, "point geometry");
    g.normal_w = get_vec(in, "point geometry");
    auto point = std::make_shared<MapPoint>(id, std::move(source), g);
    point->set_votes(version >= 3 ? get_votes(in) : votes_from_version2_label(in));
    if (version >= 4) point->set_region_views(get_region_views(in));
    if (in.get<std::uint8_t>("point flags")) bad.push_back(point);
    points.push_back(std::move(point));
  }
  if (in.remaining() != 8) in.fail("unexpected data after the points");
  for (const auto& kf : keyframes)
    for (const auto& [point_id, m] : kf->measurements())
      if (!point_ids.count(point_id))
        in.fail("keyframe " + std::to_string(kf->id()) + " measures point " + std::to_string(point_id) +
                ", which the map does not have");
  // Ids handed out after loading must not repeat the loaded ones.
  for (const auto& kf : keyframes)
    if (kf->id() >= next_kf) in.fail("keyframe id " + std::to_string(kf->id()) + " is not below the id counter");
  for (const MapPoint::Id id : point_ids)
    if (id >= next_point) in.fail("point id " + std::to_string(id) + " is not below the id counter");

  map.add(keyframes, points);
  map.update([&](MapEditor& edit) {
    for (const auto& [kf, mean, sigma] : depth_stats) edit.set_depth_stats(*kf, mean, sigma);
    for (const auto& p : bad) edit.mark_bad(*p);
  });
  map.restore_next_ids(next_kf, next_point);
  return camera;
}

}  // namespace facadeslam
