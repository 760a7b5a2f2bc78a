#pragma once
// Writes the small inputs the sequence tests read: images whose pixel value
// identifies them, garbage files standing in for corrupt images.
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/util/error.hpp"
#include "sequences/frame_source.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::test {

// prefix + number + suffix, e.g. numbered("im", 3, ".png") == "im3.png".
// (Appending rather than `"lit" + std::to_string(n)`: GCC 12 at -O3 reports a
// false -Wrestrict on that form.)
inline std::string numbered(const std::string& prefix, long long number, const std::string& suffix = "") {
  std::string name = prefix;
  name += std::to_string(number);
  name += suffix;
  return name;
}

// A colour image filled with (value, value + 1, value + 2), written losslessly
// when `path` is a PNG so the reader's output can be matched to its file.
inline void write_marked_image(const std::filesystem::path& path, int value, int width = 32, int height = 24) {
  std::filesystem::create_directories(path.parent_path());
  const cv::Mat image(height, width, CV_8UC3, cv::Scalar(value, value + 1, value + 2));
  ASSERT_TRUE(cv::imwrite(path.string(), image)) << path;
}

inline void write_image(const std::filesystem::path& path, const cv::Mat& image) {
  std::filesystem::create_directories(path.parent_path());
  ASSERT_TRUE(cv::imwrite(path.string(), image)) << path;
}

// Bytes no codec accepts, under an image name.
inline void write_garbage(const std::filesystem::path& path) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << "this is not an image \x01\x02\x03 at all, just garbage bytes";
}

// The blue channel of the top-left pixel: the `value` of write_marked_image.
inline int mark_of(const cv::Mat& image) { return image.at<cv::Vec3b>(0, 0)[0]; }

// Every remaining frame of `source`.
inline std::vector<Frame> read_all(FrameSource& source) {
  std::vector<Frame> frames;
  while (auto frame = source.next()) frames.push_back(std::move(*frame));
  return frames;
}

}  // namespace facadeslam::test
