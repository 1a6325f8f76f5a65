#include "printable_text.h"

#include <cstdint>
#include <cstdio>

namespace fosssim {

namespace {

/// Length of the valid UTF-8 sequence at bytes[i] (1..4), or 0 when it is not valid UTF-8
/// (overlong forms, surrogates and code points above U+10FFFF are invalid, per RFC 3629).
std::size_t utf8_sequence_length(std::string_view bytes, std::size_t i, std::uint32_t& code) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(bytes[k]); };
  const std::uint8_t lead = byte(i);
  std::size_t length = 0;
  if (lead < 0x80) {
    code = lead;
    return 1;
  } else if ((lead & 0xE0) == 0xC0) {
    length = 2, code = lead & 0x1F;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3, code = lead & 0x0F;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4, code = lead & 0x07;
  } else {
    return 0;
  }
  if (i + length > bytes.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  static constexpr std::uint32_t kSmallest[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < kSmallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

void append_escaped_byte(std::string& out, unsigned char byte) {
  char escaped[5];
  std::snprintf(escaped, sizeof(escaped), "\\x%02x", byte);
  out += escaped;
}

}  // namespace

std::string printable_text(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  std::size_t i = 0;
  while (i < bytes.size()) {
    std::uint32_t code = 0;
    const std::size_t length = utf8_sequence_length(bytes, i, code);
    const bool control = code < 0x20 || code == 0x7F || (code >= 0x80 && code < 0xA0) ||
                         code == 0xFFFE || code == 0xFFFF;
    if (length == 0) {
      append_escaped_byte(out, static_cast<unsigned char>(bytes[i]));
      ++i;
    } else if (control && code != '\n' && code != '\t') {
      for (std::size_t k = 0; k < length; ++k) {
        append_escaped_byte(out, static_cast<unsigned char>(bytes[i + k]));
      }
      i += length;
    } else {
      out.append(bytes.substr(i, length));
      i += length;
    }
  }
  return out;
}

std::string last_lines(const std::string& text, int max_lines) {
  std::string trimmed = text;
  while (!trimmed.empty() && trimmed.back() == '\n') trimmed.pop_back();
  std::size_t cut = trimmed.size();
  for (int line = 0; line < max_lines; ++line) {
    const std::size_t newline = trimmed.rfind('\n', cut == 0 ? 0 : cut - 1);
    if (newline == std::string::npos || cut == 0) return trimmed;
    cut = newline;
  }
  return "...\n" + trimmed.substr(cut + 1);
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

std::string indent_lines(const std::string& text, const std::string& prefix) {
  std::string out;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    out += prefix;
    out.append(text, begin, end - begin);
    out += '\n';
    begin = end + 1;
  }
  return out;
}

}  // namespace fosssim
