#include "slam/init/two_view_initialiser.hpp"

#include <string>

#include <fmt/format.h>

#include "core/util/error.hpp"
#include "slam/init/initialise_from_matches.hpp"

namespace facadeslam {
namespace {

const TwoViewOptions& validated(const TwoViewOptions& options) {
  validate(options);
  return options;
}

}  // namespace

TwoViewInitialiser::TwoViewInitialiser(Camera camera, TwoViewOptions options)
    : camera_(std::move(camera)), options_(validated(options)), tracks_(options_.tracking) {}

void TwoViewInitialiser::check_image(const cv::Mat& grey, const char* what) const {
  if (grey.empty() || grey.type() != CV_8UC1)
    throw Error(fmt::format("two-view initialiser: {} must be a non-empty 8-bit single-channel image", what));
  if (grey.cols != camera_.width() || grey.rows != camera_.height())
    throw Error(fmt::format("two-view initialiser: {} is {}x{} but the camera is {}x{}", what, grey.cols, grey.rows,
                            camera_.width(), camera_.height()));
}

void TwoViewInitialiser::reset(const cv::Mat& grey, const std::vector<Corner>& corners, double timestamp) {
  check_image(grey, "the reference image");
  tracks_.reset(grey, corners);
  // A deep copy: the caller's frame buffer may be reused for the next frame.
  reference_image_ = grey.clone();
  reference_timestamp_ = timestamp;
  has_reference_ = true;
  last_ = TwoViewResult{};
}

InitStatus TwoViewInitialiser::add_frame(const cv::Mat& grey) {
  if (!has_reference_)
    throw Error(
        "two-view initialiser: add_frame() needs a reference frame; call reset() first (also after "
        "too_few_tracks or success)");
  check_image(grey, "the frame");
  tracks_.track(grey);
  last_ = initialise_from_matches(camera_, tracks_.reference_pixels(), tracks_.current_pixels(), options_);
  // Both end this reference: the caller must reset() (a new reference after
  // too_few_tracks, or the map maker's next initialisation after success).
  if (last_.status == InitStatus::too_few_tracks || last_.status == InitStatus::success) has_reference_ = false;
  return last_.status;
}

const TwoViewResult& TwoViewInitialiser::result() const {
  if (last_.status != InitStatus::success)
    throw Error(fmt::format("two-view initialiser: result() requested but the latest attempt ended with {}{}",
                            to_string(last_.status), last_.reason.empty() ? "" : " (" + last_.reason + ")"));
  return last_;
}

}  // namespace facadeslam
