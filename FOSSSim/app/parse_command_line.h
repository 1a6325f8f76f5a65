#pragma once
// The one way FOSSSim's programs parse their command lines and report usage errors.

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>

#include "app/exit_codes.h"

namespace fosssim {

/// Parses argv into `app`. Returns the status the program should exit with now: 0 after
/// printing --help or --version, 2 after a usage error (reported on standard error as
/// "NAME: error: ...", followed by `hint`); nullopt when the program should go on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv,
                                             const std::string& hint = "") {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
  } catch (const CLI::CallForVersion&) {
    std::cout << app.version() << "\n";
  } catch (const CLI::ParseError& error) {
    const std::string name = app.get_name();
    std::cerr << name << ": error: " << error.what() << "\n"
              << (hint.empty() ? "Run " + name + " --help for the options." : hint) << "\n";
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace fosssim
