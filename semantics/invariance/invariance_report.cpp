#include "semantics/invariance/invariance_report.hpp"

#include <cmath>
#include <string>

#include <fmt/printf.h>

namespace facadeslam::semantics {
namespace {

template <typename T>
Json array_of(const std::vector<T>& values) {
  Json a = Json::array();
  for (const T& v : values) a.push_back(Json(v));
  return a;
}

// {"<descriptor>": rows[d]} for per-descriptor tables.
template <typename Row, typename Convert>
Json by_descriptor(const InvarianceResult& result, const std::vector<Row>& rows, Convert convert) {
  Json j = Json::object();
  for (std::size_t d = 0; d < rows.size(); ++d) j[result.descriptors[d]] = convert(rows[d]);
  return j;
}

Json case_json(const InvarianceResult& result, const InvarianceCaseResult& r) {
  const InvarianceCaseInfo& info = case_info(r.id);
  Json j = Json::object();
  j["case"] = std::string(info.name);
  j["title"] = std::string(info.title);
  j["parameter"] = std::string(info.parameter);
  j["values"] = array_of(r.values);
  j["match_rate"] = by_descriptor(result, r.match_rate, [](const std::vector<double>& row) { return array_of(row); });
  const auto counts = [](const std::vector<std::size_t>& row) {
    Json a = Json::array();
    for (const std::size_t n : row) a.push_back(static_cast<unsigned long long>(n));
    return a;
  };
  j["compared"] = by_descriptor(result, r.compared, counts);
  j["matched"] = by_descriptor(result, r.matched, counts);
  j["per_image"] = by_descriptor(result, r.per_image, [](const std::vector<std::vector<double>>& per_value) {
    Json a = Json::array();
    for (const auto& per_image : per_value) a.push_back(array_of(per_image));
    return a;
  });
  return j;
}

std::string rate_text(double v) { return std::isfinite(v) ? fmt::sprintf("%.3f", v) : std::string("-"); }

}  // namespace

Json to_json(const InvarianceResult& result) {
  Json j = Json::object();
  Json images = Json::array();
  for (const auto& path : result.images) images.push_back(path.string());
  j["images"] = std::move(images);
  j["image_count"] = static_cast<unsigned long long>(result.images.size());
  j["grid_step"] = result.step;
  j["margin"] = result.margin;
  j["reference_keypoints"] = static_cast<unsigned long long>(result.reference_keypoints);
  Json descriptors = Json::array();
  for (std::size_t d = 0; d < result.descriptors.size(); ++d) {
    Json entry = Json::object();
    entry["name"] = result.descriptors[d];
    entry["width"] = result.descriptor_widths[d];
    descriptors.push_back(std::move(entry));
  }
  j["descriptors"] = std::move(descriptors);
  j["match_rule"] =
      "share of the keypoints kept in the changed image whose descriptor's nearest neighbour (L2, brute force) among "
      "the changed image's keypoints is their own counterpart, strictly (ties are misses); the mean over the images";
  Json cases = Json::array();
  for (const InvarianceCaseResult& r : result.cases) cases.push_back(case_json(result, r));
  j["cases"] = std::move(cases);
  j["seconds"] = result.seconds;
  return j;
}

std::string invariance_table(const InvarianceResult& r) {
  std::string out;
  out += fmt::sprintf("invariance: %zu images, %zu reference keypoints (grid step %d, margin %d), %.1f s\n",
                      r.images.size(), r.reference_keypoints, r.step, r.margin, r.seconds);
  for (const InvarianceCaseResult& c : r.cases) {
    const InvarianceCaseInfo& info = case_info(c.id);
    out += fmt::sprintf("\n%s: match rate per %s\n  %10s", std::string(info.title).c_str(),
                        std::string(info.parameter).c_str(), "");
    for (const std::string& name : r.descriptors) out += fmt::sprintf(" %13s", name.c_str());
    out.push_back('\n');
    for (std::size_t v = 0; v < c.values.size(); ++v) {
      out += fmt::sprintf("  %10g", c.values[v]);
      for (std::size_t d = 0; d < r.descriptors.size(); ++d)
        out += fmt::sprintf(" %13s", rate_text(c.match_rate[d][v]).c_str());
      out.push_back('\n');
    }
  }
  return out;
}

}  // namespace facadeslam::semantics
