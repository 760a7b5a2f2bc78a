#include "sequences/sequence_options.hpp"

#include <cmath>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

constexpr std::size_t kMaxLoops = 1000000;

}  // namespace

void validate(const SequenceOptions& options) {
  if (options.stride == 0) throw Error("sequence options: stride must be at least 1 (got 0)");
  if (options.loops == 0 || options.loops > kMaxLoops)
    throw Error("sequence options: loops must be between 1 and 1000000 (got " + std::to_string(options.loops) + ")");
  if (!std::isfinite(options.fps) || options.fps <= 0.0)
    throw Error("sequence options: fps must be a positive number (got " + std::to_string(options.fps) + ")");
}

CorruptPolicy corrupt_policy_from_string(const std::string& text) {
  if (text == "stop") return CorruptPolicy::stop;
  if (text == "skip") return CorruptPolicy::skip;
  throw Error("sequence options: on-corrupt must be 'stop' or 'skip' (got '" + text + "')");
}

std::string to_string(CorruptPolicy policy) { return policy == CorruptPolicy::skip ? "skip" : "stop"; }

}  // namespace facadeslam
