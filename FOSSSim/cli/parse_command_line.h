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

}  // namespace fosssim
