#include "core/util/error.hpp"

namespace facadeslam {

void fail_file(const std::filesystem::path& path, const std::string& what) { throw Error(path.string() + ": " + what); }

namespace {

// The length of the valid UTF-8 sequence of 2 to 4 bytes at text[i], or 0.
std::size_t utf8_sequence(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  unsigned min = 0;
  if (lead >= 0xC2 && lead <= 0xDF)
    length = 2, min = 0x80;
  else if (lead >= 0xE0 && lead <= 0xEF)
    length = 3, min = 0x800;
  else if (lead >= 0xF0 && lead <= 0xF4)
    length = 4, min = 0x10000;
  else
    return 0;
  if (i + length > text.size()) return 0;
  unsigned code = lead & (0x7F >> length);
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  if (code < min || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out.push_back(static_cast<char>(c));
      ++i;
      continue;
    }
    if (const std::size_t n = c >= 0x80 ? utf8_sequence(text, i) : 0; n > 0) {
      out.append(text.substr(i, n));
      i += n;
      continue;
    }
    static const char kHex[] = "0123456789abcdef";
    out.append("\\x").push_back(kHex[c >> 4]);
    out.push_back(kHex[c & 15]);
    ++i;
  }
  return out;
}

std::string quoted_for_message(std::string_view text) {
  std::string out = "'";
  if (text.size() <= kMaxQuotedBytes) return out.append(printable(text)).append("'");
  out.append(printable(text.substr(0, kMaxQuotedBytes))).append("...' (");
  return out.append(std::to_string(text.size())).append(" bytes)");
}

std::string one_line_message(std::string_view text, std::size_t max_bytes) {
  std::string line = printable(text);
  if (line.size() <= max_bytes) return line;
  // The head names the file and what failed, the tail what was expected.
  // Cut between characters, not inside a UTF-8 sequence.
  const auto continuation = [&](std::size_t i) { return (static_cast<unsigned char>(line[i]) & 0xC0) == 0x80; };
  std::size_t head = max_bytes - max_bytes / 3 - 5, tail_start = line.size() - max_bytes / 3;
  while (head > 0 && continuation(head)) --head;
  while (tail_start < line.size() && continuation(tail_start)) ++tail_start;
  std::string shortened = line.substr(0, head);
  return shortened.append(" ... ").append(line.substr(tail_start));
}

}  // namespace facadeslam
