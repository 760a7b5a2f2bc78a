#pragma once
// The whole `facadeslam synth` job: render every frame of a scene and write
// the sequence folder (sequence_writer.hpp has the layout).
#include <filesystem>
#include <functional>
#include <string>

#include "sequences/synth/scene.hpp"

namespace facadeslam::synth {

struct SynthOptions {
  // Also write a contact sheet of `contact_sheet_frames` frames here (empty: none).
  std::filesystem::path contact_sheet;
  int contact_sheet_frames = 6;
  // Called after each frame with the number done so far.
  std::function<void(int done)> progress;
};

struct SynthSummary {
  int frames = 0;
  double seconds = 0.0;  // wall-clock time of rendering and writing
  std::string renderer;  // GL_RENDERER
};

SynthSummary synthesize_sequence(const SceneSpec& spec, const std::filesystem::path& folder,
                                 const SynthOptions& options = {});

}  // namespace facadeslam::synth
