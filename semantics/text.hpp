#pragma once
// cat("a", s, 3, "b"): builds a message by appending its parts. GCC 12 warns
// falsely (-Wrestrict, at -O3) on `"literal" + std::string`, and warnings
// are errors here, so messages in semantics/ are built with this instead.
#include <concepts>
#include <string>
#include <string_view>

namespace facadeslam::semantics {

namespace detail {
inline void append_part(std::string& out, std::string_view part) { out.append(part); }
inline void append_part(std::string& out, char c) { out.push_back(c); }
template <std::integral T>
requires(!std::same_as<T, char> && !std::same_as<T, bool>) void append_part(std::string& out, T value) {
  out.append(std::to_string(value));
}
}  // namespace detail

template <typename... Parts>
std::string cat(const Parts&... parts) {
  std::string out;
  (detail::append_part(out, parts), ...);
  return out;
}

}  // namespace facadeslam::semantics
