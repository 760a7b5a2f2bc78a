#pragma once
// The process's resident memory (what `top` calls RES), for the soak runs'
// memory curve.
#include <cstdint>
#include <optional>

namespace facadeslam {

// Bytes resident now, from /proc/self/statm; nothing where that is not
// available (not Linux).
std::optional<std::uint64_t> resident_memory_bytes();

}  // namespace facadeslam
