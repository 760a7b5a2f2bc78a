#pragma once
// What every fuzz target shares: the input bytes as a file (the readers
// under test take paths, as the program's users give them), and the
// contract they are fuzzed against. A reader may reject its input only with
// facadeslam::Error (one clear line naming the file); anything else (another
// exception type, a crash, a sanitizer report, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "core/util/error.hpp"

namespace facadeslam::fuzz {

// A per-process scratch folder under TMPDIR (fuzz runs may be parallel).
inline const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    std::filesystem::path p = std::filesystem::temp_directory_path();
    std::string name = "facadeslam-fuzz-";
    p /= name.append(std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return p;
  }();
  return folder;
}

inline std::filesystem::path write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = scratch_folder() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

// Runs `read`; Error is the accepted way to say no, anything else aborts
// with the exception's text so that libFuzzer keeps the input.
template <class Read>
void expect_clean_rejection(Read&& read) {
  try {
    read();
  } catch (const Error&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: an exception other than facadeslam::Error: %s\n", e.what());
    std::abort();
  }
}

}  // namespace facadeslam::fuzz
