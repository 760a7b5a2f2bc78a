#include "core/plot/png_file.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "core/util/atomic_write.hpp"
#include "core/util/error.hpp"
#include "core/util/png_signature.hpp"

namespace facadeslam::plot {

void save_png(const std::filesystem::path& path, const cv::Mat& image, const std::vector<int>& parameters) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".png") fail_file(path, "expected a file name ending in .png for the picture");
  std::vector<unsigned char> encoded;
  try {
    if (!cv::imencode(".png", image, encoded, parameters)) fail_file(path, "cannot encode the PNG picture");
  } catch (const cv::Exception& e) {
    fail_file(path, "cannot encode the PNG picture (" + e.err + ")");
  }
  const std::vector<unsigned char> png = sign_png(encoded);
  const auto write_bytes = [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  };
  write_atomically(path, write_bytes, /*binary=*/true);
}

}  // namespace facadeslam::plot
