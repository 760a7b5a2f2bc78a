#include "calib/image_files.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include "core/util/error.hpp"

namespace facadeslam::calib {
namespace {

bool has_image_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  constexpr std::array<const char*, 4> kExtensions = {".png", ".jpg", ".jpeg", ".bmp"};
  return std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end();
}

}  // namespace

std::vector<std::filesystem::path> list_image_files(const std::filesystem::path& folder) {
  std::error_code ec;
  if (!std::filesystem::exists(folder, ec))
    fail_file(folder, "no such folder (expected a folder of chessboard images)");
  if (!std::filesystem::is_directory(folder, ec))
    fail_file(folder, "not a folder (expected a folder of chessboard images)");

  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    if (entry.is_regular_file(ec) && has_image_extension(entry.path())) files.push_back(entry.path());
  }
  if (ec) fail_file(folder, "cannot list the folder: " + ec.message());
  if (files.empty()) fail_file(folder, "no image files (expected .png, .jpg, .jpeg or .bmp chessboard images)");
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace facadeslam::calib
