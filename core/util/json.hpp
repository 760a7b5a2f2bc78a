#pragma once
// JSON for the reports and results the project writes (report.json, evaluation
// results, genomes): nlohmann/json with objects in insertion order, so that a
// report reads top-down as it was written. Configs are YAML, models binary.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace facadeslam {

using Json = nlohmann::ordered_json;

// Pretty-printed with two-space indent and a final newline. Non-finite numbers
// are written as null (JSON has no NaN), invalid UTF-8 in strings (a file name
// from a Latin-1 system) as U+FFFD: the output always parses.
std::string json_text(const Json& json);
// The same for nlohmann's sorted-key type (the optimiser's checkpoints).
std::string json_text(const nlohmann::json& json);

// Writes json_text(json) atomically to `path` (see atomic_write.hpp).
void write_json(const std::filesystem::path& path, const Json& json);
void write_json(const std::filesystem::path& path, const nlohmann::json& json);

}  // namespace facadeslam
