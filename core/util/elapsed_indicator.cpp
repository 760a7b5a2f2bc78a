#include "core/util/elapsed_indicator.hpp"

#include <chrono>
#include <cstdio>

#include "core/util/progress.hpp"

namespace facadeslam {

ElapsedIndicator::ElapsedIndicator(std::string label) : label_(std::move(label)) {
  // Progress decides whether anything may be drawn here (terminal, verbosity, thread).
  if (!Progress::drawing_enabled()) return;
  thread_ = std::thread([this] {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock lock(mutex_);
    while (!stop_.wait_for(lock, std::chrono::seconds(1), [this] { return stopping_; })) {
      const auto seconds =
          std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "\r%s: %lld s\x1b[K", label_.c_str(), static_cast<long long>(seconds));
      std::fflush(stderr);
    }
  });
}

ElapsedIndicator::~ElapsedIndicator() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  stop_.notify_all();
  thread_.join();
  std::fprintf(stderr, "\r\x1b[K");
  std::fflush(stderr);
}

}  // namespace facadeslam
