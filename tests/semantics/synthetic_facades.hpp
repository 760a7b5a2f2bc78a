#pragma once
// A tiny LabelMeFacade-layout dataset written by the tests themselves:
// sky on top, a brick building with dark windows in the middle, road at the
// bottom, with the boundaries and textures varying from image to image.
#include <filesystem>
#include <fstream>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/map/semantic_classes.hpp"

namespace facadeslam::semantics::test_util {

inline cv::Scalar label_colour(std::string_view class_name) {
  for (const auto& c : kSemanticClasses)
    if (c.name == class_name) return cv::Scalar(c.b, c.g, c.r);
  return cv::Scalar(255, 255, 255);
}

// Photo and label of synthetic facade `index`.
inline void synthetic_facade(int index, cv::Size size, cv::Mat& photo, cv::Mat& label) {
  cv::RNG rng(static_cast<std::uint64_t>(1000 + index));
  photo.create(size, CV_8UC3);
  label.create(size, CV_8UC3);
  const int sky_end = size.height / 3 + rng.uniform(-4, 5);
  const int road_start = 2 * size.height / 3 + rng.uniform(-4, 5);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      cv::Vec3b colour;
      if (y < sky_end)
        colour = cv::Vec3b(static_cast<uchar>(220 - y), static_cast<uchar>(170 - y / 2), 110);
      else if (y < road_start)
        colour = ((y / 4 + (x / 8) % 2) % 2) ? cv::Vec3b(60, 80, 170) : cv::Vec3b(90, 110, 190);  // bricks
      else
        colour = cv::Vec3b::all(static_cast<uchar>(95 + rng.uniform(-25, 26)));
      photo.at<cv::Vec3b>(y, x) = colour;
    }
  label.setTo(label_colour("sky"));
  label.rowRange(sky_end, road_start).setTo(label_colour("building"));
  label.rowRange(road_start, size.height).setTo(label_colour("road"));
  for (int w = 0; w < 3; ++w) {
    const cv::Rect window(8 + w * size.width / 3 + rng.uniform(0, 4), sky_end + 6, size.width / 8,
                          (road_start - sky_end) / 2);
    cv::rectangle(photo, window, cv::Scalar(40, 30, 25), cv::FILLED);
    cv::rectangle(label, window, label_colour("window"), cv::FILLED);
  }
  cv::Mat noise(size, CV_8UC3);
  rng.fill(noise, cv::RNG::UNIFORM, cv::Scalar::all(0), cv::Scalar::all(10));
  cv::add(photo, noise, photo);
}

// root/{train.txt, test.txt, images/, labels/} with n_train + n_test images.
inline void write_synthetic_dataset(const std::filesystem::path& root, int n_train, int n_test,
                                    cv::Size size = {120, 90}) {
  std::filesystem::create_directories(root / "images");
  std::filesystem::create_directories(root / "labels");
  std::ofstream train(root / "train.txt"), test(root / "test.txt");
  for (int i = 0; i < n_train + n_test; ++i) {
    std::string name = "facade_";
    name.append(std::to_string(i));
    cv::Mat photo, label;
    synthetic_facade(i, size, photo, label);
    cv::imwrite((root / "images" / (name + ".jpg")).string(), photo);
    cv::imwrite((root / "labels" / (name + ".png")).string(), label);
    (i < n_train ? train : test) << name << "\n";
  }
}

}  // namespace facadeslam::semantics::test_util
