#include "semantics/evaluation/label_comparison.hpp"

#include <cmath>

#include <fmt/format.h>

namespace facadeslam::semantics {
namespace {

std::string percent(double v) { return std::isfinite(v) ? fmt::format("{:.1f}", 100.0 * v) : "-"; }

}  // namespace

Json comparison_json(const std::vector<LabelEvaluation>& runs) {
  const auto names = evaluation_class_names();
  Json rows = Json::array();
  for (const LabelEvaluation& r : runs) {
    Json row = Json::object();
    row["descriptor"] = r.descriptor;
    row["descriptor_width"] = r.descriptor_width;
    row["overall_recognition_rate"] = r.confusion.overall_recognition_rate();
    row["average_recognition_rate"] = r.confusion.average_recognition_rate();
    Json recall = Json::object();
    for (int k = 0; k < r.confusion.classes() && k < static_cast<int>(names.size()); ++k)
      recall[names[static_cast<std::size_t>(k)]] = r.confusion.metrics(k).recall;
    row["recall"] = std::move(recall);
    row["extraction_ms_per_image"] = r.extraction_ms_per_image();
    row["forest_ms_per_image"] = r.forest_ms_per_image();
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string comparison_table(const std::vector<LabelEvaluation>& runs) {
  const auto names = evaluation_class_names();
  std::string header = "| descriptor | values | overall % | average %";
  std::string rule = "|---|---:|---:|---:";
  for (const std::string& n : names) {
    header += " | " + n;
    rule += "|---:";
  }
  header += " | extraction ms/image | forest ms/image |\n";
  rule += "|---:|---:|\n";
  std::string table = header + rule;
  for (const LabelEvaluation& r : runs) {
    table +=
        fmt::format("| {} | {} | {} | {}", r.descriptor, r.descriptor_width,
                    percent(r.confusion.overall_recognition_rate()), percent(r.confusion.average_recognition_rate()));
    for (int k = 0; k < static_cast<int>(names.size()); ++k)
      table += " | " + (k < r.confusion.classes() ? percent(r.confusion.metrics(k).recall) : std::string("-"));
    table += fmt::format(" | {:.1f} | {:.1f} |\n", r.extraction_ms_per_image(), r.forest_ms_per_image());
  }
  return table;
}

}  // namespace facadeslam::semantics
