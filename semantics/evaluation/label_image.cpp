#include "semantics/evaluation/label_image.hpp"

#include <string>
#include <system_error>

#include <opencv2/imgcodecs.hpp>

#include "core/map/semantic_classes.hpp"
#include "core/util/error.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {

std::uint8_t class_of_colour(const cv::Vec3b& bgr) {
  const auto id = semantic_class_by_colour(bgr[2], bgr[1], bgr[0]);
  return id ? *id : kUnknownClass;
}

namespace {

// "various (0,0,0), building (128,0,0), ...": the colours a label image may hold.
std::string class_colour_list() {
  std::string list;
  for (const SemanticClass& c : kSemanticClasses)
    list += cat(list.empty() ? "" : ", ", c.name, " (", int{c.r}, ",", int{c.g}, ",", int{c.b}, ")");
  return list;
}

}  // namespace

cv::Mat read_label_image(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail_file(path, "no such label image");
  cv::Mat label;
  try {
    label = cv::imread(path.string(), cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    fail_file(path, cat("cannot decode the label image (", e.err, ")"));
  }
  if (label.empty()) fail_file(path, "cannot decode the label image (expected a colour PNG)");
  // A colour that is no class is a dataset in another label scheme (or a
  // resized, blended label image): its keypoints would be dropped silently.
  for (int y = 0; y < label.rows; ++y)
    for (int x = 0; x < label.cols; ++x) {
      const cv::Vec3b& bgr = label.at<cv::Vec3b>(y, x);
      if (class_of_colour(bgr) == kUnknownClass)
        fail_file(path, cat("pixel (", x, ", ", y, ") has the colour RGB(", int{bgr[2]}, ", ", int{bgr[1]}, ", ",
                            int{bgr[0]}, "), expected one of the nine class colours (", class_colour_list(), ")"));
    }
  return label;
}

std::vector<std::uint8_t> classes_at(const cv::Mat& label_bgr, const std::vector<cv::Point2f>& keypoints) {
  std::vector<std::uint8_t> classes;
  classes.reserve(keypoints.size());
  for (const cv::Point2f& p : keypoints) {
    const cv::Point pixel(cvRound(p.x), cvRound(p.y));
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= label_bgr.cols || pixel.y >= label_bgr.rows)
      throw Error("ground truth: keypoint outside the label image");
    classes.push_back(class_of_colour(label_bgr.at<cv::Vec3b>(pixel)));
  }
  return classes;
}

}  // namespace facadeslam::semantics
