#include "core/util/json.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>

#include "core/util/atomic_write.hpp"
#include "core/util/error.hpp"

namespace facadeslam {
namespace {

void escape_into(std::string& out, const std::string& s) {
  out += '"';
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

void newline(std::string& out, int indent, int depth) {
  if (indent <= 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent * depth), ' ');
}

}  // namespace

Json& Json::operator[](const std::string& key) {
  if (std::holds_alternative<std::nullptr_t>(value_)) value_ = Object{};
  auto* object = std::get_if<Object>(&value_);
  if (!object) throw Error("internal: JSON value is not an object (key '" + key + "')");
  for (auto& [k, v] : *object)
    if (k == key) return v;
  object->emplace_back(key, Json());
  return object->back().second;
}

void Json::push_back(Json value) {
  if (std::holds_alternative<std::nullptr_t>(value_)) value_ = Array{};
  auto* array = std::get_if<Array>(&value_);
  if (!array) throw Error("internal: JSON value is not an array");
  array->push_back(std::move(value));
}

const Json* Json::find(const std::string& key) const {
  const auto* object = std::get_if<Object>(&value_);
  if (!object) return nullptr;
  for (const auto& [k, v] : *object)
    if (k == key) return &v;
  return nullptr;
}

double Json::as_double() const {
  if (const auto* d = std::get_if<double>(&value_)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&value_)) return static_cast<double>(*i);
  throw Error("internal: JSON value is not a number");
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  if (indent > 0) out += '\n';
  return out;
}

void Json::dump_to(std::string& out, int indent, int depth) const {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::nullptr_t>) {
          out += "null";
        } else if constexpr (std::is_same_v<T, bool>) {
          out += v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          out += std::to_string(v);
        } else if constexpr (std::is_same_v<T, double>) {
          if (!std::isfinite(v)) {
            out += "null";
          } else {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.10g", v);
            out += buf;
          }
        } else if constexpr (std::is_same_v<T, std::string>) {
          escape_into(out, v);
        } else if constexpr (std::is_same_v<T, Array>) {
          if (v.empty()) {
            out += "[]";
            return;
          }
          // Short arrays of scalars stay on one line (matrices, vectors).
          const bool flat = v.size() <= 16 && std::all_of(v.begin(), v.end(), [](const Json& j) {
                              return !j.is_array() && !j.is_object();
                            });
          out += '[';
          for (std::size_t i = 0; i < v.size(); ++i) {
            if (i) out += flat ? ", " : ",";
            if (!flat) newline(out, indent, depth + 1);
            v[i].dump_to(out, indent, depth + 1);
          }
          if (!flat) newline(out, indent, depth);
          out += ']';
        } else {
          if (v.empty()) {
            out += "{}";
            return;
          }
          out += '{';
          for (std::size_t i = 0; i < v.size(); ++i) {
            if (i) out += ',';
            newline(out, indent, depth + 1);
            escape_into(out, v[i].first);
            out += indent > 0 ? ": " : ":";
            v[i].second.dump_to(out, indent, depth + 1);
          }
          newline(out, indent, depth);
          out += '}';
        }
      },
      value_);
}

void write_json(const std::filesystem::path& path, const Json& json) {
  write_text_atomically(path, json.dump());
}

}  // namespace facadeslam
