#pragma once
// Logging goes through spdlog to stderr. The command line picks the level
// once (--verbose / --quiet); libraries only call spdlog::info/debug/warn.
namespace facadeslam {

enum class Verbosity { quiet, normal, verbose };

void configure_logging(Verbosity verbosity);
Verbosity current_verbosity();

}  // namespace facadeslam
