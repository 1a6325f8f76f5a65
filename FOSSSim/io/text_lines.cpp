#include "io/text_lines.h"

#include <charconv>
#include <cmath>

#if defined(__EMSCRIPTEN__)
#include <fast_float/fast_float.h>
#endif

namespace fosssim {

namespace {
bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}
}  // namespace

std::vector<Word> split_words(std::string_view text, char comment) {
  std::vector<Word> words;
  int line = 1;
  std::size_t k = 0;
  while (k < text.size()) {
    const char c = text[k];
    if (c == '\n') {
      ++line;
      ++k;
    } else if (is_space(c)) {
      ++k;
    } else if (c == comment) {
      while (k < text.size() && text[k] != '\n') ++k;
    } else {
      const std::size_t start = k;
      while (k < text.size() && !is_space(text[k]) && text[k] != comment) ++k;
      words.push_back({text.substr(start, k - start), line});
    }
  }
  return words;
}

std::vector<std::string_view> split_line(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && is_space(line[k])) ++k;
    const std::size_t start = k;
    while (k < line.size() && !is_space(line[k])) ++k;
    if (k > start) words.push_back(line.substr(start, k - start));
  }
  return words;
}

namespace {
/// Drops one leading '+' (which std::from_chars does not take), but not from "+-…".
std::string_view without_plus(std::string_view text) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  return text;
}
}  // namespace

std::from_chars_result double_from_chars(const char* first, const char* last, double& value) {
#if defined(__EMSCRIPTEN__)
  const fast_float::from_chars_result result = fast_float::from_chars(first, last, value);
  return {result.ptr, result.ec};
#else
  return std::from_chars(first, last, value);
#endif
}

bool parse_finite(std::string_view text, double& value) {
  text = without_plus(text);
  if (text.empty()) return false;
  const auto [end, error] = double_from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

bool parse_int(std::string_view text, int& value) {
  text = without_plus(text);
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

std::string quote(std::string_view text) { return "\"" + std::string(text) + "\""; }

}  // namespace fosssim
