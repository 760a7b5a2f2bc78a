// `facadeslam render-map`: a picture of a replay's labelled point cloud
// (map.ply), coloured by class, with the keyframe cameras and the trajectory,
// rendered headless (OSMesa) from an oblique or a top view.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "apps/output_kinds.hpp"
#include "core/map/point_cloud_reader.hpp"
#include "core/map/semantic_classes.hpp"
#include "core/plot/png_file.hpp"
#include "core/trajectory/trajectory_io.hpp"
#include "core/util/error.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/output_policy.hpp"
#include "render/map_view.hpp"
#include "render/map_view_framing.hpp"

namespace facadeslam::apps {
// Named, so that a unity build can hold every command's Options and run().
namespace render_map_command {
namespace {

struct Options {
  std::filesystem::path map_ply, keyframes, trajectory, out;
  std::string view = "oblique";
  std::string size = "1280x720";
  float point_size = 0.f;  // 0: by image height
};

// The class name and colour of each label present, from the file's own
// class table (falling back to ours), with its count, in id order.
std::vector<render::LegendEntry> class_legend(const LabelledPointCloud& cloud) {
  std::map<int, std::size_t> counts;
  for (const LabelledPoint& p : cloud.points) ++counts[p.label];
  std::vector<render::LegendEntry> legend;
  for (const auto& [label, count] : counts) {
    std::string name(semantic_class(static_cast<std::uint8_t>(label)).name);
    for (const PointCloudClass& c : cloud.classes)
      if (c.id == label) name = c.name;
    // The colour the points are drawn in: that of the first point with the label.
    // (A copy of the binding: clang 14 cannot capture a structured binding.)
    const int wanted = label;
    const auto first = std::find_if(cloud.points.begin(), cloud.points.end(),
                                    [wanted](const LabelledPoint& p) { return p.label == wanted; });
    legend.push_back({name + " (" + std::to_string(count) + ")", cv::Vec3b(first->b, first->g, first->r), false});
  }
  return legend;
}

void run(const Options& o) {
  require_file(o.map_ply, "a map.ply written by `facadeslam replay`");
  if (!o.keyframes.empty()) require_file(o.keyframes, "a TUM keyframes.txt written by `facadeslam replay`");
  if (!o.trajectory.empty()) require_file(o.trajectory, "a TUM trajectory.txt written by `facadeslam replay`");
  std::string extension = o.out.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (extension != ".png") fail_file(o.out, "expected an output file name ending in .png");
  int width = 0, height = 0;
  try {
    std::tie(width, height) = parse_image_size(o.size, "--size");
  } catch (const Error& e) {
    throw CLI::ValidationError(e.what());  // a bad command line: exit code 2
  }
  // The picture replaces only a picture, never an input (output_policy.hpp).
  OutputPlan plan;
  plan.input(o.map_ply, "--map-ply");
  plan.input(o.keyframes, "--keyframes");
  plan.input(o.trajectory, "--trajectory");
  plan.output_file(o.out, "--out", png_picture_kind());
  plan.check();
  require_writable_output(o.out);
  const InterruptGuard interrupts(InterruptResponse::end_at_once);

  const LabelledPointCloud cloud = read_labelled_point_cloud(o.map_ply);
  render::MapViewContent content;
  content.points_w.reserve(cloud.points.size());
  content.colours_bgr.reserve(cloud.points.size());
  for (const LabelledPoint& p : cloud.points) {
    content.points_w.push_back(p.p_w);
    content.colours_bgr.emplace_back(p.b, p.g, p.r);
  }
  content.legend = class_legend(cloud);

  render::MapViewStyle style;
  std::vector<Eigen::Isometry3d> cameras_T_c_w;  // for "up" and "forward"
  std::vector<Eigen::Vector3d> anchors_w;        // always in the picture
  if (!o.keyframes.empty()) {
    for (const StampedPose& kf : read_trajectory(o.keyframes, TrajectoryFormat::tum)) {
      content.keyframes_T_c_w.push_back(kf.T_w_c.inverse());
      anchors_w.push_back(kf.T_w_c.translation());
    }
    cameras_T_c_w = content.keyframes_T_c_w;
    content.legend.push_back(
        {"keyframes (" + std::to_string(content.keyframes_T_c_w.size()) + ")", style.keyframe_bgr, true});
  }
  if (!o.trajectory.empty()) {
    const Trajectory trajectory = read_trajectory(o.trajectory, TrajectoryFormat::tum);
    for (const StampedPose& pose : trajectory) content.trajectory_w.push_back(pose.T_w_c.translation());
    if (cameras_T_c_w.empty())
      for (const StampedPose& pose : trajectory) cameras_T_c_w.push_back(pose.T_w_c.inverse());
    if (anchors_w.empty()) anchors_w = content.trajectory_w;
    content.legend.push_back(
        {"trajectory (" + std::to_string(trajectory.size()) + " frames)", style.trajectory_bgr, true});
  }

  const render::MapViewKind kind = o.view == "top" ? render::MapViewKind::top : render::MapViewKind::oblique;
  const render::MapViewFraming framing = render::frame_map_view(
      content.points_w, anchors_w, render::view_axes_from_cameras(cameras_T_c_w), kind, width, height);
  // Sizes that read well at 1280x720, scaled with the picture.
  const float scale = static_cast<float>(height) / 720.f;
  style.point_size = o.point_size > 0 ? o.point_size : std::max(3.f, std::round(6.f * scale));
  style.frustum_line_width = std::max(1.f, std::round(1.f * scale));
  style.trajectory_line_width = std::max(1.f, std::round(3.f * scale));
  style.frustum_depth = 0.02 * framing.box_diagonal;

  render::MapView view;
  const cv::Mat picture = view.render(content, framing.camera, style);
  plot::save_png(o.out, picture);
  std::printf("render-map: %zu points, %zu keyframes, %zu trajectory poses, %s view -> %s (%dx%d)\n",
              content.points_w.size(), content.keyframes_T_c_w.size(), content.trajectory_w.size(), o.view.c_str(),
              o.out.string().c_str(), width, height);
  std::fflush(stdout);
}

}  // namespace
}  // namespace render_map_command

void add_render_map_command(CLI::App& app) {
  using namespace render_map_command;
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "render-map", "Picture of a replay's labelled point cloud (map.ply) coloured by class, rendered headless");
  cmd->add_option("--map-ply", o->map_ply, "The labelled point cloud a replay wrote (OUT/map.ply)")->required();
  cmd->add_option("--keyframes", o->keyframes, "Draw the keyframe cameras of OUT/keyframes.txt (TUM)");
  cmd->add_option("--trajectory", o->trajectory, "Draw the camera path of OUT/trajectory.txt (TUM)");
  cmd->add_option("--out", o->out, "PNG file to write (replaces only a PNG picture facadeslam drew)")
      ->required()
      ->check(kNonEmptyPath);
  cmd->add_option("--view", o->view,
                  "oblique: from behind the cameras and above; top: straight down (up = the keyframes' mean -y axis)")
      ->check(CLI::IsMember({"oblique", "top"}))
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Picture size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--point-size", o->point_size, "Dot diameter in pixels (default: 6 at 720 rows, scaled)")
      ->check(CLI::Range(1.0, 64.0));
  cmd->callback([o] { run(*o); });
}

}  // namespace facadeslam::apps
