#pragma once
// The one way FOSSSim's programs parse their command lines and report usage errors.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace fosssim {

/// Parses argv into `app`. Returns the status the program should exit with now: 0 after
/// printing --help or --version, 2 after a usage error (reported on standard error as
/// "NAME: error: ...", followed by `hint`); nullopt when the program should go on.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv,
                                      const std::string& hint = "");

/// True when `text` is a number as the scene readers take it: decimal digits with an optional
/// sign, point and exponent ("0.01", "-3", "1e-4", "+2"), finite. Refused: hexadecimal
/// ("0x10"), binary and octal prefixes, digit separators ("1_000"), "inf", "nan", values that
/// overflow a double ("1e400") and surrounding spaces.
bool is_decimal_number(const std::string& text);

/// A check for numeric options: refuses what is_decimal_number refuses, which CLI11 alone
/// would read (it takes "0x10" as 16).
CLI::Validator decimal_number();

/// A check for options naming a file or folder: refuses an empty name, which would otherwise
/// mean "not given" and write nothing.
CLI::Validator nonempty_name();

}  // namespace fosssim
