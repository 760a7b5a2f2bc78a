#include "core/util/atomic_write.hpp"

#include <atomic>
#include <fstream>
#include <system_error>
#include <unistd.h>

#include "core/util/error.hpp"
#include "core/util/interrupt.hpp"

namespace facadeslam {
namespace {

std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  // Keep the extension last: cv::imwrite picks the codec from it.
  // (Built by appending: GCC 12 warns falsely on `"." + std::string`.)
  std::string name = ".";
  name.append(path.stem().string())
      .append(".tmp")
      .append(std::to_string(::getpid()))
      .append("_")
      .append(std::to_string(counter++))
      .append(path.extension().string());
  std::filesystem::path tmp = path;
  tmp.replace_filename(name);
  return tmp;
}

void ensure_parent(const std::filesystem::path& path) {
  const auto parent = path.parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  if (ec) fail_file(parent, "cannot create output folder (" + ec.message() + ")");
}

void commit(const std::filesystem::path& tmp, const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    fail_file(path, "cannot move the finished file into place");
  }
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path& tmp)>& write) {
  ensure_parent(path);
  const auto tmp = temporary_beside(path);
  // A second Ctrl-C while the file is written removes it (interrupt.hpp).
  const AbortCleanupFile cleanup(tmp);
  try {
    write(tmp);
    if (!std::filesystem::exists(tmp)) fail_file(path, "the writer produced no output");
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
  commit(tmp, path);
}

void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write, bool binary) {
  write_file_atomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, binary ? std::ios::binary | std::ios::out : std::ios::out);
    if (!out) fail_file(path, "cannot open for writing");
    write(out);
    out.flush();
    if (!out) fail_file(path, "write failed (disk full?)");
  });
}

void write_text_atomically(const std::filesystem::path& path, std::string_view text) {
  write_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace facadeslam
