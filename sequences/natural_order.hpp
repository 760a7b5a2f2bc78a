#pragma once
// File-name order that people expect: runs of digits compare as numbers, so
// frame2.png comes before frame10.png.
#include <string_view>

namespace facadeslam {

// Strict weak order: digit runs compare by value (then fewer leading zeros
// first), other characters case-insensitively; names equal under those rules
// fall back to plain byte order so the result never depends on listing order.
bool natural_less(std::string_view a, std::string_view b);

}  // namespace facadeslam
