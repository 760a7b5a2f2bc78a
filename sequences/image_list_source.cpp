#include "sequences/image_list_source.hpp"

#include <utility>

#include <spdlog/spdlog.h>

#include "core/util/error.hpp"
#include "sequences/frame_selection.hpp"
#include "sequences/image_decoding.hpp"

namespace facadeslam {
namespace {

std::string size_text(const cv::Size& s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

}  // namespace

std::vector<ImageEntry> select_entries(std::vector<ImageEntry> all, const SequenceOptions& options,
                                       const std::filesystem::path& origin) {
  std::vector<ImageEntry> kept;
  kept.reserve(selected_count(all.size(), options));
  for (auto& entry : all) {
    if (options.limit != 0 && kept.size() >= options.limit) break;
    if (passes_start_and_stride(entry.index, options)) kept.push_back(std::move(entry));
  }
  if (kept.empty() && !all.empty())
    fail_file(origin, "start " + std::to_string(options.start) + " skips all " + std::to_string(all.size()) +
                          " images (expected a start below the number of images)");
  return kept;
}

ImageListSource::ImageListSource(std::vector<ImageEntry> selected, CorruptPolicy on_corrupt, std::string what)
    : entries_(std::move(selected)), on_corrupt_(on_corrupt), what_(std::move(what)) {}

std::string ImageListSource::description() const { return what_ + " (" + std::to_string(entries_.size()) + " images)"; }

std::optional<Frame> ImageListSource::next() {
  while (next_entry_ < entries_.size()) {
    const ImageEntry& entry = entries_[next_entry_++];
    std::optional<cv::Mat> image = read_image_bgr8(entry.path);
    if (!image) {
      if (on_corrupt_ == CorruptPolicy::stop)
        fail_file(entry.path,
                  "cannot be decoded as an image (corrupt or truncated file?); "
                  "use the 'skip' corrupt-frame policy to pass over such images");
      spdlog::warn("{}: cannot be decoded as an image, skipped (frame {})", entry.path.string(), entry.index);
      ++stats_.frames_skipped_corrupt;
      stats_.corrupt_paths.push_back(entry.path);
      continue;
    }
    check_size(*image, entry.path);
    ++stats_.frames_read;
    return Frame{entry.index, entry.timestamp, std::move(*image), entry.path};
  }
  return std::nullopt;
}

void ImageListSource::check_size(const cv::Mat& image, const std::filesystem::path& path) {
  if (first_path_.empty()) {
    expected_size_ = image.size();
    first_path_ = path;
    return;
  }
  if (image.size() != expected_size_)
    fail_file(path, "image is " + size_text(image.size()) + " but the sequence's first frame (" + first_path_.string() +
                        ") is " + size_text(expected_size_) + " (expected every frame to have the same size)");
}

std::vector<std::filesystem::path> ImageListSource::image_files() const {
  std::vector<std::filesystem::path> files;
  files.reserve(entries_.size());
  for (const ImageEntry& entry : entries_) files.push_back(entry.path);
  return files;
}

}  // namespace facadeslam
