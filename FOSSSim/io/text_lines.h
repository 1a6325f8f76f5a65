#pragma once
// Small helpers for line-oriented text formats (OBJ, MEDIT): words with their line numbers,
// strict number parsing; whole-file reads come from io/input_files.h.

#include <charconv>
#include <string>
#include <string_view>
#include <vector>

#include "io/input_files.h"
#include "io/scene_error.h"

namespace fosssim {

/// A word of a text and the 1-based line it is on.
struct Word {
  std::string_view text;
  int line = 0;
};

/// The whitespace-separated words of `text`, skipping comments from `comment` to the end of
/// the line. The views point into `text`.
std::vector<Word> split_words(std::string_view text, char comment = '#');

/// The words of one line (no comment handling).
std::vector<std::string_view> split_line(std::string_view line);

/// std::from_chars for a double in the general format, in every build: Emscripten 3.1.6's C++
/// library lacks it, and fast_float (correctly rounded too, so with the same result) stands in.
std::from_chars_result double_from_chars(const char* first, const char* last, double& value);

/// Parses the whole of `text` as one finite decimal number (locale-independent).
bool parse_finite(std::string_view text, double& value);

/// Parses the whole of `text` as a decimal integer within the range of int.
bool parse_int(std::string_view text, int& value);

/// `"text"`, for messages.
std::string quote(std::string_view text);

/// Reads the file at `path` and returns parse_text(text, path); throws SceneError when it cannot
/// be read or parsed.
template <typename ParseText>
auto parse_text_file(const std::string& path, ParseText parse_text) {
  return parse_text(read_text_file(path), path);
}

}  // namespace fosssim
