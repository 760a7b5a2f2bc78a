#pragma once
// Little-endian binary encoding for the map file. The reader checks every
// read against the data it has, so a truncated or corrupt file gives an Error
// naming the file instead of undefined behaviour.
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <type_traits>

#include <opencv2/core.hpp>

namespace facadeslam {

static_assert(std::endian::native == std::endian::little, "map files are little-endian; add byte swapping");

class BinaryWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_arithmetic_v<T>);
    buffer_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void put_string(const std::string& s);
  void put_bytes(const void* data, std::size_t size) { buffer_.append(static_cast<const char*>(data), size); }
  // Type, rows, cols, then the pixels row by row.
  void put_mat(const cv::Mat& m);
  const std::string& buffer() const { return buffer_; }

 private:
  std::string buffer_;
};

class BinaryReader {
 public:
  BinaryReader(const std::string& data, std::filesystem::path origin) : data_(data), origin_(std::move(origin)) {}

  template <class T>
  T get(const char* what) {
    static_assert(std::is_arithmetic_v<T>);
    T value;
    std::memcpy(&value, take(sizeof(T), what), sizeof(T));
    return value;
  }
  std::string get_string(const char* what);
  void get_bytes(void* out, std::size_t size, const char* what) { std::memcpy(out, take(size, what), size); }
  cv::Mat get_mat(const char* what);

  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return data_.size() - pos_; }
  // Fails naming the file: "<file>: corrupt map file (<what>)".
  [[noreturn]] void corrupt(const std::string& what) const;

 private:
  const char* take(std::size_t size, const char* what);
  const std::string& data_;
  std::filesystem::path origin_;
  std::size_t pos_ = 0;
};

// FNV-1a 64-bit: a cheap checksum that catches truncation and bit rot.
std::uint64_t fnv1a64(const char* data, std::size_t size);

}  // namespace facadeslam
