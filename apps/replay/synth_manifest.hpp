#pragma once
// A synthetic sequence carries its manifest, synth.json (sequences/synth/
// sequence_writer.hpp): `replay` checks that the frame list beside it is
// the one that run wrote, so that a folder edited or mixed by hand is
// refused with one line instead of replayed against the wrong ground truth.
#include <filesystem>

namespace facadeslam::apps {

// For a TUM list (`sequence` is a folder with rgb.txt, or the list itself)
// with a synth.json beside it: the manifest parses, and its frame count is
// the number of frames the list holds. Error naming synth.json otherwise.
// Anything else (no manifest, an image folder, a video): nothing to check.
void check_synth_manifest(const std::filesystem::path& sequence);

}  // namespace facadeslam::apps
