#pragma once
// One table per options struct binds each setting once: its YAML key (the
// member's name), the member, the values it accepts and what it means. The
// same table reads a YAML mapping into the struct (every key optional, the
// struct's value its default, unknown keys errors) and writes the struct back
// as commented YAML (`facadeslam config --dump`), so the reader, the shipped
// file and its documentation cannot drift apart.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/config/config_node.hpp"
#include "core/config/settings_writer.hpp"

namespace facadeslam {

template <class Options>
class SettingsTable {
 public:
  using Reader = std::function<void(const ConfigNode&, Options&)>;
  using Writer = std::function<void(SettingsWriter&, const Options&)>;

  // A number, a flag or a string held in `member`; `range` bounds numbers.
  template <class T>
  SettingsTable& add(const std::string& key, T Options::*member, std::string doc, Range range = {}) {
    static_assert(std::is_arithmetic_v<T> || std::is_same_v<T, std::string>, "a number, a flag or a string");
    entries_.push_back({[key, member, range](const ConfigNode& node, Options& options) {
                          T& value = options.*member;
                          static_cast<void>(range);  // flags and strings have none
                          if constexpr (std::is_same_v<T, bool>) {
                            value = node.get_bool(key, value);
                          } else if constexpr (std::is_same_v<T, std::string>) {
                            value = node.get_string(key, value);
                          } else if constexpr (std::is_floating_point_v<T>) {
                            value = static_cast<T>(node.get_double(key, range, static_cast<double>(value)));
                          } else {
                            // Integers of any width are read through int: the table's
                            // ranges keep them within it.
                            const Range bounded = integer_range<T>(range);
                            value = static_cast<T>(node.get_int(key, bounded, static_cast<int>(value)));
                          }
                        },
                        [key, member, doc = std::move(doc)](SettingsWriter& out, const Options& options) {
                          out.value(key, SettingsWriter::format(options.*member), doc);
                        }});
    return *this;
  }

  // A nested options struct, its settings one level down under `key`.
  template <class Sub>
  SettingsTable& add(const std::string& key, Sub Options::*member, SettingsTable<Sub> table, std::string doc = {}) {
    auto shared = std::make_shared<const SettingsTable<Sub>>(std::move(table));
    entries_.push_back({[key, member, shared](const ConfigNode& node, Options& options) {
                          if (const auto child = node.optional_child(key)) shared->read(*child, options.*member);
                        },
                        [key, member, shared, doc = std::move(doc)](SettingsWriter& out, const Options& options) {
                          out.open(key, doc);
                          shared->write(out, options.*member);
                          out.close();
                        }});
    return *this;
  }

  // Anything else (a list, one value per class): how it is read and written.
  SettingsTable& add_custom(Reader read, Writer write) {
    entries_.push_back({std::move(read), std::move(write)});
    return *this;
  }

  // A rule across settings, checked once the mapping is read (e.g. a lower
  // threshold not above an upper one): fail through the node.
  SettingsTable& check(std::function<void(const ConfigNode&, const Options&)> rule) {
    rules_.push_back(std::move(rule));
    return *this;
  }

  // Reads `node`'s keys over `options`; fails on an unknown key.
  void read(const ConfigNode& node, Options& options) const {
    for (const Entry& entry : entries_) entry.read(node, options);
    node.finish();
    for (const auto& rule : rules_) rule(node, options);
  }

  void write(SettingsWriter& out, const Options& options) const {
    for (const Entry& entry : entries_) entry.write(out, options);
  }

  // The YAML file at `path` read over `options` (Error naming the file and key).
  Options load(const std::filesystem::path& path, Options options = {}) const {
    read(ConfigNode::load_file(path), options);
    return options;
  }

  // Every setting as YAML, each under what it means (`facadeslam config --dump`).
  void write_yaml(std::ostream& out, const Options& options) const {
    SettingsWriter writer(out);
    write(writer, options);
  }

 private:
  struct Entry {
    Reader read;
    Writer write;
  };

  template <class T>
  static Range integer_range(Range range) {
    const double lowest = std::is_signed_v<T> ? static_cast<double>(std::numeric_limits<int>::min()) : 0.0;
    range.min = std::max(range.min, lowest);
    range.max = std::min(range.max, static_cast<double>(std::numeric_limits<int>::max()));
    return range;
  }

  std::vector<Entry> entries_;
  std::vector<std::function<void(const ConfigNode&, const Options&)>> rules_;
};

}  // namespace facadeslam
