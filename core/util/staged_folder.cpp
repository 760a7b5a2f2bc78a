#include "core/util/staged_folder.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <string>
#include <system_error>
#include <vector>
#include <fcntl.h>  // AT_FDCWD
#include <unistd.h>

#include "core/util/error.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/output_lock.hpp"
#include "core/util/path_checks.hpp"

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
// ended (killed with SIGKILL, or the machine went down). With `start`, the
// abandoned staging folder furthest on (if any is further on than the
// target) is kept and returned, the others removed.
fs::path remove_stale_siblings(const fs::path& target, const StagedFolderStart& start) {
  std::error_code ec;
  std::string prefix = ".";
  prefix.append(target.filename().string());
  fs::path kept;
  for (const char* infix : {".tmp-", ".old-"}) {
    std::string begin = prefix;
    begin.append(infix);
    std::vector<fs::path> stale;
    for (fs::directory_iterator it(target.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name.size() <= begin.size() || name.compare(0, begin.size(), begin) != 0) continue;
      const std::string digits = name.substr(begin.size());
      if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
      const long pid = std::stol(digits);
      if (pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
      stale.push_back(it->path());
    }
    for (const fs::path& path : stale) {
      const bool candidate =
          std::string(infix) == ".tmp-" && start.from_target && start.abandoned_is_newer && fs::is_directory(path, ec);
      if (candidate && start.abandoned_is_newer(path, kept.empty() ? target : kept)) {
        if (!kept.empty()) fs::remove_all(kept, ec);
        kept = path;
        continue;
      }
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  }
  return kept;
}

// The files of `from` into the empty folder `to`: hard links (the runs that
// continue a folder replace files by renaming, never write into them), or
// copies where links cannot be made.
void fill_from(const fs::path& from, const fs::path& to, const fs::path& target) {
  std::error_code ec;
  fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::create_hard_links, ec);
  if (!ec) return;
  for (fs::directory_iterator it(to, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code ignored;
    fs::remove_all(it->path(), ignored);
  }
  ec.clear();
  fs::copy(from, to, fs::copy_options::recursive, ec);
  if (ec) {
    std::string what = "cannot copy the earlier run's files to continue it (";
    fail_file(target, what.append(ec.message()).append(")"));
  }
}

[[noreturn]] void fail_move(const fs::path& target, const char* what, const std::error_code& ec) {
  std::string text = what;
  fail_file(target, text.append(" (").append(ec.message()).append(")"));
}

}  // namespace

StagedFolder::StagedFolder(fs::path target, const StagedFolderStart& start) {
  std::error_code ec;
  target_ = fs::absolute(target, ec).lexically_normal();
  if (target_.has_filename() == false) target_ = target_.parent_path();
  if (ec || target_.filename().empty() || target_ == target_.root_path())
    fail_file(target, "expected an output folder that can be replaced as a whole, not the file system root");
  if (fs::exists(target_, ec) && !fs::is_directory(target_, ec))
    fail_file(target, "an output folder, but it is a file");
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
  try {
    lock_ = std::make_unique<OutputLock>(target_);
  } catch (const Error&) {
    if (!created_root_.empty()) fs::remove_all(created_root_, ec);
    throw;
  }
  const fs::path abandoned = remove_stale_siblings(target_, start);
  staging_ = sibling(target_, ".tmp-", ::getpid());
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec) || ec) {
    std::string what = "cannot make a folder beside it (";
    if (!created_root_.empty()) fs::remove_all(created_root_, ec);
    fail_file(target, what.append(ec ? ec.message() : std::string("it exists")).append(")"));
  }
  abort_cleanup_ = std::make_unique<AbortCleanupFile>(staging_);
  if (!abandoned.empty() || (start.from_target && is_existing_folder(target_))) {
    try {
      fill_from(abandoned.empty() ? target_ : abandoned, staging_, target);
    } catch (const Error&) {
      abort_cleanup_.reset();
      fs::remove_all(staging_, ec);
      if (!created_root_.empty()) fs::remove_all(created_root_, ec);
      throw;
    }
    // Its files live on in the staging folder.
    if (!abandoned.empty()) fs::remove_all(abandoned, ec);
  }
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  // The lock goes last (a member): the folders are cleaned up under it.
  abort_cleanup_.reset();
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
  abort_cleanup_.reset();
}

}  // namespace facadeslam
