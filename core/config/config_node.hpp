#pragma once
// Validated access to YAML configuration. Every failure names the file, the
// full key and what was expected, e.g.
//   configs/camera/demo.yaml: key 'intrinsics.fx': expected a number in (0, 1e+06], got '-3'
// Readers call get()/child() for every key they understand and finish() at
// the end: any key that was never read is reported as unknown, so a typo in a
// config file is an error rather than a silently ignored setting.
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace facadeslam {

// Inclusive/exclusive numeric bounds for validation.
struct Range {
  double min = -1e300;
  double max = 1e300;
  bool min_exclusive = false;
  bool max_exclusive = false;

  static Range positive(double max = 1e300) { return {0.0, max, true, false}; }
  static Range non_negative(double max = 1e300) { return {0.0, max, false, false}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  bool contains(double v) const;
  std::string describe() const;
};

class ConfigNode {
 public:
  // Parses a YAML file; a missing file, a syntax error or a top level that is
  // not a mapping fails with the file name (and line for syntax errors).
  static ConfigNode load_file(const std::filesystem::path& path);
  // For YAML held in memory (tests, embedded defaults); `origin` stands in
  // for the file name in messages.
  static ConfigNode parse_string(const std::string& yaml, const std::string& origin);

  bool has(const std::string& key) const;

  std::string get_string(const std::string& key) const;
  std::string get_string(const std::string& key, const std::string& fallback) const;
  // One of `allowed` (exact match).
  std::string get_choice(const std::string& key, std::initializer_list<std::string> allowed) const;
  std::string get_choice(const std::string& key, std::initializer_list<std::string> allowed,
                         const std::string& fallback) const;
  double get_double(const std::string& key, Range range = {}) const;
  double get_double(const std::string& key, Range range, double fallback) const;
  int get_int(const std::string& key, Range range = {}) const;
  int get_int(const std::string& key, Range range, int fallback) const;
  bool get_bool(const std::string& key) const;
  bool get_bool(const std::string& key, bool fallback) const;
  // A sequence of numbers; `size` 0 accepts any length.
  std::vector<double> get_doubles(const std::string& key, std::size_t size = 0, Range range = {}) const;
  // A sequence of strings, each one of `allowed`; duplicates are an error.
  std::vector<std::string> get_choices(const std::string& key, const std::vector<std::string>& allowed) const;

  // A nested mapping (required / optional).
  ConfigNode child(const std::string& key) const;
  std::optional<ConfigNode> optional_child(const std::string& key) const;
  // A list of mappings (a scene's facades, trajectory segments, ...): one
  // node per item, whose keys appear in messages as "facades[2].width"; an
  // absent key is an empty list. Each item must be finish()ed by its reader.
  std::vector<ConfigNode> get_mappings(const std::string& key) const;

  // Fails on the first key of this mapping that no get/child call has read.
  // Call it on each mapping after reading it.
  void finish() const;

  [[noreturn]] void fail(const std::string& key, const std::string& expected, const std::string& got = {}) const;
  const std::string& origin() const { return *origin_; }
  std::string full_key(const std::string& key) const;

 private:
  ConfigNode(YAML::Node node, std::shared_ptr<const std::string> origin, std::string prefix);
  YAML::Node required(const std::string& key) const;
  std::string scalar_text(const YAML::Node& node) const;

  YAML::Node node_;
  std::shared_ptr<const std::string> origin_;
  std::string prefix_;
  std::shared_ptr<std::set<std::string>> read_keys_;
};

}  // namespace facadeslam
