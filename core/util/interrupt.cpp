#include "core/util/interrupt.hpp"

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <iterator>
#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

namespace facadeslam {
namespace {

volatile std::sig_atomic_t g_requested = 0;  // the signal that asked to stop, 0 before one came
volatile std::sig_atomic_t g_end_at_once = 0;
constexpr int kHandledSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction g_previous[std::size(kHandledSignals)];

// The abort clean-up folder: an absolute path, valid while g_cleanup_set.
char g_cleanup[4096];
volatile std::sig_atomic_t g_cleanup_set = 0;
// The files being written: a slot is free (0), being filled (1) or holds an
// absolute path the handler may remove (2). Lock-free atomics, so that the
// handler can read them.
struct CleanupFileSlot {
  std::atomic<int> state{0};
  char path[4096];
};
static_assert(std::atomic<int>::is_always_lock_free);
std::array<CleanupFileSlot, kAbortCleanupFiles> g_cleanup_files;
// Inside AbortDeferral: the signal that came meanwhile (0: none).
volatile std::sig_atomic_t g_deferring = 0, g_deferred_signal = 0;

// Removes `name` (relative to `dir_fd`, or absolute) and everything below it
// with async-signal-safe calls only (no allocation, no stdio).
void remove_tree(int dir_fd, const char* name, int depth) {
  if (::unlinkat(dir_fd, name, 0) == 0 || depth > 32) return;
  const int fd = ::openat(dir_fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  alignas(8) char buffer[4096];
  // Entries removed while listing may hide others: list again until a pass
  // removes nothing.
  for (int pass = 0; pass < 64; ++pass) {
    bool removed = false;
    ::lseek(fd, 0, SEEK_SET);
    for (;;) {
      const ssize_t n = ::getdents64(fd, buffer, sizeof buffer);
      if (n <= 0) break;
      for (ssize_t offset = 0; offset < n;) {
        const auto* entry = reinterpret_cast<const struct dirent64*>(buffer + offset);
        offset += entry->d_reclen;
        if (std::strcmp(entry->d_name, ".") == 0 || std::strcmp(entry->d_name, "..") == 0) continue;
        remove_tree(fd, entry->d_name, depth + 1);
        removed = true;
      }
    }
    if (!removed) break;
  }
  ::close(fd);
  ::unlinkat(dir_fd, name, AT_REMOVEDIR);
}

// The exit code a shell gives a process ended by `signal` (130 for SIGINT),
// the same from the handler and from AbortDeferral's end.
[[noreturn]] void die_of(int signal) { ::_exit(128 + signal); }

extern "C" void on_interrupt(int signal) {
  if (g_requested || g_end_at_once) {
    // The second one: now, as if we had never caught it (once a folder
    // being moved into place is there).
    if (g_deferring) {
      g_deferred_signal = signal;
      return;
    }
    for (CleanupFileSlot& slot : g_cleanup_files)
      if (slot.state.load(std::memory_order_acquire) == 2) remove_tree(AT_FDCWD, slot.path, 0);
    if (g_cleanup_set) remove_tree(AT_FDCWD, g_cleanup, 0);
    die_of(signal);
  }
  g_requested = signal;
}

}  // namespace

InterruptGuard::InterruptGuard(InterruptResponse response) {
  g_requested = 0;
  g_end_at_once = response == InterruptResponse::end_at_once;
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  // Each signal blocks the others while its handler runs: a SIGTERM landing
  // inside the SIGINT handler's clean-up must not start a second one.
  for (const int signal : kHandledSignals) sigaddset(&action.sa_mask, signal);
  for (std::size_t i = 0; i < std::size(kHandledSignals); ++i) sigaction(kHandledSignals[i], &action, &g_previous[i]);
}

InterruptGuard::~InterruptGuard() {
  for (std::size_t i = 0; i < std::size(kHandledSignals); ++i) sigaction(kHandledSignals[i], &g_previous[i], nullptr);
  g_end_at_once = 0;
}

bool interrupt_requested() { return g_requested != 0; }

int interrupt_exit_code() { return g_requested != 0 ? 128 + g_requested : kExitInterrupted; }

void set_abort_cleanup_folder(const std::filesystem::path& folder) {
  g_cleanup_set = 0;
  if (folder.empty()) return;
  std::error_code ec;
  const std::string absolute = std::filesystem::absolute(folder, ec).string();
  if (ec || absolute.size() >= sizeof g_cleanup) return;
  std::memcpy(g_cleanup, absolute.c_str(), absolute.size() + 1);
  g_cleanup_set = 1;
}

AbortCleanupFile::AbortCleanupFile(const std::filesystem::path& file) {
  std::error_code ec;
  const std::string absolute = std::filesystem::absolute(file, ec).string();
  if (ec || absolute.size() >= sizeof(CleanupFileSlot::path)) return;
  for (int i = 0; i < kAbortCleanupFiles; ++i) {
    CleanupFileSlot& slot = g_cleanup_files[static_cast<std::size_t>(i)];
    int free = 0;
    if (!slot.state.compare_exchange_strong(free, 1, std::memory_order_acquire)) continue;
    std::memcpy(slot.path, absolute.c_str(), absolute.size() + 1);
    slot.state.store(2, std::memory_order_release);
    slot_ = i;
    return;
  }
}

AbortCleanupFile::~AbortCleanupFile() {
  if (slot_ >= 0) g_cleanup_files[static_cast<std::size_t>(slot_)].state.store(0, std::memory_order_release);
}

AbortDeferral::AbortDeferral() {
  g_deferred_signal = 0;
  g_deferring = 1;
}

AbortDeferral::~AbortDeferral() {
  g_deferring = 0;
  if (const int signal = g_deferred_signal; signal != 0) die_of(signal);
}

}  // namespace facadeslam
