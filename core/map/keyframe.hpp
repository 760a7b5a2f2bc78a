#pragma once
// A keyframe: a frame the map maker keeps, with its pose, its images (grey
// pyramid with FAST corners, and the colour image for the semantic worker),
// its small blurry image for relocalisation, and the measurements of map
// points in it.
//
// Threads: the images are immutable. The pose, the depth statistics and the
// measurements belong to the Map: they change only through Map::update (an
// exclusive lock; only a holder of a non-const Map, the map maker, can call
// it). Other threads read them under Map::read or from Map::snapshot_keyframes;
// the map maker, their only writer, may also read them directly.
#include <cstdint>
#include <map>
#include <memory>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/image/frame.hpp"
#include "core/image/image_pyramid.hpp"
#include "core/lie/se3.hpp"
#include "core/map/map_point.hpp"
#include "core/map/measurement.hpp"

namespace facadeslam {

// The optical axis (the camera's +z) in world coordinates: the third row of R_c_w.
inline Eigen::Vector3d optical_axis_w(const SE3d& T_c_w) { return T_c_w.rotation_matrix().row(2).transpose(); }

class KeyFrame {
 public:
  using Id = std::uint64_t;

  // Keeps the frame's images (shared, not copied) and builds its small blurry
  // image. `measurements` are the points measured in it when it is made;
  // later ones come through Map::add / Map::update.
  KeyFrame(Id id, const Frame& frame, const SE3d& T_c_w, Measurements measurements = {});

  Id id() const { return id_; }
  std::size_t frame_index() const { return frame_index_; }
  double timestamp() const { return timestamp_; }

  const std::shared_ptr<const ImagePyramid>& pyramid() const { return pyramid_; }
  const cv::Mat& colour() const { return colour_; }                // 8-bit BGR, may be empty
  const cv::Mat& small_blurred() const { return small_blurred_; }  // for relocalisation

  // Owned by the Map (see above).
  const SE3d& T_c_w() const { return T_c_w_; }
  Eigen::Vector3d centre_w() const { return T_c_w_.inverse().translation(); }
  Eigen::Vector3d optical_axis_w() const { return facadeslam::optical_axis_w(T_c_w_); }
  const Measurements& measurements() const { return measurements_; }
  // Scene depth statistics of the points measured here, used for the
  // keyframe-distance test and the epipolar search range.
  double mean_depth() const { return mean_depth_; }
  double depth_sigma() const { return depth_sigma_; }

 private:
  friend class MapEditor;
  friend class Map;

  const Id id_;
  const std::size_t frame_index_;
  const double timestamp_;
  SE3d T_c_w_;
  const std::shared_ptr<const ImagePyramid> pyramid_;
  const cv::Mat colour_;
  const cv::Mat small_blurred_;
  Measurements measurements_;
  double mean_depth_ = 1.0;
  double depth_sigma_ = 0.0;
};

}  // namespace facadeslam
