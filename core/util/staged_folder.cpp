#include "core/util/staged_folder.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <string>
#include <system_error>
#include <unistd.h>

#include "core/util/error.hpp"
#include "core/util/interrupt.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

// ".NAME<infix><pid>" beside `target`. Built by appending: GCC 12 warns
// falsely on "literal" + std::string.
fs::path sibling(const fs::path& target, const char* infix, long pid) {
  std::string name = ".";
  name.append(target.filename().string()).append(infix).append(std::to_string(pid));
  return target.parent_path() / name;
}

// Staging and old folders of earlier runs of `target` whose process has
// ended (killed with SIGKILL, or the machine went down).
void remove_stale_siblings(const fs::path& target) {
  std::error_code ec;
  std::string prefix = ".";
  prefix.append(target.filename().string());
  for (const char* infix : {".tmp-", ".old-"}) {
    std::string start = prefix;
    start.append(infix);
    for (fs::directory_iterator it(target.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name.size() <= start.size() || name.compare(0, start.size(), start) != 0) continue;
      const std::string digits = name.substr(start.size());
      if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
      const long pid = std::stol(digits);
      if (pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
      std::error_code ignored;
      fs::remove_all(it->path(), ignored);
    }
  }
}

[[noreturn]] void fail_move(const fs::path& target, const char* what, const std::error_code& ec) {
  std::string text = what;
  fail_file(target, text.append(" (").append(ec.message()).append(")"));
}

}  // namespace

StagedFolder::StagedFolder(fs::path target) {
  std::error_code ec;
  target_ = fs::absolute(target, ec).lexically_normal();
  if (target_.has_filename() == false) target_ = target_.parent_path();
  if (ec || target_.filename().empty() || target_ == target_.root_path())
    fail_file(target, "expected an output folder that can be replaced as a whole, not the file system root");
  if (fs::exists(target_, ec) && !fs::is_directory(target_, ec)) fail_file(target, "an output folder, but it is a file");
  // The ancestors that do not exist yet are made now and removed again if
  // the run fails.
  fs::path first_missing;
  for (fs::path p = target_.parent_path(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    first_missing = p;
    if (p == p.parent_path()) break;
  }
  fs::create_directories(target_.parent_path(), ec);
  if (ec) {
    std::string what = "cannot create its parent folder (";
    fail_file(target, what.append(ec.message()).append(")"));
  }
  created_root_ = first_missing;
  remove_stale_siblings(target_);
  staging_ = sibling(target_, ".tmp-", ::getpid());
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec) || ec) {
    std::string what = "cannot make a folder beside it (";
    if (!created_root_.empty()) fs::remove_all(created_root_, ec);
    fail_file(target, what.append(ec ? ec.message() : std::string("it exists")).append(")"));
  }
  set_abort_cleanup_folder(staging_);
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  set_abort_cleanup_folder({});
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (!created_root_.empty()) fs::remove_all(created_root_, ec);
}

bool StagedFolder::contains(const fs::path& p) const {
  if (p.empty()) return false;
  std::error_code ec;
  const fs::path absolute = fs::absolute(p, ec).lexically_normal();
  const fs::path relative = absolute.lexically_relative(target_);
  return !ec && !relative.empty() && *relative.begin() != "..";
}

fs::path StagedFolder::staged(const fs::path& p) const {
  if (!contains(p)) return p;
  std::error_code ec;
  const fs::path relative = fs::absolute(p, ec).lexically_normal().lexically_relative(target_);
  return relative == "." ? staging_ : staging_ / relative;
}

void StagedFolder::commit() {
  if (committed_) return;
  // A second Ctrl-C from here on waits for the folder to be in place.
  const AbortDeferral deferral;
  std::error_code ec;
  const bool replacing = fs::exists(target_, ec);
  if (!replacing) {
    fs::rename(staging_, target_, ec);
    if (ec) fail_move(target_, "cannot move the finished output folder into place", ec);
  } else if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
    // The staging name now holds the old folder.
    fs::remove_all(staging_, ec);
  } else {
    const fs::path old = sibling(target_, ".old-", ::getpid());
    fs::remove_all(old, ec);
    fs::rename(target_, old, ec);
    if (ec) fail_move(target_, "cannot move the previous output folder aside", ec);
    fs::rename(staging_, target_, ec);
    if (ec) {
      std::error_code ignored;
      fs::rename(old, target_, ignored);
      fail_move(target_, "cannot move the finished output folder into place", ec);
    }
    fs::remove_all(old, ec);
  }
  committed_ = true;
  set_abort_cleanup_folder({});
}

}  // namespace facadeslam
