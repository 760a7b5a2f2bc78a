#include "tests/support/small_map.hpp"

#include <random>

#include "core/map/binary_stream.hpp"

namespace facadeslam::test {

Camera small_test_camera() { return Camera(160, 120, PinholeRadTan{150, 150, 79.5, 59.5, 0.01, 0, 0, 0, 0}); }

void build_test_map(Map& map, int n_points, const Camera& camera) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> pixel(0, 255);
  std::vector<std::shared_ptr<KeyFrame>> keyframes;
  std::vector<Frame> frames;
  std::vector<SE3d> poses;
  for (int k = 0; k < 2; ++k) {
    cv::Mat colour(camera.height(), camera.width(), CV_8UC3);
    for (int y = 0; y < colour.rows; ++y)
      for (int x = 0; x < colour.cols; ++x)
        colour.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<std::uint8_t>(pixel(rng)), static_cast<std::uint8_t>(x),
                                               static_cast<std::uint8_t>(y));
    frames.push_back(
        {static_cast<std::size_t>(7 + 3 * k), 10.0 + k, colour, {}, std::make_shared<const ImagePyramid>(colour)});
    poses.push_back(SE3d::exp((Eigen::Matrix<double, 6, 1>() << 0.1 * k, 0.02, -0.03, 0.01, 0.05 * k, 0).finished()));
  }
  // The keyframes' measurements, made before the keyframes (ids come first).
  const KeyFrame::Id first_keyframe = map.next_keyframe_id_value();
  std::vector<Measurements> measurements(2);
  std::vector<std::shared_ptr<MapPoint>> points;
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < n_points; ++i) {
    PatchSource source{first_keyframe, frames[0].pyramid, i % 4, {20.0 + i, 30.0 + 0.5 * i}};
    PointGeometry g;
    g.p_w << u(rng), u(rng), 4 + u(rng);  // drawn in order (a call's arguments would not be)
    g.right_w = Eigen::Vector3d(0.01, 0, 0);
    g.down_w = Eigen::Vector3d(0, 0.01, 0);
    g.normal_w = Eigen::Vector3d(0, 0, -1);
    auto p = std::make_shared<MapPoint>(map.new_point_id(), source, g);
    if (i % 3 == 0) {
      ClassVotes votes{};
      votes[static_cast<std::size_t>(i % 9)] = 0.5f + 0.01f * static_cast<float>(i);
      votes[static_cast<std::size_t>((i + 4) % 9)] = 0.25f;
      p->set_votes(votes);
      p->set_region_views(
          {.views = static_cast<std::uint32_t>(i % 4 + 1), .in_region = static_cast<std::uint32_t>(i % 2)});
    }
    for (std::size_t k = 0; k < measurements.size(); ++k)
      measurements[k][p->id()] = {i % 4, {20.0 + i + static_cast<double>(k), 30.25 + i}, k == 0};
    points.push_back(p);
  }
  for (std::size_t k = 0; k < frames.size(); ++k)
    keyframes.push_back(std::make_shared<KeyFrame>(map.new_keyframe_id(), frames[k], poses[k], measurements[k]));
  map.add(keyframes, points);
  map.update([&](MapEditor& edit) {
    for (std::size_t k = 0; k < keyframes.size(); ++k) edit.set_depth_stats(*keyframes[k], 4.0 + k, 0.5);
  });
}

std::string with_map_checksum(std::string body) {
  const std::uint64_t checksum = fnv1a64(body.data(), body.size());
  body.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);  // little-endian, as ByteWriter puts it
  return body;
}

}  // namespace facadeslam::test
