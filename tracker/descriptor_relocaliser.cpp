#include "tracker/descriptor_relocaliser.hpp"

#include <unordered_set>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

namespace facadeslam {
namespace {

// ORB's own pyramid: 8 levels, 1.2 apart (its defaults). A map point found
// at our level l (2^l) is described at ORB's octave nearest that scale.
constexpr float kOrbScale = 1.2f;
constexpr int kOrbLevels = 8;
constexpr int kOrbPatch = 31;

int orb_octave_for_level(int level) {
  const double octave = level * std::log(2.0) / std::log(static_cast<double>(kOrbScale));
  return std::clamp(static_cast<int>(std::lround(octave)), 0, kOrbLevels - 1);
}

// ORB's orientation: the direction of the intensity centroid of a disc of
// radius 15 around the corner. OpenCV computes it only for the corners its
// own detector finds, so for given positions we compute it here, on the
// level the point was measured at.
float intensity_centroid_angle_deg(const cv::Mat& image, const cv::Point2f& centre) {
  constexpr int r = kOrbPatch / 2;
  const int cx = static_cast<int>(std::lround(centre.x)), cy = static_cast<int>(std::lround(centre.y));
  double m10 = 0, m01 = 0;
  for (int dy = -r; dy <= r; ++dy) {
    const int y = cy + dy;
    if (y < 0 || y >= image.rows) continue;
    const auto* row = image.ptr<std::uint8_t>(y);
    const int half = static_cast<int>(std::sqrt(static_cast<double>(r * r - dy * dy)));
    for (int dx = -half; dx <= half; ++dx) {
      const int x = cx + dx;
      if (x < 0 || x >= image.cols) continue;
      m10 += dx * row[x];
      m01 += dy * row[x];
    }
  }
  double angle = std::atan2(m01, m10) * 180.0 / std::numbers::pi;
  if (angle < 0) angle += 360.0;
  return static_cast<float>(angle);
}

}  // namespace

DescriptorRelocaliser::DescriptorRelocaliser(Camera camera, DescriptorRelocaliserOptions options)
    : camera_(std::move(camera)),
      options_(options),
      orb_(cv::ORB::create(options.frame_features, kOrbScale, kOrbLevels, kOrbPatch, 0, 2, cv::ORB::HARRIS_SCORE,
                           kOrbPatch)) {}

const DescriptorRelocaliser::KeyFrameDescriptors& DescriptorRelocaliser::descriptors_of(const KeyFrame& keyframe,
                                                                                        const Map& map) {
  KeyFrameDescriptors& entry = cache_[keyframe.id()];
  // The measurements are copied only when the descriptors are (re)computed.
  const std::size_t count = map.read([&](const MapView&) { return keyframe.measurements().size(); });
  if (!entry.descriptors.empty() && 4 * count < 5 * entry.measurements) return entry;
  const Measurements measurements = map.read([&](const MapView&) { return keyframe.measurements(); });

  const ImagePyramid& pyramid = *keyframe.pyramid();
  std::vector<cv::KeyPoint> keypoints;
  std::vector<MapPoint::Id> ids;
  keypoints.reserve(measurements.size());
  for (const auto& [id, m] : measurements) {
    const int level = std::clamp(m.level, 0, pyramid.levels() - 1);
    const Eigen::Vector2d x_level = ImagePyramid::level0_to_level(m.pixel, level);
    const cv::Point2f at_level(static_cast<float>(x_level.x()), static_cast<float>(x_level.y()));
    const int octave = orb_octave_for_level(level);
    cv::KeyPoint kp(cv::Point2f(static_cast<float>(m.pixel.x()), static_cast<float>(m.pixel.y())),
                    kOrbPatch * std::pow(kOrbScale, static_cast<float>(octave)),
                    intensity_centroid_angle_deg(pyramid.level(level).image, at_level), 0.f, octave,
                    static_cast<int>(ids.size()));
    keypoints.push_back(kp);
    ids.push_back(id);
  }
  cv::Mat descriptors;
  // OpenCV drops keypoints too near the border; class_id maps the survivors back.
  orb_->compute(pyramid.level(0).image, keypoints, descriptors);
  entry.measurements = measurements.size();
  entry.points.clear();
  for (const cv::KeyPoint& kp : keypoints) entry.points.push_back(ids[static_cast<std::size_t>(kp.class_id)]);
  entry.descriptors = descriptors;
  return entry;
}

std::optional<DescriptorRelocalisation> DescriptorRelocaliser::relocalise(
    const ImagePyramid& frame, const Map& map, const std::vector<KeyFrameSnapshot>& keyframes) {
  if (!options_.enabled || keyframes.empty()) return std::nullopt;
  // The descriptors of keyframes no longer in the map (culled) go: a long
  // run would otherwise keep every keyframe's.
  std::unordered_set<KeyFrame::Id> live;
  for (const KeyFrameSnapshot& kf : keyframes) live.insert(kf.keyframe->id());
  std::erase_if(cache_, [&](const auto& entry) { return !live.contains(entry.first); });
  std::vector<cv::KeyPoint> frame_keypoints;
  cv::Mat frame_descriptors;
  orb_->detectAndCompute(frame.level(0).image, cv::noArray(), frame_keypoints, frame_descriptors);
  if (static_cast<int>(frame_keypoints.size()) < options_.min_inliers) return std::nullopt;
  // Normalised image coordinates: PnP then needs no camera matrix and the
  // camera model (distortion, ATAN) is applied exactly.
  std::vector<cv::Point2d> frame_rays;
  frame_rays.reserve(frame_keypoints.size());
  for (const cv::KeyPoint& kp : frame_keypoints) {
    const Eigen::Vector3d ray = camera_.unproject(Eigen::Vector2d(kp.pt.x, kp.pt.y));
    frame_rays.emplace_back(ray.x() / ray.z(), ray.y() / ray.z());
  }

  const cv::BFMatcher matcher(cv::NORM_HAMMING);
  std::optional<DescriptorRelocalisation> best;
  const std::size_t tried = std::min(keyframes.size(), static_cast<std::size_t>(options_.max_keyframes));
  for (std::size_t k = 0; k < tried; ++k) {
    const KeyFrameDescriptors& kf = descriptors_of(*keyframes[k].keyframe, map);
    if (kf.descriptors.rows < options_.min_inliers) continue;
    std::vector<std::vector<cv::DMatch>> knn;
    matcher.knnMatch(frame_descriptors, kf.descriptors, knn, 2);
    // Ratio test, then one frame feature per map point (the closest). Kept
    // in id order: the RANSAC sample order, and so its result, must not
    // depend on a hash map's iteration order.
    std::map<MapPoint::Id, cv::DMatch> per_point;
    for (const auto& m : knn) {
      if (m.empty() || m[0].distance > options_.max_hamming) continue;
      if (m.size() > 1 && m[0].distance > options_.ratio * m[1].distance) continue;
      const MapPoint::Id id = kf.points[static_cast<std::size_t>(m[0].trainIdx)];
      const auto [it, inserted] = per_point.emplace(id, m[0]);
      if (!inserted && m[0].distance < it->second.distance) it->second = m[0];
    }
    if (static_cast<int>(per_point.size()) < options_.min_inliers) continue;

    std::vector<cv::Point3d> object;
    std::vector<cv::Point2d> image;
    map.read([&](const MapView& view) {
      for (const auto& [id, match] : per_point) {
        const auto point = view.point(id);
        if (!point || point->is_bad()) continue;
        const Eigen::Vector3d& p = point->geometry().p_w;
        object.emplace_back(p.x(), p.y(), p.z());
        image.push_back(frame_rays[static_cast<std::size_t>(match.queryIdx)]);
      }
    });
    if (static_cast<int>(object.size()) < options_.min_inliers) continue;

    cv::Mat rvec, tvec;
    std::vector<int> inliers;
    const double error = options_.ransac_error_px / camera_.fx();
    if (!cv::solvePnPRansac(object, image, cv::Mat::eye(3, 3, CV_64F), cv::noArray(), rvec, tvec, false,
                            options_.ransac_iterations, static_cast<float>(error), 0.99, inliers, cv::SOLVEPNP_EPNP))
      continue;
    if (static_cast<int>(inliers.size()) < options_.min_inliers) continue;
    if (best && static_cast<int>(inliers.size()) <= best->inliers) continue;
    std::vector<cv::Point3d> object_in;
    std::vector<cv::Point2d> image_in;
    for (const int i : inliers) {
      object_in.push_back(object[static_cast<std::size_t>(i)]);
      image_in.push_back(image[static_cast<std::size_t>(i)]);
    }
    cv::solvePnPRefineLM(object_in, image_in, cv::Mat::eye(3, 3, CV_64F), cv::noArray(), rvec, tvec);
    cv::Mat R_cv;
    cv::Rodrigues(rvec, R_cv);
    Eigen::Matrix3d R;
    Eigen::Vector3d t;
    cv::cv2eigen(R_cv, R);
    cv::cv2eigen(tvec, t);
    if (!R.allFinite() || !t.allFinite()) continue;
    best = DescriptorRelocalisation{keyframes[k].keyframe, SE3d(R, t), static_cast<int>(object.size()),
                                    static_cast<int>(inliers.size())};
  }
  return best;
}

}  // namespace facadeslam
