#pragma once
// `replay --render DIR`: the augmented view of every N-th frame, rendered on
// the replay thread after the frame is tracked (never inside the tracker, so
// tracking results are the same with and without it). Each rendered frame is
// the AR view (render/ar/ar_view.hpp: the image, the map points the tracker
// found in it, the virtual object on the map's dominant plane) beside the
// map view from a camera following above and behind. Written (on a writer
// thread with a bounded queue: render_frame_writer.hpp) as
// DIR/frames/ar_NNNNNN.png, DIR/augmented.mp4 and DIR/contact_sheet.png.
//
// "Found in this frame" is read without touching the tracker: every search
// bumps a map point's counters (MapPoint::count_search), so the points whose
// found count rose while the frame was tracked are those it measured.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <opencv2/core.hpp>

#include "core/util/json.hpp"
#include "slam/system.hpp"

namespace facadeslam::apps {

struct ReplayRenderOptions {
  std::filesystem::path dir;
  // The folder's name for the report: `dir` may be a staging folder that
  // becomes it when the replay succeeds. Empty: `dir`.
  std::filesystem::path reported_dir;
  std::size_t every = 1;  // render frames 0, N, 2N, ...
  double video_fps = 30.0;
  std::string title = "facadeslam replay";  // the contact sheet's, before "augmented view | map view"
  // depth.txt of a synthetic sequence: the object's occlusion is scored
  // against its true depth (report: render.occlusion_iou). Empty: not scored.
  std::filesystem::path truth_depth_list;
};

class ReplayRender {
 public:
  // Creates DIR (and DIR/frames), checks that files can be written there,
  // opens the video and the OSMesa contexts: everything that can fail does
  // so here, before the replay starts. Error naming what failed.
  ReplayRender(ReplayRenderOptions options, const Camera& camera);
  ~ReplayRender();
  ReplayRender(const ReplayRender&) = delete;
  ReplayRender& operator=(const ReplayRender&) = delete;

  // Call for every frame, in order: before System::process (the map's
  // search counters as they are) and after it with the frame's image (a
  // copy: the System keeps its own). Only every N-th frame is drawn; every
  // tracked frame extends the trajectory.
  bool wants(std::size_t frame_number) const { return frame_number % options_.every == 0; }
  void before_tracking(std::size_t frame_number, const System& system);
  void after_tracking(std::size_t frame_number, const FrameReport& report, const cv::Mat& image, const System& system);

  // Closes the video, writes the contact sheet; the report's "render" object.
  Json finish(double replay_fps);
  // "avc1 (H.264)" or "mp4v (MPEG-4 part 2)": what OpenCV's FFmpeg offered.
  std::string video_codec() const;

 private:
  struct Impl;
  ReplayRenderOptions options_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace facadeslam::apps
