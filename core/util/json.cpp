#include "core/util/json.hpp"

#include "core/util/atomic_write.hpp"

namespace facadeslam {
namespace {

template <typename AnyJson>
std::string indented_text(const AnyJson& json) {
  return json.dump(2, ' ', false, AnyJson::error_handler_t::replace) + '\n';
}

}  // namespace

std::string json_text(const Json& json) { return indented_text(json); }
std::string json_text(const nlohmann::json& json) { return indented_text(json); }

void write_json(const std::filesystem::path& path, const Json& json) { write_text_atomically(path, json_text(json)); }
void write_json(const std::filesystem::path& path, const nlohmann::json& json) {
  write_text_atomically(path, json_text(json));
}

}  // namespace facadeslam
