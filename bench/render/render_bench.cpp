// Frames per second of the synthetic-sequence renderer at 640x480 on the demo
// street (configs/scenes/demo.yaml, whose photos are committed): the bare
// render of colour + labels + depth at three anisotropic-filtering levels,
// the full frame of `facadeslam synth` (plus lighting, noise, quantisation),
// and, as the peer measured in the same run, encoding that frame's three
// PNGs — the other half of what `synth` spends per frame.
//
// The augmented view of `replay --render` (render/ar/ar_view.hpp) at 640x480
// and 1226x370 (KITTI's size), undistorted and distorted: the overlay alone
// (image upload, the object, ~300 points, read-back, legend) and with the
// map view beside it; the street render at the same sizes is its peer in
// the same run (compare ratios, not absolute times, on a shared machine).
#include <filesystem>
#include <memory>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/imgcodecs.hpp>

#include "render/ar/ar_view.hpp"
#include "render/ar/follow_camera.hpp"
#include "render/ar/map_occlusion.hpp"
#include "render/ar/video_writer.hpp"
#include "render/map_view.hpp"
#include "render/offscreen_renderer.hpp"
#include "sequences/synth/camera_path.hpp"
#include "sequences/synth/frame_synthesizer.hpp"
#include "sequences/synth/label_classes.hpp"
#include "sequences/synth/scene_loader.hpp"
#include "sequences/synth/street_scene.hpp"

namespace {

using namespace facadeslam;

const synth::SceneSpec& demo_scene() {
  static const synth::SceneSpec spec = synth::load_scene("configs/scenes/demo.yaml");
  return spec;
}

constexpr double kMidSequence = 2.5;  // seconds: a view down the street

// Frames per second of process CPU time (all threads, llvmpipe's included):
// stable on a shared machine, unlike wall time.
void frames_per_second(benchmark::State& state) {
  state.counters["frames_per_cpu_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_RenderColourLabelDepth(benchmark::State& state) {
  const synth::SceneSpec& spec = demo_scene();
  render::Renderer renderer(render::RendererSettings{0.05, static_cast<float>(state.range(0))});
  const synth::StreetScene street(spec, renderer);
  const synth::CameraPath path(spec.start, spec.trajectory, spec.handheld, spec.seed);
  const render::Scene scene = street.at(kMidSequence);
  const Eigen::Isometry3d T_w_c = path.T_w_c(kMidSequence);
  static const bool described = (benchmark::AddCustomContext("renderer", renderer.gl_renderer()), true);
  (void)described;
  for (auto _ : state) {
    const render::RenderResult out = renderer.render(scene, spec.camera, T_w_c);
    benchmark::DoNotOptimize(out.colour.data);
  }
  frames_per_second(state);
}
BENCHMARK(BM_RenderColourLabelDepth)
    ->ArgName("anisotropy")
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(16)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

void BM_SynthFrame(benchmark::State& state) {
  const synth::SceneSpec& spec = demo_scene();
  synth::FrameSynthesizer synthesizer(spec);
  int index = 0;
  for (auto _ : state) {
    const synth::SynthFrame frame = synthesizer.render(index);
    benchmark::DoNotOptimize(frame.colour.data);
    index = (index + 1) % spec.frames;
  }
  frames_per_second(state);
}
BENCHMARK(BM_SynthFrame)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

// The peer: encoding the three PNGs of one frame (what `synth` writes).
void BM_EncodeFramePngs(benchmark::State& state) {
  const synth::SceneSpec& spec = demo_scene();
  synth::FrameSynthesizer synthesizer(spec);
  const synth::SynthFrame frame = synthesizer.render(75);
  const cv::Mat label_colours = synth::colours_from_label_ids(frame.labels);
  std::vector<std::uint8_t> buffer;
  for (auto _ : state) {
    cv::imencode(".png", frame.colour, buffer);
    cv::imencode(".png", label_colours, buffer);
    cv::imencode(".png", frame.depth_mm, buffer);
    benchmark::DoNotOptimize(buffer.data());
  }
  frames_per_second(state);
}
BENCHMARK(BM_EncodeFramePngs)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

// The demo camera at `width` x `height` (range 0, 1), with the lens
// distortion of a typical phone (range 2 = 1) or none.
// The demo's and KITTI's image sizes, each with and without lens distortion.
void at_both_sizes_plain_and_distorted(benchmark::internal::Benchmark* b) {
  b->ArgNames({"width", "height", "distorted"});
  for (const int distorted : {0, 1}) b->Args({640, 480, distorted})->Args({1226, 370, distorted});
  b->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);
}

Camera bench_camera(const benchmark::State& state) {
  const Camera base = demo_scene().camera.resized(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  if (state.range(2) == 0) return base;
  return Camera(base.width(), base.height(),
                PinholeRadTan{.fx = base.fx(),
                              .fy = base.fy(),
                              .cx = base.cx(),
                              .cy = base.cy(),
                              .k1 = -0.12,
                              .k2 = 0.03,
                              .p1 = 0.0005,
                              .p2 = -0.0004});
}

// The street at the AR view's sizes: the peer of the overlay.
void BM_RenderStreetAtSize(benchmark::State& state) {
  const synth::SceneSpec& spec = demo_scene();
  render::Renderer renderer;
  const synth::StreetScene street(spec, renderer);
  const synth::CameraPath path(spec.start, spec.trajectory, spec.handheld, spec.seed);
  const render::Scene scene = street.at(kMidSequence);
  const Camera camera = bench_camera(state);
  for (auto _ : state) {
    const render::RenderResult out = renderer.render(scene, camera, path.T_w_c(kMidSequence), render::kColour);
    benchmark::DoNotOptimize(out.colour.data);
  }
  frames_per_second(state);
}
BENCHMARK(BM_RenderStreetAtSize)->Apply(at_both_sizes_plain_and_distorted);

// A frame of the street with ~300 "measured" points on its surfaces (from
// the depth image) and the object standing on the road ahead.
struct ArBenchFrame {
  render::ar::ArFrameContent content;
  std::vector<Eigen::Vector3f> map_points;
};

ArBenchFrame ar_bench_frame(const Camera& camera) {
  const synth::SceneSpec& spec = demo_scene();
  render::Renderer renderer;
  const synth::StreetScene street(spec, renderer);
  const synth::CameraPath path(spec.start, spec.trajectory, spec.handheld, spec.seed);
  const Eigen::Isometry3d T_w_c = path.T_w_c(kMidSequence);
  const render::RenderResult out = renderer.render(street.at(kMidSequence), camera, T_w_c);
  ArBenchFrame frame;
  out.colour.convertTo(frame.content.image, CV_8UC3);
  frame.content.T_w_c = T_w_c;
  std::mt19937 random(4);
  while (frame.content.points.size() < 300) {
    const int x = static_cast<int>(random() % static_cast<unsigned>(camera.width()));
    const int y = static_cast<int>(random() % static_cast<unsigned>(camera.height()));
    const float z = out.depth.at<float>(y, x);
    if (z <= 0.f) continue;
    const Eigen::Vector3d ray = camera.unproject(Eigen::Vector2d(x, y));
    const Eigen::Vector3d p_w = T_w_c * (ray * (z / ray.z()));
    frame.content.points.push_back({p_w, cv::Vec3b(0, 0, 255)});
    frame.map_points.emplace_back(p_w.cast<float>());
  }
  // The object 6 m ahead on the ground (the street's ground is z = 0).
  render::ar::VirtualObject object;
  Eigen::Vector3d ahead = T_w_c * Eigen::Vector3d(0.5, 0.0, 6.0);
  ahead.z() = 0.0;
  object.T_w_o.translation() = ahead;
  object.size = 1.2;
  frame.content.object = object;
  frame.content.legend = {{"building", cv::Vec3b(0, 0, 128), false}, {"level 0", cv::Vec3b(0, 0, 255), false}};
  return frame;
}

void BM_ArOverlay(benchmark::State& state) {
  const Camera camera = bench_camera(state);
  const ArBenchFrame frame = ar_bench_frame(camera);
  render::ar::ArView view(camera);
  for (auto _ : state) {
    const cv::Mat image = view.render(frame.content);
    benchmark::DoNotOptimize(image.data);
  }
  frames_per_second(state);
}
BENCHMARK(BM_ArOverlay)->Apply(at_both_sizes_plain_and_distorted);

// The same overlay with the map hiding the object: the occluders' depth
// made from the frame's points every frame (half of them a facade's
// surface, half sparse), then the object tested against it. Its ratio to
// BM_ArOverlay of the same run is the cost of occlusion.
void BM_ArOverlayWithOcclusion(benchmark::State& state) {
  const Camera camera = bench_camera(state);
  ArBenchFrame frame = ar_bench_frame(camera);
  render::ar::ArView view(camera);
  std::vector<render::ar::OccluderPoint> occluders;
  for (std::size_t i = 0; i < frame.map_points.size(); ++i)
    occluders.push_back({frame.map_points[i].cast<double>(),
                         i % 2 ? render::ar::OccluderKind::sparse : render::ar::OccluderKind::surface});
  const double spacing = render::ar::point_spacing(occluders);
  const Eigen::Isometry3d T_c_w = frame.content.T_w_c->inverse();
  for (auto _ : state) {
    const render::PinholeIntrinsics& intrinsics = view.object_intrinsics();
    frame.content.occluder_depth = render::ar::occluder_depth(
        occluders, T_c_w, intrinsics, spacing, {}, render::ar::object_region(*frame.content.object, T_c_w, intrinsics));
    const cv::Mat image = view.render(frame.content);
    benchmark::DoNotOptimize(image.data);
  }
  frames_per_second(state);
}
BENCHMARK(BM_ArOverlayWithOcclusion)->Apply(at_both_sizes_plain_and_distorted);

// The overlay and the map view beside it (what `replay --render` draws per
// frame, before PNG and video encoding).
void BM_ArOverlayWithMapView(benchmark::State& state) {
  const Camera camera = bench_camera(state);
  const ArBenchFrame frame = ar_bench_frame(camera);
  render::ar::ArView view(camera);
  render::MapView map_view;
  render::MapViewContent content;
  content.points_w = frame.map_points;
  content.colours_bgr.assign(frame.map_points.size(), cv::Vec3b(0, 0, 128));
  const render::MapViewCamera map_camera = render::ar::follow_camera(
      *frame.content.T_w_c, render::ViewAxes{Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()}, 8.0,
      camera.height() * 4 / 3, camera.height());
  for (auto _ : state) {
    const cv::Mat image = view.render(frame.content);
    const cv::Mat map_image = map_view.render(content, map_camera);
    benchmark::DoNotOptimize(image.data);
    benchmark::DoNotOptimize(map_image.data);
  }
  frames_per_second(state);
}
BENCHMARK(BM_ArOverlayWithMapView)
    ->ArgNames({"width", "height", "distorted"})
    ->Args({640, 480, 0})
    ->Args({1226, 370, 0})
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

// What the writer thread of `replay --render` spends per 1280x480 frame
// (the overlay beside a map view): the PNG at zlib level 1, and the video
// frame (H.264 where OpenCV's FFmpeg offers it).
cv::Mat composed_frame() {
  const Camera camera = demo_scene().camera;
  const ArBenchFrame frame = ar_bench_frame(camera);
  render::ar::ArView view(camera);
  cv::Mat composed(camera.height(), 2 * camera.width(), CV_8UC3, cv::Scalar::all(238));
  view.render(frame.content).copyTo(composed(cv::Rect(0, 0, camera.width(), camera.height())));
  return composed;
}

void BM_EncodeArFramePng(benchmark::State& state) {
  const cv::Mat frame = composed_frame();
  std::vector<std::uint8_t> buffer;
  for (auto _ : state) {
    cv::imencode(".png", frame, buffer, {cv::IMWRITE_PNG_COMPRESSION, static_cast<int>(state.range(0))});
    benchmark::DoNotOptimize(buffer.data());
  }
  state.counters["bytes"] = static_cast<double>(buffer.size());
  frames_per_second(state);
}
BENCHMARK(BM_EncodeArFramePng)
    ->ArgName("zlib_level")
    ->Arg(1)
    ->Arg(9)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

void BM_EncodeArFrameVideo(benchmark::State& state) {
  const cv::Mat frame = composed_frame();
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "facadeslam-bench-ar.mp4";
  {
    render::ar::Mp4Writer video(path, 30.0, frame.size());
    static const bool described = (benchmark::AddCustomContext("ar_video_codec", video.fourcc()), true);
    (void)described;
    for (auto _ : state) video.write(frame);
  }  // not finished: the temporary file is removed
  frames_per_second(state);
}
BENCHMARK(BM_EncodeArFrameVideo)->MeasureProcessCPUTime()->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
