#pragma once
// Several descriptors' label evaluations side by side (`facadeslam evaluate
// labels --descriptor all`): one row per descriptor with the overall and
// average recognition rate, every class' recall and the time per image.
#include <string>
#include <vector>

#include "core/util/json.hpp"
#include "semantics/evaluation/label_evaluation.hpp"

namespace facadeslam::semantics {

// [{descriptor, descriptor_width, overall_recognition_rate,
//   average_recognition_rate, recall: {class: r}, extraction_ms_per_image,
//   forest_ms_per_image}, ...] in the order given.
Json comparison_json(const std::vector<LabelEvaluation>& runs);

// The same as a Markdown table (rates in percent, times in ms per image),
// for a terminal and for notes.
std::string comparison_table(const std::vector<LabelEvaluation>& runs);

}  // namespace facadeslam::semantics
