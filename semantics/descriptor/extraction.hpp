#pragma once
// Descriptor extraction: one row of active values per keypoint, in module
// order (module_layout.hpp). Modules without an active value are not run,
// and a module only computes its active values (per channel where that
// saves work), which is where the descriptor's speed comes from.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/descriptor/descriptor_params.hpp"
#include "semantics/descriptor/prepared_image.hpp"

namespace facadeslam::semantics {

// What extraction computed, for tests and profiling.
struct ExtractionStats {
  std::uint64_t keypoints = 0;
  std::array<std::uint64_t, kModuleCount> module_calls{};  // one per keypoint per run module
  std::array<std::uint64_t, 3> moment_calls{};             // patch moments per colour channel

  std::uint64_t calls(Module m) const { return module_calls[static_cast<std::size_t>(m)]; }
};

// The extraction schedule of an activation mask: which modules run, which
// colour channels need patch moments (and to which order), which values
// become columns.
struct ExtractionPlan {
  std::array<std::uint64_t, kModuleCount> bits{};  // per-module activation
  std::vector<Module> modules;                     // modules with an active value, in order
  std::array<int, 3> moment_order{-1, -1, -1};     // per channel; -1 = no moments needed
  std::vector<int> columns;                        // value index (0..184) of each output column
};

ExtractionPlan plan_extraction(const ActivationMask& activation);

// A CV_32F matrix with keypoints.size() rows and params.active_value_count()
// columns (active values in module order). `image` must come from prepare()
// with the same preprocessing parameters (colour space, blur, Canny,
// gradient operator) and a border >= params.patch_radius. Each keypoint's
// patch is centred on the pixel nearest to it; a keypoint that is not finite
// or does not round to a pixel of the image is an Error naming it. A
// keypoint's row does not depend on the other keypoints of the call (they
// share work, never results).
cv::Mat extract(const PreparedImage& image, const std::vector<cv::Point2f>& keypoints, const DescriptorParams& params,
                ExtractionStats* stats = nullptr);

// Names of the output columns (value_names() of the active values).
std::vector<std::string> active_value_names(const DescriptorParams& params);

}  // namespace facadeslam::semantics
