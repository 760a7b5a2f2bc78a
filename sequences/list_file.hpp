#pragma once
// The small text lists a sequence may come with (TUM rgb.txt, times.txt):
// one record per line, blank lines and '#' comments ignored. Every error
// names the file and the line.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace facadeslam {

struct ListLine {
  std::size_t number = 0;           // 1-based line number in the file
  std::vector<std::string> fields;  // whitespace-separated, comment removed
};

// The non-empty records of `path`; Error when it cannot be opened
// (`what_expected` completes the message, e.g. "a TUM rgb.txt list").
std::vector<ListLine> read_list_file(const std::filesystem::path& path, const std::string& what_expected);

// Parses one timestamp field (a finite number of seconds); Error naming the
// file and line otherwise.
double parse_timestamp(std::string_view field, const std::filesystem::path& path, std::size_t line);

// Error naming the file and `line` unless `current` is after `previous`
// (read from `previous_line`).
void require_increasing(double previous, std::size_t previous_line, double current, std::size_t line,
                        const std::filesystem::path& path);

// "path: line N: what" as an Error.
[[noreturn]] void fail_line(const std::filesystem::path& path, std::size_t line, const std::string& what);

}  // namespace facadeslam
