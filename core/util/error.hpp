#pragma once
// One exception type for every user-facing failure (bad file, bad value, bad
// option). The `facadeslam` command catches it at the top and prints its
// message as one line with a non-zero exit; nothing below the apps layer
// prints or exits on its own.
#include <stdexcept>
#include <string>
#include <filesystem>

namespace facadeslam {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// "<path>: <what>" — every message about a file starts with the file.
[[noreturn]] void fail_file(const std::filesystem::path& path, const std::string& what);

}  // namespace facadeslam
