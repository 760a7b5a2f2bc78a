#pragma once
// zlib (Debian's zlib1g) for the .fsmodel payload: deflate, inflate to a
// known size, CRC-32. Errors are Error messages without a file name (the
// caller names the file).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace facadeslam::semantics {

std::vector<unsigned char> deflate_bytes(const std::vector<unsigned char>& bytes);

// Throws Error unless `compressed` inflates to exactly `size` bytes.
std::vector<unsigned char> inflate_bytes(const std::vector<unsigned char>& compressed, std::size_t size);

std::uint32_t crc32_of(const std::vector<unsigned char>& bytes);

}  // namespace facadeslam::semantics
