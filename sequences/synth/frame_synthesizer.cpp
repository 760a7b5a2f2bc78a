#include "sequences/synth/frame_synthesizer.hpp"

#include "core/util/error.hpp"
#include "sequences/synth/image_output.hpp"
#include "sequences/synth/lighting.hpp"

namespace facadeslam::synth {

FrameSynthesizer::FrameSynthesizer(const SceneSpec& spec)
    : spec_(spec),
      renderer_(render::RendererSettings{0.05, static_cast<float>(spec.anisotropy)}),
      street_(spec, renderer_),
      path_(spec.start, spec.trajectory, spec.handheld, spec.seed) {}

SynthFrame FrameSynthesizer::render(int index) {
  if (index < 0 || index >= spec_.frames)
    throw Error("synth: frame " + std::to_string(index) + " is outside 0.." + std::to_string(spec_.frames - 1));
  SynthFrame frame;
  frame.index = index;
  frame.timestamp = timestamp(index);
  frame.T_w_c = path_.T_w_c(frame.timestamp);

  const int samples = spec_.motion_blur.shutter > 0.0 ? spec_.motion_blur.samples : 1;
  cv::Mat colour;
  render::RenderResult at_timestamp;
  if (samples <= 1) {
    at_timestamp = renderer_.render(street_.at(frame.timestamp), spec_.camera, frame.T_w_c);
    colour = at_timestamp.colour;
  } else {
    // Sub-frames spread evenly over the exposure, centred on the timestamp;
    // with an odd count the middle one is exactly at the timestamp and also
    // gives the labels and depth.
    const double exposure = spec_.motion_blur.shutter / spec_.fps;
    colour = cv::Mat::zeros(spec_.camera.height(), spec_.camera.width(), CV_32FC3);
    for (int k = 0; k < samples; ++k) {
      const bool middle = samples % 2 == 1 && k == samples / 2;
      const double t = middle ? frame.timestamp : frame.timestamp + exposure * ((k + 0.5) / samples - 0.5);
      render::RenderResult sub =
          renderer_.render(street_.at(t), spec_.camera, path_.T_w_c(t), middle ? render::kAllLayers : render::kColour);
      colour += sub.colour;
      if (middle) at_timestamp = sub;
    }
    colour /= samples;
    if (samples % 2 == 0)
      at_timestamp =
          renderer_.render(street_.at(frame.timestamp), spec_.camera, frame.T_w_c, render::kLabels | render::kDepth);
  }
  apply_illumination(colour, illumination_at(spec_.lighting, frame.timestamp));
  add_pixel_noise(colour, spec_.noise_sigma, spec_.seed, index);
  frame.colour = quantise(colour);
  frame.labels = at_timestamp.labels;
  frame.depth_mm = depth_millimetres(at_timestamp.depth);
  return frame;
}

}  // namespace facadeslam::synth
