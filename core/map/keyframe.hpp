#pragma once
// A keyframe: a frame the map maker keeps, with its pose, its images (grey
// pyramid with FAST corners, and the colour image for the semantic worker),
// a small blurred image for relocalisation, and the measurements of map points
// in it.
//
// Threads: everything but the pose and the measurements is immutable once the
// keyframe is in the map. The pose is guarded by Map::mutex() (bundle
// adjustment writes it, the tracker reads it). Measurements are created and
// edited by the map maker thread only, which is also the only reader apart
// from map saving (done with the map maker stopped or idle).
#include <cstdint>
#include <map>
#include <memory>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/image/image_pyramid.hpp"
#include "core/lie/se3.hpp"
#include "core/map/map_point.hpp"

namespace facadeslam {

// Where a map point was seen in a keyframe.
// The optical axis (the camera's +z) in world coordinates: the third row of R_c_w.
inline Eigen::Vector3d optical_axis_w(const SE3d& T_c_w) { return T_c_w.rotation_matrix().row(2).transpose(); }

struct Measurement {
  int level = 0;                   // pyramid level it was found at
  Eigen::Vector2d pixel{0, 0};     // level-0 pixel coordinates
  bool from_source = false;        // this keyframe is the point's source
};

class KeyFrame {
 public:
  using Id = std::uint64_t;

  KeyFrame(Id id, double timestamp, const SE3d& T_c_w, std::shared_ptr<const ImagePyramid> pyramid,
           cv::Mat colour, cv::Mat small_blurred);

  Id id() const { return id_; }
  double timestamp() const { return timestamp_; }

  // Guarded by Map::mutex().
  const SE3d& T_c_w() const { return T_c_w_; }
  void set_T_c_w(const SE3d& T_c_w) { T_c_w_ = T_c_w; }
  Eigen::Vector3d centre_w() const { return T_c_w_.inverse().translation(); }
  Eigen::Vector3d optical_axis_w() const { return facadeslam::optical_axis_w(T_c_w_); }

  const std::shared_ptr<const ImagePyramid>& pyramid() const { return pyramid_; }
  const cv::Mat& colour() const { return colour_; }           // 8-bit BGR, may be empty
  const cv::Mat& small_blurred() const { return small_blurred_; }  // for relocalisation

  // Map maker thread only.
  std::map<MapPoint::Id, Measurement>& measurements() { return measurements_; }
  const std::map<MapPoint::Id, Measurement>& measurements() const { return measurements_; }

  // Scene depth statistics of the points measured here, used for the
  // keyframe-distance test and the epipolar search range. Guarded by
  // Map::mutex() like the pose.
  double mean_depth() const { return mean_depth_; }
  double depth_sigma() const { return depth_sigma_; }
  void set_depth_stats(double mean, double sigma) {
    mean_depth_ = mean;
    depth_sigma_ = sigma;
  }

 private:
  const Id id_;
  const double timestamp_;
  SE3d T_c_w_;
  const std::shared_ptr<const ImagePyramid> pyramid_;
  const cv::Mat colour_;
  const cv::Mat small_blurred_;
  std::map<MapPoint::Id, Measurement> measurements_;
  double mean_depth_ = 1.0;
  double depth_sigma_ = 0.0;
};

}  // namespace facadeslam
