#pragma once
// Relocalisation across a real viewpoint change, beyond PTAM: PTAM's small
// blurry image (relocaliser.hpp) only finds a pose that is a rotation about
// a keyframe's centre, so it cannot bridge views a metre or two and 15-20
// degrees apart (the Strecha facades) nor a car's return from another lane.
// Here, as ORB-SLAM does, binary descriptors (OpenCV's ORB) of the current
// frame are matched against descriptors computed at the map points measured
// in a few keyframes, and the 2D-3D matches give a pose by PnP with RANSAC.
// As with the small blurry image the result is only a starting pose: the
// tracker runs its normal search from it and decides.
//
// Keyframe descriptors are computed once per keyframe and cached (a keyframe's
// images never change; its measurements only grow, and a cache entry is
// recomputed when they have grown by a quarter). The tracker thread owns the
// relocaliser; it reads the map only through its snapshots and Map::read.
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include "core/camera/camera.hpp"
#include "core/image/image_pyramid.hpp"
#include "core/lie/se3.hpp"
#include "core/map/map.hpp"

namespace facadeslam {

struct DescriptorRelocaliserOptions {
  bool enabled = true;
  int frame_features = 1500;     // ORB features detected in the current frame
  int max_keyframes = 4;         // keyframes tried, most similar small blurry image first
  float ratio = 0.8f;            // Lowe's ratio test on Hamming distances
  int max_hamming = 64;          // of 256 bits
  int min_inliers = 20;          // PnP inliers for a pose worth tracking from
  double ransac_error_px = 4.0;  // level-0 pixels
  int ransac_iterations = 300;
};

struct DescriptorRelocalisation {
  std::shared_ptr<const KeyFrame> keyframe;  // whose points gave the pose
  SE3d T_c_w;
  int matches = 0, inliers = 0;
};

class DescriptorRelocaliser {
 public:
  DescriptorRelocaliser(Camera camera, DescriptorRelocaliserOptions options);

  // `keyframes`: the map's keyframes ranked, most promising first (only the
  // first max_keyframes are tried); the best PnP solution over them, or
  // nothing. Cached descriptors of keyframes not among them are dropped.
  std::optional<DescriptorRelocalisation> relocalise(const ImagePyramid& frame, const Map& map,
                                                     const std::vector<KeyFrameSnapshot>& keyframes);
  // Forgets the cached keyframe descriptors (a map reset).
  void clear() { cache_.clear(); }

 private:
  struct KeyFrameDescriptors {
    std::size_t measurements = 0;      // how many the keyframe had when computed
    std::vector<MapPoint::Id> points;  // one per descriptor row
    cv::Mat descriptors;               // CV_8U, 32 bytes per row
  };
  const KeyFrameDescriptors& descriptors_of(const KeyFrame& keyframe, const Map& map);

  Camera camera_;
  DescriptorRelocaliserOptions options_;
  cv::Ptr<cv::ORB> orb_;
  std::unordered_map<KeyFrame::Id, KeyFrameDescriptors> cache_;
};

}  // namespace facadeslam
