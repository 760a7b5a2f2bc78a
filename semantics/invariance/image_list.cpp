#include "semantics/invariance/image_list.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <system_error>

#include "core/util/error.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

namespace fs = std::filesystem;

constexpr const char* kImageExtensions = ".jpg .jpeg .png .bmp .ppm .pgm .tif .tiff";

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_image_name(const fs::path& path) {
  const std::string e = lower(path.extension().string());
  for (const char* known : {".jpg", ".jpeg", ".png", ".bmp", ".ppm", ".pgm", ".tif", ".tiff"})
    if (e == known) return true;
  return false;
}

bool is_file(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

std::string trimmed(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = line.find_last_not_of(" \t\r\n");
  return line.substr(first, last - first + 1);
}

void add_folder(const fs::path& folder, std::vector<fs::path>& out) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec))
    if (entry.is_regular_file(ec) && is_image_name(entry.path())) found.push_back(entry.path());
  if (ec) fail_file(folder, cat("cannot read the folder (", ec.message(), ")"));
  if (found.empty()) fail_file(folder, cat("no image files in the folder (expected ", kImageExtensions, ")"));
  std::sort(found.begin(), found.end());
  out.insert(out.end(), found.begin(), found.end());
}

fs::path resolve_list_entry(const fs::path& folder, const std::string& entry) {
  const fs::path direct = folder / entry;
  if (is_file(direct)) return direct;
  for (const char* extension : {".jpg", ".jpeg", ".png"}) {
    const fs::path candidate = folder / "images" / cat(entry, extension);
    if (is_file(candidate)) return candidate;
  }
  return {};
}

void add_list(const fs::path& list, std::vector<fs::path>& out) {
  std::ifstream in(list);
  if (!in) fail_file(list, "cannot open the image list");
  const fs::path folder = list.parent_path();
  const std::size_t before = out.size();
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string entry = trimmed(line);
    if (entry.empty() || entry[0] == '#') continue;
    const fs::path image = resolve_list_entry(folder, entry);
    if (image.empty())
      fail_file(list, cat("line ", line_number, ": no image '", entry,
                          "' (looked for it beside the list and as images/", entry, ".jpg/.jpeg/.png)"));
    out.push_back(image);
  }
  if (out.size() == before) fail_file(list, "the image list names no image");
}

}  // namespace

std::vector<fs::path> list_images(const std::vector<fs::path>& inputs, std::size_t max_images) {
  if (inputs.empty()) throw Error("no images given (expected image files, folders of images or a .txt list)");
  std::vector<fs::path> images;
  for (const fs::path& input : inputs) {
    std::error_code ec;
    if (fs::is_directory(input, ec))
      add_folder(input, images);
    else if (!is_file(input))
      fail_file(input, "no such image file, folder or list");
    else if (lower(input.extension().string()) == ".txt")
      add_list(input, images);
    else if (is_image_name(input))
      images.push_back(input);
    else
      fail_file(input, cat("not an image file name (expected ", kImageExtensions, ", a folder or a .txt list)"));
  }
  if (max_images > 0 && images.size() > max_images) images.resize(max_images);
  return images;
}

}  // namespace facadeslam::semantics
