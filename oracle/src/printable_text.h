#pragma once
// Turning arbitrary bytes (a candidate's standard error, a file name) into text that every
// report format can hold: valid UTF-8 without control characters.

#include <string>
#include <string_view>

namespace fosssim {

/// Valid UTF-8 sequences are kept, except control characters; newlines and tabs are kept, every
/// other control character and every byte that is not part of valid UTF-8 becomes "\xNN". The
/// result is safe in JSON strings and in XML 1.0 text and attributes (after the usual escaping).
std::string printable_text(std::string_view bytes);

/// The last `max_lines` lines of `text` (without a trailing empty line); "..." marks a cut.
std::string last_lines(const std::string& text, int max_lines);

/// The first line of `text`.
std::string first_line(const std::string& text);

/// `text` with every line prefixed by `prefix`.
std::string indent_lines(const std::string& text, const std::string& prefix);

}  // namespace fosssim
