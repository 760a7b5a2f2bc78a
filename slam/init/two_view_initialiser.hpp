#pragma once
// PTAM-style automatic map initialisation without a key press. The map
// maker hands it a reference frame (reset), then every following frame
// (add_frame); corners of the reference are tracked with KLT, and as soon as
// the tracks show enough parallax the two views are reconstructed
// (initialise_from_matches), choosing a homography or an essential matrix by
// score. Pure geometry: no threads, no Map.
//
// What the caller does with each status:
//  * need_more_parallax, degenerate: keep calling add_frame with new frames
//    (the reference and the tracks are kept; last_attempt().reason says why).
//  * too_few_tracks: the tracks died; call reset() with the current frame
//    (its pyramid's level-0 corners) to start again.
//  * success: result() holds the pose and the points; the reference frame is
//    the first keyframe (reference_timestamp()), the frame just given to
//    add_frame the second. Call reset() before using the object again.
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera/camera.hpp"
#include "core/image/fast_detector.hpp"
#include "slam/init/corner_tracks.hpp"
#include "slam/init/init_options.hpp"
#include "slam/init/two_view_result.hpp"

namespace facadeslam {

class TwoViewInitialiser {
 public:
  // `camera` is the level-0 camera of the frames. Throws Error for options
  // out of range.
  explicit TwoViewInitialiser(Camera camera, TwoViewOptions options = {});

  // Makes `grey` (8-bit grey, the camera's size) the reference frame and
  // starts tracks at its level-0 FAST `corners` (ImagePyramid::level(0)).
  // Throws Error for a wrong image or corners outside it.
  void reset(const cv::Mat& grey, const std::vector<Corner>& corners, double timestamp);

  // Tracks the reference corners into `grey` (8-bit grey, the camera's size)
  // and tries to initialise. Throws Error before reset(), after too_few_tracks
  // or success without a new reset(), or for a wrong image.
  InitStatus add_frame(const cv::Mat& grey);

  bool has_reference() const { return has_reference_; }
  double reference_timestamp() const { return reference_timestamp_; }
  // The reference frame (the first keyframe on success).
  const cv::Mat& reference_image() const { return reference_image_; }
  // Frames given to add_frame since reset().
  int frames_since_reset() const { return tracks_.frames_tracked(); }
  const CornerTracks& tracks() const { return tracks_; }
  const Camera& camera() const { return camera_; }
  const TwoViewOptions& options() const { return options_; }

  // The latest add_frame's full outcome (status, reason, diagnostics).
  const TwoViewResult& last_attempt() const { return last_; }
  // The reconstruction; throws Error unless the latest add_frame succeeded.
  const TwoViewResult& result() const;

 private:
  void check_image(const cv::Mat& grey, const char* what) const;

  Camera camera_;
  TwoViewOptions options_;
  CornerTracks tracks_;
  cv::Mat reference_image_;
  double reference_timestamp_ = 0.0;
  bool has_reference_ = false;
  TwoViewResult last_;
};

}  // namespace facadeslam
