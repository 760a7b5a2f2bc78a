#include "core/util/progress.hpp"

#include <cstdio>
#include <unistd.h>

#include "core/util/logging.hpp"

namespace facadeslam {
namespace {
thread_local bool silenced_on_this_thread = false;
}  // namespace

bool Progress::terminal_attached() { return ::isatty(STDOUT_FILENO) && ::isatty(STDERR_FILENO); }

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), enabled_(drawing_enabled()) {}

bool Progress::drawing_enabled() {
  return terminal_attached() && current_verbosity() != Verbosity::quiet && !silenced_on_this_thread;
}

Progress::SilenceOnThisThread::SilenceOnThisThread() : previous_(silenced_on_this_thread) {
  silenced_on_this_thread = true;
}
Progress::SilenceOnThisThread::~SilenceOnThisThread() { silenced_on_this_thread = previous_; }

Progress::~Progress() { finish(); }

void Progress::update(std::size_t done, const std::string& status) {
  done_ = done;
  if (!enabled_) return;
  // At most ten redraws a second, and always the last one.
  if (drawn_ && since_draw_.elapsed_ms() < 100 && done_ < total_) return;
  drawn_ = true;
  since_draw_.restart();
  draw(status);
}

void Progress::draw(const std::string& status) {
  constexpr int kWidth = 30;
  const double fraction = total_ ? static_cast<double>(done_) / static_cast<double>(total_) : 1.0;
  const int filled = static_cast<int>(fraction * kWidth);
  const double elapsed = since_start_.elapsed_s();
  const double rate = elapsed > 0 ? static_cast<double>(done_) / elapsed : 0.0;
  // Time left at the rate so far, once there is a rate.
  std::string eta;
  if (rate > 0 && done_ < total_) {
    const auto left = static_cast<long>(static_cast<double>(total_ - done_) / rate + 0.5);
    eta = left >= 3600 ? " ETA " + std::to_string(left / 3600) + "h" + std::to_string(left % 3600 / 60) + "m"
          : left >= 60 ? " ETA " + std::to_string(left / 60) + "m" + std::to_string(left % 60) + "s"
                       : " ETA " + std::to_string(left) + "s";
  }
  std::fprintf(stderr, "\r%s [%s%s] %zu/%zu %.1f/s%s %s\x1b[K", label_.c_str(),
               std::string(static_cast<std::size_t>(filled), '#').c_str(),
               std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(), done_, total_, rate, eta.c_str(),
               status.c_str());
  std::fflush(stderr);
}

void Progress::finish() {
  if (!enabled_ || finished_) return;
  finished_ = true;
  draw("");
  std::fputc('\n', stderr);
}

}  // namespace facadeslam
