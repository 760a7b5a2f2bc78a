#include "core/map/semantic_classes.hpp"

namespace facadeslam {

const SemanticClass& semantic_class(std::uint8_t id) {
  return id < kSemanticClasses.size() ? kSemanticClasses[id] : kUnlabelledClass;
}

std::optional<std::uint8_t> semantic_class_by_name(std::string_view name) {
  for (const auto& c : kSemanticClasses)
    if (c.name == name) return c.id;
  return std::nullopt;
}

std::optional<std::uint8_t> semantic_class_by_colour(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  for (const auto& c : kSemanticClasses)
    if (c.r == r && c.g == g && c.b == b) return c.id;
  return std::nullopt;
}

}  // namespace facadeslam
