#include "apps/cli_support.hpp"

#include "core/util/error.hpp"

namespace facadeslam::apps {

void require_file(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail_file(path, "no such file (expected " + what + ")");
  if (!std::filesystem::is_regular_file(path, ec)) fail_file(path, "not a regular file (expected " + what + ")");
}

}  // namespace facadeslam::apps
