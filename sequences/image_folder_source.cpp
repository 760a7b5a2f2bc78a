#include "sequences/image_folder_source.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <vector>

#include "core/util/error.hpp"
#include "sequences/list_file.hpp"
#include "sequences/natural_order.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

constexpr const char* kExpectedImages = "expected image files: png, jpg, jpeg, bmp, tif, tiff, pgm or ppm";

std::string lowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::vector<fs::path> list_images(const fs::path& folder) {
  std::error_code ec;
  if (!fs::exists(folder, ec)) fail_file(folder, "no such folder (expected an image folder)");
  if (!fs::is_directory(folder, ec)) fail_file(folder, "not a folder (expected an image folder)");
  std::vector<fs::path> images;
  fs::directory_iterator it(folder, ec);
  if (ec) fail_file(folder, "cannot list the folder (" + ec.message() + ")");
  for (const auto& entry : it) {
    const std::string name = entry.path().filename().string();
    // Hidden files are editor/OS debris (e.g. macOS "._image.png" resource
    // forks), never frames.
    if (name.empty() || name.front() == '.') continue;
    if (!entry.is_regular_file(ec) || !has_image_extension(entry.path())) continue;
    images.push_back(entry.path());
  }
  std::sort(images.begin(), images.end(), [](const fs::path& a, const fs::path& b) {
    return natural_less(a.filename().string(), b.filename().string());
  });
  return images;
}

// The explicit option, else times.txt / timestamps.txt beside the images.
fs::path find_timestamps_file(const fs::path& folder, const SequenceOptions& options) {
  std::error_code ec;
  if (!options.timestamps_file.empty()) {
    if (!fs::is_regular_file(options.timestamps_file, ec))
      fail_file(options.timestamps_file, "no such timestamps file (expected a text file with one timestamp per image)");
    return options.timestamps_file;
  }
  const fs::path times = folder / "times.txt";
  const fs::path timestamps = folder / "timestamps.txt";
  const bool has_times = fs::is_regular_file(times, ec);
  const bool has_timestamps = fs::is_regular_file(timestamps, ec);
  if (has_times && has_timestamps)
    fail_file(folder,
              "holds both times.txt and timestamps.txt (expected at most one "
              "timestamps file, or name one explicitly)");
  if (has_times) return times;
  if (has_timestamps) return timestamps;
  return {};
}

std::vector<double> read_timestamps(const fs::path& file, std::size_t image_count, const fs::path& folder) {
  const auto lines = read_list_file(file, "a timestamps file with one number per image line");
  std::vector<double> times;
  times.reserve(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const ListLine& line = lines[i];
    if (line.fields.size() != 1)
      fail_line(file, line.number,
                "expected one timestamp per line, found " + std::to_string(line.fields.size()) + " fields");
    times.push_back(parse_timestamp(line.fields[0], file, line.number));
    if (i > 0) require_increasing(times[i - 1], lines[i - 1].number, times[i], line.number, file);
  }
  if (times.size() != image_count)
    fail_file(file, "holds " + std::to_string(times.size()) + " timestamps but " + folder.string() + " holds " +
                        std::to_string(image_count) + " images (expected one timestamp per image, in name order)");
  return times;
}

std::vector<ImageEntry> folder_entries(const fs::path& folder, const SequenceOptions& options) {
  validate(options);
  const auto images = list_images(folder);
  if (images.empty()) fail_file(folder, std::string("no images found (") + kExpectedImages + ")");
  std::vector<double> times;
  if (const fs::path file = find_timestamps_file(folder, options); !file.empty())
    times = read_timestamps(file, images.size(), folder);
  std::vector<ImageEntry> all;
  all.reserve(images.size());
  for (std::size_t i = 0; i < images.size(); ++i)
    all.push_back({i, times.empty() ? static_cast<double>(i) / options.fps : times[i], images[i]});
  return select_entries(std::move(all), options, folder);
}

}  // namespace

bool has_image_extension(const fs::path& path) {
  static const std::array<std::string, 8> kExtensions = {".png", ".jpg",  ".jpeg", ".bmp",
                                                         ".tif", ".tiff", ".pgm",  ".ppm"};
  const std::string ext = lowercase(path.extension().string());
  return std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end();
}

ImageFolderSource::ImageFolderSource(const fs::path& folder, const SequenceOptions& options)
    : ImageListSource(folder_entries(folder, options), options.on_corrupt, "image folder " + folder.string()) {}

}  // namespace facadeslam
