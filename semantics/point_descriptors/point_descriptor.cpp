#include "semantics/point_descriptors/point_descriptor.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/error.hpp"
#include "semantics/point_descriptors/edd_descriptor.hpp"
#include "semantics/point_descriptors/modular_descriptor.hpp"
#include "semantics/point_descriptors/orb_descriptor.hpp"
#include "semantics/point_descriptors/sift_descriptor.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {

std::vector<std::string> expand_descriptor_names(const std::vector<std::string>& given) {
  std::vector<std::string> names;
  const auto add = [&](std::string_view n) {
    if (std::find(names.begin(), names.end(), n) == names.end()) names.emplace_back(n);
  };
  for (const std::string& name : given) {
    if (name != "all") {
      add(name);
      continue;
    }
    for (const std::string_view n : kPointDescriptorNames) add(n);
  }
  return names;
}

std::unique_ptr<PointDescriptor> make_point_descriptor(std::string_view name, const Genome& genome) {
  const int patch_side = 2 * genome.decode().patch_radius + 1;
  if (name == "modular") return std::make_unique<ModularDescriptor>(genome);
  if (name == "sift") return std::make_unique<SiftDescriptor>(SiftDescriptor::Channels::grey, patch_side);
  if (name == "opponent-sift") return std::make_unique<SiftDescriptor>(SiftDescriptor::Channels::opponent, patch_side);
  if (name == "orb") return std::make_unique<OrbDescriptor>();
  if (name == "edd") return std::make_unique<EddDescriptor>();
  std::string known;
  for (const std::string_view n : kPointDescriptorNames) known.append(known.empty() ? "" : ", ").append(n);
  throw Error(cat("unknown descriptor '", name, "' (expected one of ", known, ")"));
}

void check_descriptor_input(std::string_view descriptor, const cv::Mat& bgr,
                            const std::vector<cv::Point2f>& keypoints) {
  if (bgr.empty() || bgr.type() != CV_8UC3)
    throw Error(cat(descriptor, " descriptor: expected a non-empty 8-bit BGR image"));
  for (std::size_t i = 0; i < keypoints.size(); ++i) {
    const cv::Point2f& p = keypoints[i];
    const bool inside = std::isfinite(p.x) && std::isfinite(p.y) && cvRound(p.x) >= 0 && cvRound(p.x) < bgr.cols &&
                        cvRound(p.y) >= 0 && cvRound(p.y) < bgr.rows;
    if (!inside)
      throw Error(
          cat(descriptor, " descriptor: keypoint ", i, " is not inside the ", bgr.cols, "x", bgr.rows, " image"));
  }
}

}  // namespace facadeslam::semantics
