#include "apps/cli_support.hpp"

#include <fstream>
#include <string>
#include <unistd.h>

#include "core/util/error.hpp"

namespace facadeslam::apps {

void require_file(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail_file(path, "no such file (expected " + what + ")");
  if (!std::filesystem::is_regular_file(path, ec)) fail_file(path, "not a regular file (expected " + what + ")");
}

void require_writable_output(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail_file(path, "is a folder (expected an output file name)");
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder)) {
    std::string what = "cannot create its folder (";
    fail_file(path, what.append(ec ? ec.message() : std::string("not a folder")).append(")"));
  }
  // Built by appending: GCC 12 warns falsely on "literal" + std::string.
  std::string name = ".";
  name.append(path.filename().string()).append(".probe").append(std::to_string(::getpid()));
  const std::filesystem::path probe = folder / name;
  {
    std::ofstream out(probe);
    if (!out) fail_file(path, "its folder is not writable");
  }
  std::filesystem::remove(probe, ec);
}

}  // namespace facadeslam::apps
