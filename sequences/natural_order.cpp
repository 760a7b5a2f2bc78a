#include "sequences/natural_order.hpp"

#include <cctype>
#include <cstddef>

namespace facadeslam {
namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

// -1, 0, 1 like strcmp, ignoring case and reading digit runs as numbers.
int natural_compare(std::string_view a, std::string_view b) {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    if (is_digit(a[i]) && is_digit(b[j])) {
      const std::size_t a_begin = i;
      const std::size_t b_begin = j;
      while (i < a.size() && is_digit(a[i])) ++i;
      while (j < b.size() && is_digit(b[j])) ++j;
      std::string_view da = a.substr(a_begin, i - a_begin);
      std::string_view db = b.substr(b_begin, j - b_begin);
      const std::size_t zeros_a =
          da.find_first_not_of('0') == std::string_view::npos ? da.size() : da.find_first_not_of('0');
      const std::size_t zeros_b =
          db.find_first_not_of('0') == std::string_view::npos ? db.size() : db.find_first_not_of('0');
      // Compare the significant digits: longer is larger, then digit by digit.
      // Never converted to an integer, so arbitrarily long runs are fine.
      const std::string_view sa = da.substr(zeros_a);
      const std::string_view sb = db.substr(zeros_b);
      if (sa.size() != sb.size()) return sa.size() < sb.size() ? -1 : 1;
      if (const int c = sa.compare(sb); c != 0) return c < 0 ? -1 : 1;
      if (zeros_a != zeros_b) return zeros_a < zeros_b ? -1 : 1;
      continue;
    }
    const char ca = lower(a[i]);
    const char cb = lower(b[j]);
    if (ca != cb) return ca < cb ? -1 : 1;
    ++i;
    ++j;
  }
  if (i < a.size()) return 1;
  if (j < b.size()) return -1;
  return 0;
}

}  // namespace

bool natural_less(std::string_view a, std::string_view b) {
  const int c = natural_compare(a, b);
  if (c != 0) return c < 0;
  return a < b;
}

}  // namespace facadeslam
