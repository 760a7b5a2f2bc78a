#pragma once
// Genome files. Two forms, chosen by the file extension:
//  - `.json`: named parameter fields and the names of the active values
//    (readable, hand-editable; see genome_to_json for the layout);
//  - anything else: the 211-character 0/1 text of Genome::to_string().
// Both round-trip exactly. Every failure is an Error naming the file.
#include <filesystem>
#include <string>
#include <string_view>

#include "core/util/json.hpp"
#include "semantics/descriptor/genome.hpp"

namespace facadeslam::semantics {

// {"format": "facadeslam-genome", "version": 1, "colour_space": "XYZ",
//  "patch_radius": 10, "gaussian_kernel": 7, "gaussian_sigma": 1.5,
//  "forest_depth": 35, "forest_size": 100, "split_variables": 16,
//  "canny_kernel": 5, "canny_low_threshold": 65, "canny_high_threshold": 195,
//  "gradient_operator": "Sobel", "active_value_count": 93,
//  "active_values": ["x_norm", ...]}
// canny_high_threshold and active_value_count are informative: on reading
// they must agree with canny_low_threshold and active_values.
Json genome_to_json(const Genome& genome);

// Parses the JSON form; `where` (usually the file name) starts every message.
Genome genome_from_json(std::string_view json_text, std::string_view where);

void save_genome(const std::filesystem::path& path, const Genome& genome);
Genome load_genome(const std::filesystem::path& path);

}  // namespace facadeslam::semantics
