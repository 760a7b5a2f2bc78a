#include "sequences/frame_selection.hpp"

#include <algorithm>

namespace facadeslam {

bool passes_start_and_stride(std::size_t index, const SequenceOptions& options) {
  return index >= options.start && (index - options.start) % options.stride == 0;
}

std::size_t selected_count(std::size_t total, const SequenceOptions& options) {
  if (total <= options.start) return 0;
  const std::size_t kept = (total - options.start + options.stride - 1) / options.stride;
  return options.limit == 0 ? kept : std::min(kept, options.limit);
}

}  // namespace facadeslam
