#pragma once
// Helpers shared by the subcommands: option validators with messages that
// name what was expected.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace facadeslam::apps {

// Exit codes, documented in the README.
inline constexpr int kExitOk = 0;
inline constexpr int kExitError = 1;       // bad input, failed run
inline constexpr int kExitUsage = 2;       // bad command line
inline constexpr int kExitNotInitialised = 3;  // replay ran, but the map never initialised

// A file that must exist and be a regular file.
void require_file(const std::filesystem::path& path, const std::string& what);

// An output file that can be written: not a folder, and its folder exists
// or can be made, and takes a new file (probed with an empty file; the
// probe and any folder made for it are removed again). For checks before
// long runs.
void require_writable_output(const std::filesystem::path& path);

// The same for an output folder, without creating anything: `folder` is a
// writable folder, or its nearest existing ancestor is one (the run makes
// the rest at the end). An Error naming the folder otherwise.
void require_creatable_folder(const std::filesystem::path& folder);

// An output folder that a run replaces as a whole (core/util/staged_folder.hpp)
// must not hold anything else: it is absent, empty, or an earlier run's
// output folder (it holds `marker`, or only names from `outputs` and hidden
// leftovers). An Error naming the folder and `command` otherwise, so that
// `--out .` or `--out ~` never replaces a folder of other files.
void require_replaceable_folder(const std::filesystem::path& folder, const std::string& marker,
                                const std::vector<std::string>& outputs, const std::string& command);

// A bad value on the command line: CLI::ValidationError "<option>: <message>",
// which main() turns into exit code 2.
[[noreturn]] void fail_usage(const std::string& option, const std::string& message);

// "640x480" -> (640, 480), each side in [16, 8192]; an Error naming
// `option` otherwise.
std::pair<int, int> parse_image_size(const std::string& text, const std::string& option);

}  // namespace facadeslam::apps
