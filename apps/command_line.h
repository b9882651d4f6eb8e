// Command-line errors in framedyn's own form. CLI11 reports a bad command
// line in its words ("--modes: Value 0 not in range [1 - 100000]"); the
// program says, like every other input error, where (the command line and
// the option), what it expected and what it found (docs/errors.md, CLI rows).
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

#include "core/error.h"

namespace framedyn::apps {

// The message for a CLI11 parse error; `command` is the subcommand being
// parsed when the error happened (nullptr: none yet), `first_argument` the
// first word after "framedyn" (the command the user meant; "" if none).
std::string command_line_message(const CLI::ParseError& error, const CLI::App* command, const std::string& first_argument);

// An input error located on the command line, e.g. at("--modes") for
// "command line: --modes: expected ..., found ...".
core::InputLocation command_line(const std::string& option);

// `--inertia-relief` asked for a frame (mesh `mesh_path`) its supports hold
// against every rigid motion: nothing to relieve (static, random).
core::InputError nothing_to_relieve(const std::string& mesh_path);

// A check of a numeric option whose failure reads "expected EXPECTED, found
// 'VALUE'" (CLI11's own range checks print "Value 0 not in range 1 to
// 100000", and 2.2e-308 for "positive"); `integer` refuses "2.5" too.
CLI::Validator number_check(const std::string& expected, const std::function<bool(double)>& ok, bool integer);

}  // namespace framedyn::apps
