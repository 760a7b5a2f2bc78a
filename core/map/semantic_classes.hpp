#pragma once
// The semantic class table shared by the map, the point cloud writer, the
// semantic worker and the evaluation: LabelMeFacade's nine classes with its
// label colours (RGB), in this id order.
#include <array>
#include <bitset>
#include <cstdint>
#include <optional>
#include <string_view>

namespace facadeslam {

struct SemanticClass {
  std::uint8_t id;
  std::string_view name;
  std::uint8_t r, g, b;  // LabelMeFacade label colour
};

inline constexpr std::array<SemanticClass, 9> kSemanticClasses{{
    {0, "various", 0, 0, 0},
    {1, "building", 128, 0, 0},
    {2, "car", 128, 0, 128},
    {3, "door", 128, 128, 0},
    {4, "pavement", 128, 128, 128},
    {5, "road", 128, 64, 0},
    {6, "sky", 0, 128, 128},
    {7, "vegetation", 0, 128, 0},
    {8, "window", 0, 0, 128},
}};

// A set of classes, by id.
using ClassSet = std::bitset<kSemanticClasses.size()>;

// Colour used for points that carry no label yet.
inline constexpr SemanticClass kUnlabelledClass{255, "unlabelled", 200, 200, 200};

const SemanticClass& semantic_class(std::uint8_t id);  // unknown ids give kUnlabelledClass
std::optional<std::uint8_t> semantic_class_by_name(std::string_view name);
// The class whose label colour is exactly (r, g, b), if any.
std::optional<std::uint8_t> semantic_class_by_colour(std::uint8_t r, std::uint8_t g, std::uint8_t b);

}  // namespace facadeslam
