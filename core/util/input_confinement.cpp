#include "core/util/input_confinement.hpp"

#include <atomic>

#include "core/util/error.hpp"
#include "core/util/output_policy.hpp"

namespace facadeslam {
namespace {

std::atomic<bool> g_outside_allowed{false};

}  // namespace

void allow_paths_outside_inputs(bool allowed) { g_outside_allowed = allowed; }

bool paths_outside_inputs_allowed() { return g_outside_allowed; }

bool path_confined(const std::filesystem::path& path, const std::filesystem::path& folder) {
  return g_outside_allowed || lies_within(path, folder);
}

void require_confined(const std::filesystem::path& path, const std::filesystem::path& folder,
                      const std::filesystem::path& listed_in, std::size_t line, const std::string& as_written) {
  if (path_confined(path, folder)) return;
  std::string what = line > 0 ? "line " + std::to_string(line) + ": " : std::string();
  what.append(quoted_for_message(as_written)).append(" leads outside ");
  what.append(folder.empty() ? std::string(".") : folder.string());
  fail_file(listed_in,
            what.append(" (paths in it must stay inside its folder; pass --allow-outside-paths to read it)"));
}

}  // namespace facadeslam
