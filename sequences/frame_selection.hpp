#pragma once
// start/stride/limit in one place so that every reader selects the same
// frames: frame i of the whole sequence is kept when i >= start and
// (i - start) is a multiple of stride, up to `limit` kept frames.
#include <cstddef>

#include "sequences/sequence_options.hpp"

namespace facadeslam {

// Whether frame `index` passes start and stride (limit is counted by the caller).
bool passes_start_and_stride(std::size_t index, const SequenceOptions& options);

// How many of `total` frames are kept, limit included.
std::size_t selected_count(std::size_t total, const SequenceOptions& options);

}  // namespace facadeslam
