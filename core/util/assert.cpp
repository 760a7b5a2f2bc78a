#include "core/util/assert.hpp"

#include <cstdio>
#include <cstdlib>

namespace facadeslam::detail {

void assertion_failed(const char* condition, const char* what, const char* file, int line) {
  std::fprintf(stderr, "facadeslam: internal error at %s:%d: %s (%s does not hold); please report it\n", file, line,
               what, condition);
  std::fflush(stderr);
  std::abort();
}

}  // namespace facadeslam::detail
