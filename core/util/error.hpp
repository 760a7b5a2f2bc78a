#pragma once
// One exception type for every user-facing failure (bad file, bad value, bad
// option). The `facadeslam` command catches it at the top and prints its
// message as one line with a non-zero exit; nothing below the apps layer
// prints or exits on its own.
#include <stdexcept>
#include <string>
#include <filesystem>
#include <string_view>

namespace facadeslam {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// "<path>: <what>" — every message about a file starts with the file.
[[noreturn]] void fail_file(const std::filesystem::path& path, const std::string& what);

// `text` fit for a one-line message on a terminal: control bytes, DEL and
// bytes that are not valid UTF-8 (a hostile file's raw bytes) as \xNN;
// valid UTF-8 (a path with umlauts) is kept.
std::string printable(std::string_view text);
// printable(text) in single quotes, its first kMaxQuotedBytes bytes only
// ("... (N bytes)" after them): a 1 MB line of a hostile file is not echoed.
std::string quoted_for_message(std::string_view text);
inline constexpr std::size_t kMaxQuotedBytes = 80;

// A whole message fit for one terminal line: printable(), and when longer
// than `max_bytes`, its start and end around " ... ": what failed and what
// was expected stay.
std::string one_line_message(std::string_view text, std::size_t max_bytes = 480);

}  // namespace facadeslam
