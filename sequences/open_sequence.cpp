#include "sequences/open_sequence.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/util/error.hpp"
#include "core/util/path_checks.hpp"
#include "sequences/image_folder_source.hpp"
#include "sequences/looping_source.hpp"
#include "sequences/tum_list_source.hpp"
#include "sequences/video_source.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

bool has_txt_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".txt";
}

}  // namespace

SequenceKind detect_sequence_kind(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec))
    fail_file(path,
              "no such file or folder (expected an image folder, a TUM rgb.txt list or a "
              "video file)");
  // A FIFO or a device would block or never end: said for what it is.
  if (!is_existing_folder(path) && !is_readable_file(path))
    fail_file(path, describe_path(path) + " (expected an image folder, a TUM rgb.txt list or a video file)");
  if (fs::is_directory(path, ec))
    return fs::is_regular_file(path / "rgb.txt", ec) ? SequenceKind::tum_list : SequenceKind::image_folder;
  return has_txt_extension(path) ? SequenceKind::tum_list : SequenceKind::video;
}

namespace {

std::unique_ptr<FrameSource> open_one_pass(const fs::path& path, const SequenceOptions& options) {
  const SequenceKind kind = detect_sequence_kind(path);
  if (!options.timestamps_file.empty() && kind != SequenceKind::image_folder)
    fail_file(options.timestamps_file, "a timestamps file applies only to an image folder, but " + path.string() +
                                           " is read as a " + (kind == SequenceKind::video ? "video" : "TUM list") +
                                           " (which carries its own timestamps)");
  switch (kind) {
    case SequenceKind::image_folder: return std::make_unique<ImageFolderSource>(path, options);
    case SequenceKind::tum_list:
      return std::make_unique<TumListSource>(is_existing_folder(path) ? path / "rgb.txt" : path, options);
    case SequenceKind::video: return std::make_unique<VideoSource>(path, options);
  }
  throw Error("open_sequence: unknown sequence kind");  // unreachable; keeps -Wreturn-type quiet
}

}  // namespace

std::unique_ptr<FrameSource> open_sequence(const fs::path& path, const SequenceOptions& options) {
  validate(options);
  if (options.loops <= 1) return open_one_pass(path, options);
  return std::make_unique<LoopingSource>([path, options] { return open_one_pass(path, options); }, options.loops);
}

}  // namespace facadeslam
