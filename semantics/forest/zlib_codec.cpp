#include "semantics/forest/zlib_codec.hpp"

#include <zlib.h>

#include "core/util/error.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {

std::vector<unsigned char> deflate_bytes(const std::vector<unsigned char>& bytes) {
  uLongf size = compressBound(static_cast<uLong>(bytes.size()));
  std::vector<unsigned char> out(size);
  // Level 9: the model is written once and shipped, so size beats speed.
  const int status = compress2(out.data(), &size, bytes.data(), static_cast<uLong>(bytes.size()), Z_BEST_COMPRESSION);
  if (status != Z_OK) throw Error(cat("zlib compression failed (status ", status, ")"));
  out.resize(size);
  return out;
}

std::vector<unsigned char> inflate_bytes(const std::vector<unsigned char>& compressed, std::size_t size) {
  std::vector<unsigned char> out(size);
  uLongf got = static_cast<uLongf>(size);
  const int status = uncompress(out.data(), &got, compressed.data(), static_cast<uLong>(compressed.size()));
  if (status != Z_OK) throw Error(cat("the compressed data is damaged (zlib status ", status, ")"));
  if (got != size) throw Error(cat("the compressed data holds ", got, " bytes, the header says ", size));
  return out;
}

std::uint32_t crc32_of(const std::vector<unsigned char>& bytes) {
  return static_cast<std::uint32_t>(crc32(crc32(0L, Z_NULL, 0), bytes.data(), static_cast<uInt>(bytes.size())));
}

}  // namespace facadeslam::semantics
