#include "cli/parse_command_line.h"

#include <iostream>

#include "cli/exit_codes.h"

namespace fosssim {

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv,
                                      const std::string& hint) {
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
