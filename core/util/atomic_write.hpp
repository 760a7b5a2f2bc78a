#pragma once
// Outputs are written to a temporary file beside the target and renamed into
// place, so that an interrupted run never leaves a half-written file behind.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace facadeslam {

// Calls `write` with a stream to a temporary file in the target's folder,
// then renames it onto `path`. If `write` throws, or the stream fails, the
// temporary file is removed, `path` is untouched and an Error names the file.
// Creates the parent folder if needed.
void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                      bool binary = false);

void write_text_atomically(const std::filesystem::path& path, std::string_view text);

// For writers that need a file name (cv::imwrite, OpenCV FileStorage):
// `write` receives the temporary path (same extension as `path`) and must
// create it; the file is then renamed onto `path`.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path& tmp)>& write);

}  // namespace facadeslam
