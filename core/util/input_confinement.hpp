#pragma once
// Paths named inside input files (an rgb.txt's images, a dataset's
// train.txt/test.txt names, a scene file's photos) stay inside the folder
// the file belongs to, so that a file from elsewhere cannot make
// a command read /etc/passwd or climb out with ../../..: the user passes
// --allow-outside-paths to read such paths on purpose. Paths are compared
// resolved (symbolic links followed), so a link out of the folder counts as
// outside too.
#include <cstddef>
#include <filesystem>
#include <string>

namespace facadeslam {

// Set once from the command line (--allow-outside-paths); off by default.
void allow_paths_outside_inputs(bool allowed);
bool paths_outside_inputs_allowed();

// Whether `path` lies inside `folder` (both resolved), or leaving is allowed.
bool path_confined(const std::filesystem::path& path, const std::filesystem::path& folder);

// An Error "<listed_in>: line N: '<as_written>' leads outside <folder>
// (...)" unless path_confined(path, folder). `line` 0: no line number.
void require_confined(const std::filesystem::path& path, const std::filesystem::path& folder,
                      const std::filesystem::path& listed_in, std::size_t line, const std::string& as_written);

}  // namespace facadeslam
