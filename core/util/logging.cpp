#include "core/util/logging.hpp"

#include <atomic>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace facadeslam {
namespace {
std::atomic<Verbosity> g_verbosity{Verbosity::normal};
}

void configure_logging(Verbosity verbosity) {
  g_verbosity = verbosity;
  auto logger = spdlog::stderr_color_mt("facadeslam");
  logger->set_pattern("[%H:%M:%S.%e] [%^%l%$] %v");
  spdlog::set_default_logger(logger);
  switch (verbosity) {
    case Verbosity::quiet: spdlog::set_level(spdlog::level::warn); break;
    case Verbosity::normal: spdlog::set_level(spdlog::level::info); break;
    case Verbosity::verbose: spdlog::set_level(spdlog::level::debug); break;
  }
}

Verbosity current_verbosity() { return g_verbosity; }

}  // namespace facadeslam
