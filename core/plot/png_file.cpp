#include "core/plot/png_file.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "core/util/atomic_write.hpp"
#include "core/util/error.hpp"

namespace facadeslam::plot {

void save_png(const std::filesystem::path& path, const cv::Mat& image) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".png") fail_file(path, "expected a file name ending in .png for the plot");
  write_file_atomically(path, [&](const std::filesystem::path& tmp) {
    bool written = false;
    try {
      // Maximum zlib effort: plots are committed under docs/, and level 9
      // costs milliseconds on pictures of this size.
      written = cv::imwrite(tmp.string(), image, {cv::IMWRITE_PNG_COMPRESSION, 9});
    } catch (const cv::Exception& e) {
      fail_file(path, "cannot write the PNG plot (" + e.err + ")");
    }
    if (!written) fail_file(path, "cannot write the PNG plot");
  });
}

}  // namespace facadeslam::plot
