#include "sequences/image_decoding.hpp"

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

std::optional<cv::Mat> read_image_bgr8(const std::filesystem::path& path) {
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
