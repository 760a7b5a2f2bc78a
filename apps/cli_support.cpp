#include "apps/cli_support.hpp"

#include <algorithm>
#include <fstream>
#include <string>
#include <unistd.h>

#include "core/util/error.hpp"
#include "core/util/path_checks.hpp"

namespace facadeslam::apps {

void require_file(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail_file(path, "no such file (expected " + what + ")");
  if (!std::filesystem::is_regular_file(path, ec)) fail_file(path, "not a regular file (expected " + what + ")");
}

void require_readable_file(const std::filesystem::path& path, const std::string& what) {
  if (!path_exists(path)) fail_file(path, "no such file (expected " + what + ")");
  if (!is_readable_file(path)) fail_file(path, describe_path(path) + " (expected " + what + ")");
}

void require_readable_if_present(const std::filesystem::path& path, const std::string& what) {
  if (path.empty() || !path_exists(path) || is_existing_folder(path) || is_readable_file(path)) return;
  fail_file(path, describe_path(path) + " (expected " + what + ")");
}

CLI::Validator whole_number(long long min, long long max) {
  const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  return CLI::Validator(
      [min, max, range](const std::string& text) -> std::string {
        std::size_t start = text.size() > 1 && text[0] == '+' ? 1 : 0;
        const bool negative = text.size() > 1 && text[0] == '-';
        if (negative) start = 1;
        const std::string digits = text.substr(start);
        bool fits =
            !digits.empty() && digits.size() <= 18 && digits.find_first_not_of("0123456789") == std::string::npos;
        if (fits) {
          const long long value = negative ? -std::stoll(digits) : std::stoll(digits);
          fits = value >= min && value <= max;
        }
        if (fits) return {};
        return "expected a whole number in " + range + ", got " + quoted_for_message(text);
      },
      "INT in " + range, "whole number");
}

const CLI::Validator kNonEmptyPath(
    [](const std::string& text) -> std::string { return text.empty() ? "expected a path, got ''" : std::string(); },
    "PATH", "non-empty path");

void require_writable_output(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail_file(path, "is a folder (expected an output file name)");
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  // The folders made for the probe are removed again (the writers make
  // them when they write): a run that fails later leaves no empty folder.
  std::filesystem::path first_missing;
  for (std::filesystem::path p = std::filesystem::absolute(folder, ec).lexically_normal();
       !p.empty() && !std::filesystem::exists(p, ec) && p != p.parent_path(); p = p.parent_path())
    first_missing = p;
  struct RemoveMade {
    std::filesystem::path root;
    ~RemoveMade() {
      std::error_code ignored;
      if (!root.empty()) std::filesystem::remove_all(root, ignored);
    }
  } remove_made{first_missing};
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

void require_creatable_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::path existing = std::filesystem::absolute(folder, ec).lexically_normal();
  while (!existing.empty() && !std::filesystem::exists(existing, ec) && existing.has_parent_path() &&
         existing.parent_path() != existing)
    existing = existing.parent_path();
  if (!std::filesystem::is_directory(existing, ec))
    fail_file(folder, existing == std::filesystem::absolute(folder, ec).lexically_normal()
                          ? "an output folder, but it is a file"
                          : "an output folder, but " + existing.string() + " is not a folder");
  // A probe folder made and removed at once: permission bits do not tell
  // root (or /proc) the truth.
  std::string name = ".facadeslam-probe-";
  name.append(std::to_string(::getpid()));
  const std::filesystem::path probe = existing / name;
  if (!std::filesystem::create_directory(probe, ec) || ec)
    fail_file(folder, "an output folder, but nothing can be made in " + existing.string());
  std::filesystem::remove(probe, ec);
}

void fail_usage(const std::string& option, const std::string& message) { throw CLI::ValidationError(option, message); }

std::pair<int, int> parse_image_size(const std::string& text, const std::string& option) {
  const auto x = text.find('x');
  const auto digits = [](const std::string& s) {
    return !s.empty() && s.size() <= 5 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  if (x == std::string::npos || !digits(text.substr(0, x)) || !digits(text.substr(x + 1)))
    throw Error(option + ": expected WIDTHxHEIGHT such as 640x480, got '" + text + "'");
  const int w = std::stoi(text.substr(0, x)), h = std::stoi(text.substr(x + 1));
  if (w < 16 || h < 16 || w > 8192 || h > 8192)
    throw Error(option + ": expected a width and height in [16, 8192], got '" + text + "'");
  return {w, h};
}

}  // namespace facadeslam::apps
