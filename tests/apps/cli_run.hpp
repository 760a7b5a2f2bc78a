#pragma once
// Running the built `facadeslam` binary from a test, as a user would, and
// reading numbers back from its JSON reports.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include <nlohmann/json.hpp>

namespace facadeslam::test {

struct CliResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read_file_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// For the shell. Built by appending: GCC 12 warns falsely on "'" + s.
inline std::string shell_quoted(const std::string& s) {
  std::string q;
  q.reserve(s.size() + 2);
  q.append(1, '\'').append(s).append(1, '\'');
  return q;
}

// Runs `binary arguments` with stdout/stderr captured in files of `scratch`.
inline CliResult run_cli(const std::string& binary, const std::string& arguments,
                         const std::filesystem::path& scratch) {
  const auto out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  std::string command = shell_quoted(binary);
  command.append(" ").append(arguments).append(" > ").append(shell_quoted(out.string()));
  command.append(" 2> ").append(shell_quoted(err.string())).append(" < /dev/null");
  const int status = std::system(command.c_str());
  CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_file_text(out);
  result.err = read_file_text(err);
  return result;
}

// The number under the first `key` in a JSON text, in document order at any
// depth; NaN when the text does not parse, the key is absent or not a number.
inline double json_number(const nlohmann::ordered_json& json, const std::string& key) {
  if (json.is_object()) {
    for (const auto& item : json.items()) {
      if (item.key() == key) return item.value().is_number() ? item.value().get<double>() : std::nan("");
      if (const double inner = json_number(item.value(), key); !std::isnan(inner)) return inner;
    }
  } else if (json.is_array()) {
    for (const auto& element : json)
      if (const double inner = json_number(element, key); !std::isnan(inner)) return inner;
  }
  return std::nan("");
}

inline double json_number(const std::string& json, const std::string& key) {
  const auto parsed = nlohmann::ordered_json::parse(json, nullptr, /*allow_exceptions=*/false);
  return parsed.is_discarded() ? std::nan("") : json_number(parsed, key);
}

}  // namespace facadeslam::test
