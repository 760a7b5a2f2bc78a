#include "core/util/output_lock.hpp"

#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/util/error.hpp"
#include "core/util/interrupt.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

// The process id the holder wrote, or empty (it may not have written it yet).
std::string holder_of(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string pid(text, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.find_first_not_of("0123456789") == std::string::npos ? pid : std::string();
}

}  // namespace

fs::path output_lock_file(const fs::path& target) {
  fs::path absolute = fs::absolute(target).lexically_normal();
  if (!absolute.has_filename()) absolute = absolute.parent_path();
  // Built by appending: GCC 12 warns falsely on "literal" + std::string.
  std::string name = ".";
  name.append(absolute.filename().string()).append(".lock");
  return absolute.parent_path() / name;
}

OutputLock::OutputLock(const fs::path& target) : lock_file_(output_lock_file(target)) {
  // The holder removes the file when it is done: a file opened just before
  // that is no longer the lock, so lock again until the locked file is the
  // one at the path.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(lock_file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
      fail_file(target, std::string("cannot make the lock file ") + lock_file_.filename().string() + " beside it (" +
                            std::strerror(errno) + ")");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string pid = holder_of(fd);
      ::close(fd);
      if (error == EWOULDBLOCK)
        fail_file(target, "another facadeslam run" + (pid.empty() ? std::string() : " (process " + pid + ")") +
                              " is writing this output now (" + lock_file_.filename().string() +
                              "); wait for it to end or choose another output");
      fail_file(target,
                std::string("cannot lock ") + lock_file_.filename().string() + " (" + std::strerror(error) + ")");
    }
    struct stat opened {
    }, at_path{};
    if (::fstat(fd, &opened) == 0 && ::lstat(lock_file_.c_str(), &at_path) == 0 && opened.st_ino == at_path.st_ino &&
        opened.st_dev == at_path.st_dev) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
        // The lock holds without the id; the other run's message just names no process.
      }
      fd_ = fd;
      abort_cleanup_ = std::make_unique<AbortCleanupFile>(lock_file_);
      return;
    }
    ::close(fd);
  }
  fail_file(target, "cannot take the lock " + lock_file_.filename().string() + " (it keeps being replaced)");
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  abort_cleanup_.reset();
  // Removed while still locked: a run waiting on this file finds it gone
  // and makes a new one (see the constructor).
  ::unlink(lock_file_.c_str());
  ::close(fd_);
}

}  // namespace facadeslam
