#include "apps/genome_option.hpp"

#include <cctype>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "core/util/error.hpp"
#include "semantics/descriptor/genome_io.hpp"

namespace facadeslam::apps {

semantics::Genome resolve_genome(const std::string& value, const std::string& option) {
  using semantics::Genome;
  if (value.empty()) return Genome::thesis_best();
  std::error_code ec;
  if (std::filesystem::is_regular_file(value, ec)) return semantics::load_genome(value);
  bool bits_only = true;
  for (const char c : value)
    bits_only = bits_only && (c == '0' || c == '1' || std::isspace(static_cast<unsigned char>(c)));
  // A genome string with a typo still gets Genome::parse's precise message.
  // A bad genome string is a bad command line (exit code 2); a bad genome
  // file, bad input (exit code 1).
  if (bits_only || value.size() == static_cast<std::size_t>(Genome::kBits)) {
    try {
      return Genome::parse(value, option);
    } catch (const Error& e) {
      throw CLI::ValidationError(e.what());
    }
  }
  std::string shown = value.substr(0, 40);
  if (value.size() > 40) shown.append("...");
  std::string message = option + ": ";
  message.append(quoted_for_message(shown)).append(" is neither a genome file nor a 211-character 0/1 string");
  throw CLI::ValidationError(message);
}

}  // namespace facadeslam::apps
