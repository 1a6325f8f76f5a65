#include "cli/parse_command_line.h"

#include <charconv>
#include <cmath>
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

bool is_decimal_number(const std::string& text) {
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-') digits.remove_prefix(1);
  if (digits.empty()) return false;
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value,
                                            std::chars_format::general);
  return error == std::errc() && end == digits.data() + digits.size() && std::isfinite(value);
}

CLI::Validator decimal_number() {
  return CLI::Validator(
      [](const std::string& text) {
        return is_decimal_number(text)
                   ? std::string()
                   : "must be a finite decimal number (like 0.01, -3 or 1e-4), found '" + text +
                         "'";
      },
      "", "DECIMAL");
}

CLI::Validator nonempty_name() {
  return CLI::Validator(
      [](const std::string& text) {
        return text.empty() ? std::string("the name cannot be empty") : std::string();
      },
      "", "NONEMPTY");
}

}  // namespace fosssim
