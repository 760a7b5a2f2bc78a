#include "slam/system.hpp"

#include <chrono>

#include <spdlog/spdlog.h>

#include "core/map/map_io.hpp"
#include "core/util/error.hpp"
#include "tracker/reloc/small_blurry_image.hpp"

namespace facadeslam {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

}  // namespace

const char* to_string(FrameStatus status) {
  switch (status) {
    case FrameStatus::initialising: return "initialising";
    case FrameStatus::initialised: return "initialised";
    case FrameStatus::tracking: return "tracking";
    case FrameStatus::lost: return "lost";
    case FrameStatus::relocalised: return "relocalised";
  }
  return "?";
}

System::System(Camera camera, SlamOptions options)
    : camera_(std::move(camera)),
      options_(std::move(options)),
      map_maker_(camera_, map_, queue_, options_.mapmaker),
      tracker_(camera_, map_, queue_, options_.tracker),
      initialiser_(camera_, options_.mapmaker.initialisation) {}

System::~System() { map_maker_.stop(); }

void System::load_map(const std::filesystem::path& path) {
  facadeslam::load_map(path, map_, &camera_);
  initialised_ = map_.keyframe_count() >= 2 && map_.point_count() > 0;
  if (!initialised_) fail_file(path, "the map has no keyframes or points to track against");
  // Nothing is known of the camera yet: the tracker starts lost and relocalises.
  tracker_.start(map_.keyframes().back()->T_c_w(), 0);
  tracker_.mark_lost();
  if (!options_.synchronous) map_maker_.start();
}

FrameReport System::process(std::size_t index, double timestamp, const cv::Mat& colour) {
  const auto t0 = Clock::now();
  FrameReport report;
  report.index = index;
  report.timestamp = timestamp;
  auto pyramid = std::make_shared<const ImagePyramid>(colour, options_.tracker.pyramid);
  report.pyramid_ms = ms_since(t0);

  if (!initialised_) {
    report = initialise(index, timestamp, colour, pyramid, report);
  } else {
    report.tracking = tracker_.track({index, timestamp, colour, pyramid});
    report.has_pose = report.tracking.tracked;
    report.T_c_w = report.tracking.T_c_w;
    report.status = !report.tracking.tracked     ? FrameStatus::lost
                    : report.tracking.relocalised ? FrameStatus::relocalised
                                                  : FrameStatus::tracking;
    if (options_.synchronous) map_maker_.process_pending();
    log_tracking(report);
  }
  report.total_ms = ms_since(t0);
  return report;
}

void System::log_tracking(const FrameReport& report) const {
  if (!spdlog::should_log(spdlog::level::debug)) return;
  const TrackingResult& t = report.tracking;
  const SearchCounts& c = t.fine_counts;
  spdlog::debug(
      "frame {}: {} ({}), coarse {}/{}, fine {}/{} of {} projected (no template {}, no corner {}, zmssd {}, "
      "sub-pixel {}, outliers {}), rms {:.2f} px, {:.2f}+{:.2f}+{:.2f}+{:.2f} ms{}",
      report.index, to_string(report.status), to_string(t.quality), t.coarse_found, t.coarse_searched, t.fine_found,
      t.fine_searched, c.projected, c.template_invalid, c.no_candidate, c.score_too_high, c.subpixel_failed,
      c.outliers, t.inlier_rms_px, report.pyramid_ms, t.timings.coarse_ms, t.timings.fine_ms, t.timings.pose_ms,
      t.keyframe_requested ? ", keyframe requested" : "");
}

FrameReport System::initialise(std::size_t index, double timestamp, const cv::Mat& colour,
                               std::shared_ptr<const ImagePyramid> pyramid, FrameReport report) {
  report.status = FrameStatus::initialising;
  const auto make_frame = [&] {
    return MapMakerFrame{index, timestamp, pyramid, colour, make_small_blurry_image(*pyramid)};
  };
  if (!reference_) {
    reference_ = make_frame();
    initialiser_.reset(pyramid->level(0).image, pyramid->level(0).corners, timestamp);
    return report;
  }
  const InitStatus status = initialiser_.add_frame(pyramid->level(0).image);
  if (status == InitStatus::too_few_tracks) {
    spdlog::debug("frame {}: initialisation restarts ({})", index, initialiser_.last_attempt().reason);
    reference_ = make_frame();
    initialiser_.reset(pyramid->level(0).image, pyramid->level(0).corners, timestamp);
    return report;
  }
  if (status != InitStatus::success) return report;

  const auto T_c_w = map_maker_.initialise(initialiser_.result(), *reference_, make_frame());
  if (!T_c_w) {
    reference_ = make_frame();
    initialiser_.reset(pyramid->level(0).image, pyramid->level(0).corners, timestamp);
    return report;
  }
  initialised_ = true;
  tracker_.start(*T_c_w, index);
  if (!options_.synchronous) map_maker_.start();
  report.status = FrameStatus::initialised;
  report.has_pose = true;
  report.T_c_w = *T_c_w;
  return report;
}

void System::finish() {
  if (options_.synchronous) {
    map_maker_.process_pending();
    if (initialised_) map_maker_.run_global_ba();
  } else {
    map_maker_.stop();
  }
}

}  // namespace facadeslam
