#include "core/util/json.hpp"

#include "core/util/atomic_write.hpp"

namespace facadeslam {

std::string json_text(const Json& json) {
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + '\n';
}

void write_json(const std::filesystem::path& path, const Json& json) {
  write_text_atomically(path, json_text(json));
}

}  // namespace facadeslam
