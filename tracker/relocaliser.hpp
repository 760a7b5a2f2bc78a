#pragma once
// Relocalisation after tracking is lost (PTAM): compare the frame's small
// blurry image with every keyframe's, take the most similar keyframe, find
// the in-image rotation and shift between the two, and turn it into a camera
// rotation about that keyframe's centre. The result is only a starting pose:
// the tracker then runs its normal coarse-to-fine search from it, and only a
// frame that tracks well counts as relocalised.
#include <memory>
#include <optional>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"
#include "core/image/small_blurry_image.hpp"
#include "core/map/map.hpp"

namespace facadeslam {

struct RelocalisationCandidate {
  std::shared_ptr<const KeyFrame> keyframe;
  SE3d T_c_w;               // proposed pose of the current frame
  double difference = 0.0;  // SBI sum of squared differences to the keyframe
};

struct RelocaliserOptions {
  // Reject when even the best keyframe differs this much per SBI pixel (RMS
  // grey levels): the frame shows something the map has never seen.
  double max_rms_difference = 25.0;
};

// `keyframes`: the map's keyframes with their poses (Map::snapshot_keyframes).
std::optional<RelocalisationCandidate> find_relocalisation_candidate(const cv::Mat& current_sbi,
                                                                     const std::vector<KeyFrameSnapshot>& keyframes,
                                                                     const Camera& camera,
                                                                     const RelocaliserOptions& options = {});

// The keyframes ordered by the similarity of their small blurry images to
// `current_sbi`, most similar first (those of another size last).
std::vector<KeyFrameSnapshot> keyframes_by_similarity(const cv::Mat& current_sbi,
                                                      std::vector<KeyFrameSnapshot> keyframes);

// The camera rotation R (current from keyframe) that best explains an SE2
// motion of the SBI, found by Gauss-Newton over sample pixels through the
// camera model (so distortion and the principal point are accounted for).
SO3d rotation_from_sbi_motion(const Se2Motion& motion, const Camera& camera, cv::Size sbi_size);

}  // namespace facadeslam
