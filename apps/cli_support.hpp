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
inline constexpr int kExitError = 1;           // bad input, failed run
inline constexpr int kExitUsage = 2;           // bad command line
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

// A bad value on the command line: CLI::ValidationError "<option>: <message>",
// which main() turns into exit code 2.
[[noreturn]] void fail_usage(const std::string& option, const std::string& message);

// Count, seed and size options: a whole number in [min, max], so that a
// negative count is refused with the range rather than wrapping round to
// 2^64 - 1 ("expected a whole number in [0, 4294967295], got '-1'").
CLI::Validator whole_number(long long min, long long max);
// The ranges of the count and seed options: a count of images, samples or
// frames (0 often meaning all), and a seed (stored in reports, where JSON
// numbers stay exact up to 2^53 - 1).
inline constexpr long long kMaxCount = 1'000'000'000'000LL;
inline constexpr long long kMaxSeed = 9'007'199'254'740'991LL;
// A path option: not empty (`--out ''` is a slip, not "the default").
extern const CLI::Validator kNonEmptyPath;

// A file that must exist and can be read (not a FIFO or device: said so).
// For inputs named on the command line.
void require_readable_file(const std::filesystem::path& path, const std::string& what);
// An input file named on the command line, when something is there: a
// regular file that can be read. A FIFO would block the reader forever, a
// device never end: an Error saying what it is ("is a FIFO (named pipe)
// (expected a camera YAML file)"). A missing path is left to the reader's
// own message. Nothing for an empty path.
void require_readable_if_present(const std::filesystem::path& path, const std::string& what);

// "640x480" -> (640, 480), each side in [16, 8192]; an Error naming
// `option` otherwise.
std::pair<int, int> parse_image_size(const std::string& text, const std::string& option);

}  // namespace facadeslam::apps
