#pragma once
// Internal invariants. A broken one is a bug in facadeslam, never the user's
// input: FACADESLAM_ASSERT names the file, line and condition on stderr and
// aborts (a core dump to debug), in every build, because the checks guarded
// are cheap and a wrong map or pose written without a word is worse than a
// stop. What the user can cause (a bad file, a bad option) throws
// facadeslam::Error instead (core/util/error.hpp): one line, exit code 1.
#define FACADESLAM_ASSERT(condition, what) \
  ((condition) ? static_cast<void>(0) : ::facadeslam::detail::assertion_failed(#condition, what, __FILE__, __LINE__))

namespace facadeslam::detail {

[[noreturn]] void assertion_failed(const char* condition, const char* what, const char* file, int line);

}  // namespace facadeslam::detail
