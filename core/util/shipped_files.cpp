#include "core/util/shipped_files.hpp"

#include <cstdlib>
#include <system_error>
#include <vector>

#include "core/util/path_checks.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

// Where the running program is (/proc/self/exe: the real file, links
// followed); empty where the system does not say.
fs::path executable_folder() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

std::vector<fs::path> shipped_roots() {
  std::vector<fs::path> roots;
  if (const char* home = std::getenv("FACADESLAM_HOME"); home != nullptr && *home != '\0') roots.emplace_back(home);
  if (const fs::path bin = executable_folder(); !bin.empty()) {
    roots.push_back(bin.parent_path());
    roots.push_back(bin.parent_path() / "share" / "facadeslam");
  }
  return roots;
}

}  // namespace

fs::path shipped_file(const fs::path& relative) {
  const std::vector<fs::path> roots = shipped_roots();
  for (const fs::path& root : roots)
    if (path_exists(root / relative)) return root / relative;
  return roots.empty() ? relative : roots.front() / relative;
}

}  // namespace facadeslam
