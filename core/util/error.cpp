#include "core/util/error.hpp"

namespace facadeslam {

void fail_file(const std::filesystem::path& path, const std::string& what) {
  throw Error(path.string() + ": " + what);
}

}  // namespace facadeslam
