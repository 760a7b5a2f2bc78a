#include "core/util/byte_stream.hpp"

#include "core/util/error.hpp"

namespace facadeslam {

void ByteWriter::put_text(std::string_view text) {
  put(static_cast<std::uint32_t>(text.size()));
  bytes_.append(text);
}

const char* ByteReader::take(std::size_t size, const char* what) {
  if (size > remaining())
    fail("the data ends inside " + std::string(what) + " (byte " + std::to_string(at_) + " of " +
         std::to_string(bytes_.size()) + "; truncated?)");
  const char* p = bytes_.data() + at_;
  at_ += size;
  return p;
}

std::size_t ByteReader::count(const char* what, std::size_t item_bytes, std::size_t max) {
  const std::size_t n = get<std::uint32_t>(what);
  if (n > max) fail(std::string(what) + " is " + std::to_string(n) + ", expected at most " + std::to_string(max));
  if (item_bytes > 0 && n > remaining() / item_bytes)
    fail(std::string(what) + " is " + std::to_string(n) + " but only " + std::to_string(remaining()) + " bytes follow");
  return n;
}

std::string ByteReader::text(const char* what, std::size_t max) {
  const std::size_t n = count(what, 1, max);
  return std::string(take(n, what), n);
}

void ByteReader::fail(const std::string& what) const { fail_file(file_, damaged_ + ": " + what); }

}  // namespace facadeslam
