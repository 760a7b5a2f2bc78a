#include "core/util/png_signature.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string_view>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
constexpr std::string_view kChunkType = "tEXt";
constexpr std::string_view kChunkText("Software\0facadeslam", 19);
constexpr std::size_t kHeaderChunkBytes = 4 + 4 + 13 + 4;  // IHDR: length, type, data, CRC

// PNG's CRC-32 (ISO 3309, reflected polynomial 0xEDB88320) over type + data.
std::uint32_t png_crc(std::string_view bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (const char byte : bytes) c = table[(c ^ static_cast<unsigned char>(byte)) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void put_u32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
}

std::uint32_t get_u32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}

}  // namespace

std::vector<unsigned char> sign_png(const std::vector<unsigned char>& png) {
  const std::size_t header_end = kSignature.size() + kHeaderChunkBytes;
  if (png.size() < header_end || std::memcmp(png.data(), kSignature.data(), kSignature.size()) != 0 ||
      std::memcmp(png.data() + 12, "IHDR", 4) != 0)
    throw Error("sign_png: the bytes are not a PNG");
  std::vector<unsigned char> out(png.begin(), png.begin() + static_cast<std::ptrdiff_t>(header_end));
  out.reserve(png.size() + 12 + kChunkText.size());
  put_u32(out, static_cast<std::uint32_t>(kChunkText.size()));
  const std::string type_and_data = std::string(kChunkType) + std::string(kChunkText);
  out.insert(out.end(), type_and_data.begin(), type_and_data.end());
  put_u32(out, png_crc(type_and_data));
  out.insert(out.end(), png.begin() + static_cast<std::ptrdiff_t>(header_end), png.end());
  return out;
}

bool is_signed_png(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  // The chunk sits right after the header; a few ancillary chunks before it
  // (another writer's) are walked over, up to the image data.
  std::array<unsigned char, 64 * 1024> head{};
  in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
  const std::size_t size = static_cast<std::size_t>(in.gcount());
  if (size < kSignature.size() || std::memcmp(head.data(), kSignature.data(), kSignature.size()) != 0) return false;
  std::size_t at = kSignature.size();
  while (at + 12 <= size) {
    const std::size_t length = get_u32(head.data() + at);
    const std::string_view type(reinterpret_cast<const char*>(head.data() + at + 4), 4);
    if (type == "IDAT" || type == "IEND" || at + 12 + length > size) return false;
    if (type == kChunkType && length == kChunkText.size() &&
        std::memcmp(head.data() + at + 8, kChunkText.data(), kChunkText.size()) == 0)
      return true;
    at += 12 + length;
  }
  return false;
}

}  // namespace facadeslam
