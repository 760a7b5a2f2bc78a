#pragma once
// The JSON report of an invariance run:
// {"images": [...], "image_count", "grid_step", "margin", "reference_keypoints",
//  "descriptors": [{"name", "width"}], "match_rule": "...",
//  "cases": [{"case": "blur", "title", "parameter", "values": [...],
//             "match_rate": {"<descriptor>": [one per value]},
//             "compared": {...}, "matched": {...},
//             "per_image": {"<descriptor>": [[one per image] per value]}}],
//  "seconds"}
// Match rates with no keypoint behind them are null.
//
// invariance_table(): the same figures as text for a terminal, one table per
// case (a row per changed value, a column per descriptor, "-" for no rate).
#include <string>

#include "core/util/json.hpp"
#include "semantics/invariance/invariance_suite.hpp"

namespace facadeslam::semantics {

Json to_json(const InvarianceResult& result);
std::string invariance_table(const InvarianceResult& result);

}  // namespace facadeslam::semantics
