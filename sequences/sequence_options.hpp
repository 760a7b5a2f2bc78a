#pragma once
// How a sequence is read: which frames (start/stride/limit, applied by every
// reader in that order), what to do with an undecodable image, and the frame
// rate used when the input carries no timestamps.
#include <cstddef>
#include <filesystem>
#include <string>

namespace facadeslam {

enum class CorruptPolicy {
  stop,  // an undecodable image is an Error naming the file
  skip,  // warn, count it in ReadStats and go on with the next image
};

struct SequenceOptions {
  std::size_t start = 0;   // skip this many frames first
  std::size_t stride = 1;  // then keep every stride-th frame (>= 1)
  std::size_t limit = 0;   // at most this many frames (0 = all)
  // Play the selected frames this many times (>= 1; looping_source.hpp).
  std::size_t loops = 1;
  CorruptPolicy on_corrupt = CorruptPolicy::stop;
  // Frames per second for image folders without a timestamps file (and
  // videos whose container has no usable frame rate); must be > 0.
  double fps = 30.0;
  // Image folders only: an explicit timestamps file (one timestamp per image,
  // in name order). Empty: use times.txt or timestamps.txt in the folder if
  // present, else index / fps.
  std::filesystem::path timestamps_file;
};

// Throws Error when stride or loops is 0, loops is absurd (> 1e6), or fps is not a positive finite number.
void validate(const SequenceOptions& options);

// "stop" / "skip" (for command lines and configs); anything else is an Error.
CorruptPolicy corrupt_policy_from_string(const std::string& text);
std::string to_string(CorruptPolicy policy);

}  // namespace facadeslam
