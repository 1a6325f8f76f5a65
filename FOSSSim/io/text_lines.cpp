#include "io/text_lines.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fosssim {

namespace {
bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}
}  // namespace

std::string read_text_file(const std::string& path) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw SceneError(path, 0, "", "is a directory, not a file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw SceneError(path, 0, "", std::string("cannot open the file: ") + std::strerror(errno));
  }
  // One read into a string of the file's size (a stream copy through rdbuf() is several times
  // slower on scenes of megabytes), then whatever more there is (a file that grew, a pipe).
  std::string content;
  const std::uintmax_t size = std::filesystem::file_size(path, ignored);
  if (size != static_cast<std::uintmax_t>(-1) && size > 0) {
    content.resize(static_cast<std::size_t>(size));
    in.read(content.data(), static_cast<std::streamsize>(size));
    content.resize(static_cast<std::size_t>(in.gcount()));
  }
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    content.append(block, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw SceneError(path, 0, "", "cannot read the file");
  return content;
}

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

bool parse_finite(std::string_view text, double& value) {
  text = without_plus(text);
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
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
