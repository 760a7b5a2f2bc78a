#include "core/util/path_checks.hpp"

#include <cerrno>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace facadeslam {

bool path_exists(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec) && !ec;
}

bool is_existing_file(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec) && !ec;
}

bool is_existing_folder(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_directory(path, ec) && !ec;
}

bool is_readable_file(const std::filesystem::path& path) {
  if (!is_existing_file(path)) return false;
  // Opened, not access(): root passes access() for files it cannot read
  // either way, and a file may vanish in between.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

std::string describe_path(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) return "cannot be looked up (" + ec.message() + ")";
  switch (status.type()) {
    case fs::file_type::not_found:
      return fs::is_symlink(fs::symlink_status(path, ec)) ? "is a symbolic link to nothing" : "does not exist";
    case fs::file_type::directory: return "is a folder";
    case fs::file_type::fifo: return "is a FIFO (named pipe)";
    case fs::file_type::character: return "is a character device";
    case fs::file_type::block: return "is a block device";
    case fs::file_type::socket: return "is a socket";
    case fs::file_type::regular: {
      const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
      if (fd < 0) return std::string("is a file that cannot be read (") + std::strerror(errno) + ")";
      ::close(fd);
      return "is a file";
    }
    default: return "is not a regular file";
  }
}

}  // namespace facadeslam
