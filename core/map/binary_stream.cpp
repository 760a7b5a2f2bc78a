#include "core/map/binary_stream.hpp"

#include "core/util/error.hpp"

namespace facadeslam {

void BinaryWriter::put_string(const std::string& s) {
  put(static_cast<std::uint32_t>(s.size()));
  buffer_.append(s);
}

void BinaryWriter::put_mat(const cv::Mat& m) {
  put(static_cast<std::int32_t>(m.type()));
  put(static_cast<std::int32_t>(m.rows));
  put(static_cast<std::int32_t>(m.cols));
  const std::size_t row_bytes = static_cast<std::size_t>(m.cols) * m.elemSize();
  for (int r = 0; r < m.rows; ++r) put_bytes(m.ptr(r), row_bytes);
}

const char* BinaryReader::take(std::size_t size, const char* what) {
  if (size > remaining()) corrupt(std::string("file ends while reading ") + what + "; truncated?");
  const char* p = data_.data() + pos_;
  pos_ += size;
  return p;
}

std::string BinaryReader::get_string(const char* what) {
  const auto size = get<std::uint32_t>(what);
  return std::string(take(size, what), size);
}

cv::Mat BinaryReader::get_mat(const char* what) {
  const auto type = get<std::int32_t>(what);
  const auto rows = get<std::int32_t>(what);
  const auto cols = get<std::int32_t>(what);
  if (rows < 0 || cols < 0 || rows > 100000 || cols > 100000 || CV_MAT_DEPTH(type) > CV_64F || CV_MAT_CN(type) > 4)
    corrupt(std::string("implausible image header for ") + what);
  // Before allocating: a header may claim more than the file holds.
  const std::size_t bytes = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols) * CV_ELEM_SIZE(type);
  if (bytes > remaining())
    corrupt(std::string(what) + " of " + std::to_string(rows) + "x" + std::to_string(cols) +
            " is larger than the rest of the file");
  cv::Mat m(rows, cols, type);
  const std::size_t row_bytes = static_cast<std::size_t>(cols) * m.elemSize();
  for (int r = 0; r < rows; ++r) get_bytes(m.ptr(r), row_bytes, what);
  return m;
}

void BinaryReader::corrupt(const std::string& what) const { fail_file(origin_, "corrupt map file (" + what + ")"); }

std::uint64_t fnv1a64(const char* data, std::size_t size) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<std::uint8_t>(data[i]);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

}  // namespace facadeslam
