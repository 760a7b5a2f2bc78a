#include "sequences/synth/synthesize.hpp"

#include <algorithm>
#include <cstdio>
#include <future>
#include <memory>

#include <opencv2/imgcodecs.hpp>

#include "core/plot/png_file.hpp"
#include "core/util/error.hpp"
#include "sequences/synth/contact_sheet.hpp"
#include "sequences/synth/frame_synthesizer.hpp"
#include "sequences/synth/label_classes.hpp"
#include "sequences/synth/sequence_writer.hpp"
#include "core/util/stopwatch.hpp"

namespace facadeslam::synth {
namespace {

Json report(const SceneSpec& spec, const std::string& renderer) {
  Json j = Json::object();
  j["generator"] = "facadeslam synth";
  j["scene"] = spec.path.string();
  j["frames"] = spec.frames;
  j["fps"] = spec.fps;
  j["seed"] = static_cast<long long>(spec.seed);
  j["width"] = spec.camera.width();
  j["height"] = spec.camera.height();
  j["camera_model"] = spec.camera.model_name();
  j["noise_sigma"] = spec.noise_sigma;
  j["anisotropy"] = spec.anisotropy;
  Json blur = Json::object();
  blur["samples"] = spec.motion_blur.samples;
  blur["shutter"] = spec.motion_blur.shutter;
  j["motion_blur"] = blur;
  j["lighting_keys"] = static_cast<int>(spec.lighting.size());
  j["facades"] = static_cast<int>(spec.facades.size());
  j["cars"] = static_cast<int>(spec.cars.size());
  j["vegetation"] = static_cast<int>(spec.vegetation.size());
  j["trajectory_seconds"] = spec.trajectory_duration();
  j["renderer"] = renderer;
  Json classes = Json::array();
  for (const auto& c : facade_classes()) classes.push_back(std::string(c.name));
  j["classes"] = classes;
  return j;
}

}  // namespace

SynthSummary synthesize_sequence(const SceneSpec& spec, const std::filesystem::path& folder,
                                 const SynthOptions& options) {
  const Stopwatch start;
  FrameSynthesizer synthesizer(spec);
  SequenceWriter writer(folder, spec);
  const std::vector<int> sheet_frames = options.contact_sheet.empty()
                                            ? std::vector<int>{}
                                            : contact_sheet_frames(spec.frames, options.contact_sheet_frames);
  ContactSheet sheet(spec.path.stem().string() + "  (" + std::to_string(spec.frames) + " frames, " +
                     std::to_string(spec.camera.width()) + "x" + std::to_string(spec.camera.height()) + ")");
  // Frame i is encoded and written on a second thread while frame i + 1 is
  // rendered (PNG encoding is about as costly as rendering). One write at a
  // time, in frame order; its error, if any, surfaces at the next get().
  std::future<void> writing;
  for (int i = 0; i < spec.frames; ++i) {
    auto frame = std::make_shared<const SynthFrame>(synthesizer.render(i));
    if (std::binary_search(sheet_frames.begin(), sheet_frames.end(), i)) {
      char caption[64];
      std::snprintf(caption, sizeof caption, "frame %d  t=%.2fs", i, frame->timestamp);
      sheet.add(caption, frame->colour, colours_from_label_ids(frame->labels));
    }
    if (writing.valid()) writing.get();
    if (options.progress && i > 0) options.progress(i);
    writing = std::async(std::launch::async, [&writer, frame] { writer.write(*frame); });
  }
  if (writing.valid()) writing.get();
  if (options.progress) options.progress(spec.frames);
  SynthSummary summary;
  summary.frames = spec.frames;
  summary.renderer = synthesizer.gl_renderer();
  writer.finish(report(spec, summary.renderer));
  if (!options.contact_sheet.empty()) plot::save_png(options.contact_sheet, sheet.image(), {});
  summary.seconds = start.elapsed_s();
  return summary;
}

}  // namespace facadeslam::synth
