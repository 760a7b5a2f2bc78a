#include "semantics/evaluation/facade_dataset.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <system_error>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "core/util/input_confinement.hpp"
#include "semantics/evaluation/label_image.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

namespace fs = std::filesystem;

constexpr const char* kLayout = "the LabelMeFacade layout: train.txt, test.txt, images/, labels/";

std::string trimmed(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = line.find_last_not_of(" \t\r\n");
  return line.substr(first, last - first + 1);
}

bool is_file(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

fs::path find_image(const fs::path& folder, const std::string& name) {
  for (const char* extension : {".jpg", ".jpeg", ".png", ".JPG"}) {
    const fs::path candidate = folder / cat(name, extension);
    if (is_file(candidate)) return candidate;
  }
  return {};
}

}  // namespace

std::vector<LabelledImage> read_facade_split(const fs::path& root, const std::string& list) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) fail_file(root, cat("no such dataset folder (expected ", kLayout, ")"));
  const fs::path list_path = root / list;
  if (!is_file(list_path)) fail_file(list_path, cat("no such file (expected ", kLayout, ")"));
  std::ifstream in(list_path);
  if (!in) fail_file(list_path, "cannot open the image list");
  std::vector<LabelledImage> entries;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    std::string name = trimmed(line);
    if (name.empty() || name[0] == '#') continue;
    // Tolerate names listed with their photo extension.
    for (const char* extension : {".jpg", ".jpeg", ".png"}) {
      const std::string e = extension;
      if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0)
        name.resize(name.size() - e.size());
    }
    // Names stay inside the dataset (core/util/input_confinement.hpp).
    require_confined(root / "images" / name, root, list_path, static_cast<std::size_t>(line_number), name);
    require_confined(root / "labels" / name, root, list_path, static_cast<std::size_t>(line_number), name);
    LabelledImage entry;
    entry.name = name;
    entry.image = find_image(root / "images", name);
    if (entry.image.empty())
      fail_file(list_path, cat("line ", line_number, ": no image images/", name, ".jpg (or .jpeg, .png)"));
    entry.label = root / "labels" / cat(name, ".png");
    if (!is_file(entry.label))
      fail_file(entry.label, cat("no label image for ", entry.image.string(), " (listed in ", list, ")"));
    entries.push_back(std::move(entry));
  }
  if (in.bad()) fail_file(list_path, "cannot read the image list");
  if (entries.empty()) fail_file(list_path, "lists no image (expected one image name per line)");
  return entries;
}

namespace {

LoadedLabelledImage seen_as(LoadedLabelledImage stored, const LabelledImage& entry) {
  LoadedLabelledImage seen = std::move(stored);
  if (entry.scale != 1.0) {
    const cv::Size size(std::max(1, static_cast<int>(std::lround(seen.bgr.cols * entry.scale))),
                        std::max(1, static_cast<int>(std::lround(seen.bgr.rows * entry.scale))));
    cv::Mat bgr, label;
    cv::resize(seen.bgr, bgr, size, 0, 0, entry.scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
    cv::resize(seen.label, label, size, 0, 0, cv::INTER_NEAREST);  // class colours must not blend
    seen.bgr = bgr;
    seen.label = label;
  }
  if (entry.grey) {
    cv::Mat grey, bgr;
    cv::cvtColor(seen.bgr, grey, cv::COLOR_BGR2GRAY);
    cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
    seen.bgr = bgr;
  }
  return seen;
}

LoadedLabelledImage load_stored(const LabelledImage& entry) {
  LoadedLabelledImage loaded;
  try {
    // Labels were drawn on the stored pixels: ignore any EXIF rotation.
    loaded.bgr = cv::imread(entry.image.string(), cv::IMREAD_COLOR | cv::IMREAD_IGNORE_ORIENTATION);
  } catch (const cv::Exception& e) {
    fail_file(entry.image, cat("cannot decode the image (", e.err, ")"));
  }
  if (loaded.bgr.empty()) fail_file(entry.image, "cannot decode the image");
  loaded.label = read_label_image(entry.label);
  if (loaded.label.size() != loaded.bgr.size())
    fail_file(entry.label, cat("label image is ", loaded.label.cols, "x", loaded.label.rows, " but its photo ",
                               entry.image.filename().string(), " is ", loaded.bgr.cols, "x", loaded.bgr.rows));
  return loaded;
}

}  // namespace

LoadedLabelledImage load_labelled_image(const LabelledImage& entry) { return seen_as(load_stored(entry), entry); }

std::vector<LabelledImage> with_views(const std::vector<LabelledImage>& images, const std::vector<double>& scales,
                                      bool grey) {
  if (scales.empty()) throw Error("training: expected at least one image scale");
  std::vector<LabelledImage> views;
  views.reserve(images.size() * scales.size());
  for (const double scale : scales) {
    if (!(scale > 0.0 && scale <= 8.0)) throw Error(cat("training: an image scale must be in (0, 8], got ", scale));
    for (LabelledImage view : images) {
      view.scale = scale;
      view.grey = grey;
      views.push_back(std::move(view));
    }
  }
  return views;
}

DecodedImageCache::DecodedImageCache(const std::vector<LabelledImage>& images, std::size_t budget_bytes) {
  for (const LabelledImage& entry : images) {
    if (decoded_.count(entry.image)) continue;
    LoadedLabelledImage loaded = load_stored(entry);
    const std::size_t size =
        loaded.bgr.total() * loaded.bgr.elemSize() + loaded.label.total() * loaded.label.elemSize();
    if (bytes_ + size > budget_bytes) break;
    bytes_ += size;
    decoded_.emplace(entry.image, std::move(loaded));
  }
}

LoadedLabelledImage DecodedImageCache::operator()(const LabelledImage& entry) const {
  const auto it = decoded_.find(entry.image);
  if (it == decoded_.end()) return load_labelled_image(entry);
  const bool as_stored = entry.scale == 1.0 && !entry.grey;
  return as_stored ? it->second : seen_as(it->second, entry);
}

}  // namespace facadeslam::semantics
