// Frames per second of the synthetic-sequence renderer at 640x480 on the demo
// street (configs/scenes/demo.yaml, whose photos are committed): the bare
// render of colour + labels + depth at three anisotropic-filtering levels,
// the full frame of `facadeslam synth` (plus lighting, noise, quantisation),
// and, as the peer measured in the same run, encoding that frame's three
// PNGs — the other half of what `synth` spends per frame.
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/imgcodecs.hpp>

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
BENCHMARK(BM_RenderColourLabelDepth)->ArgName("anisotropy")->Arg(1)->Arg(2)->Arg(4)->Arg(16)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

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

}  // namespace

BENCHMARK_MAIN();
