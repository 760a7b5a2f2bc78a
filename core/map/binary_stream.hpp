#pragma once
// What the map file adds to the little-endian byte packing of
// core/util/byte_stream.hpp: images, and the checksum over the whole file.
#include <cstdint>
#include <cstddef>

#include <opencv2/core.hpp>

#include "core/util/byte_stream.hpp"

namespace facadeslam {

// Type, rows, cols, then the pixels row by row.
void put_mat(ByteWriter& out, const cv::Mat& m);
// Rejects implausible headers and images larger than the rest of the data
// before allocating.
cv::Mat get_mat(ByteReader& in, const char* what);

// FNV-1a 64-bit: a cheap checksum that catches truncation and bit rot.
std::uint64_t fnv1a64(const char* data, std::size_t size);

}  // namespace facadeslam
