#pragma once
// Shared helpers for the gtest programs: scratch folders, the location of
// the project's sources and of ../shared/data, and a skip for tests that need
// the shared data.
#include <filesystem>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace facadeslam::test {

// The project root (tests run from there; FACADESLAM_SOURCE_DIR is set by CTest).
std::filesystem::path source_dir();

// ../shared/data beside the project root, or empty when it is absent.
std::filesystem::path shared_data_dir();

// A fresh empty folder, removed when the object goes out of scope.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

void write_text(const std::filesystem::path& path, const std::string& text);
// The whole file; throws std::runtime_error when it cannot be read.
std::string read_text(const std::filesystem::path& path);

// The message of the facadeslam::Error that `body` throws; a test failure
// (and "(no error)") when it throws none.
template <typename Body>
std::string error_of(Body&& body) {
  try {
    std::forward<Body>(body)();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a facadeslam::Error";
  return "(no error)";
}

}  // namespace facadeslam::test

// Skips the current test, with a message naming the folder, when
// ../shared/data/<sub> is not there (a user's fresh clone).
#define FACADESLAM_REQUIRE_SHARED_DATA(sub)                                                                         \
  do {                                                                                                              \
    if (::facadeslam::test::shared_data_dir().empty() ||                                                            \
        !std::filesystem::exists(::facadeslam::test::shared_data_dir() / (sub)))                                    \
      GTEST_SKIP() << "needs ../shared/data/" << (sub) << " (the project's shared datasets), which is absent here"; \
  } while (0)
