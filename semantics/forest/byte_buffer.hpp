#pragma once
// Little-endian byte packing for the .fsmodel payload (fsmodel_format.cpp).
// The reader never reads past its end: a short buffer is a damaged or
// truncated file, reported with the file's name and what was being read.
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/util/error.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {

// The format is little-endian; copying host values byte for byte is only
// right on a little-endian host (every platform the project builds on).
static_assert(std::endian::native == std::endian::little, "the .fsmodel writer assumes a little-endian host");

class ByteWriter {
 public:
  template <typename T>
    requires std::is_arithmetic_v<T>
  void put(T value) {
    const auto at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
  }
  void put_text(std::string_view text) {
    put(static_cast<std::uint32_t>(text.size()));
    bytes_.insert(bytes_.end(), text.begin(), text.end());
  }
  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
};

class ByteReader {
 public:
  ByteReader(const std::vector<unsigned char>& bytes, std::filesystem::path file) : bytes_(bytes), file_(std::move(file)) {}

  template <typename T>
    requires std::is_arithmetic_v<T>
  T get(const char* what) {
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  // A count of items that follow, each at least `item_bytes` long. Bounded
  // by `max` and by the bytes left, so that a damaged count fails here
  // rather than as a huge allocation.
  std::size_t count(const char* what, std::size_t max, std::size_t item_bytes) {
    const std::uint32_t n = get<std::uint32_t>(what);
    if (n > max) fail_file(file_, cat("damaged model file: ", what, " is ", n, ", expected at most ", max));
    if (n * item_bytes > bytes_.size() - at_)
      fail_file(file_, cat("damaged model file: ", what, " is ", n, " but only ", bytes_.size() - at_,
                           " bytes follow"));
    return n;
  }
  std::string text(const char* what, std::size_t max) {
    const std::size_t n = count(what, max, 1);
    need(n, what);
    std::string s(reinterpret_cast<const char*>(bytes_.data() + at_), n);
    at_ += n;
    return s;
  }
  bool at_end() const { return at_ == bytes_.size(); }

 private:
  void need(std::size_t n, const char* what) const {
    if (bytes_.size() - at_ < n)
      fail_file(file_, cat("damaged model file: the data ends inside ", what, " (byte ", at_, " of ", bytes_.size(), ")"));
  }
  const std::vector<unsigned char>& bytes_;
  std::filesystem::path file_;
  std::size_t at_ = 0;
};

}  // namespace facadeslam::semantics
