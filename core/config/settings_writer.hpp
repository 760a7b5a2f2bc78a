#pragma once
// Writes settings as YAML a reader can load again, each key under a comment
// saying what it means (SettingsTable::write, `facadeslam config --dump`).
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace facadeslam {

class SettingsWriter {
 public:
  explicit SettingsWriter(std::ostream& out) : out_(out) {}

  // `key: value`, under `doc` wrapped into comment lines (none when empty).
  void value(const std::string& key, const std::string& value, const std::string& doc);
  // A nested mapping: the keys written until close() are indented under `key`.
  void open(const std::string& key, const std::string& doc);
  void close();

  // YAML scalars: numbers in the shortest form that reads back exactly,
  // true/false, strings quoted when YAML would read them otherwise.
  static std::string format(bool v) { return v ? "true" : "false"; }
  static std::string format(double v);
  static std::string format(float v);
  static std::string format(const std::string& v);
  template <class T>
  requires std::is_integral_v<T>
  static std::string format(T v) { return std::to_string(v); }
  // A flow sequence: [a, b, c].
  static std::string format_list(const std::vector<std::string>& items);

 private:
  void write_doc(const std::string& doc);

  std::ostream& out_;
  int depth_ = 0;
};

}  // namespace facadeslam
