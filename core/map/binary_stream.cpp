#include "core/map/binary_stream.hpp"

#include <string>

namespace facadeslam {

void put_mat(ByteWriter& out, const cv::Mat& m) {
  out.put(static_cast<std::int32_t>(m.type()));
  out.put(static_cast<std::int32_t>(m.rows));
  out.put(static_cast<std::int32_t>(m.cols));
  const std::size_t row_bytes = static_cast<std::size_t>(m.cols) * m.elemSize();
  for (int r = 0; r < m.rows; ++r) out.put_bytes(m.ptr(r), row_bytes);
}

cv::Mat get_mat(ByteReader& in, const char* what) {
  const auto type = in.get<std::int32_t>(what);
  const auto rows = in.get<std::int32_t>(what);
  const auto cols = in.get<std::int32_t>(what);
  if (rows < 0 || cols < 0 || rows > 100000 || cols > 100000 || CV_MAT_DEPTH(type) > CV_64F || CV_MAT_CN(type) > 4)
    in.fail(std::string("implausible image header for ") + what);
  // Before allocating: a header may claim more than the file holds.
  const std::size_t bytes = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols) * CV_ELEM_SIZE(type);
  if (bytes > in.remaining())
    in.fail(std::string(what) + " of " + std::to_string(rows) + "x" + std::to_string(cols) +
            " is larger than the rest of the file");
  cv::Mat m(rows, cols, type);
  const std::size_t row_bytes = static_cast<std::size_t>(cols) * m.elemSize();
  for (int r = 0; r < rows; ++r) in.get_bytes(m.ptr(r), row_bytes, what);
  return m;
}

std::uint64_t fnv1a64(const char* data, std::size_t size) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<std::uint8_t>(data[i]);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

}  // namespace facadeslam
