#include "semantics/descriptor/genome_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <set>
#include <sstream>

#include "core/util/atomic_write.hpp"
#include "core/util/error.hpp"

namespace facadeslam::semantics {
namespace {

constexpr std::string_view kFormat = "facadeslam-genome";
constexpr int kVersion = 1;

const std::set<std::string>& known_keys() {
  static const std::set<std::string> keys{"format",
                                          "version",
                                          "colour_space",
                                          "patch_radius",
                                          "gaussian_kernel",
                                          "gaussian_sigma",
                                          "forest_depth",
                                          "forest_size",
                                          "split_variables",
                                          "canny_kernel",
                                          "canny_low_threshold",
                                          "canny_high_threshold",
                                          "gradient_operator",
                                          "active_value_count",
                                          "active_values"};
  return keys;
}

class JsonReader {
 public:
  JsonReader(const Json& root, std::string_view where) : root_(root), where_(where) {}

  [[noreturn]] void fail(const std::string& what) const { throw Error(where_ + ": " + what); }

  const Json& required(const std::string& key) const {
    const auto it = root_.find(key);
    if (it == root_.end() || it->is_null()) fail("missing key '" + key + "'");
    return *it;
  }

  int integer(const std::string& key) const {
    const Json& node = required(key);
    if (!node.is_number_integer() || node.get<std::int64_t>() != node.get<int>())
      fail("key '" + key + "' must be an integer");
    return node.get<int>();
  }

  double number(const std::string& key) const {
    const Json& node = required(key);
    if (!node.is_number()) fail("key '" + key + "' must be a number");
    return node.get<double>();
  }

  std::string text(const std::string& key) const {
    const Json& node = required(key);
    if (!node.is_string()) fail("key '" + key + "' must be a string");
    return node.get<std::string>();
  }

 private:
  const Json& root_;
  std::string where_;
};

template <typename T, std::size_t N>
std::string table_text(const std::array<T, N>& table) {
  std::ostringstream out;
  for (std::size_t i = 0; i < N; ++i) out << (i ? ", " : "") << table[i];
  return out.str();
}

template <typename T, std::size_t N>
T table_value(const JsonReader& in, const std::string& key, T value, const std::array<T, N>& table) {
  for (const T t : table) {
    if constexpr (std::is_floating_point_v<T>) {
      if (std::abs(t - value) < 1e-9) return t;
    } else if (t == value) {
      return t;
    }
  }
  std::ostringstream shown;
  shown << value;
  in.fail("key '" + key + "' = " + shown.str() + " is not one of " + table_text(table));
}

bool has_extension(const std::filesystem::path& path, std::string_view ext) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e == ext;
}

}  // namespace

Json genome_to_json(const Genome& genome) {
  const DescriptorParams p = genome.decode();
  Json json = Json::object();
  json["format"] = std::string(kFormat);
  json["version"] = kVersion;
  json["colour_space"] = std::string(colour_space_name(p.colour_space));
  json["patch_radius"] = p.patch_radius;
  json["gaussian_kernel"] = p.gaussian_kernel;
  json["gaussian_sigma"] = p.gaussian_sigma;
  json["forest_depth"] = p.forest_depth;
  json["forest_size"] = p.forest_size;
  json["split_variables"] = p.split_variables;
  json["canny_kernel"] = p.canny_kernel;
  json["canny_low_threshold"] = p.canny_low_threshold;
  json["canny_high_threshold"] = p.canny_high_threshold();
  json["gradient_operator"] = std::string(gradient_operator_name(p.gradient_operator));
  json["active_value_count"] = p.active_value_count();
  Json names = Json::array();
  for (int i = 0; i < kValueCount; ++i)
    if (p.activation.test(static_cast<std::size_t>(i))) names.push_back(value_name(i));
  json["active_values"] = std::move(names);
  return json;
}

Genome genome_from_json(std::string_view json_text, std::string_view where) {
  const Json root = [&] {
    try {
      return Json::parse(json_text);
    } catch (const Json::parse_error& e) {
      throw Error(std::string(where) + ": not valid JSON (" + e.what() + ")");
    }
  }();
  const JsonReader in(root, where);
  if (!root.is_object()) in.fail("expected a JSON object describing a genome");

  for (const auto& item : root.items())
    if (!known_keys().count(item.key())) in.fail("unknown key '" + item.key() + "'");
  if (in.text("format") != kFormat) in.fail("key 'format' must be \"" + std::string(kFormat) + "\"");
  if (in.integer("version") != kVersion) in.fail("key 'version' must be " + std::to_string(kVersion));

  DescriptorParams p;
  const std::string space = in.text("colour_space");
  const auto parsed_space = parse_colour_space(space);
  if (!parsed_space)
    in.fail("key 'colour_space' = \"" + space + "\" is not one of RGB, Lab, Luv, XYZ, HSV, HLS, YCrCb, OpponentRGB");
  p.colour_space = *parsed_space;
  p.patch_radius = table_value(in, "patch_radius", in.integer("patch_radius"), kPatchRadii);
  p.gaussian_kernel = table_value(in, "gaussian_kernel", in.integer("gaussian_kernel"), kGaussianKernels);
  p.gaussian_sigma = table_value(in, "gaussian_sigma", in.number("gaussian_sigma"), kGaussianSigmas);
  p.forest_depth = table_value(in, "forest_depth", in.integer("forest_depth"), kForestDepths);
  p.forest_size = table_value(in, "forest_size", in.integer("forest_size"), kForestSizes);
  p.split_variables = table_value(in, "split_variables", in.integer("split_variables"), kSplitVariables);
  p.canny_kernel = table_value(in, "canny_kernel", in.integer("canny_kernel"), kCannyKernels);
  p.canny_low_threshold =
      table_value(in, "canny_low_threshold", in.integer("canny_low_threshold"), kCannyLowThresholds);
  if (root.contains("canny_high_threshold") && in.integer("canny_high_threshold") != p.canny_high_threshold())
    in.fail("key 'canny_high_threshold' must be 3 x canny_low_threshold = " + std::to_string(p.canny_high_threshold()));
  const std::string op = in.text("gradient_operator");
  const auto parsed_op = parse_gradient_operator(op);
  if (!parsed_op) in.fail("key 'gradient_operator' = \"" + op + "\" is not one of Sobel, Scharr");
  p.gradient_operator = *parsed_op;

  const Json& values = in.required("active_values");
  if (!values.is_array()) in.fail("key 'active_values' must be an array of value names");
  for (const Json& node : values) {
    if (!node.is_string()) in.fail("key 'active_values' must hold only strings (value names)");
    const std::string name = node.get<std::string>();
    const auto index = value_index(name);
    if (!index) in.fail("key 'active_values' names an unknown value \"" + name + "\"");
    if (p.activation.test(static_cast<std::size_t>(*index)))
      in.fail("key 'active_values' lists \"" + name + "\" twice");
    p.activation.set(static_cast<std::size_t>(*index));
  }
  if (root.contains("active_value_count") && in.integer("active_value_count") != p.active_value_count())
    in.fail("key 'active_value_count' = " + std::to_string(in.integer("active_value_count")) +
            " but 'active_values' lists " + std::to_string(p.active_value_count()));
  return Genome::encode(p);
}

void save_genome(const std::filesystem::path& path, const Genome& genome) {
  if (has_extension(path, ".json"))
    write_json(path, genome_to_json(genome));
  else
    write_text_atomically(path, genome.to_string() + "\n");
}

Genome load_genome(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) fail_file(path, "cannot open the genome file");
  std::ostringstream content;
  content << file.rdbuf();
  if (file.bad()) fail_file(path, "cannot read the genome file");
  if (has_extension(path, ".json")) return genome_from_json(content.str(), path.string());
  return Genome::parse(content.str(), path.string());
}

}  // namespace facadeslam::semantics
