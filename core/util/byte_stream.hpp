#pragma once
// Little-endian byte packing for the binary formats: the map file
// (core/map/map_io), the .fsmodel payload (semantics/forest/fsmodel_format)
// and the PLY body (core/map/point_cloud_*). The reader never reads past its
// end: a short buffer is a truncated or damaged file, reported with the
// file's name, what was being read and where.
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

namespace facadeslam {

// The formats are little-endian; copying host values byte for byte is only
// right on a little-endian host (every platform the project builds on).
static_assert(std::endian::native == std::endian::little, "the binary formats assume a little-endian host");

class ByteWriter {
 public:
  template <class T>
  requires std::is_arithmetic_v<T>
  void put(T value) { bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T)); }
  void put_bytes(const void* data, std::size_t size) { bytes_.append(static_cast<const char*>(data), size); }
  // A 32-bit length, then the characters.
  void put_text(std::string_view text);
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  // `damaged` names what a bad read means in this format (e.g. "corrupt map
  // file"); every failure is "<file>: <damaged>: <what>". The bytes must
  // outlive the reader.
  ByteReader(std::string_view bytes, std::filesystem::path file, std::string damaged)
      : bytes_(bytes), file_(std::move(file)), damaged_(std::move(damaged)) {}

  template <class T>
  requires std::is_arithmetic_v<T> T get(const char* what) {
    T value;
    std::memcpy(&value, take(sizeof(T), what), sizeof(T));
    return value;
  }
  // `out` may be null when `size` is 0 (an image with no columns).
  void get_bytes(void* out, std::size_t size, const char* what) {
    const char* from = take(size, what);
    if (size) std::memcpy(out, from, size);
  }
  // The next `size` bytes, or a failure naming `what` if fewer are left.
  const char* take(std::size_t size, const char* what);
  // A 32-bit count of items that follow, each at least `item_bytes` long.
  // Bounded by the bytes left and by `max`, so that a damaged count fails
  // here rather than as a huge allocation.
  std::size_t count(const char* what, std::size_t item_bytes,
                    std::size_t max = std::numeric_limits<std::uint32_t>::max());
  // put_text's text, at most `max` characters.
  std::string text(const char* what, std::size_t max = std::numeric_limits<std::uint32_t>::max());

  std::size_t position() const { return at_; }
  std::size_t remaining() const { return bytes_.size() - at_; }
  bool at_end() const { return at_ == bytes_.size(); }
  [[noreturn]] void fail(const std::string& what) const;

 private:
  std::string_view bytes_;
  std::filesystem::path file_;
  std::string damaged_;
  std::size_t at_ = 0;
};

}  // namespace facadeslam
