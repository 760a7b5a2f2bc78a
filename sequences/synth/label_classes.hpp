#pragma once
// The LabelMeFacade classes (Froehlich et al. 2010), the class table of every
// synthetic sequence: ids 0-8 in the dataset's documented order, with the
// colours its label PNGs use. Synthetic label PNGs use the same colours, so a
// tool that reads LabelMeFacade reads them too.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <opencv2/core.hpp>

namespace facadeslam::synth {

enum class FacadeClass : std::uint8_t {
  various = 0,
  building = 1,
  car = 2,
  door = 3,
  pavement = 4,
  road = 5,
  sky = 6,
  vegetation = 7,
  window = 8,
};

inline constexpr int kClassCount = 9;

struct ClassInfo {
  FacadeClass id;
  std::string_view name;
  cv::Vec3b rgb;  // the LabelMeFacade colour, R G B
};

const std::array<ClassInfo, kClassCount>& facade_classes();
const ClassInfo& class_info(FacadeClass id);
constexpr std::uint8_t id_of(FacadeClass c) { return static_cast<std::uint8_t>(c); }
std::optional<FacadeClass> class_by_name(std::string_view name);

// A LabelMeFacade label map as cv::imread(path, IMREAD_COLOR) gives it (8-bit
// BGR) -> CV_8UC1 class ids. Error naming `source` and the first pixel whose
// colour is not one of the nine.
cv::Mat label_ids_from_colours(const cv::Mat& bgr, const std::filesystem::path& source);

// Class ids -> 8-bit BGR colours (for cv::imwrite). Ids outside 0..8 are
// drawn white, which no class uses.
cv::Mat colours_from_label_ids(const cv::Mat& ids);

// The text of labels.txt: a commented header, then "id name r g b" per class.
std::string class_table_text();

}  // namespace facadeslam::synth
