#pragma once
// A TUM RGB-D style list (rgb.txt): one "timestamp relative/path.png" per
// line, '#' comments and blank lines ignored, paths relative to the list's
// folder (absolute paths are used as they are; paths cannot contain spaces).
//
// Errors, each naming the list file and line: a line that is not exactly a
// timestamp and a path, a timestamp that is not a number or not after the
// previous one, and a listed image that does not exist. A missing image is
// an Error whatever the corrupt policy, and is found when the list is opened:
// it means the list and the folder disagree (wrong folder, partial copy),
// which is worth stopping for before any processing starts. Images that exist
// but cannot be decoded follow the corrupt policy while reading.
#include <filesystem>

#include "sequences/image_list_source.hpp"
#include "sequences/sequence_options.hpp"

namespace facadeslam {

class TumListSource : public ImageListSource {
 public:
  // Parses and checks the list (no image is decoded yet). Error when the list
  // is missing, empty or malformed (see above).
  TumListSource(const std::filesystem::path& list_file, const SequenceOptions& options);
};

}  // namespace facadeslam
