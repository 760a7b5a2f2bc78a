#include "sequences/synth/label_classes.hpp"

#include <sstream>

#include "core/util/error.hpp"

namespace facadeslam::synth {

const std::array<ClassInfo, kClassCount>& facade_classes() {
  static const std::array<ClassInfo, kClassCount> classes = {{
      {FacadeClass::various, "various", {0, 0, 0}},
      {FacadeClass::building, "building", {128, 0, 0}},
      {FacadeClass::car, "car", {128, 0, 128}},
      {FacadeClass::door, "door", {128, 128, 0}},
      {FacadeClass::pavement, "pavement", {128, 128, 128}},
      {FacadeClass::road, "road", {128, 64, 0}},
      {FacadeClass::sky, "sky", {0, 128, 128}},
      {FacadeClass::vegetation, "vegetation", {0, 128, 0}},
      {FacadeClass::window, "window", {0, 0, 128}},
  }};
  return classes;
}

const ClassInfo& class_info(FacadeClass id) { return facade_classes()[id_of(id)]; }

std::optional<FacadeClass> class_by_name(std::string_view name) {
  for (const auto& c : facade_classes())
    if (c.name == name) return c.id;
  return std::nullopt;
}

cv::Mat label_ids_from_colours(const cv::Mat& bgr, const std::filesystem::path& source) {
  if (bgr.empty() || bgr.type() != CV_8UC3) fail_file(source, "expected an 8-bit colour label map");
  // Colour -> id through a base-3 key: every class colour channel is 0, 64 or 128.
  std::array<int, 27> lookup;
  lookup.fill(-1);
  const auto key = [](int r, int g, int b) { return (r / 64) * 9 + (g / 64) * 3 + b / 64; };
  for (const auto& c : facade_classes()) lookup[key(c.rgb[0], c.rgb[1], c.rgb[2])] = id_of(c.id);
  cv::Mat ids(bgr.size(), CV_8UC1);
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      const int r = p[2], g = p[1], b = p[0];
      const bool on_grid = r % 64 == 0 && g % 64 == 0 && b % 64 == 0 && r <= 128 && g <= 128 && b <= 128;
      const int id = on_grid ? lookup[key(r, g, b)] : -1;
      if (id < 0)
        fail_file(source, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") has colour (" +
                              std::to_string(r) + ", " + std::to_string(g) + ", " + std::to_string(b) +
                              "), which is not one of the nine LabelMeFacade class colours");
      ids.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(id);
    }
  return ids;
}

cv::Mat colours_from_label_ids(const cv::Mat& ids) {
  cv::Mat bgr(ids.size(), CV_8UC3);
  for (int y = 0; y < ids.rows; ++y)
    for (int x = 0; x < ids.cols; ++x) {
      const std::uint8_t id = ids.at<std::uint8_t>(y, x);
      const cv::Vec3b rgb = id < kClassCount ? facade_classes()[id].rgb : cv::Vec3b(255, 255, 255);
      bgr.at<cv::Vec3b>(y, x) = {rgb[2], rgb[1], rgb[0]};
    }
  return bgr;
}

std::string class_table_text() {
  std::ostringstream out;
  out << "# facadeslam synthetic sequence: class table of the label PNGs (LabelMeFacade classes)\n"
      << "# id name red green blue\n";
  for (const auto& c : facade_classes())
    out << int(id_of(c.id)) << " " << c.name << " " << int(c.rgb[0]) << " " << int(c.rgb[1]) << " " << int(c.rgb[2])
        << "\n";
  return out.str();
}

}  // namespace facadeslam::synth
