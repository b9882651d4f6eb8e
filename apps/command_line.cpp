// Command-line errors in framedyn's own form; see command_line.h.
#include "apps/command_line.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <utility>

namespace framedyn::apps {

namespace {

// Text after `prefix` if `text` starts with it.
bool after(const std::string& text, const std::string& prefix, std::string& rest) {
  if (text.rfind(prefix, 0) != 0) return false;
  rest = text.substr(prefix.size());
  return true;
}

std::string help_of(const CLI::App* command) {
  return command ? fmt::format("framedyn {} --help", command->get_name()) : std::string("framedyn --help");
}

}  // namespace

core::InputLocation command_line(const std::string& option) { return {"command line", 0, option}; }

core::InputError nothing_to_relieve(const std::string& mesh_path) {
  return core::InputError(command_line("--inertia-relief"),
                          "a frame whose supports leave rigid motions free (inertia relief takes the loads' unbalanced part by those motions' "
                          "accelerations)",
                          mesh_path + ", held against every rigid motion by its supports");
}

CLI::Validator number_check(const std::string& expected, const std::function<bool(double)>& ok, bool integer) {
  return CLI::Validator(
      [expected, ok, integer](std::string& input) {
        char* end = nullptr;
        const double v = std::strtod(input.c_str(), &end);
        const bool number = !input.empty() && end == input.c_str() + input.size() && std::isfinite(v);
        if (number && (!integer || v == std::floor(v)) && ok(v)) return std::string();
        return fmt::format("expected {}, found '{}'", expected, input);
      },
      "");
}

std::string command_line_message(const CLI::ParseError& error, const CLI::App* command, const std::string& first_argument) {
  const std::string kind = error.get_name(), text = error.what();
  std::string rest;
  // A std::string, not what()'s pointer into the temporary error (freed at the end of the return).
  // Every command, as main registers them.
  static const char* const kCommands = "a command: modes, static, harmonic, random, run, frame-response, sweep or rainflow (framedyn --help)";
  const auto located = [](const std::string& key, const std::string& expected, const std::string& found) -> std::string {
    return core::InputError(command_line(key), expected, found).what();
  };
  if (kind == "RequiredError") {
    // An unknown command is not an extra argument to CLI11 but a missing command.
    if (text == "A subcommand is required")
      return located("", kCommands,
                     first_argument.empty() || first_argument[0] == '-' ? std::string("none") : "'" + first_argument + "'");
    const std::size_t at = text.rfind(" is required");
    if (at != std::string::npos) {
      const std::string name = text.substr(0, at);
      return located(name, fmt::format("a value for {} (required; {})", name, help_of(command)), "none");
    }
  }
  // CLI11 names an extras error after the subcommand, not "ExtrasError": match the text.
  if (after(text, "The following argument was not expected: ", rest) || after(text, "The following arguments were not expected: ", rest))
    return located("", command ? fmt::format("the options of framedyn {} ({})", command->get_name(), help_of(command))
                               : std::string(kCommands),
                   "'" + rest + "'");
  if (kind == "ConversionError" && after(text, "Could not convert: ", rest)) {
    const std::size_t eq = rest.find(" = ");
    if (eq != std::string::npos) return located(rest.substr(0, eq), "a number", "'" + rest.substr(eq + 3) + "'");
  }
  if (kind == "ValidationError") {
    // "--modes: expected ..., found '0'" from number_check: the option, then the message.
    const std::size_t colon = text.find(": ");
    if (colon != std::string::npos) return core::InputError(command_line(text.substr(0, colon)), text.substr(colon + 2)).what();
  }
  if (kind == "ExcludesError") {
    // "--verbose excludes --quiet" (or the other way round, by the order given): named the same either way.
    const std::size_t at = text.find(" excludes ");
    if (at != std::string::npos) {
      std::string a = text.substr(0, at), b = text.substr(at + 10);
      if (b < a) std::swap(a, b);
      return located(a, fmt::format("at most one of {} and {} ({})", a, b, help_of(command)), "both");
    }
  }
  if (kind == "ArgumentMismatch") {
    // "--modes: 1 required INT missing": the option is the text before the colon.
    const std::size_t colon = text.find(": ");
    if (colon != std::string::npos && text.rfind("-", 0) == 0) return located(text.substr(0, colon), "a value after the option", "none");
  }
  return core::InputError(command_line(""), text + " (" + help_of(command) + ")").what();
}

}  // namespace framedyn::apps
