#include "sequences/list_file.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

std::string format_seconds(double t) {
  std::ostringstream out;
  out.precision(17);
  out << t;
  return out.str();
}

}  // namespace

void fail_line(const std::filesystem::path& path, std::size_t line, const std::string& what) {
  fail_file(path, "line " + std::to_string(line) + ": " + what);
}

std::vector<ListLine> read_list_file(const std::filesystem::path& path, const std::string& what_expected) {
  std::ifstream in(path);
  if (!in) fail_file(path, "cannot open the file (expected " + what_expected + ")");
  std::vector<ListLine> lines;
  std::string text;
  std::size_t number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    std::istringstream fields(text);
    ListLine line{number, {}};
    for (std::string field; fields >> field;) line.fields.push_back(field);
    if (!line.fields.empty()) lines.push_back(std::move(line));
  }
  if (in.bad()) fail_file(path, "read error (expected " + what_expected + ")");
  return lines;
}

double parse_timestamp(std::string_view field, const std::filesystem::path& path, std::size_t line) {
  const std::string text(field);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
    fail_line(path, line, quoted_for_message(text) + " is not a timestamp (expected a number of seconds)");
  return value;
}

void require_increasing(double previous, std::size_t previous_line, double current, std::size_t line,
                        const std::filesystem::path& path) {
  if (current > previous) return;
  fail_line(path, line,
            "timestamp " + format_seconds(current) + " is not after the previous one (" + format_seconds(previous) +
                " on line " + std::to_string(previous_line) + "); expected strictly increasing timestamps");
}

}  // namespace facadeslam
