#pragma once
// One entry point that picks the reader from what the path is:
//   a folder holding rgb.txt  -> TumListSource on that rgb.txt
//   any other folder          -> ImageFolderSource
//   a file ending in .txt     -> TumListSource
//   any other file            -> VideoSource
#include <filesystem>
#include <memory>

#include "sequences/frame_source.hpp"
#include "sequences/sequence_options.hpp"

namespace facadeslam {

enum class SequenceKind { image_folder, tum_list, video };

// The reader open_sequence() would use for `path`. Error when the path does
// not exist: "PATH: no such file or folder (expected an image folder, a TUM
// rgb.txt list or a video file)".
SequenceKind detect_sequence_kind(const std::filesystem::path& path);

// Opens the reader (listing or opening only; frames are decoded by next()).
// Error on invalid options, on a timestamps file given for anything but an
// image folder, and on every bad input the readers report.
std::unique_ptr<FrameSource> open_sequence(const std::filesystem::path& path, const SequenceOptions& options);

}  // namespace facadeslam
