#include "core/config/settings_writer.hpp"

#include <array>
#include <charconv>
#include <sstream>

namespace facadeslam {
namespace {

constexpr std::size_t kCommentWidth = 100;

template <class T>
std::string shortest(T v) {
  std::array<char, 64> buffer{};
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
  return error == std::errc{} ? std::string(buffer.data(), end) : std::string(".nan");
}

}  // namespace

std::string SettingsWriter::format(double v) { return shortest(v); }
std::string SettingsWriter::format(float v) { return shortest(v); }

std::string SettingsWriter::format(const std::string& v) {
  // Plain scalars that YAML would read as something else, or not at all,
  // are double-quoted.
  const bool plain = !v.empty() && v.find_first_of(":#{}[],&*!|>'\"%@`\\\n") == std::string::npos && v.front() != ' ' &&
                     v.back() != ' ' && v.front() != '-' && v.front() != '?' && v != "true" && v != "false" &&
                     v != "null" && v != "~";
  if (plain) return v;
  std::string quoted = "\"";
  for (const char c : v) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c == '\n' ? std::string("\\n") : std::string(1, c);
  }
  return quoted + "\"";
}

std::string SettingsWriter::format_list(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
  return out + "]";
}

void SettingsWriter::write_doc(const std::string& doc) {
  const std::string indent(static_cast<std::size_t>(2 * depth_), ' ');
  std::istringstream words(doc);
  std::string word, line;
  while (words >> word) {
    if (!line.empty() && indent.size() + 2 + line.size() + 1 + word.size() > kCommentWidth) {
      out_ << indent << "# " << line << '\n';
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out_ << indent << "# " << line << '\n';
}

void SettingsWriter::value(const std::string& key, const std::string& value, const std::string& doc) {
  write_doc(doc);
  out_ << std::string(static_cast<std::size_t>(2 * depth_), ' ') << key << ": " << value << '\n';
}

void SettingsWriter::open(const std::string& key, const std::string& doc) {
  if (depth_ == 0) out_ << '\n';
  write_doc(doc);
  out_ << std::string(static_cast<std::size_t>(2 * depth_), ' ') << key << ":\n";
  ++depth_;
}

void SettingsWriter::close() { --depth_; }

}  // namespace facadeslam
