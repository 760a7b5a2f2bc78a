#include "core/config/config_node.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string join(std::initializer_list<std::string> items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "'" : ", '") + item + "'";
  return out;
}

}  // namespace

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (min_exclusive ? v <= min : v < min) return false;
  if (max_exclusive ? v >= max : v > max) return false;
  return true;
}

std::string Range::describe() const {
  const bool has_min = min > -1e299, has_max = max < 1e299;
  if (!has_min && !has_max) return "a finite number";
  if (!has_max) return std::string("a number ") + (min_exclusive ? "> " : ">= ") + format_number(min);
  if (!has_min) return std::string("a number ") + (max_exclusive ? "< " : "<= ") + format_number(max);
  return std::string("a number in ") + (min_exclusive ? "(" : "[") + format_number(min) + ", " + format_number(max) +
         (max_exclusive ? ")" : "]");
}

ConfigNode::ConfigNode(YAML::Node node, std::shared_ptr<const std::string> origin, std::string prefix)
    : node_(std::move(node)),
      origin_(std::move(origin)),
      prefix_(std::move(prefix)),
      read_keys_(std::make_shared<std::set<std::string>>()) {}

ConfigNode ConfigNode::load_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) fail_file(path, "cannot open the YAML file");
  std::stringstream text;
  text << in.rdbuf();
  return parse_string(text.str(), path.string());
}

ConfigNode ConfigNode::parse_string(const std::string& yaml, const std::string& origin) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw Error(origin + ": not valid YAML (line " + std::to_string(e.mark.line + 1) + ": " + e.msg + ")");
  }
  if (!root.IsMap()) throw Error(origin + ": expected a YAML mapping of keys at the top level");
  return ConfigNode(root, std::make_shared<const std::string>(origin), "");
}

std::string ConfigNode::full_key(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }

void ConfigNode::fail(const std::string& key, const std::string& expected, const std::string& got) const {
  std::string message = *origin_ + ": key '" + full_key(key) + "': expected " + expected;
  // A value of hundreds of characters (a pasted blob, a fuzzer's) would
  // bury the message: its start is enough to recognise it.
  constexpr std::size_t kShownValue = 80;
  if (!got.empty() && got.size() <= kShownValue) message += ", got '" + got + "'";
  if (got.size() > kShownValue)
    message.append(", got '")
        .append(got, 0, kShownValue)
        .append("...' (")
        .append(std::to_string(got.size()))
        .append(" characters)");
  throw Error(message);
}

bool ConfigNode::has(const std::string& key) const { return static_cast<bool>(node_[key]); }

namespace {

// Levenshtein distance, for "is 'sede' a misspelling of 'seed'?".
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

YAML::Node ConfigNode::required(const std::string& key) const {
  const YAML::Node value = node_[key];
  if (!value) {
    // A key of this mapping that nothing reads and is spelt almost like
    // the missing one is named: the typo is the likely cause.
    for (const auto& entry : node_) {
      const std::string present = entry.first.Scalar();
      if (!read_keys_->count(present) && edit_distance(present, key) <= 2) {
        std::string what = "a value (required key is missing; is '";
        fail(key, what.append(present).append("' a misspelling of it?)"));
      }
    }
    fail(key, "a value (required key is missing)");
  }
  read_keys_->insert(key);
  return value;
}

std::string ConfigNode::scalar_text(const YAML::Node& node) const {
  if (node.IsScalar()) return node.Scalar();
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

std::string ConfigNode::get_string(const std::string& key) const {
  const YAML::Node v = required(key);
  if (!v.IsScalar()) fail(key, "a string", scalar_text(v));
  return v.Scalar();
}

std::string ConfigNode::get_string(const std::string& key, const std::string& fallback) const {
  return has(key) ? get_string(key) : (read_keys_->insert(key), fallback);
}

std::string ConfigNode::get_choice(const std::string& key, std::initializer_list<std::string> allowed) const {
  const std::string value = get_string(key);
  for (const auto& a : allowed)
    if (a == value) return value;
  fail(key, "one of " + join(allowed), value);
}

std::string ConfigNode::get_choice(const std::string& key, std::initializer_list<std::string> allowed,
                                   const std::string& fallback) const {
  if (!has(key)) {
    read_keys_->insert(key);
    return fallback;
  }
  return get_choice(key, allowed);
}

double ConfigNode::get_double(const std::string& key, Range range) const {
  const YAML::Node v = required(key);
  double value = 0.0;
  if (!v.IsScalar() || !YAML::convert<double>::decode(v, value)) fail(key, range.describe(), scalar_text(v));
  if (!range.contains(value)) fail(key, range.describe(), v.Scalar());
  return value;
}

double ConfigNode::get_double(const std::string& key, Range range, double fallback) const {
  if (!has(key)) {
    read_keys_->insert(key);
    return fallback;
  }
  return get_double(key, range);
}

int ConfigNode::get_int(const std::string& key, Range range) const {
  const YAML::Node v = required(key);
  long long value = 0;
  const std::string expected = "an integer (" + range.describe() + ")";
  if (!v.IsScalar() || !YAML::convert<long long>::decode(v, value)) fail(key, expected, scalar_text(v));
  if (!range.contains(static_cast<double>(value)) || value > 2147483647LL || value < -2147483647LL)
    fail(key, expected, v.Scalar());
  return static_cast<int>(value);
}

int ConfigNode::get_int(const std::string& key, Range range, int fallback) const {
  if (!has(key)) {
    read_keys_->insert(key);
    return fallback;
  }
  return get_int(key, range);
}

bool ConfigNode::get_bool(const std::string& key) const {
  const YAML::Node v = required(key);
  bool value = false;
  if (!v.IsScalar() || !YAML::convert<bool>::decode(v, value)) fail(key, "true or false", scalar_text(v));
  return value;
}

bool ConfigNode::get_bool(const std::string& key, bool fallback) const {
  if (!has(key)) {
    read_keys_->insert(key);
    return fallback;
  }
  return get_bool(key);
}

std::vector<double> ConfigNode::get_doubles(const std::string& key, std::size_t size, Range range) const {
  const YAML::Node v = required(key);
  const std::string expected =
      (size ? "a list of " + std::to_string(size) + " numbers" : std::string("a list of numbers")) +
      (range.min > -1e299 || range.max < 1e299 ? " (each " + range.describe() + ")" : "");
  if (!v.IsSequence()) fail(key, expected, scalar_text(v));
  if (size && v.size() != size) fail(key, expected, "a list of " + std::to_string(v.size()));
  std::vector<double> out;
  for (const auto& item : v) {
    double value = 0.0;
    if (!item.IsScalar() || !YAML::convert<double>::decode(item, value) || !range.contains(value))
      fail(key, expected, scalar_text(item));
    out.push_back(value);
  }
  return out;
}

std::vector<std::string> ConfigNode::get_choices(const std::string& key,
                                                 const std::vector<std::string>& allowed) const {
  const YAML::Node v = required(key);
  std::string expected = "a list of distinct names out of";
  for (const auto& a : allowed) expected += " " + a;
  if (!v.IsSequence()) fail(key, expected, scalar_text(v));
  std::vector<std::string> out;
  for (const auto& item : v) {
    const std::string text = item.IsScalar() ? item.Scalar() : scalar_text(item);
    if (!item.IsScalar() || std::find(allowed.begin(), allowed.end(), text) == allowed.end() ||
        std::find(out.begin(), out.end(), text) != out.end())
      fail(key, expected, text);
    out.push_back(text);
  }
  return out;
}

ConfigNode ConfigNode::child(const std::string& key) const {
  const YAML::Node v = required(key);
  if (!v.IsMap()) fail(key, "a mapping of keys", scalar_text(v));
  return ConfigNode(v, origin_, full_key(key));
}

std::optional<ConfigNode> ConfigNode::optional_child(const std::string& key) const {
  if (!has(key)) {
    read_keys_->insert(key);
    return std::nullopt;
  }
  return child(key);
}

std::vector<ConfigNode> ConfigNode::get_mappings(const std::string& key) const {
  std::vector<ConfigNode> items;
  if (!has(key)) {
    read_keys_->insert(key);
    return items;
  }
  const YAML::Node v = required(key);
  if (!v.IsSequence()) fail(key, "a list of mappings (lines starting with '- ')", scalar_text(v));
  for (std::size_t i = 0; i < v.size(); ++i) {
    std::string item_key = key;
    item_key.append("[").append(std::to_string(i)).append("]");
    if (!v[i].IsMap()) fail(item_key, "a mapping of keys", scalar_text(v[i]));
    items.push_back(ConfigNode(v[i], origin_, full_key(item_key)));
  }
  return items;
}

void ConfigNode::finish() const {
  for (const auto& entry : node_) {
    // A key that is itself a list, a mapping or null (`[a]: 1`, `~: 1`)
    // can never be one this program reads.
    if (!entry.first.IsScalar()) {
      std::string where = prefix_.empty() ? std::string("at the top level") : "in '";
      if (!prefix_.empty()) where.append(prefix_).append("'");
      throw Error(*origin_ + ": " + where + ": expected keys that are plain names, got " + scalar_text(entry.first) +
                  " as a key");
    }
    const std::string key = entry.first.Scalar();
    if (!read_keys_->count(key)) fail(key, "no such key here (unknown key; check its spelling)");
  }
}

}  // namespace facadeslam
