#include "apps/replay/replay_render.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/replay/render_frame_writer.hpp"
#include "apps/replay/replay_log.hpp"
#include "core/map/semantic_classes.hpp"
#include "core/plot/png_file.hpp"
#include "core/util/error.hpp"
#include "core/util/median.hpp"
#include "core/util/stopwatch.hpp"
#include "render/ar/ar_view.hpp"
#include "render/ar/contact_sheet.hpp"
#include "render/ar/follow_camera.hpp"
#include "render/ar/map_occlusion.hpp"
#include "render/ar/object_placement.hpp"
#include "render/ar/occlusion_score.hpp"
#include "render/ar/plane_finder.hpp"
#include "render/ar/video_writer.hpp"
#include "render/ar/virtual_object.hpp"
#include "render/map_view.hpp"
#include "sequences/list_file.hpp"
#include "render/map_view_framing.hpp"

namespace facadeslam::apps {
// Named, so that a unity build cannot clash with other files' helpers.
namespace replay_render_detail {
namespace {

namespace fs = std::filesystem;

// PTAM's colours for the pyramid level a point's patch comes from (points
// without a class yet): red, yellow, green, blue from fine to coarse.
const std::array<cv::Vec3b, 4> kLevelBgr{{{0, 0, 255}, {0, 230, 255}, {0, 200, 0}, {255, 120, 0}}};

// Before a plane is looked for: a map this small is mostly the two
// initial keyframes' points, whose plane may be a poor guess.
constexpr std::size_t kMinPointsForPlane = 80;
constexpr std::size_t kMinKeyframesForPlane = 3;
// An object out of the camera's view for this many frames of the sequence,
// and at least this many rendered frames running, is placed again ahead of
// the newest keyframe: a camera that walks or drives past it would otherwise
// leave it behind for the rest of the sequence (street-walk --render-every 4:
// in view in 28 of 141 rendered frames without; KITTI 06 snippet 10 of 47).
// Hidden behind the map counts as in view.
constexpr std::size_t kReplaceAfterFramesOutOfView = 5;
constexpr std::size_t kReplaceAfterRenderedFramesOutOfView = 2;

cv::Vec3b class_bgr(const SemanticClass& c) { return {c.b, c.g, c.r}; }

struct PointColour {
  cv::Vec3b bgr;
  std::string legend;
};

PointColour point_colour(const PointSnapshot& point) {
  const SemanticLabel label = point.point->label();
  if (label.label != kUnlabelled) {
    const SemanticClass& c = semantic_class(label.label);
    return {class_bgr(c), std::string(c.name)};
  }
  const int level = std::clamp(point.source.level, 0, static_cast<int>(kLevelBgr.size()) - 1);
  return {kLevelBgr[static_cast<std::size_t>(level)], "level " + std::to_string(level)};
}

int even(int n) { return n + (n & 1); }

bool is_class(const SemanticLabel& label, std::string_view name) {
  return label.label != kUnlabelled && semantic_class(label.label).name == name;
}

// What a point's label lets it do to the object (render/ar/map_occlusion.hpp).
render::ar::OccluderKind occluder_kind(const SemanticLabel& label) {
  using render::ar::OccluderKind;
  if (is_class(label, "sky") || is_class(label, "road") || is_class(label, "pavement")) return OccluderKind::none;
  if (is_class(label, "building") || is_class(label, "window") || is_class(label, "door")) return OccluderKind::surface;
  return OccluderKind::sparse;  // vegetation, car, various, and points not labelled yet
}

// depth.txt beside a synthetic sequence: "timestamp depth/NNNNNN.png" per
// frame (sequences/synth/sequence_writer.hpp); empty when there is none.
std::vector<std::pair<double, fs::path>> read_depth_list(const fs::path& list) {
  std::vector<std::pair<double, fs::path>> out;
  if (list.empty()) return out;
  for (const ListLine& line : read_list_file(list, "a depth list ('timestamp depth/NNNNNN.png' per line)")) {
    if (line.fields.size() != 2) fail_line(list, line.number, "expected 'timestamp depth/NNNNNN.png'");
    out.emplace_back(parse_timestamp(line.fields[0], list, line.number), list.parent_path() / line.fields[1]);
  }
  return out;
}

}  // namespace
}  // namespace replay_render_detail

namespace fs = std::filesystem;

struct ReplayRender::Impl {
  Camera camera;
  render::ar::ArView ar_view;
  render::MapView map_view;
  cv::Size map_view_size, frame_size;
  fs::path frames_dir, video_path, sheet_path;
  std::unique_ptr<render::ar::Mp4Writer> video;
  render::ar::FrameSampleSheet sheet;
  std::unique_ptr<RenderFrameWriter> writer;  // after what it writes into: stops first

  std::unordered_map<MapPoint::Id, std::uint32_t> found_before;
  std::vector<Eigen::Vector3d> trajectory_w;
  std::optional<render::ar::VirtualObject> object;
  Json plane;  // the last placement's; null until the object is placed in the current map
  // Why there is no object yet: the largest map seen, whether a plane was
  // looked for in it and not found (said in the report and on the log).
  std::size_t most_points = 0, most_keyframes = 0, placements = 0;
  std::optional<std::size_t> last_frame_in_view, last_map_reset;
  std::size_t rendered_out_of_view = 0;
  bool tracked = false, no_plane_found = false;
  std::optional<render::ar::Plane> ground;  // the object stands on it
  double ground_band = 0.0;
  render::ar::MapSpacing spacing;  // for the occluders' splats
  // Scoring against the true depth (synthetic sequences only).
  std::vector<std::pair<double, fs::path>> truth_depth;
  render::ar::OcclusionScore occlusion;
  std::size_t frames_with_object = 0, frames_object_visible = 0;
  std::size_t rendered = 0, without_overlay = 0;
  std::vector<double> render_ms;

  Impl(const ReplayRenderOptions& options, const Camera& c)
      : camera(c),
        ar_view(c),
        map_view_size(replay_render_detail::even(c.height() * 4 / 3), c.height()),
        frame_size(replay_render_detail::even(c.width() + map_view_size.width), replay_render_detail::even(c.height())),
        frames_dir(options.dir / "frames"),
        video_path(options.dir / "augmented.mp4"),
        sheet_path(options.dir / "contact_sheet.png"),
        sheet(options.title + ": augmented view | map view", 12, 3, std::min(480, frame_size.width)),
        truth_depth(replay_render_detail::read_depth_list(options.truth_depth_list)) {
    video = std::make_unique<render::ar::Mp4Writer>(video_path, options.video_fps, frame_size);
    writer = std::make_unique<RenderFrameWriter>(*video, sheet);
  }

  // Places the object once, on the dominant plane of the map as it is when
  // it first has enough points; from then on it stays where it is.
  void place_object(const std::vector<PointSnapshot>& points, const std::vector<KeyFrameSnapshot>& keyframes,
                    std::size_t frame_number) {
    tracked = true;
    most_points = std::max(most_points, points.size());
    most_keyframes = std::max(most_keyframes, keyframes.size());
    if (object || points.size() < replay_render_detail::kMinPointsForPlane ||
        keyframes.size() < replay_render_detail::kMinKeyframesForPlane)
      return;
    std::vector<render::ar::PlacementPoint> placement_points;
    placement_points.reserve(points.size());
    for (const PointSnapshot& p : points) {
      const SemanticLabel label = p.point->label();
      placement_points.push_back({p.geometry.p_w, replay_render_detail::is_class(label, "road") ||
                                                      replay_render_detail::is_class(label, "pavement")});
    }
    std::vector<Eigen::Isometry3d> keyframes_T_c_w;
    keyframes_T_c_w.reserve(keyframes.size());
    for (const KeyFrameSnapshot& kf : keyframes) keyframes_T_c_w.push_back(kf.T_c_w.isometry());
    // Seen from the newest keyframe: the object appears in the view it is placed in.
    const auto placement = render::ar::place_object(placement_points, keyframes_T_c_w);
    no_plane_found = !placement;
    if (!placement) return;
    object = placement->object;
    ++placements;
    last_frame_in_view = frame_number;
    if (placement->on_ground) ground = placement->fit.plane;
    ground_band = placement->ground_band;
    const render::ar::PlaneFit* fit = &placement->fit;
    const bool ground = placement->on_ground;
    plane = Json::object();
    plane["kind"] = ground ? "ground" : "facade";
    plane["why"] = placement->reason;
    plane["inliers"] = fit->inliers.size();
    plane["points"] = points.size();
    plane["placed_at_frame"] = frame_number;
    plane["placements"] = placements;
    Json normal = Json::array();
    for (int i = 0; i < 3; ++i) normal.push_back(object->T_w_o.linear()(i, 2));
    plane["normal_w"] = normal;
    plane["object_size"] = object->size;
    spdlog::info("render: virtual object placed on the {} plane ({} of {} points) at frame {}",
                 ground ? "ground" : "facade", fit->inliers.size(), points.size(), frame_number);
  }

  // The map's occluders as the camera sees them, in the object's geometry.
  cv::Mat occluders(const std::vector<PointSnapshot>& points, const Eigen::Isometry3d& T_c_w) {
    std::vector<render::ar::OccluderPoint> occluder_points;
    occluder_points.reserve(points.size());
    for (const PointSnapshot& p : points) {
      const bool on_ground = ground && std::abs(ground->signed_distance(p.geometry.p_w)) <= ground_band;
      occluder_points.push_back({p.geometry.p_w, on_ground ? render::ar::OccluderKind::none
                                                           : replay_render_detail::occluder_kind(p.point->label())});
    }
    const render::PinholeIntrinsics& intrinsics = ar_view.object_intrinsics();
    // Off-screen (an empty region): nothing to hide, nothing drawn.
    return render::ar::occluder_depth(occluder_points, T_c_w, intrinsics, spacing.of(occluder_points), {},
                                      render::ar::object_region(*object, T_c_w, intrinsics));
  }

  // The frame's occlusion against the true depth: the map's scale from the
  // points the tracker found (the true depth at their pixels over theirs).
  // Returns whether the object is in the camera's view (hidden or not).
  bool score_occlusion(double timestamp, const render::ar::ArFrameContent& content, const Eigen::Isometry3d& T_c_w) {
    ++frames_with_object;
    const cv::Mat object_z = render::ar::object_depth(*object, camera, T_c_w);
    const bool in_view = render::ar::leaves_object_visible(object_z, cv::Mat());
    const cv::Mat& occluder_z = content.occluder_depth;
    if (render::ar::leaves_object_visible(object_z, occluder_z)) ++frames_object_visible;
    if (truth_depth.empty() || occluder_z.size() != object_z.size()) return in_view;
    const auto nearest = std::min_element(truth_depth.begin(), truth_depth.end(), [&](const auto& a, const auto& b) {
      return std::abs(a.first - timestamp) < std::abs(b.first - timestamp);
    });
    if (std::abs(nearest->first - timestamp) > 1e-3) return in_view;
    const cv::Mat depth_mm = cv::imread(nearest->second.string(), cv::IMREAD_ANYDEPTH);
    if (depth_mm.type() != CV_16UC1 || depth_mm.size() != object_z.size())
      throw Error(nearest->second.string() + ": expected a 16-bit depth PNG of the camera's size");
    std::vector<double> ratios;
    for (const render::ar::ArPoint& p : content.points) {
      const Eigen::Vector3d p_c = T_c_w * p.p_w;
      if (p_c.z() <= 0) continue;
      const Eigen::Vector2d px = camera.project(p_c);
      const int u = static_cast<int>(std::lround(px.x())), v = static_cast<int>(std::lround(px.y()));
      if (u < 0 || v < 0 || u >= depth_mm.cols || v >= depth_mm.rows) continue;
      const std::uint16_t mm = depth_mm.at<std::uint16_t>(v, u);
      if (mm > 0) ratios.push_back(mm * 1e-3 / p_c.z());
    }
    if (ratios.size() < 10) return in_view;
    const double metres_per_unit = median(std::move(ratios));
    cv::Mat truth_z;
    depth_mm.convertTo(truth_z, CV_32F, 1e-3 / metres_per_unit);
    occlusion.add_frame(object_z, occluder_z, truth_z);
    return in_view;
  }

  // Gives the object up when it has been out of view too long (placed again
  // on the next rendered frame).
  void forget_object_left_behind(std::size_t frame_number, bool in_view) {
    rendered_out_of_view = in_view ? 0 : rendered_out_of_view + 1;
    if (in_view) last_frame_in_view = frame_number;
    if (!last_frame_in_view || rendered_out_of_view < replay_render_detail::kReplaceAfterRenderedFramesOutOfView ||
        frame_number < *last_frame_in_view + replay_render_detail::kReplaceAfterFramesOutOfView)
      return;
    object.reset();
    ground.reset();
    rendered_out_of_view = 0;
    occlusion.break_sequence();  // the next object's hidden share is no change from this one's
  }

  // Why no object stands in the view (only asked when none does).
  std::string why_no_object() const {
    using replay_render_detail::kMinKeyframesForPlane, replay_render_detail::kMinPointsForPlane;
    if (!tracked) return "no rendered frame was tracked";
    const std::string since = last_map_reset ? " since the map reset at frame " + std::to_string(*last_map_reset) : "";
    if (no_plane_found)
      return "no plane to stand it on among the map's " + std::to_string(most_points) + " points" + since;
    return "the map never had " + std::to_string(kMinPointsForPlane) + " points in " +
           std::to_string(kMinKeyframesForPlane) + " keyframes to look for a plane in (at most " +
           std::to_string(most_points) + " points, " + std::to_string(most_keyframes) + " keyframes)" + since;
  }

  cv::Mat draw_map_view(const std::vector<PointSnapshot>& points, const std::vector<KeyFrameSnapshot>& keyframes,
                        const std::optional<Eigen::Isometry3d>& T_w_c) {
    render::MapViewContent content;
    content.points_w.reserve(points.size());
    content.colours_bgr.reserve(points.size());
    for (const PointSnapshot& p : points) {
      content.points_w.emplace_back(p.geometry.p_w.cast<float>());
      content.colours_bgr.push_back(replay_render_detail::class_bgr(semantic_class(p.point->label().label)));
    }
    std::vector<double> depths;
    for (const KeyFrameSnapshot& kf : keyframes) {
      content.keyframes_T_c_w.push_back(kf.T_c_w.isometry());
      depths.push_back(kf.mean_depth);
    }
    content.trajectory_w = trajectory_w;
    render::MapViewStyle style;
    content.legend = {{"keyframes (" + std::to_string(keyframes.size()) + ")", style.keyframe_bgr, true},
                      {"trajectory", style.trajectory_bgr, true}};
    if (keyframes.empty() || (!T_w_c && trajectory_w.empty())) {
      cv::Mat empty(map_view_size, CV_8UC3, style.background_bgr);
      cv::putText(empty, "no map yet", {12, map_view_size.height / 2}, cv::FONT_HERSHEY_SIMPLEX, 0.6,
                  cv::Scalar::all(90), 1, cv::LINE_AA);
      return empty;
    }
    // Follow the current camera, or the last tracked one while lost.
    Eigen::Isometry3d follow = T_w_c ? *T_w_c : Eigen::Isometry3d::Identity();
    if (!T_w_c) follow = keyframes.back().T_c_w.inverse().isometry();
    const double depth = median(depths);
    const render::MapViewCamera view =
        render::ar::follow_camera(follow, render::view_axes_from_cameras(content.keyframes_T_c_w), depth,
                                  map_view_size.width, map_view_size.height);
    style.point_size = std::max(2.f, std::round(3.f * map_view_size.height / 480.f));
    style.frustum_depth = 0.12 * depth;
    style.trajectory_line_width = 2.f;
    return map_view.render(content, view, style);
  }
};

ReplayRender::ReplayRender(ReplayRenderOptions options, const Camera& camera) : options_(std::move(options)) {
  if (options_.every == 0) throw Error("--render-every must be at least 1");
  // The folder first: a bad one fails before any OSMesa context exists.
  const fs::path frames_dir = options_.dir / "frames";
  try {
    fs::create_directories(frames_dir);
  } catch (const fs::filesystem_error& e) {
    throw Error(options_.dir.string() + ": cannot create the render folder (" + e.code().message() + ")");
  }
  require_writable_output(options_.dir / "contact_sheet.png");
  require_writable_output(frames_dir / "ar_000000.png");
  impl_ = std::make_unique<Impl>(options_, camera);
}

ReplayRender::~ReplayRender() = default;

void ReplayRender::before_tracking(std::size_t frame_number, const System& system) {
  if (!wants(frame_number)) return;
  auto& found_before = impl_->found_before;
  found_before.clear();
  system.map().read([&](const MapView& view) {
    for (const auto& [id, point] : view.points()) found_before[id] = point->times_found();
  });
}

void ReplayRender::after_tracking(std::size_t frame_number, const FrameReport& report, const cv::Mat& image,
                                  const System& system) {
  Impl& m = *impl_;
  if (report.map_reset) {
    // The map was given up: its world frame and scale go with it, so the
    // object and the trajectory so far are placed again in the next map.
    m.object.reset();
    m.ground.reset();
    m.trajectory_w.clear();
    m.plane = Json();
    m.most_points = m.most_keyframes = 0;
    m.no_plane_found = false;
    m.last_map_reset = frame_number;
    m.last_frame_in_view.reset();
    m.rendered_out_of_view = 0;
    m.spacing.reset();
    m.occlusion.break_sequence();
  }
  std::optional<Eigen::Isometry3d> T_w_c;
  if (report.has_pose) {
    T_w_c = report.T_c_w.inverse().isometry();
    m.trajectory_w.emplace_back(T_w_c->translation());
  }
  if (!wants(frame_number)) return;
  const Stopwatch stopwatch;
  const std::vector<PointSnapshot> points = system.map().snapshot_points();
  const std::vector<KeyFrameSnapshot> keyframes = system.map().snapshot_keyframes();
  if (T_w_c) m.place_object(points, keyframes, frame_number);

  render::ar::ArFrameContent content;
  content.image = image;
  content.T_w_c = T_w_c;
  content.object = m.object;
  if (T_w_c && m.object) content.occluder_depth = m.occluders(points, T_w_c->inverse());
  std::map<std::string, cv::Vec3b> legend;
  if (T_w_c) {
    for (const PointSnapshot& p : points) {
      const auto before = m.found_before.find(p.point->id());
      if (before == m.found_before.end() || p.point->times_found() <= before->second) continue;
      const replay_render_detail::PointColour colour = replay_render_detail::point_colour(p);
      content.points.push_back({p.geometry.p_w, colour.bgr});
      legend.emplace(colour.legend, colour.bgr);
    }
  }
  for (const auto& [text, bgr] : legend) content.legend.push_back({text, bgr, false});
  render::ar::ArFrameStats stats;
  cv::Mat ar = m.ar_view.render(content, &stats);
  if (T_w_c && m.object)
    m.forget_object_left_behind(frame_number, m.score_occlusion(report.timestamp, content, T_w_c->inverse()));
  const bool overlay = stats.object_drawn || stats.points_drawn > 0;
  if (!overlay) ++m.without_overlay;
  const std::string status = std::string(to_string(report.status)) + (T_w_c ? "" : " (no overlay)");
  const std::string caption =
      "frame " + std::to_string(frame_number) + "  " + status + "  " + std::to_string(stats.points_drawn) + " points";
  cv::putText(ar, caption, {8, ar.rows - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar::all(0), 3, cv::LINE_AA);
  cv::putText(ar, caption, {8, ar.rows - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar::all(255), 1, cv::LINE_AA);

  cv::Mat frame(m.frame_size, CV_8UC3, cv::Scalar::all(0));
  ar.copyTo(frame(cv::Rect(0, 0, ar.cols, ar.rows)));
  const cv::Mat map_picture = m.draw_map_view(points, keyframes, T_w_c);
  map_picture.copyTo(frame(cv::Rect(ar.cols, 0, map_picture.cols, map_picture.rows)));

  char name[32];
  std::snprintf(name, sizeof name, "ar_%06zu.png", frame_number);
  // Drawing time only: the writer thread encodes and writes meanwhile.
  m.render_ms.push_back(stopwatch.elapsed_ms());
  m.writer->write(m.frames_dir / name, caption, std::move(frame));
  ++m.rendered;
}

std::string ReplayRender::video_codec() const {
  return impl_->video->fourcc() + " (" + impl_->video->codec_name() + ")";
}

Json ReplayRender::finish(double replay_fps) {
  Impl& m = *impl_;
  m.writer->finish();
  m.video->finish();
  if (!m.sheet.empty()) plot::save_png(m.sheet_path, m.sheet.image());
  Json out = Json::object();
  out["frames_rendered"] = m.rendered;
  out["frames_without_overlay"] = m.without_overlay;
  out["every"] = options_.every;
  const fs::path reported = options_.reported_dir.empty() ? options_.dir : options_.reported_dir;
  out["frames_dir"] = (reported / m.frames_dir.filename()).string();
  out["video"] = (reported / m.video_path.filename()).string();
  out["video_codec"] = video_codec();
  out["contact_sheet"] = m.sheet.empty() ? Json() : Json((reported / m.sheet_path.filename()).string());
  out["frame_size"] = std::to_string(m.frame_size.width) + "x" + std::to_string(m.frame_size.height);
  out["gl_renderer"] = m.ar_view.gl_renderer();
  // The last placement, also when the object was given up out of view
  // just before the end (it would have been placed again).
  if (!m.plane.is_null()) {
    out["plane"] = m.plane;
  } else {
    const std::string why = m.why_no_object();
    spdlog::warn("render: no virtual object in the view: {}", why);
    out["plane"] = Json{{"kind", "none"}, {"why", why}};
  }
  // Occlusion by the map: frames the object was drawn in, those where part
  // of it showed; with a synthetic sequence's true depth, how well the map
  // hid it (render/ar/occlusion_score.hpp).
  out["frames_with_object"] = m.frames_with_object;
  out["frames_object_visible"] = m.frames_object_visible;
  if (m.occlusion.frames() > 0) {
    out["occlusion_iou"] = m.occlusion.iou() ? Json(*m.occlusion.iou()) : Json();
    out["occlusion_frames_scored"] = m.occlusion.frames();
    out["occlusion_hidden_render"] = m.occlusion.hidden_share_render();
    out["occlusion_hidden_truth"] = m.occlusion.hidden_share_truth();
    const auto or_null = [](const std::optional<double>& v) { return v ? Json(*v) : Json(); };
    out["occlusion_precision"] = or_null(m.occlusion.precision());
    out["occlusion_recall"] = or_null(m.occlusion.recall());
    out["occlusion_flicker"] = m.occlusion.flicker_render();
    out["occlusion_flicker_truth"] = m.occlusion.flicker_truth();
  }
  out["render_ms"] = timing_summary(m.render_ms);
  out["replay_fps"] = replay_fps;
  return out;
}

}  // namespace facadeslam::apps
