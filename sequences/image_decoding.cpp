#include "sequences/image_decoding.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

std::string depth_name(int depth) {
  switch (depth) {
    case CV_8U: return "8-bit unsigned";
    case CV_8S: return "8-bit signed";
    case CV_16U: return "16-bit unsigned";
    case CV_16S: return "16-bit signed";
    case CV_32S: return "32-bit integer";
    case CV_32F: return "32-bit float";
    case CV_64F: return "64-bit float";
    default: return "depth " + std::to_string(depth);
  }
}

}  // namespace

namespace {

// A PNG must end with its IEND chunk and a JPEG with its EOI marker (within
// the last KiB: some writers append a few bytes). A file cut short is
// corrupt without asking the decoder, which would also print libpng's or
// libjpeg's own line ("libpng error: Read Error") on stderr.
bool truncated_png_or_jpeg(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char head[4] = {};
  if (!in.read(head, sizeof head)) return false;
  const bool png = std::memcmp(head, "\x89PNG", 4) == 0;
  const bool jpeg = static_cast<unsigned char>(head[0]) == 0xFF && static_cast<unsigned char>(head[1]) == 0xD8;
  if (!png && !jpeg) return false;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff tail_size = std::min<std::streamoff>(size, 1024);
  std::string tail(static_cast<std::size_t>(tail_size), '\0');
  in.seekg(size - tail_size);
  if (!in.read(tail.data(), tail_size)) return true;
  return png ? tail.find("IEND") == std::string::npos : tail.find("\xFF\xD9") == std::string::npos;
}

}  // namespace

std::optional<cv::Mat> read_image_bgr8(const std::filesystem::path& path) {
  if (truncated_png_or_jpeg(path)) return std::nullopt;
  cv::Mat decoded;
  try {
    // UNCHANGED keeps 16-bit and alpha so that we convert them ourselves,
    // consistently across formats, instead of per-codec defaults.
    decoded = cv::imread(path.string(), cv::IMREAD_UNCHANGED | cv::IMREAD_IGNORE_ORIENTATION);
  } catch (const cv::Exception&) {
    // Some codecs throw on malformed data instead of returning an empty Mat.
    return std::nullopt;
  }
  if (decoded.empty()) return std::nullopt;
  return to_bgr8(decoded, path);
}

cv::Mat to_bgr8(const cv::Mat& decoded, const std::filesystem::path& origin) {
  cv::Mat eight_bit;
  switch (decoded.depth()) {
    case CV_8U: eight_bit = decoded; break;
    case CV_16U: decoded.convertTo(eight_bit, CV_8U, 255.0 / 65535.0); break;
    case CV_32F:
    case CV_64F: decoded.convertTo(eight_bit, CV_8U, 255.0); break;
    default:
      fail_file(origin, "unsupported pixel type (" + depth_name(decoded.depth()) +
                            "); expected 8-bit, 16-bit unsigned or float images");
  }
  cv::Mat bgr;
  switch (eight_bit.channels()) {
    case 1: cv::cvtColor(eight_bit, bgr, cv::COLOR_GRAY2BGR); break;
    case 3: bgr = eight_bit; break;
    case 4: cv::cvtColor(eight_bit, bgr, cv::COLOR_BGRA2BGR); break;
    default:
      fail_file(origin, "unsupported image with " + std::to_string(eight_bit.channels()) +
                            " channels; expected grey (1), colour (3) or colour + alpha (4)");
  }
  return bgr;
}

}  // namespace facadeslam
